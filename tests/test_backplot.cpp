// The backplot (display/overlay/backplot.h): its pixels against a double-precision
// line through the projected ends, the depth test against a rendered part,
// and redraws inside rectangles against a full redraw, in both pixel and
// depth formats.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "display/overlay/backplot.h"
#include "display/raster/clip.h"
#include "tests/rng.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = 1000000;
constexpr int32_t kW = 320, kH = 240;

struct Scene {
  t::TestGrid<uint16_t> tg;
  t::TestFrame f;
  Renderer<uint16_t> r;
  std::vector<uint32_t> rendered;  // the part without a path
};

void make_scene(Scene* s, PixelFormat fmt, ZFormat zf, ViewPreset preset) {
  t::make_pocketed(&s->tg);
  t::make_frame(&s->f, kW, kH, fmt);
  RenderOptions opt;
  opt.zformat = zf;
  CHECK(t::init_renderer(&s->r, s->tg.g, &s->f, opt));
  renderer_set_camera(&s->r, renderer_fit(s->r, preset));
  render_full(&s->r, &s->tg.g, CutterPose{});
  s->rendered = s->f.pixels;
}

DepthView depth_of(const Renderer<uint16_t>& r) {
  DepthView d;
  d.z = r.target.z;
  d.stride_bytes = r.target.z_stride;
  d.format = r.target.zformat;
  return d;
}

double uniform01(t::Rng* rng) { return static_cast<double>(rng->next() >> 11) / 9007199254740992.0; }

PathSegment seg(double x0, double y0, double z0, double x1, double y1, double z1, PathKind k) {
  auto nm = [](double v) { return static_cast<int64_t>(std::llround(v * mm)); };
  return PathSegment{PointNm{nm(x0), nm(y0), nm(z0)}, PointNm{nm(x1), nm(y1), nm(z1)}, k};
}

// Pixels of the frame that differ from `base`.
std::vector<int> changed(const FrameView& fb, const std::vector<uint32_t>& base) {
  std::vector<int> out;
  const int bpp = pixel_bytes(fb.format);
  const uint8_t* now = static_cast<const uint8_t*>(fb.pixels);
  const uint8_t* was = reinterpret_cast<const uint8_t*>(base.data());
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x)
      if (std::memcmp(now + y * fb.stride_bytes + x * bpp, was + y * fb.stride_bytes + x * bpp, bpp) != 0)
        out.push_back(y * fb.width + x);
  return out;
}

}  // namespace

