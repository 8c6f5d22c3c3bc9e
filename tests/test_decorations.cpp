// The picture's decorations and framing (display/overlay/decorations.h,
// display/overlay/box_outline.h, camera_fit_inside, the stock view's initial
// camera, the legend's captions): the triad's arrows point where the
// machine's axes go on the screen, the scale bar is a 1-2-5 length as long
// as the view shows it, the stock is framed inside the picture, clear of
// the legend and the decorations, for every preset and a range of stock
// shapes; wrong answers (a mirrored axis, a bar off by a step, a box
// outside) are caught as well as right ones passed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/math/trig.h"
#include "display/overlay/box_outline.h"
#include "display/overlay/decorations.h"
#include "display/overlay/font.h"
#include "display/overlay/legend.h"
#include "display/view/stock_view.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;

BoxNm box_mm(double x1, double y1, double z1) {
  return BoxNm{PointNm{0, 0, 0}, PointNm{static_cast<int64_t>(x1 * mm), static_cast<int64_t>(y1 * mm),
                                          static_cast<int64_t>(z1 * mm)}};
}

SceneFrame scene_of(const BoxNm& b) {
  SceneFrame s{};
  s.box = b;
  s.x0_nm = b.lo.x_nm;
  s.y0_nm = b.lo.y_nm;
  s.z0_nm = b.lo.z_nm;
  s.pitch_nm = 100000;
  s.lsb_nm = 1000;
  s.stock_top_nm = b.hi.z_nm;
  return s;
}

// The screen position of a machine point, in pixels.
void screen_px(const View& v, PointNm p, double* x, double* y) {
  const RasterVertex r = clip_project(v.proj, view_point(v, p));
  *x = r.x_q4 / 16.0;
  *y = r.y_q4 / 16.0;
}

Camera camera_at(int k, Projection proj) {
  Camera c = camera_preset(static_cast<ViewPreset>(k % 4));
  c.projection = proj;
  if (k >= 4) {  // off-preset directions
    c.azimuth_bam += static_cast<uint32_t>(k) * 0x13579BDu;
    c.elevation_bam = static_cast<int32_t>(bam_from_mdeg(static_cast<int64_t>((k * 37) % 170 - 85) * 1000));
  }
  return c;
}

const BoxNm kShapes[] = {box_mm(100, 70, 20), box_mm(20, 200, 5), box_mm(300, 10, 50), box_mm(50, 50, 50),
                         box_mm(400, 300, 2), box_mm(5, 5, 80)};
const int32_t kSizes[][2] = {{640, 480}, {320, 240}, {480, 272}, {200, 400}};

}  // namespace

TEST(triad_points_where_the_axes_go_on_screen) {
  int checked = 0;
  for (int k = 0; k < 40; ++k) {
    for (int proj = 0; proj < 2; ++proj) {
      const BoxNm b = box_mm(100, 60, 25);
      Camera c = camera_at(k, proj ? Projection::kPerspective : Projection::kOrthographic);
      camera_fit(&c, b, 640, 480);
      View v;
      view_build(c, scene_of(b), 640, 480, &v);
      std::vector<uint32_t> px(640 * 480, 0);
      const FrameView fb{px.data(), 640, 480, 640 * 4, PixelFormat::kXrgb8888};
      const Triad t = decorations_triad(fb, v, b, ScreenRect{0, 0, 640, 480});
      // The screen direction of each axis at the target (the frame's centre).
      const PointNm o = c.target;
      double x0, y0;
      screen_px(v, o, &x0, &y0);
      for (int a = 0; a < 3; ++a) {
        PointNm e = o;
        (a == 0 ? e.x_nm : a == 1 ? e.y_nm : e.z_nm) += 10 * mm;
        double x1, y1;
        screen_px(v, e, &x1, &y1);
        const double dx = x1 - x0, dy = y1 - y0, n = std::hypot(dx, dy);
        const double tx = t.tip[a][0], ty = t.tip[a][1], tn = std::hypot(tx, ty);
        if (n < 1 || tn < 6) continue;  // nearly along the view: a dot
        // Same direction within 6 degrees (the tip is rounded to a pixel).
        const double cosang = (dx * tx + dy * ty) / (n * tn);
        CHECK_GT(cosang, std::cos(6 * 3.14159265 / 180));
        ++checked;
      }
      // Drawn: the X colour on the X shaft, half way to its tip.
      decorations_draw(fb, v, b, ScreenRect{0, 0, 640, 480});
      if (std::hypot(t.tip[0][0], t.tip[0][1]) >= 12) {
        const Rgb got = pixel_unpack(fb.format, frame_pixel(fb, t.ox + t.tip[0][0] / 2, t.oy + t.tip[0][1] / 2));
        CHECK(got.r > 200 && got.g < 100 && got.b < 100);
      }
    }
  }
  CHECK_GT(checked, 150);
  // A false alarm would be a mirrored axis passing: the iso view's X goes
  // to the lower right, Y to the upper right, Z straight up.
  const BoxNm b = box_mm(100, 60, 25);
  Camera c = camera_preset(ViewPreset::kIso);
  camera_fit(&c, b, 640, 480);
  View v;
  view_build(c, scene_of(b), 640, 480, &v);
  std::vector<uint32_t> px(640 * 480, 0);
  const FrameView fb{px.data(), 640, 480, 640 * 4, PixelFormat::kXrgb8888};
  const Triad t = decorations_triad(fb, v, b, ScreenRect{0, 0, 640, 480});
  CHECK(t.tip[0][0] > 0 && t.tip[0][1] > 0);
  CHECK(t.tip[1][0] > 0 && t.tip[1][1] < 0);
  CHECK(t.tip[2][0] == 0 && t.tip[2][1] < 0);
}

