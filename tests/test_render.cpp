// display/surface/render.h: incremental redraw equals a full redraw, the surface is
// watertight, no heap while drawing, golden frame hashes.
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "core/math/trig.h"
#include "display/colour/material_colours.h"
#include "display/surface/render.h"
#include "display/colour/slope_colours.h"
#include "display/colour/thin_colours.h"
#include "display/colour/tool_colours.h"
#include "tests/alloc_count.h"
#include "tests/golden_check.h"
#include "tests/rng.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;

using t::Rng;

Camera with_angles(Camera c, int32_t az_mdeg, int32_t el_mdeg) {
  c.azimuth_bam = bam_from_mdeg(az_mdeg);
  c.elevation_bam = static_cast<int32_t>(bam_from_mdeg(el_mdeg));
  return c;
}

// How one incremental-redraw run is set up.
struct IncCase {
  const char* name;
  PixelFormat format;
  ZFormat zformat;
  Projection projection;
  int32_t az_mdeg, el_mdeg;
  int tool;  // drawn tool: 0 ball, 1 flat, 2 bull, 3 vbit
  // A colour mode: none, classes from the tops' heights, or --color tool,
  // slope or thin.
  enum Colours { kNone, kHeights, kTool, kSlope, kThin, kTexture } colours = kNone;
};

// A stock of several textures for the textured cases (kTexture): a layers
// material (a band boundary at 4 mm) under marble from 8 mm, a granite
// cylinder and a wood box inserted.
const StockComposition& textured_stock() {
  static StockComposition c;
  static bool made = false;
  if (made) return c;
  made = true;
  composition_clear(&c);
  Material m[4];
  m[0].texture.kind = TextureKind::kLayers;
  m[0].texture.layers.boundary_z_nm[0] = 4 * mm;
  m[1].texture.kind = TextureKind::kMarble;
  m[1].texture.marble.period_nm = 9 * mm;
  m[2].texture.kind = TextureKind::kGranite;
  m[3].texture.kind = TextureKind::kWood;
  uint8_t k[4];
  for (int n = 0; n < 4; ++n) CHECK(ok(composition_add_material(&c, m[n], &k[n])));
  CHECK(ok(composition_add_layer(&c, -mm, 8 * mm, k[0])));
  CHECK(ok(composition_add_layer(&c, 8 * mm, 30 * mm, k[1])));
  CHECK(ok(composition_add_cylinder(&c, 30 * mm, 20 * mm, 7 * mm, 2 * mm, 14 * mm, k[2])));
  CHECK(ok(composition_add_box(&c, BoxNm{PointNm{2 * mm, 2 * mm, 10 * mm}, PointNm{14 * mm, 12 * mm, 18 * mm}}, k[3])));
  return c;
}

// A colour mode for the test: eight classes by height (1 mm bands), so a cut
// changes classes, and the incremental classification must keep up.
template <class H>
struct HeightClasses {
  const DexelGrid<H>* g = nullptr;
  std::vector<uint8_t> cls;
  std::vector<uint32_t> luts;
  SurfaceColours sc;
  void init(const DexelGrid<H>& grid) {
    g = &grid;
    cls.assign(size_t(grid.nx) * grid.ny, 0);
    luts.assign(size_t(8) * kShadeLevels, 0);
    sc.cls = cls.data();
    sc.luts = luts.data();
    sc.nclasses = 8;
    for (int k = 0; k < 8; ++k) sc.colour[k] = Rgb{uint8_t(30 * k), uint8_t(200 - 20 * k), uint8_t(90 + 15 * k)};
    sc.ctx = this;
    sc.classify = [](void* ctx, GridRect r, uint8_t* c) {
      const HeightClasses* h = static_cast<const HeightClasses*>(ctx);
      for (int32_t j = max_of(r.j0, 0); j < min_of(r.j1, h->g->ny); ++j)
        for (int32_t i = max_of(r.i0, 0); i < min_of(r.i1, h->g->nx); ++i) {
          const size_t k = h->g->index(i, j);
          c[k] = uint8_t((int64_t(h->g->top[k]) * h->g->lsb_nm / 1000000) % 8);
        }
    };
  }
};