namespace {

// Over a depth buffer that lets everything through: every lit pixel's
// centre within half the width (plus the rounding of the projected ends
// and of one step, 2/16 pixel) of the line
// through the ends as view_point and clip_project place them, `w` pixels
// per pixel centre along the longer axis, and for rapids only the dashes
// (w times as long).
void check_pixels_follow_line(int32_t w) {
  static Scene s;
  make_scene(&s, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso);
  std::vector<uint32_t> far_z(static_cast<size_t>(kW) * kH, 0xFFFFFFFFu);
  DepthView z{reinterpret_cast<const uint8_t*>(far_z.data()), kW * 4, ZFormat::kZ32};
  t::Rng rng(7);
  int lit_total = 0, worst_off_q4 = 0;
  for (int k = 0; k < 300; ++k) {
    // Ends mostly over the part; one in ten far outside the frame (clipped).
    const double spread = k % 10 == 0 ? 2000.0 : 80.0;
    auto coord = [&](double centre) { return centre + (uniform01(&rng) - 0.5) * spread; };
    const PathKind kind = k % 3 == 0 ? PathKind::kRapid : PathKind::kFeed;
    const PathSegment sg = seg(coord(30), coord(20), coord(10), coord(30), coord(20), coord(10), kind);
    frame_fill(s.f.fb, ScreenRect{0, 0, kW, kH}, 0);
    std::vector<uint32_t> black(s.f.pixels.size(), 0);
    backplot_draw(s.f.fb, z, s.r.view, &sg, 1, 0, ScreenRect{0, 0, kW, kH}, BackplotColours(), w);
    const std::vector<int> lit = changed(s.f.fb, black);
    lit_total += static_cast<int>(lit.size());
    // The line in screen q4, in double, from the unclipped ends.
    const ClipVertex ca = view_point(s.r.view, sg.a), cb = view_point(s.r.view, sg.b);
    const double ax = static_cast<double>(ca.x), ay = static_cast<double>(ca.y);
    const double dx = static_cast<double>(cb.x - ca.x), dy = static_cast<double>(cb.y - ca.y);
    const bool x_major = std::fabs(dx) >= std::fabs(dy);
    const double len = x_major ? std::fabs(dx) : std::fabs(dy);
    if (len < 16) continue;  // shorter than a pixel: one pixel, checked below
    int on_axis = 0, dashes_ok = 0;
    for (int p : lit) {
      const int px = p % kW, py = p / kW;
      const double cx = 16.0 * px + 8, cy = 16.0 * py + 8;
      // Distance along the minor axis from the line at this major coordinate.
      const double tt = x_major ? (cx - ax) / dx : (cy - ay) / dy;
      const double off = x_major ? std::fabs(cy - (ay + dy * tt)) : std::fabs(cx - (ax + dx * tt));
      worst_off_q4 = std::max(worst_off_q4, static_cast<int>(std::ceil(off)));
      CHECK(off <= 8.0 * w + 2.0);
      CHECK(tt >= -1e-9 && tt <= 1 + 1e-9);
      ++on_axis;
      const int step = x_major ? px : py;
      if (kind == PathKind::kRapid && ((step / (kBackplotDashPx * w)) & 1) == 0) ++dashes_ok;
    }
    // Pixel centres along the major axis inside the frame and the segment.
    const double lo = x_major ? std::min(ax, ax + dx) : std::min(ay, ay + dy);
    const double hi = x_major ? std::max(ax, ax + dx) : std::max(ay, ay + dy);
    int expect = 0;
    const int limit = x_major ? kW : kH;
    for (int p = 0; p < limit; ++p) {
      const double c = 16.0 * p + 8;
      if (c < lo || c > hi) continue;
      const double tt = x_major ? (c - ax) / dx : (c - ay) / dy;
      const double m = (x_major ? ay + dy * tt : ax + dx * tt) / 16.0;
      if (kind == PathKind::kRapid && ((p / (kBackplotDashPx * w)) & 1)) continue;
      // The pixels across: the one m falls in, or the w whose centres lie
      // within w / 2 of it; those inside the frame.
      const int first = w == 1 ? static_cast<int>(std::floor(m)) : static_cast<int>(std::ceil(m - 0.5 - w / 2.0));
      for (int i = first; i < first + w; ++i) expect += i >= 0 && i < (x_major ? kH : kW);
    }
    if (kind == PathKind::kRapid) CHECK_EQ(dashes_ok, on_axis);
    // Allow one pixel either way where the line leaves the frame or a
    // clipped end was moved onto the guard band (w across).
    if (std::abs(on_axis - expect) > 2 * w) std::printf("  segment %d: %d lit, %d expected\n", k, on_axis, expect);
    CHECK(std::abs(on_axis - expect) <= 2 * w);
  }
  std::printf("  backplot %d px wide: %d pixels lit by 300 segments, worst offset %.2f px\n", static_cast<int>(w),
              lit_total, worst_off_q4 / 16.0);
  CHECK(lit_total > 10000 * w);
}

}  // namespace

TEST(backplot_pixels_follow_the_projected_line) {
  check_pixels_follow_line(1);
  // Two pixels across: a supersampled frame's line (display/view/stock_view.h).
  check_pixels_follow_line(2);
}

TEST(backplot_depth_test_hides_the_path_behind_the_part) {
  static Scene s;
  make_scene(&s, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso);
  const DepthView z = depth_of(s.r);
  auto lit_by = [&](const PathSegment& sg) {
    std::memcpy(s.f.pixels.data(), s.rendered.data(), s.rendered.size() * 4);
    backplot_draw(s.f.fb, z, s.r.view, &sg, 1, 1, ScreenRect{0, 0, kW, kH}, BackplotColours());
    return static_cast<int>(changed(s.f.fb, s.rendered).size());
  };
  // The block is 60 x 40 x 20 mm (tests/scene_util.h): along its top, on
  // the top, a hair below it (the path runs on the surface it cuts), and
  // 5 mm inside the solid corner the pocket does not reach.
  const int on_top = lit_by(seg(2, 2, 20, 2, 38, 20, PathKind::kFeed));
  const int hair_below = lit_by(seg(2, 2, 19.95, 2, 38, 19.95, PathKind::kFeed));
  const int inside = lit_by(seg(2, 2, 15, 2, 38, 15, PathKind::kFeed));
  const int above = lit_by(seg(2, 2, 25, 2, 38, 25, PathKind::kFeed));
  std::printf("  backplot depth: on top %d, 0.05 mm below %d, 5 mm inside %d, above %d pixels (bias %d units)\n",
              on_top, hair_below, inside, above, static_cast<int>(backplot_depth_bias(s.r.view)));
  CHECK(on_top > 20);
  CHECK(hair_below * 10 >= on_top * 9);
  CHECK_EQ(inside, 0);
  CHECK(above > 20);
}