TEST(scale_bar_is_a_round_length_as_long_as_the_view_shows_it) {
  int seen_sub_mm = 0, seen_big = 0;
  for (int k = 0; k < 48; ++k) {
    for (int proj = 0; proj < 2; ++proj) {
      const BoxNm b = kShapes[k % 6];
      const int32_t* size = kSizes[k % 4];
      Camera c = camera_at(k, proj ? Projection::kPerspective : Projection::kOrthographic);
      camera_fit(&c, b, size[0], size[1]);
      if (k % 3 == 1) c.view_height_nm /= 40, c.distance_nm /= 3;  // zoomed in
      if (k % 3 == 2) c.view_height_nm /= 2000;                     // to a hundredth of a mm
      View v;
      view_build(c, scene_of(b), size[0], size[1], &v);
      const int32_t max_px = 120;
      const ScaleBar bar = scale_bar_choose(v, b, max_px);
      // 1, 2 or 5 times a power of ten.
      int64_t m = bar.length_nm;
      while (m % 10 == 0) m /= 10;
      CHECK(m == 1 || m == 2 || m == 5);
      CHECK_LE(bar.length_px, max_px);
      // As long as the view shows it at the stock's centre, along screen right.
      const PointNm cen{b.hi.x_nm / 2, b.hi.y_nm / 2, b.hi.z_nm / 2};
      const PointNm end{cen.x_nm + static_cast<int64_t>(std::llround(bar.length_nm * (v.right_q30[0] / 1073741824.0))),
                        cen.y_nm + static_cast<int64_t>(std::llround(bar.length_nm * (v.right_q30[1] / 1073741824.0))),
                        cen.z_nm};
      double x0, y0, x1, y1;
      screen_px(v, cen, &x0, &y0);
      screen_px(v, end, &x1, &y1);
      CHECK_NEAR(std::hypot(x1 - x0, y1 - y0), bar.length_px, 1.5);
      // The next round length up would not fit: the bar is the longest.
      const int64_t next = m == 2 ? bar.length_nm / 2 * 5 : bar.length_nm * 2;
      CHECK_GT(static_cast<double>(bar.length_px) * next / bar.length_nm, max_px - 1.0);
      seen_sub_mm += bar.length_nm < mm;
      seen_big += bar.length_nm >= 50 * mm;
    }
  }
  CHECK_GT(seen_sub_mm, 0);
  CHECK_GT(seen_big, 0);
}

TEST(scale_bar_labels) {
  char t[16];
  const struct { int64_t nm; const char* want; } kCases[] = {
      {10 * mm, "10 mm"}, {mm / 2, "0.5 mm"}, {mm / 50, "0.02 mm"}, {1000, "0.001 mm"}, {200 * mm, "200 mm"},
      {1000000 * mm, "1000000 mm"}, {mm, "1 mm"}};
  for (const auto& c : kCases) {
    const int32_t n = scale_bar_label(c.nm, t);
    CHECK_EQ(std::string(t), std::string(c.want));
    CHECK_EQ(n, static_cast<int32_t>(std::strlen(c.want)));
  }
}