// One renderer's colour mode of an IncCase, with its memory.
template <class H>
struct ModeColours {
  HeightClasses<H> heights;
  std::vector<uint8_t> cls;
  std::vector<uint32_t> luts, shadow;
  ToolProvenance<H> tool;
  SurfaceColours tool_colours;
  SlopeColours<H> slope;
  ThinColours<H> thin;
  MaterialColours<H> material;
  std::vector<uint32_t> texture;
  // The mode's classes for g (null for none).
  const SurfaceColours* init(IncCase::Colours c, const DexelGrid<H>& g) {
    const size_t n = size_t(g.nx) * g.ny;
    cls.assign(n, 0);
    shadow.assign(n, 0);
    luts.assign(size_t(kMaxColourClasses) * kShadeLevels, 0);
    switch (c) {
      case IncCase::kHeights: heights.init(g); return &heights.sc;
      case IncCase::kTool:
        provenance_init(&tool, g, 1, kToolColourSlots, cls.data(), shadow.data(), nullptr);
        tool_colours_init(&tool_colours, tool, luts.data());
        return &tool_colours;
      case IncCase::kSlope: slope_colours_init(&slope, g, cls.data(), luts.data()); return &slope.colours;
      case IncCase::kThin: thin_colours_init(&thin, g, 3 * mm, cls.data(), luts.data()); return &thin.colours;
      case IncCase::kTexture:  // uncut tops (the stock's top) tinted
        texture.assign(material_texture_bytes(g) / 4 + 1, 0);
        material_colours_init(&material, g, textured_stock(), cls.data(), luts.data());
        material_colours_texture(&material, texture.data(), g.top[g.index(1, 1)]);
        return &material.colours;
      default: return nullptr;
    }
  }
};

template <class H>
void incremental_run(const IncCase& ic, uint64_t seed, int steps) {
  t::TestGrid<H> tg;
  t::make_block(&tg, 48, 40, mm, 20 * mm);
  t::TestCutter tools[4];
  t::make_cutter(tg.g, t::ball_tool(6 * mm), &tools[0]);
  t::make_cutter(tg.g, t::flat_tool(4 * mm), &tools[1]);
  t::make_cutter(tg.g, t::bull_tool(8 * mm, 2 * mm), &tools[2]);
  t::make_cutter(tg.g, t::vbit_tool(6 * mm, 90000), &tools[3]);
  RenderOptions opt;
  opt.zformat = ic.zformat;
  t::TestFrame fa, fb;
  t::make_frame(&fa, 320, 240, ic.format);
  t::make_frame(&fb, 320, 240, ic.format);
  static Renderer<H> ra, rb;
  CHECK(t::init_renderer(&ra, tg.g, &fa, opt));
  CHECK(t::init_renderer(&rb, tg.g, &fb, opt));
  Camera cam = renderer_fit(ra, ViewPreset::kIso);
  cam.projection = ic.projection;
  cam = with_angles(cam, ic.az_mdeg, ic.el_mdeg);
  camera_fit(&cam, renderer_stock_box(ra), 320, 240);
  for (Renderer<H>* r : {&ra, &rb}) {
    renderer_set_camera(r, cam);
    renderer_set_tool(r, &tools[ic.tool].profile);
  }
  // Each renderer its own classes: the full redraw's must not hide the
  // incremental one's.
  ModeColours<H> ca, cb;
  renderer_set_colours(&ra, ca.init(ic.colours, tg.g));
  renderer_set_colours(&rb, cb.init(ic.colours, tg.g));
  Rng rng(seed);
  CutterPose pose{true, PointNm{10 * mm, 10 * mm, 30 * mm}};
  render_full(&ra, &tg.g, pose);
  std::vector<uint32_t> before;
  int mismatches = 0, uncovered = 0;
  for (int step = 0; step < steps; ++step) {
    // A random move of a random tool: across the block, into it, through it.
    const int32_t tool_number = int32_t(rng.range(0, 3));
    const t::TestCutter& c = tools[tool_number];
    const PointNm a{rng.range(-5 * mm, 53 * mm), rng.range(-5 * mm, 45 * mm), rng.range(-2 * mm, 22 * mm)};
    PointNm b = a;
    if (rng.range(0, 3)) b = PointNm{a.x_nm + rng.range(-15 * mm, 15 * mm), a.y_nm + rng.range(-15 * mm, 15 * mm), a.z_nm + rng.range(-3 * mm, 3 * mm)};
    CutStats st;
    if (rng.range(0, 9)) stamp_line(&tg.g, c.c, a, b, &st);
    if (ic.colours == IncCase::kTool)  // as the cut pass reports every record
      for (ModeColours<H>* m : {&ca, &cb}) {
        provenance_set_tool(&m->tool, tool_number);
        provenance_record(&m->tool, tg.g.dirty, 1);
      }
    if (rng.range(0, 9) == 0) pose.visible = !pose.visible;
    if (rng.range(0, 3)) pose.tip = b;
    before = fa.pixels;
    const RenderResult res = render_update(&ra, &tg.g, pose);
    CHECK(!res.full);
    CHECK_EQ(tg.g.dirty.empty(), true);
    // Every pixel that changed lies in a returned rectangle.
    FrameView old = fa.fb;
    old.pixels = before.data();
    uncovered += t::uncovered_changes(fa.fb, old, res);
    // And the frame equals a full redraw of the same scene.
    render_full(&rb, &tg.g, pose);
    if (frame_hash(fa.fb) != frame_hash(fb.fb) && mismatches++ == 0)
      t::report_first_difference(ic.name, step, fa.fb, fb.fb, "incremental");
  }
  CHECK_EQ(mismatches, 0);
  CHECK_EQ(uncovered, 0);
  char name[64];
  std::snprintf(name, sizeof name, "incremental-%s", ic.name);
  t::dump_frame(fa.fb, name);
}

}  // namespace