namespace {

void check_rect_redraws(PixelFormat fmt, ZFormat zf, int32_t w) {
  static Scene s;
  make_scene(&s, fmt, zf, ViewPreset::kIso);
  const DepthView z = depth_of(s.r);
  // A path like a program's: zig rows on the top, plunges, rapids above,
  // arcs as chords, some of it off the frame.
  std::vector<PathSegment> path;
  t::Rng rng(11);
  PointNm at{0, 0, 30 * mm};
  for (int k = 0; k < 400; ++k) {
    PointNm to{static_cast<int64_t>((uniform01(&rng) * 70 - 5) * mm), static_cast<int64_t>((uniform01(&rng) * 50 - 5) * mm),
               static_cast<int64_t>((uniform01(&rng) * 30) * mm)};
    path.push_back(PathSegment{at, to, k % 4 == 0 ? PathKind::kRapid : PathKind::kFeed});
    at = to;
  }
  const uint32_t n = static_cast<uint32_t>(path.size());
  const ScreenRect all{0, 0, kW, kH};
  const BackplotColours colours;
  auto full = [&](uint32_t done) {
    std::memcpy(s.f.pixels.data(), s.rendered.data(), s.rendered.size() * 4);
    backplot_draw(s.f.fb, z, s.r.view, path.data(), n, done, all, colours, w);
    return s.f.pixels;
  };
  t::Rng pick(5);
  int differ = 0;
  for (int trial = 0; trial < 40; ++trial) {
    // The path with `from` pieces done, then `to` done: redrawn only inside
    // backplot_bounds of the pieces that turned, and inside a random
    // rectangle (what a renderer repaints); the frame equals a full draw.
    const uint32_t from = static_cast<uint32_t>(uniform01(&pick) * n), to = from + static_cast<uint32_t>(uniform01(&pick) * (n - from));
    const std::vector<uint32_t> want = full(to);
    full(from);
    const int32_t x0 = static_cast<int32_t>(uniform01(&pick) * kW), y0 = static_cast<int32_t>(uniform01(&pick) * kH);
    const ScreenRect repaint{x0, y0, x0 + 1 + static_cast<int32_t>(uniform01(&pick) * 80), y0 + 1 + static_cast<int32_t>(uniform01(&pick) * 60)};
    const ScreenRect turned = backplot_bounds(s.f.fb, s.r.view, path.data(), from, to, w);
    // As the renderer does: the part repainted in both, then the path.
    for (const ScreenRect& rect : {turned, repaint}) {
      const ScreenRect c = rect_intersect(rect, all);
      const int bpp = pixel_bytes(fmt);
      uint8_t* dst = reinterpret_cast<uint8_t*>(s.f.pixels.data());
      const uint8_t* src = reinterpret_cast<const uint8_t*>(s.rendered.data());
      for (int32_t y = c.y0; y < c.y1; ++y)
        std::memcpy(dst + y * s.f.fb.stride_bytes + c.x0 * bpp, src + y * s.f.fb.stride_bytes + c.x0 * bpp,
                    static_cast<size_t>(c.x1 - c.x0) * bpp);
    }
    backplot_draw(s.f.fb, z, s.r.view, path.data(), n, to, turned, colours, w);
    backplot_draw(s.f.fb, z, s.r.view, path.data(), n, to, repaint, colours, w);
    if (s.f.pixels != want) ++differ;
  }
  CHECK_EQ(differ, 0);
  // The whole frame repainted 4x4 tile by tile (the renderer's tiles), the
  // path drawn inside each: the full draw, to the pixel at every tile edge.
  const std::vector<uint32_t> whole = full(n / 2);
  std::memcpy(s.f.pixels.data(), s.rendered.data(), s.rendered.size() * 4);
  for (int32_t y = 0; y < kH; y += 4)
    for (int32_t x = 0; x < kW; x += 4)
      backplot_draw(s.f.fb, z, s.r.view, path.data(), n, n / 2, ScreenRect{x, y, x + 4, y + 4}, colours, w);
  CHECK(s.f.pixels == whole);
  // And a draw inside a rectangle changes nothing outside it.
  full(0);
  const std::vector<uint32_t> before = s.f.pixels;
  const ScreenRect r{40, 30, 200, 170};
  backplot_draw(s.f.fb, z, s.r.view, path.data(), n, n, r, colours, w);
  int outside = 0, inside = 0;
  for (int p : changed(s.f.fb, before)) {
    const int x = p % kW, y = p / kW;
    if (x < r.x0 || x >= r.x1 || y < r.y0 || y >= r.y1) ++outside;
    else ++inside;
  }
  CHECK_EQ(outside, 0);
  CHECK(inside > 100);
}

}  // namespace

TEST(backplot_redraw_in_rectangles_equals_a_full_redraw) {
  check_rect_redraws(PixelFormat::kXrgb8888, ZFormat::kZ32, 1);
  check_rect_redraws(PixelFormat::kRgb565, ZFormat::kZ16, 1);
  check_rect_redraws(PixelFormat::kXrgb8888, ZFormat::kZ32, 2);
  check_rect_redraws(PixelFormat::kRgb565, ZFormat::kZ16, 2);
}