TEST(box_outline_meets_only_what_it_covers) {
  const BoxNm b = box_mm(100, 70, 20);
  Camera c = camera_preset(ViewPreset::kIso);
  camera_fit(&c, b, 640, 480);
  View v;
  view_build(c, scene_of(b), 640, 480, &v);
  const ScreenRect bounds = box_outline_bounds(v, b);
  // The iso outline is a hexagon: its bounding box's corners are outside it.
  CHECK(!box_outline_meets(v, b, ScreenRect{bounds.x0, bounds.y1 - 40, bounds.x0 + 40, bounds.y1}));
  CHECK(!box_outline_meets(v, b, ScreenRect{bounds.x1 - 30, bounds.y0, bounds.x1, bounds.y0 + 30}));
  CHECK(!box_outline_meets(v, b, ScreenRect{0, 0, 10, 10}));
  // Its centre and its extreme points are inside.
  CHECK(box_outline_meets(v, b, ScreenRect{320, 240, 321, 241}));
  CHECK(box_outline_meets(v, b, ScreenRect{bounds.x0, 0, bounds.x0 + 2, 480}));
  CHECK(box_outline_meets(v, b, ScreenRect{0, bounds.y1 - 2, 640, 480}));
  CHECK(box_outline_meets(v, b, ScreenRect{0, 0, 640, 480}));  // a rectangle around it
  CHECK(!box_outline_meets(v, b, ScreenRect{0, 0, 0, 0}));
}

TEST(fit_inside_frames_the_box_in_the_rectangle) {
  int cases = 0;
  for (int proj = 0; proj < 2; ++proj)
    for (int p = 0; p < 4; ++p)
      for (const BoxNm& b : kShapes)
        for (const auto& size : kSizes) {
          const int32_t w = size[0], h = size[1];
          const ScreenRect insides[3] = {{0, 0, w, h}, {0, 0, w, h - h / 7}, {w / 5, h / 10, w, h}};
          for (const ScreenRect& in : insides) {
            Camera c = camera_preset(static_cast<ViewPreset>(p));
            c.projection = proj ? Projection::kPerspective : Projection::kOrthographic;
            camera_fit_inside(&c, b, w, h, in);
            View v;
            view_build(c, scene_of(b), w, h, &v);
            const ScreenRect r = box_outline_bounds(v, b);
            CHECK_GE(r.x0, in.x0);
            CHECK_GE(r.y0, in.y0);
            CHECK_LE(r.x1, in.x1);
            CHECK_LE(r.y1, in.y1);
            // And filling it along one axis (not framed far too small;
            // perspective frames the bounding sphere, loose for a long box).
            const double fill = std::fmax(double(r.x1 - r.x0) / (in.x1 - in.x0), double(r.y1 - r.y0) / (in.y1 - in.y0));
            CHECK_GE(fill, proj ? 0.05 : 0.88);
            ++cases;
          }
        }
  CHECK_EQ(cases, 2 * 4 * 6 * 4 * 3);
  // The whole frame is camera_fit's camera, field for field.
  for (int p = 0; p < 4; ++p) {
    Camera a = camera_preset(static_cast<ViewPreset>(p)), b = a;
    camera_fit(&a, kShapes[0], 640, 480);
    camera_fit_inside(&b, kShapes[0], 640, 480, ScreenRect{0, 0, 640, 480});
    CHECK(a.target == b.target);
    CHECK_EQ(a.view_height_nm, b.view_height_nm);
  }
}