TEST(incremental_equals_full_redraw) {
  const IncCase cases[] = {
      {"iso", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, -45000, 35264, 0},
      {"top-565", PixelFormat::kRgb565, ZFormat::kZ16, Projection::kOrthographic, -90000, 90000, 1},
      {"persp", PixelFormat::kXrgb8888, ZFormat::kZ16, Projection::kPerspective, 30000, 40000, 2},
      {"below", PixelFormat::kRgb565, ZFormat::kZ32, Projection::kOrthographic, 120000, -30000, 3},
      {"low", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kPerspective, 200000, 8000, 0},
      {"iso-colours", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, -45000, 35264, 0, IncCase::kHeights},
      {"persp-colours", PixelFormat::kRgb565, ZFormat::kZ16, Projection::kPerspective, 30000, 40000, 2, IncCase::kHeights},
      {"iso-tool", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, -45000, 35264, 0, IncCase::kTool},
      {"top-slope", PixelFormat::kRgb565, ZFormat::kZ16, Projection::kOrthographic, -90000, 90000, 1, IncCase::kSlope},
      {"iso-slope", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, -45000, 35264, 3, IncCase::kSlope},
      {"persp-thin", PixelFormat::kXrgb8888, ZFormat::kZ16, Projection::kPerspective, 30000, 40000, 2, IncCase::kThin},
      {"iso-texture", PixelFormat::kXrgb8888, ZFormat::kZ32, Projection::kOrthographic, -45000, 35264, 0, IncCase::kTexture},
      {"persp-texture", PixelFormat::kRgb565, ZFormat::kZ16, Projection::kPerspective, 30000, 40000, 2, IncCase::kTexture},
      {"below-texture", PixelFormat::kXrgb8888, ZFormat::kZ16, Projection::kOrthographic, 120000, -30000, 3, IncCase::kTexture},
  };
  uint64_t seed = 11;
  for (const IncCase& ic : cases) incremental_run<uint16_t>(ic, seed++, 100);
  incremental_run<uint8_t>(cases[0], seed++, 40);
  incremental_run<uint8_t>(cases[11], seed++, 40);  // iso-texture
  incremental_run<uint32_t>(cases[2], seed++, 40);
}

