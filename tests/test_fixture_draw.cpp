// Fixtures drawn by the renderer (display/surface/fixture_draw.h, render.h
// renderer_set_fixtures): the box's pixels against its projected corners,
// each visible face in its own flat shade, the depth test against the
// stock both ways, incremental redraw equal to a full redraw with the
// cutter passing in front of and behind a fixture (both pixel formats,
// orthographic and perspective, a fixture clipped by the near plane), no
// fixtures drawing the frame of before, the count limit.
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <vector>

#include "core/math/trig.h"
#include "display/surface/render.h"
#include "tests/alloc_count.h"
#include "tests/rng.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;
constexpr int32_t kW = 320, kH = 240;

// The test block: 48 x 40 dexels of 1 mm, 20 mm high; the border dexels
// are holes, so the material is the box of dexels 1 .. n-2 (scene_util.h).
BoxNm material_box(const DexelGrid<uint16_t>& g) {
  return BoxNm{PointNm{g.x0_nm + g.pitch_nm, g.y0_nm + g.pitch_nm, 0},
               PointNm{g.x0_nm + (g.nx - 2) * g.pitch_nm, g.y0_nm + (g.ny - 2) * g.pitch_nm, 20 * mm}};
}

BoxNm box_mm(double x0, double y0, double z0, double x1, double y1, double z1) {
  auto nm = [](double v) { return static_cast<int64_t>(std::llround(v * mm)); };
  return BoxNm{PointNm{nm(x0), nm(y0), nm(z0)}, PointNm{nm(x1), nm(y1), nm(z1)}};
}

BoxNm box_union(BoxNm a, const BoxNm& b) {
  a.lo = PointNm{std::min(a.lo.x_nm, b.lo.x_nm), std::min(a.lo.y_nm, b.lo.y_nm), std::min(a.lo.z_nm, b.lo.z_nm)};
  a.hi = PointNm{std::max(a.hi.x_nm, b.hi.x_nm), std::max(a.hi.y_nm, b.hi.y_nm), std::max(a.hi.z_nm, b.hi.z_nm)};
  return a;
}