namespace {

// A stock view over a block of the shape's x:y proportions, framed as the
// CLI frames it: a legend with captions and decorations on; supersampled
// 2x2 as the CLI's stills and saved frames are (tools/run/run_render.cpp).
struct ViewCase {
  t::TestGrid<height_t> grid;
  t::TestFrame frame;
  std::unique_ptr<StockView> view{new StockView()};
  std::vector<uint64_t> big;
  ViewLegend legend;
  bool init(int32_t nx, int32_t ny, int64_t height_nm, int32_t w, int32_t h, const CameraChoice& cam,
            bool supersampled = false) {
    t::make_block(&grid, nx, ny, 500000, height_nm);
    t::make_frame(&frame, w, h, PixelFormat::kXrgb8888);
    if (supersampled) big.assign(stock_view_supersample_bytes(w, h, PixelFormat::kXrgb8888) / 8 + 1, 0);
    stock_view_set_supersample(view.get(), supersampled ? big.data() : nullptr);
    frame.scratch.assign(stock_view_scratch_bytes(grid.g, w, h, supersampled) / 8 + 1, 0);
    if (!ok(stock_view_init(view.get(), grid.g, frame.fb, cam, frame.scratch.data(), frame.scratch.size() * 8)))
      return false;
    legend.n = 3;
    for (int k = 0; k < 3; ++k) legend.colour[k] = Rgb{static_cast<uint8_t>(80 * k), 100, 100};
    std::strcpy(legend.labels[0], "-1");
    std::strcpy(legend.labels[1], "+1");
    std::strcpy(legend.title, "MM");
    std::strcpy(legend.low_caption, "gouge (cut below the design)");
    std::strcpy(legend.high_caption, "material left");
    stock_view_set_legend(view.get(), &legend);
    stock_view_set_decorations(view.get(), true);
    return true;
  }
};

}  // namespace

TEST(stock_view_frames_the_stock_clear_of_legend_and_decorations) {
  const int32_t kGrids[][3] = {{200, 140, 20}, {40, 400, 5}, {600, 20, 50}, {100, 100, 50}, {300, 225, 2}, {10, 10, 80}};
  int reserved = 0, cases = 0;
  for (int p = 0; p < 4; ++p)
    for (const auto& g : kGrids)
      for (const auto& size : kSizes) {
        ViewCase vc;
        CameraChoice cam;
        cam.preset = static_cast<ViewPreset>(p);
        CHECK(vc.init(g[0], g[1], g[2] * mm, size[0], size[1], cam));
        StockView& sv = *vc.view;
        const View& v = sv.r.view;
        DexelGrid<height_t>* grid = &vc.grid.g;
        // The tool far above the stock: clipped at the top if need be.
        stock_view_draw(&sv, grid, CutterPose{true, PointNm{g[0] * 250000, g[1] * 250000, 500 * mm}});
        const BoxNm stock = renderer_stock_box(sv.r);
        const ScreenRect area = stock_view_picture_area(sv);
        CHECK_LT(area.y1, size[1]);  // the legend took its strip
        const ScreenRect r = box_outline_bounds(v, stock);
        CHECK_GE(r.x0, 0);
        CHECK_GE(r.y0, 0);
        CHECK_LE(r.x1, area.x1);
        CHECK_LE(r.y1, area.y1);
        const ScreenRect deco = decorations_rect(sv.fb, v, stock, area);
        CHECK(!deco.empty());
        CHECK(!box_outline_meets(v, stock, deco));
        reserved += r.y1 <= deco.y0;
        ++cases;
      }
  // Some views needed the strip above the decorations (a top view of a
  // wide stock), not all (an iso view leaves the corner free).
  std::printf("  %d of %d framed above the decorations\n", reserved, cases);
  CHECK_GT(reserved, 0);
  CHECK_LT(reserved, cases);
}