namespace {

// A block milled inside its border (pocket, ball channel, V groove, no
// through hole): its silhouette is the projection of the stock's box.
template <class H>
void make_milled_inside(t::TestGrid<H>* tg) {
  t::make_block(tg, 60, 44, mm, 20 * mm);
  t::TestCutter flat, ball, vbit;
  t::make_cutter(tg->g, t::flat_tool(6 * mm), &flat);
  t::make_cutter(tg->g, t::ball_tool(8 * mm), &ball);
  t::make_cutter(tg->g, t::vbit_tool(6 * mm, 90000), &vbit);
  CutStats st;
  for (int64_t y = 10 * mm; y <= 24 * mm; y += 3 * mm)
    stamp_line(&tg->g, flat.c, PointNm{10 * mm, y, 12 * mm}, PointNm{28 * mm, y, 12 * mm}, &st);
  stamp_line(&tg->g, ball.c, PointNm{36 * mm, 9 * mm, 17 * mm}, PointNm{52 * mm, 30 * mm, 9 * mm}, &st);
  stamp_line(&tg->g, vbit.c, PointNm{8 * mm, 33 * mm, 18 * mm}, PointNm{50 * mm, 36 * mm, 17 * mm}, &st);
  stamp_line(&tg->g, flat.c, PointNm{20 * mm, 18 * mm, 12 * mm}, PointNm{20 * mm, 18 * mm, 2 * mm}, &st);
}

struct P2 {
  double x, y;
};
double cross(P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Convex hull, counterclockwise (in x right, y down coordinates: clockwise
// on the screen), Andrew's monotone chain.
std::vector<P2> hull(std::vector<P2> p) {
  std::sort(p.begin(), p.end(), [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
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

}  // namespace

TEST(milled_block_is_watertight_from_16_directions) {
  t::TestGrid<uint16_t> tg;
  make_milled_inside(&tg);
  RenderOptions opt;
  opt.table = false;
  opt.gradient = false;
  opt.background_top = Rgb{255, 0, 255};
  t::TestFrame f;
  t::make_frame(&f, 320, 240, PixelFormat::kXrgb8888);
  static Renderer<uint16_t> r;
  CHECK(t::init_renderer(&r, tg.g, &f, opt));
  const uint32_t bg = pixel_pack(PixelFormat::kXrgb8888, opt.background_top);
  const int32_t elevations[4] = {15000, 35000, 62000, -25000};
  int checked = 0;
  for (int proj = 0; proj < 2; ++proj) {
    for (int k = 0; k < 16; ++k) {
      Camera c = with_angles(renderer_fit(r, ViewPreset::kIso), 7000 + k * 22500, elevations[k % 4]);
      c.projection = proj ? Projection::kPerspective : Projection::kOrthographic;
      camera_fit(&c, renderer_stock_box(r), 320, 240);
      renderer_set_camera(&r, c);
      render_full(&r, &tg.g, CutterPose{});
      // The material's box: dexels 1 .. n-2 (the border is holes), 0 to 20 mm.
      std::vector<P2> pts;
      for (int q = 0; q < 8; ++q) {
        const PointNm p{tg.g.x0_nm + ((q & 1) ? 58 : 1) * mm, tg.g.y0_nm + ((q & 2) ? 42 : 1) * mm, (q & 4) ? 20 * mm : 0};
        const RasterVertex v = clip_project(r.view.proj, view_point(r.view, p));
        pts.push_back(P2{v.x_q4 / 16.0, v.y_q4 / 16.0});
      }
      const std::vector<P2> h = hull(pts);
      int holes = 0;
      for (int32_t y = 0; y < 240; ++y) {
        for (int32_t x = 0; x < 320; ++x) {
          const P2 centre{x + 0.5, y + 0.5};
          bool inside = true;
          for (size_t e = 0; e < h.size() && inside; ++e) {
            const P2 a = h[e], b = h[(e + 1) % h.size()];
            inside = cross(a, b, centre) / std::hypot(b.x - a.x, b.y - a.y) > 1.5;
          }
          if (!inside) continue;
          ++checked;
          if (frame_pixel(f.fb, x, y) == bg && holes++ == 0) {
            std::printf("direction %d (%s): background at (%d, %d)\n", k, proj ? "perspective" : "orthographic", x, y);
            t::dump_frame(f.fb, "watertight_actual");
          }
        }
      }
      CHECK_EQ(holes, 0);
      if (k == 5) t::dump_frame(f.fb, proj ? "watertight-persp" : "watertight-ortho");
    }
  }
  CHECK_GT(checked, 32 * 10000);
}

TEST(drawing_allocates_nothing) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  t::TestCutter c;
  t::make_cutter(tg.g, t::ball_tool(4 * mm), &c);
  t::TestFrame f;
  t::make_frame(&f, 320, 240, PixelFormat::kRgb565);
  static Renderer<uint16_t> r;
  CHECK(t::init_renderer(&r, tg.g, &f));
  const uint64_t before = t::heap_allocations();
  renderer_set_tool(&r, &c.profile);
  renderer_set_camera(&r, renderer_fit(r, ViewPreset::kIso));
  RenderResult res = render_full(&r, &tg.g, CutterPose{true, PointNm{30 * mm, 20 * mm, 15 * mm}});
  CutStats st;
  stamp_line(&tg.g, c.c, PointNm{30 * mm, 20 * mm, 15 * mm}, PointNm{40 * mm, 25 * mm, 15 * mm}, &st);
  res = render_update(&r, &tg.g, CutterPose{true, PointNm{40 * mm, 25 * mm, 15 * mm}});
  CHECK_EQ(t::heap_allocations() - before, 0u);
  CHECK_GT(res.nrects, 0);
  CHECK_GT(res.stats.pixels_written, 0u);
}

TEST(renderer_init_checks_its_memory) {
  t::TestGrid<uint16_t> tg;
  t::make_block(&tg, 30, 20, mm, 10 * mm);
  t::TestFrame f;
  t::make_frame(&f, 64, 48, PixelFormat::kXrgb8888);
  static Renderer<uint16_t> r;
  RenderOptions opt;
  const size_t n = renderer_scratch_bytes(tg.g, 64, 48, opt.zformat);
  // z-buffer, two shade bytes per dexel, blocks and tiles.
  CHECK_GE(n, size_t(64 * 48 * 4 + 2 * 30 * 20));
  std::vector<uint64_t> mem(n / 8 + 1);
  CHECK_EQ(renderer_init(&r, tg.g, f.fb, opt, mem.data(), n - 1), Status::kBufferTooSmall);
  CHECK_EQ(renderer_init(&r, tg.g, f.fb, opt, nullptr, n), Status::kBufferTooSmall);
  FrameView bad = f.fb;
  bad.stride_bytes = 10;
  CHECK_EQ(renderer_init(&r, tg.g, bad, opt, mem.data(), n), Status::kBadArgument);
  bad = f.fb;
  bad.width = 0;
  CHECK_EQ(renderer_init(&r, tg.g, bad, opt, mem.data(), n), Status::kBadArgument);
  CHECK_EQ(renderer_init(&r, tg.g, f.fb, opt, mem.data(), n), Status::kOk);
  opt.zformat = ZFormat::kZ16;
  CHECK_LT(renderer_scratch_bytes(tg.g, 64, 48, opt.zformat), n);
  // A grid of another size than the renderer's draws nothing.
  t::TestGrid<uint16_t> other;
  t::make_block(&other, 31, 20, mm, 10 * mm);
  const RenderResult res = render_full(&r, &other.g, CutterPose{});
  CHECK_EQ(res.nrects, 0);
}

TEST(surface_is_closed_even_with_holes) {
  // With back faces drawn too, a ray through a closed surface crosses it an
  // even number of times; a crack, a missing side face or a missing
  // diagonal makes some pixel odd. And with faces pointing outwards it
  // enters as often as it leaves: front faces are exactly half the
  // crossings (a face turned inside out breaks that). Counted with the
  // rasterizer's coverage mode over the mesh's own triangles, bottoms
  // included, on the pocketed block (through hole, diagonals, fins) from 32
  // directions.
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  // Thin walls and single dexels between holes, too.
  t::TestCutter flat;
  t::make_cutter(tg.g, t::flat_tool(3 * mm), &flat);
  CutStats st;
  stamp_line(&tg.g, flat.c, PointNm{40 * mm, 30 * mm, -mm}, PointNm{52 * mm, 36 * mm, -mm}, &st);
  stamp_line(&tg.g, flat.c, PointNm{40 * mm, 34 * mm, -mm}, PointNm{52 * mm, 40 * mm, -mm}, &st);
  const int32_t w = 320, h = 240;
  std::vector<uint8_t> count(size_t(w) * h), front(size_t(w) * h);
  std::vector<uint8_t> shade_top(tg.top.size(), 128), shade_wall(tg.top.size(), 128);
  ShadeCache shades{shade_top.data(), shade_wall.data()};
  SceneFrame scene;
  scene.box = BoxNm{PointNm{-5 * mm, -5 * mm, -mm}, PointNm{65 * mm, 45 * mm, 30 * mm}};
  scene.x0_nm = tg.g.x0_nm;
  scene.y0_nm = tg.g.y0_nm;
  scene.z0_nm = tg.g.z0_nm;
  scene.pitch_nm = tg.g.pitch_nm;
  scene.lsb_nm = tg.g.lsb_nm;
  scene.stock_top_nm = 20 * mm;
  const BoxNm stock{PointNm{0, 0, 0}, PointNm{60 * mm, 40 * mm, 20 * mm}};
  int odd_total = 0;
  for (int proj = 0; proj < 2; ++proj) {
    for (int k = 0; k < 16; ++k) {
      Camera c = with_angles(camera_preset(ViewPreset::kIso), 3000 + k * 22500, (k % 2 ? 1 : -1) * (10000 + 5000 * (k % 7)));
      c.projection = proj ? Projection::kPerspective : Projection::kOrthographic;
      camera_fit(&c, stock, w, h);
      View v;
      view_build(c, scene, w, h, &v);
      for (int cull = 0; cull < 2; ++cull) {
        std::vector<uint8_t>& buf = cull ? front : count;
        std::fill(buf.begin(), buf.end(), 0);
        RasterTarget t;
        t.color = buf.data();
        t.color_stride = w;
        t.clip = ScreenRect{0, 0, w, h};
        t.cull_back = cull != 0;
        t.count_coverage = true;
        MeshPass<uint16_t> pass;
        pass.grid = &tg.g;
        pass.view = &v;
        pass.shades = &shades;
        pass.bottoms = true;
        pass.target = &t;
        for (int32_t by = 0; by < blocks_across(tg.g.ny); ++by)
          for (int32_t bx = 0; bx < blocks_across(tg.g.nx); ++bx)
            mesh_draw_cells(pass, block_cells(tg.g, bx, by), false, false, false, 0, 0);
      }
      int odd = 0, covered = 0;
      for (size_t q = 0; q < count.size(); ++q) {
        odd += (count[q] & 1) || count[q] != 2 * front[q];
        covered += count[q] != 0;
      }
      CHECK_GT(covered, 5000);
      if (odd && odd_total == 0) std::printf("direction %d (%s): %d pixels cross the surface an odd number of times or not as often in as out\n", k, proj ? "perspective" : "orthographic", odd);
      odd_total += odd;
    }
  }
  CHECK_EQ(odd_total, 0);
}

namespace {

// One golden frame: a scene, a camera, a format; checked against
// tests/golden/hashes.txt and its picture tests/golden/frames/NAME.png.
template <class H>
void golden_frame(const char* name, int scene, ViewPreset view, Projection proj, int tool, PixelFormat fmt, ZFormat zf,
                  int32_t w, int32_t h) {
  t::TestGrid<H> tg;
  if (scene == 0) t::make_block(&tg, 40, 30, mm, 15 * mm);
  else t::make_pocketed(&tg);
  t::TestCutter c;
  const Tool tools[4] = {t::ball_tool(8 * mm), t::flat_tool(8 * mm), t::bull_tool(8 * mm, 2 * mm), t::vbit_tool(8 * mm, 60000)};
  t::make_cutter(tg.g, tools[tool < 0 ? 0 : tool], &c);
  RenderOptions opt;
  opt.zformat = zf;
  t::TestFrame f;
  t::make_frame(&f, w, h, fmt);
  static Renderer<H> r;
  if (!CHECK(t::init_renderer(&r, tg.g, &f, opt))) return;
  Camera cam = renderer_fit(r, view);
  if (proj == Projection::kPerspective) {
    cam.projection = proj;
    camera_fit(&cam, renderer_stock_box(r), w, h);
  }
  if (view == ViewPreset::kRight && tool >= 0 && proj == Projection::kOrthographic && scene == 1 && w == 200) {
    // The tool close up, from the front and a little above.
    cam = with_angles(cam, -90000, 15000);
    cam.view_height_nm = 16 * mm;
    cam.target = PointNm{44 * mm, 15 * mm, 24 * mm};
  }
  renderer_set_tool(&r, &c.profile);
  renderer_set_camera(&r, cam);
  render_full(&r, &tg.g, CutterPose{tool >= 0, PointNm{44 * mm, 15 * mm, 21 * mm}});
  t::dump_frame(f.fb, name);
  CHECK_GOLDEN_FRAME(name, f.fb);
}

}  // namespace

TEST(golden_frames) {
  // Frame hashes (display/raster/framebuffer.h frame_hash: pixel values, little
  // endian, row by row), so every compiler and CPU must draw the same bits;
  // a frame that differs leaves its expected, actual and difference
  // pictures (tests/golden_check.h). Update only on purpose (make bless),
  // with the reason in the commit.
  using P = PixelFormat;
  using Z = ZFormat;
  const auto O = Projection::kOrthographic, Pp = Projection::kPerspective;
  golden_frame<uint16_t>("golden-block-iso", 0, ViewPreset::kIso, O, -1, P::kXrgb8888, Z::kZ32, 320, 240);
  golden_frame<uint16_t>("golden-pocket-iso", 1, ViewPreset::kIso, O, 0, P::kXrgb8888, Z::kZ32, 320, 240);
  golden_frame<uint16_t>("golden-pocket-top", 1, ViewPreset::kTop, O, 0, P::kXrgb8888, Z::kZ32, 320, 240);
  golden_frame<uint16_t>("golden-pocket-front", 1, ViewPreset::kFront, O, 0, P::kXrgb8888, Z::kZ32, 320, 240);
  golden_frame<uint16_t>("golden-pocket-right", 1, ViewPreset::kRight, O, 0, P::kXrgb8888, Z::kZ32, 320, 240);
  golden_frame<uint16_t>("golden-tool-ball", 1, ViewPreset::kRight, O, 0, P::kXrgb8888, Z::kZ32, 200, 150);
  golden_frame<uint16_t>("golden-tool-flat", 1, ViewPreset::kRight, O, 1, P::kXrgb8888, Z::kZ32, 200, 150);
  golden_frame<uint16_t>("golden-tool-bull", 1, ViewPreset::kRight, O, 2, P::kXrgb8888, Z::kZ32, 200, 150);
  golden_frame<uint16_t>("golden-tool-vbit", 1, ViewPreset::kRight, O, 3, P::kXrgb8888, Z::kZ32, 200, 150);
  golden_frame<uint16_t>("golden-pocket-565", 1, ViewPreset::kIso, O, 0, P::kRgb565, Z::kZ16, 480, 272);
  golden_frame<uint16_t>("golden-pocket-persp", 1, ViewPreset::kIso, Pp, 0, P::kXrgb8888, Z::kZ16, 320, 240);
  golden_frame<uint8_t>("golden-pocket-u8", 1, ViewPreset::kIso, O, 0, P::kXrgb8888, Z::kZ32, 320, 240);
  golden_frame<uint32_t>("golden-pocket-u32", 1, ViewPreset::kIso, O, 0, P::kRgb565, Z::kZ32, 320, 240);
}