struct P2 {
  double x, y;
};
double cross(P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// A machine point on the screen, pixels (pixel (x, y) spans [x, x + 1)).
P2 screen_of(const View& v, PointNm p) {
  const RasterVertex s = clip_project(v.proj, view_point(v, p));
  return P2{s.x_q4 / 16.0, s.y_q4 / 16.0};
}

// The convex hull of a box's eight projected corners (Andrew's monotone
// chain; counterclockwise in x right, y down coordinates).
std::vector<P2> box_hull(const View& v, const BoxNm& b) {
  std::vector<P2> p;
  for (int k = 0; k < 8; ++k)
    p.push_back(screen_of(v, PointNm{(k & 1) ? b.hi.x_nm : b.lo.x_nm, (k & 2) ? b.hi.y_nm : b.lo.y_nm,
                                     (k & 4) ? b.hi.z_nm : b.lo.z_nm}));
  std::sort(p.begin(), p.end(), [](P2 u, P2 w) { return u.x < w.x || (u.x == w.x && u.y < w.y); });
  std::vector<P2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// The signed distance (pixels) of pixel (x, y)'s centre inside the hull:
// positive inside, negative outside (the worst edge).
double inside_by(const std::vector<P2>& h, int32_t x, int32_t y) {
  const P2 c{x + 0.5, y + 0.5};
  double d = 1e30;
  for (size_t e = 0; e < h.size(); ++e) {
    const P2 a = h[e], b = h[(e + 1) % h.size()];
    d = std::min(d, cross(a, b, c) / std::hypot(b.x - a.x, b.y - a.y));
  }
  return d;
}

// The stored values fixture faces can have in r's current frame: face f
// is flat, lut_fixture[shade of f].
std::vector<uint32_t> fixture_values(const Renderer<uint16_t>& r) {
  std::vector<uint32_t> v;
  for (int f = 0; f < kFixtureFaces; ++f) v.push_back(r.lut_fixture[r.fixture_shades.face[f]]);
  return v;
}
bool is_fixture(const std::vector<uint32_t>& values, uint32_t px) {
  return std::find(values.begin(), values.end(), px) != values.end();
}

struct Scene {
  t::TestGrid<uint16_t> tg;
  t::TestFrame f;
  Renderer<uint16_t> r;
};

// The test block in an iso view fitted to the block and `extra` (so the
// fixtures are in the frame).
void make_scene(Scene* s, PixelFormat fmt, ZFormat zf, const BoxNm& extra) {
  t::make_block(&s->tg, 48, 40, mm, 20 * mm);
  t::make_frame(&s->f, kW, kH, fmt);
  RenderOptions opt;
  opt.zformat = zf;
  CHECK(t::init_renderer(&s->r, s->tg.g, &s->f, opt));
  Camera c = camera_preset(ViewPreset::kIso);
  camera_fit(&c, box_union(renderer_stock_box(s->r), extra), kW, kH);
  renderer_set_camera(&s->r, c);
}

}  // namespace

TEST(fixture_fills_its_projection_and_nothing_else) {
  // A vice jaw beside the block on its +x side (the side the iso view sees).
  static Scene s;
  const BoxNm jaw = box_mm(52, 8, 0, 60, 30, 14);
  make_scene(&s, PixelFormat::kXrgb8888, ZFormat::kZ32, jaw);
  render_full(&s.r, &s.tg.g, CutterPose{});
  const std::vector<uint32_t> without = s.f.pixels;
  CHECK_EQ(renderer_set_fixtures(&s.r, &jaw, 1), Status::kOk);
  render_full(&s.r, &s.tg.g, CutterPose{});
  t::dump_frame(s.f.fb, "fixture-beside");
  const std::vector<uint32_t> values = fixture_values(s.r);
  // The three faces the view sees (+x, -y, top) differ from each other and
  // from the workpiece, table and background.
  const uint32_t px = values[1], my = values[2], top = values[5];
  CHECK(px != my && my != top && px != top);
  const std::vector<P2> h = box_hull(s.r.view, jaw);
  int inside = 0, inside_ok = 0, outside_fixture = 0, changed_outside = 0, before_fixture = 0;
  for (int32_t y = 0; y < kH; ++y) {
    for (int32_t x = 0; x < kW; ++x) {
      const uint32_t p = frame_pixel(s.f.fb, x, y);
      FrameView old = s.f.fb;
      old.pixels = const_cast<uint32_t*>(without.data());
      before_fixture += is_fixture(values, frame_pixel(old, x, y));
      const double d = inside_by(h, x, y);
      if (d > 1.0) {
        ++inside;
        inside_ok += is_fixture(values, p);
      } else if (d < -1.0) {
        outside_fixture += is_fixture(values, p);
        changed_outside += p != frame_pixel(old, x, y);
      }
    }
  }
  std::printf("  fixture beside: %d pixels well inside its projection, %d of them fixture-coloured\n", inside, inside_ok);
  CHECK_GT(inside, 1000);
  CHECK_EQ(inside_ok, inside);
  CHECK_EQ(outside_fixture, 0);
  CHECK_EQ(changed_outside, 0);  // the rest of the frame is the frame without it
  CHECK_EQ(before_fixture, 0);   // and its colours appear nowhere without it
  // Each face in its own shade: the centres of the top, +x and -y faces.
  auto at = [&](double xm, double ym, double zm) {
    const P2 q = screen_of(s.r.view, box_mm(xm, ym, zm, 0, 0, 0).lo);
    return frame_pixel(s.f.fb, static_cast<int32_t>(q.x), static_cast<int32_t>(q.y));
  };
  CHECK_EQ(at(56, 19, 14), top);
  CHECK_EQ(at(60, 19, 7), px);
  CHECK_EQ(at(56, 8, 7), my);
}

TEST(fixture_depth_against_the_stock) {
  static Scene s;
  // Behind: a tall plate on the far (-x) side, its top 10 mm above the
  // block's; every point of it is farther than the block from the iso eye.
  const BoxNm behind = box_mm(-14, 6, 0, -6, 32, 30);
  // In front: a tall post on the near (-y) side, 40 mm high.
  const BoxNm front = box_mm(14, -12, 0, 26, -4, 40);
  make_scene(&s, PixelFormat::kXrgb8888, ZFormat::kZ32, box_union(behind, front));
  render_full(&s.r, &s.tg.g, CutterPose{});
  const std::vector<uint32_t> plain = s.f.pixels;
  FrameView old = s.f.fb;
  old.pixels = const_cast<uint32_t*>(plain.data());
  const BoxNm both[2] = {behind, front};
  const std::vector<P2> hs = box_hull(s.r.view, material_box(s.tg.g));
  for (int which = 0; which < 2; ++which) {
    CHECK_EQ(renderer_set_fixtures(&s.r, &both[which], 1), Status::kOk);
    render_full(&s.r, &s.tg.g, CutterPose{});
    t::dump_frame(s.f.fb, which ? "fixture-front" : "fixture-behind");
    const std::vector<uint32_t> values = fixture_values(s.r);
    const std::vector<P2> hf = box_hull(s.r.view, both[which]);
    int overlap = 0, stock_kept = 0, fixture_shown = 0, fixture_above = 0;
    for (int32_t y = 0; y < kH; ++y) {
      for (int32_t x = 0; x < kW; ++x) {
        const double in_f = inside_by(hf, x, y), in_s = inside_by(hs, x, y);
        const uint32_t p = frame_pixel(s.f.fb, x, y);
        if (in_f > 1.0 && in_s > 1.0) {
          ++overlap;
          stock_kept += p == frame_pixel(old, x, y);
          fixture_shown += is_fixture(values, p);
        } else if (in_f > 1.0 && in_s < -1.0) {
          fixture_above += is_fixture(values, p);
        }
      }
    }
    std::printf("  fixture %s: %d pixels over the block: %d block, %d fixture; %d fixture pixels off the block\n",
                which ? "in front" : "behind", overlap, stock_kept, fixture_shown, fixture_above);
    CHECK_GT(overlap, 500);
    CHECK_GT(fixture_above, 200);
    if (which == 0) {
      CHECK_EQ(stock_kept, overlap);  // the block hides the plate
      CHECK_EQ(fixture_shown, 0);
    } else {
      CHECK_EQ(fixture_shown, overlap);  // the post hides the block
    }
  }
}

namespace {

Camera with_angles(Camera c, int32_t az_mdeg, int32_t el_mdeg) {
  c.azimuth_bam = bam_from_mdeg(az_mdeg);
  c.elevation_bam = static_cast<int32_t>(bam_from_mdeg(el_mdeg));
  return c;
}

struct IncCase {
  const char* name;
  PixelFormat format;
  ZFormat zformat;
  Projection projection;
  int32_t az_mdeg, el_mdeg;
  bool near_clip;  // add a long plate that reaches behind the eye
};

// Cuts and cutter moves, drawn incrementally by one renderer and whole by
// another: the frames must be equal after every step, and every changed
// pixel inside a returned rectangle. The cutter sweeps back and forth
// along y at x = 34 mm, through the clamp on the block's edge, in front of
// the jaw and, on the far side, behind it.
void incremental_run(const IncCase& ic, uint64_t seed, int steps) {
  t::TestGrid<uint16_t> tg;
  t::make_block(&tg, 48, 40, mm, 20 * mm);
  t::TestCutter ball;
  t::make_cutter(tg.g, t::ball_tool(6 * mm), &ball);
  std::vector<BoxNm> fixtures = {
      box_mm(52, 8, 0, 60, 30, 14),     // jaw beside the block
      box_mm(30, -6, 18, 38, 5, 24),    // toe clamp over the -y edge, on the top
      box_mm(-12, 10, 0, -4, 28, 30),   // plate behind
  };
  if (ic.near_clip) fixtures.push_back(box_mm(-1000, 60, 0, 1000, 64, 30));  // a long wall behind, past the eye
  RenderOptions opt;
  opt.zformat = ic.zformat;
  t::TestFrame fa, fb;
  t::make_frame(&fa, kW, kH, ic.format);
  t::make_frame(&fb, kW, kH, ic.format);
  static Renderer<uint16_t> ra, rb;
  CHECK(t::init_renderer(&ra, tg.g, &fa, opt));
  CHECK(t::init_renderer(&rb, tg.g, &fb, opt));
  Camera cam = with_angles(renderer_fit(ra, ViewPreset::kIso), ic.az_mdeg, ic.el_mdeg);
  cam.projection = ic.projection;
  camera_fit(&cam, box_union(renderer_stock_box(ra), box_mm(-12, -6, 0, 60, 39, 24)), kW, kH);
  const int n = static_cast<int>(fixtures.size());
  for (Renderer<uint16_t>* r : {&ra, &rb}) {
    renderer_set_camera(r, cam);
    renderer_set_tool(r, &ball.profile);
    CHECK_EQ(renderer_set_fixtures(r, fixtures.data(), n), Status::kOk);
  }
  t::Rng rng(seed);
  CutterPose pose{true, PointNm{34 * mm, -20 * mm, 16 * mm}};
  render_full(&ra, &tg.g, pose);
  if (ic.near_clip) {
    // The wall's far end is behind the eye: outside the near plane (plane 0).
    int behind = 0;
    for (int k = 0; k < 8; ++k) behind += ra.fixture_mesh[3].oc[k] & 1;
    CHECK_GT(behind, 0);
  }
  std::vector<uint32_t> before;
  int mismatches = 0, uncovered = 0;
  for (int step = 0; step < steps; ++step) {
    // The cutter's sweep past the fixtures: y from -20 to 60 mm and back;
    // every other step also a random cut into the block.
    const int64_t phase = (step * 4) % 160, y = (phase < 80 ? phase : 160 - phase) * mm - 20 * mm;
    const PointNm a = pose.tip;
    pose.tip = PointNm{34 * mm + rng.range(-2 * mm, 2 * mm), y, 16 * mm + rng.range(-2 * mm, 2 * mm)};
    CutStats st;
    stamp_line(&tg.g, ball.c, a, pose.tip, &st);
    if (step % 2) {
      const PointNm c{rng.range(0, 48 * mm), rng.range(0, 40 * mm), rng.range(10 * mm, 22 * mm)};
      stamp_line(&tg.g, ball.c, c, PointNm{c.x_nm + rng.range(-8 * mm, 8 * mm), c.y_nm + rng.range(-8 * mm, 8 * mm), c.z_nm}, &st);
    }
    if (step % 17 == 16) pose.visible = !pose.visible;
    before = fa.pixels;
    const RenderResult res = render_update(&ra, &tg.g, pose);
    CHECK(!res.full);
    FrameView old = fa.fb;
    old.pixels = before.data();
    uncovered += t::uncovered_changes(fa.fb, old, res);
    render_full(&rb, &tg.g, pose);
    if (frame_hash(fa.fb) != frame_hash(fb.fb) && mismatches++ == 0)
      t::report_first_difference(ic.name, step, fa.fb, fb.fb, "fixture_incremental");
  }
  CHECK_EQ(mismatches, 0);
  CHECK_EQ(uncovered, 0);
  char name[64];
  std::snprintf(name, sizeof name, "fixture-incremental-%s", ic.name);
  t::dump_frame(fa.fb, name);
}

}  // namespace

TEST(fixture_incremental_equals_full_redraw) {
  const IncCase cases[] = {
      {"iso", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, -45000, 35264, false},
      {"iso-565", PixelFormat::kRgb565, ZFormat::kZ16, Projection::kOrthographic, -45000, 35264, false},
      {"persp", PixelFormat::kXrgb8888, ZFormat::kZ16, Projection::kPerspective, -30000, 30000, false},
      {"persp-565-near", PixelFormat::kRgb565, ZFormat::kZ32, Projection::kPerspective, -60000, 20000, true},
      {"low-back", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, 150000, 10000, false},
  };
  uint64_t seed = 31;
  for (const IncCase& ic : cases) incremental_run(ic, seed++, 60);
}

TEST(fixture_drawing_allocates_nothing) {
  static Scene s;
  const BoxNm jaw[2] = {box_mm(52, 8, 0, 60, 30, 14), box_mm(30, -6, 18, 38, 5, 24)};
  make_scene(&s, PixelFormat::kRgb565, ZFormat::kZ16, box_union(jaw[0], jaw[1]));
  t::TestCutter c;
  t::make_cutter(s.tg.g, t::ball_tool(4 * mm), &c);
  const uint64_t before = t::heap_allocations();
  CHECK_EQ(renderer_set_fixtures(&s.r, jaw, 2), Status::kOk);
  renderer_set_tool(&s.r, &c.profile);
  render_full(&s.r, &s.tg.g, CutterPose{true, PointNm{30 * mm, 20 * mm, 15 * mm}});
  CutStats st;
  stamp_line(&s.tg.g, c.c, PointNm{30 * mm, 20 * mm, 15 * mm}, PointNm{34 * mm, 0, 15 * mm}, &st);
  const RenderResult res = render_update(&s.r, &s.tg.g, CutterPose{true, PointNm{34 * mm, 0, 15 * mm}});
  CHECK_EQ(t::heap_allocations() - before, 0u);
  CHECK_GT(res.nrects, 0);
}

TEST(no_fixtures_draws_the_frame_of_before) {
  // Fixtures set and then removed: the frame (scene frame, depths, pixels)
  // is the one of a renderer that never had any.
  static Scene a, b;
  const BoxNm far_plate = box_mm(-80, -10, -30, -60, 50, 60);  // widens the scene frame a lot
  make_scene(&a, PixelFormat::kXrgb8888, ZFormat::kZ16, far_plate);
  make_scene(&b, PixelFormat::kXrgb8888, ZFormat::kZ16, far_plate);
  const CutterPose none{};
  render_full(&b.r, &b.tg.g, none);
  CHECK_EQ(renderer_set_fixtures(&a.r, &far_plate, 1), Status::kOk);
  render_full(&a.r, &a.tg.g, none);
  CHECK(frame_hash(a.f.fb) != frame_hash(b.f.fb));
  CHECK_EQ(renderer_set_fixtures(&a.r, nullptr, 0), Status::kOk);
  const RenderResult res = render_update(&a.r, &a.tg.g, none);
  CHECK(res.full);  // setting fixtures makes the next frame whole
  CHECK_EQ(frame_hash(a.f.fb), frame_hash(b.f.fb));
  // Bad arguments change nothing.
  CHECK_EQ(renderer_set_fixtures(&a.r, nullptr, 2), Status::kBadArgument);
  CHECK_EQ(renderer_set_fixtures(&a.r, &far_plate, -1), Status::kBadArgument);
  CHECK_EQ(a.r.nfixtures, 0);
  CHECK(!render_update(&a.r, &a.tg.g, none).full);
}

TEST(fixtures_beyond_the_limit_are_reported_and_the_first_drawn) {
  static Scene s;
  std::vector<BoxNm> boxes;
  for (int k = 0; k < kFixturesMax + 2; ++k) boxes.push_back(box_mm(52, -6 + 6 * k, 0, 56, -3 + 6 * k, 2));
  make_scene(&s, PixelFormat::kXrgb8888, ZFormat::kZ32, box_union(boxes.front(), boxes.back()));
  CHECK_EQ(renderer_set_fixtures(&s.r, boxes.data(), kFixturesMax + 2), Status::kBufferTooSmall);
  CHECK_EQ(s.r.nfixtures, kFixturesMax);
  render_full(&s.r, &s.tg.g, CutterPose{});
  const std::vector<uint32_t> values = fixture_values(s.r);
  // Fixture-coloured pixels inside box k's projection and no other's.
  auto coloured = [&](int k) {
    std::vector<std::vector<P2>> h;
    for (const BoxNm& b : boxes) h.push_back(box_hull(s.r.view, b));
    int n = 0;
    for (int32_t y = 0; y < kH; ++y)
      for (int32_t x = 0; x < kW; ++x) {
        bool other = false;
        for (size_t q = 0; q < h.size(); ++q) other |= static_cast<int>(q) != k && inside_by(h[q], x, y) > -1.0;
        n += !other && inside_by(h[static_cast<size_t>(k)], x, y) > 1.0 && is_fixture(values, frame_pixel(s.f.fb, x, y));
      }
    return n;
  };
  CHECK_GT(coloured(0), 20);
  CHECK_GT(coloured(kFixturesMax - 1), 20);
  CHECK_EQ(coloured(kFixturesMax), 0);
  CHECK_EQ(coloured(kFixturesMax + 1), 0);
}