namespace {

// Twelve cuts drawn one at a time (a partial redraw each, as `dexmill run`
// saves its frames) against the same cuts drawn once; the frame's hash.
uint64_t incremental_equals_full(bool supersampled) {
  ViewCase a, b;
  CameraChoice cam;
  CHECK(a.init(120, 80, 20 * mm, 320, 240, cam, supersampled));
  CHECK(b.init(120, 80, 20 * mm, 320, 240, cam, supersampled));
  t::TestCutter cutter;
  t::make_cutter(a.grid.g, t::ball_tool(6 * mm), &cutter);
  stock_view_draw(a.view.get(), &a.grid.g, CutterPose{true, PointNm{0, 0, 30 * mm}});
  for (int k = 0; k < 12; ++k) {
    const PointNm p0{(5 + 4 * k) * mm, 10 * mm, 16 * mm}, p1{(7 + 4 * k) * mm, 30 * mm, 17 * mm};
    CutStats st;
    stamp_line(&a.grid.g, cutter.c, p0, p1, &st);
    stock_view_note(a.view.get(), a.grid.g.dirty);
    a.grid.g.dirty = GridRect::none();
    stock_view_draw(a.view.get(), &a.grid.g, CutterPose{true, p1});
  }
  // The same cuts drawn once.
  for (int k = 0; k < 12; ++k) {
    const PointNm p0{(5 + 4 * k) * mm, 10 * mm, 16 * mm}, p1{(7 + 4 * k) * mm, 30 * mm, 17 * mm};
    CutStats st;
    stamp_line(&b.grid.g, cutter.c, p0, p1, &st);
  }
  b.grid.g.dirty = GridRect::none();
  stock_view_draw(b.view.get(), &b.grid.g, CutterPose{true, PointNm{51 * mm, 30 * mm, 17 * mm}});
  CHECK_EQ(frame_hash(a.frame.fb), frame_hash(b.frame.fb));
  // Decorations off: the corner is the background again.
  stock_view_set_decorations(b.view.get(), false);
  stock_view_draw(b.view.get(), &b.grid.g, CutterPose{true, PointNm{51 * mm, 30 * mm, 17 * mm}});
  CHECK(frame_hash(a.frame.fb) != frame_hash(b.frame.fb));
  return frame_hash(a.frame.fb);
}

}  // namespace

TEST(decorations_redrawn_incrementally_equal_a_full_frame) { incremental_equals_full(false); }

// Supersampled, the repainted rectangles are resolved on the renderer's
// 4-pixel tiles (display/view/stock_view.h), so a partial redraw still equals a
// full one; and the picture is not the aliased one.
TEST(supersampled_redrawn_incrementally_equal_a_full_frame) {
  CHECK(incremental_equals_full(true) != incremental_equals_full(false));
}

TEST(legend_captions_say_which_end_is_a_gouge) {
  // Every character of the captions has a glyph (a space is blank).
  const char* caps[2] = {"gouge (cut below the design)", "material left"};
  for (const char* c : caps)
    for (const char* q = c; *q; ++q) {
      const uint8_t* g = font_glyph(*q);
      int bits = 0;
      for (int r = 0; r < 7; ++r) bits += g[r];
      CHECK(*q == ' ' ? bits == 0 : bits != 0);
    }
  std::vector<uint32_t> with(640 * 480, 0), without(640 * 480, 0), text(640 * 480, 0);
  const FrameView fw{with.data(), 640, 480, 640 * 4, PixelFormat::kXrgb8888};
  const FrameView fo{without.data(), 640, 480, 640 * 4, PixelFormat::kXrgb8888};
  const FrameView ft{text.data(), 640, 480, 640 * 4, PixelFormat::kXrgb8888};
  const Rgb colour[3] = {{200, 30, 30}, {250, 250, 250}, {30, 160, 60}};
  const char* labels[2] = {"-0.05", "+0.05"};
  legend_draw(fw, colour, 3, labels, "MM", caps[0], caps[1]);
  legend_draw(fo, colour, 3, labels, "MM");
  const ScreenRect rw = legend_rect(fw, true), ro = legend_rect(fo);
  CHECK_LT(rw.y0, ro.y0);  // a row taller
  CHECK_EQ(rw.y1, 480);
  // The caption row: the left caption's pixels are the font's, at the
  // legend's margin; the uncaptioned legend has no ink there.
  const int32_t s = legend_font_scale(fw), y = rw.y0 + 2 * s;
  frame_fill(ft, ScreenRect{0, 0, 640, 480}, pixel_pack(ft.format, Rgb{24, 28, 36}));
  font_draw(ft, 4 * s, y, caps[0], std::strlen(caps[0]), pixel_pack(ft.format, Rgb{230, 232, 236}), s);
  const int32_t left_w = font_text_width(std::strlen(caps[0]), s);
  int same = 0, ink = 0, ink_without = 0;
  for (int32_t yy = y; yy < y + kFontCellH * s; ++yy)
    for (int32_t x = 0; x < 4 * s + left_w; ++x) {
      same += frame_pixel(fw, x, yy) == frame_pixel(ft, x, yy);
      ink += pixel_unpack(fw.format, frame_pixel(fw, x, yy)).r == 230;
    }
  for (int32_t yy = ro.y0; yy < ro.y0 + 2 * s; ++yy)
    for (int32_t x = 0; x < 640; ++x) ink_without += pixel_unpack(fo.format, frame_pixel(fo, x, yy)).r == 230;
  CHECK_EQ(same, (4 * s + left_w) * kFontCellH * s);
  CHECK_GT(ink, 500);
  CHECK_EQ(ink_without, 0);
  // The right caption ends at or before the frame's edge, after the left one.
  int32_t last_ink = -1;
  for (int32_t yy = y; yy < y + kFontCellH * s; ++yy)
    for (int32_t x = 4 * s + left_w; x < 640; ++x)
      if (pixel_unpack(fw.format, frame_pixel(fw, x, yy)).r == 230) last_ink = std::max(last_ink, x);
  CHECK_GT(last_ink, 4 * s + left_w + font_text_width(10, s));
  CHECK_LT(last_ink, 640);
}

TEST(legend_captions_shorten_on_narrow_frames) {
  // 160 wide: "gouge" without its bracket, then "material left", apart;
  // 60 wide: no room for both, no captions (rather than overlapping ones).
  const char* caps[2] = {"gouge (cut below the design)", "material left"};
  const Rgb colour[3] = {{200, 30, 30}, {250, 250, 250}, {30, 160, 60}};
  const char* labels[2] = {"-0.05", "+0.05"};
  for (int32_t w : {160, 60}) {
    std::vector<uint32_t> px(static_cast<size_t>(w) * 120, 0), want(px.size(), 0);
    const FrameView fb{px.data(), w, 120, w * 4, PixelFormat::kXrgb8888};
    const FrameView ft{want.data(), w, 120, w * 4, PixelFormat::kXrgb8888};
    legend_draw(fb, colour, 3, labels, "MM", caps[0], caps[1]);
    const int32_t y = legend_rect(fb, true).y0 + 2;  // scale 1
    frame_fill(ft, ScreenRect{0, 0, w, 120}, pixel_pack(ft.format, Rgb{24, 28, 36}));
    if (w == 160) {
      font_draw(ft, 4, y, "gouge", 5, pixel_pack(ft.format, Rgb{230, 232, 236}), 1);
      // Ending where "gouge material left" would (wider than the swatches' 3 x 36).
      const int32_t right = 4 + font_text_width(5 + 13 + 1, 1);
      font_draw(ft, right - font_text_width(13, 1) + 1, y, caps[1], 13, pixel_pack(ft.format, Rgb{230, 232, 236}), 1);
    }
    int differ = 0;
    for (int32_t yy = y; yy < y + kFontCellH; ++yy)
      for (int32_t x = 0; x < w; ++x) differ += frame_pixel(fb, x, yy) != frame_pixel(ft, x, yy);
    CHECK_EQ(differ, 0);
  }
}

TEST(decorations_give_way_on_a_thumbnail) {
  // A top view of a wide block in 64 x 48 pixels: framing above the
  // decorations would leave the stock a sliver, so they are left out and
  // the stock fills the picture; at 640 x 480 they are drawn below it.
  for (int32_t w : {64, 640}) {
    const int32_t h = w * 3 / 4;
    ViewCase with, without;
    CameraChoice cam;
    cam.preset = ViewPreset::kTop;
    CHECK(with.init(200, 140, 20 * mm, w, h, cam));
    CHECK(without.init(200, 140, 20 * mm, w, h, cam));
    stock_view_set_legend(with.view.get(), nullptr);
    stock_view_set_legend(without.view.get(), nullptr);
    stock_view_set_decorations(without.view.get(), false);
    stock_view_draw(with.view.get(), &with.grid.g, CutterPose{});
    stock_view_draw(without.view.get(), &without.grid.g, CutterPose{});
    const bool same = frame_hash(with.frame.fb) == frame_hash(without.frame.fb);
    CHECK_EQ(same, w == 64);
    const ScreenRect r = box_outline_bounds(with.view->r.view, renderer_stock_box(with.view->r));
    CHECK_GE(static_cast<double>(r.x1 - r.x0) / w, w == 64 ? 0.88 : 0.6);
    CHECK_LE(r.y1, h);
  }
}
