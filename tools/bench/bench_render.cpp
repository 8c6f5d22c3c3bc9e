// `dexmill bench render-...`: the display on the paper's three workpieces
// (Table 2: 80x40, 128x128, 256x256 after zig milling with ball cutters of 9,
// 12 and 6 dexels) and on a 1024x1024 grid; the paper drew a whole workpiece
// in 20 s to 2 min 30 s and a local update in 80-120 ms.
//
//   render-wN    full frame (surface extraction, shading, rasterization) at
//                640x480 and 480x272, one line each: the fastest of repeated
//                runs, ns per frame pixel, triangles submitted, pixels
//                written (fragments passing the depth test)
//   update-w3    the local update after one instance of motion of the
//                6-dexel cutter (cutting excluded), over three finishing
//                stripes: median, mean and worst time, the area redrawn
//                (pixels of the returned rectangles) and ns per such pixel
//   render-1k    full frame of a 1024x1024 block (not milled: zig milling it
//                would take the bench most of a minute), both sizes
//   material-w3-PRESET
//                w3 drawn plain and in a material preset's colours
//                (textured), full frame and update-w3's updates, with
//                their ratios (the target: textured within 1.5x of plain)
//
// The zig milling: x-parallel stripes one dexel apart, the tool tip following
// a smooth relief, lifted between stripes (the lift is not cut).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/config.h"
#include "core/cut/stamp.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "core/material/material_preset.h"
#include "display/colour/material_colours.h"
#include "display/surface/render.h"
#include "tools/bench/bench.h"

namespace dexmill {
namespace {

constexpr int64_t kPitch = kNmPerMm / 2;  // 0.5 mm dexels
constexpr int64_t kStock = 20 * kNmPerMm;

struct Work {
  DexelGrid<height_t> g;
  std::vector<height_t> top, bottom;
  ToolProfile profile;
  std::vector<int32_t> words;
  CutterDexels c;
};

// The relief under the stripes: a smooth bump field 2 to 10 mm deep.
int64_t relief_nm(int64_t x, int64_t y, int64_t sx, int64_t sy) {
  const double u = static_cast<double>(x) / static_cast<double>(sx), v = static_cast<double>(y) / static_cast<double>(sy);
  const double d = 6.0 + 2.5 * std::sin(6.2832 * 1.5 * u) * std::cos(6.2832 * v) + 1.5 * std::cos(6.2832 * 2.5 * (u + v));
  return kStock - static_cast<int64_t>(d * kNmPerMm);
}

void make_work(Work* w, int32_t n_x, int32_t n_y, int32_t tool_dexels, bool mill) {
  GridGeometry geo{};
  geo.nx = n_x;
  geo.ny = n_y;
  geo.x0_nm = 0;
  geo.y0_nm = 0;
  geo.pitch_nm = kPitch;
  geo.z0_nm = 0;
  geo.lsb_nm = lsb_for_range(kStock + kStock / 4, DEXMILL_HEIGHT_BITS);
  w->top.assign(static_cast<size_t>(n_x) * n_y, 0);
  w->bottom.assign(w->top.size(), 0);
  grid_init(&w->g, geo, w->top.data(), w->bottom.data(), w->top.size());
  grid_block_stock(&w->g, grid_height_of_z(w->g, kStock));
  const Tool tool{ToolKind::kBall, tool_dexels * kPitch, 0, 0, 0, 40 * kNmPerMm};
  w->profile = tool_profile(tool);
  w->words.resize(cutter_storage_words(cutter_reach_dex(w->profile, kPitch)));
  cutter_build(w->profile, kPitch, geo.lsb_nm, w->words.data(), w->words.size(), &w->c);
  if (!mill) return;
  CutStats st;
  const int64_t sx = (n_x - 1) * kPitch, sy = (n_y - 1) * kPitch;
  for (int32_t j = 0; j < n_y; ++j) {
    const int64_t y = j * kPitch;
    for (int32_t i = 0; i + 4 < n_x; i += 4) {
      const int64_t xa = i * kPitch, xb = (i + 4) * kPitch;
      stamp_line(&w->g, w->c, PointNm{xa, y, relief_nm(xa, y, sx, sy)}, PointNm{xb, y, relief_nm(xb, y, sx, sy)}, &st);
    }
  }
}

struct Frame {
  std::vector<uint32_t> pixels;
  std::vector<uint64_t> scratch;
  FrameView fb;
};

Renderer<height_t> g_renderer;  // ~20 KB of state: static, as a controller would keep it

void setup(Renderer<height_t>* r, Frame* f, const DexelGrid<height_t>& g, int32_t w, int32_t h) {
  f->pixels.assign(static_cast<size_t>(w) * h, 0);
  f->fb = FrameView{f->pixels.data(), w, h, w * 4, PixelFormat::kXrgb8888};
  RenderOptions opt;
  const size_t n = renderer_scratch_bytes(g, w, h, opt.zformat);
  f->scratch.assign((n + 7) / 8, 0);
  renderer_init(r, g, f->fb, opt, f->scratch.data(), n);
  renderer_set_camera(r, renderer_fit(*r, ViewPreset::kIso));
}

void full_frame(const char* name, int32_t n_x, int32_t n_y, int32_t tool_dexels, bool mill) {
  static Work w;
  make_work(&w, n_x, n_y, tool_dexels, mill);
  const int32_t sizes[2][2] = {{640, 480}, {480, 272}};
  for (const auto& s : sizes) {
    Frame f;
    setup(&g_renderer, &f, w.g, s[0], s[1]);
    renderer_set_tool(&g_renderer, &w.profile);
    const CutterPose pose{true, PointNm{(n_x / 2) * kPitch, (n_y / 2) * kPitch, kStock}};
    RenderResult res;
    // main's best_time_s takes the seconds the function measured itself.
    const double sec = bench::best_time_s(
        [&] {
          const double t0 = bench::now_s();
          res = render_full(&g_renderer, &w.g, pose);
          return bench::now_s() - t0;
        },
        0.5, 200);
    const double px = static_cast<double>(s[0]) * s[1];
    bench::result(name, "size=%dx%d grid=%dx%d ms=%.3f triangles=%llu pixels=%llu ns_per_pixel=%.2f seconds=%.6f", s[0],
                  s[1], n_x, n_y, sec * 1e3, static_cast<unsigned long long>(res.stats.triangles),
                  static_cast<unsigned long long>(res.stats.pixels_written), sec * 1e9 / px, sec);
  }
}

void bench_w1(const char* name) { full_frame(name, 80, 40, 9, true); }
void bench_w2(const char* name) { full_frame(name, 128, 128, 12, true); }
void bench_w3(const char* name) { full_frame(name, 256, 256, 6, true); }
void bench_1k(const char* name) { full_frame(name, 1024, 1024, 6, false); }

// The local updates of the finishing stripes on w (set up by make_work,
// drawn once by r): per update, its time and what it drew.
struct Updates {
  std::vector<double> times;
  uint64_t tris = 0, pixels = 0, rects = 0, area = 0;
  double median() const { return times[times.size() / 2]; }
};

Updates run_updates(Work* w, Renderer<height_t>* r) {
  // One instance of motion per update: a finishing pass along stripes that
  // follows the relief 0.5 mm below the milled surface, so every instance
  // cuts, as the paper's local update does.
  const int64_t sx = 255 * kPitch, sy = 255 * kPitch;
  Updates u;
  CutStats st;
  for (int32_t j = 60; j < 240; j += 60) {
    for (int32_t i = 8; i < 248; ++i) {
      const int64_t x = i * kPitch, y = j * kPitch, z = relief_nm(x, y, sx, sy) - kNmPerMm / 2;
      stamp_instance(&w->g, w->c, i, j, grid_height_of_z(w->g, z), &st);
      const CutterPose pose{true, PointNm{x, y, z}};
      const double t0 = bench::now_s();
      const RenderResult res = render_update(r, &w->g, pose);
      u.times.push_back(bench::now_s() - t0);
      u.tris += res.stats.triangles;
      u.pixels += res.stats.pixels_written;
      u.rects += static_cast<uint64_t>(res.nrects);
      for (int k = 0; k < res.nrects; ++k) u.area += static_cast<uint64_t>(res.rects[k].area());
    }
  }
  // Each update is different, so the median stands for the typical one (a
  // shared machine's interruptions go to the mean and the maximum).
  std::sort(u.times.begin(), u.times.end());
  return u;
}

void bench_update_w3(const char* name) {
  static Work w;
  make_work(&w, 256, 256, 6, true);
  Frame f;
  setup(&g_renderer, &f, w.g, 640, 480);
  renderer_set_tool(&g_renderer, &w.profile);
  render_full(&g_renderer, &w.g, CutterPose{true, PointNm{0, 0, kStock}});
  const Updates u = run_updates(&w, &g_renderer);
  const int n = static_cast<int>(u.times.size());
  double total = 0;
  for (double t : u.times) total += t;
  const double median = u.median(), mean = total / n;
  bench::result(name,
                "size=640x480 grid=256x256 tool=ball:6dex updates=%d ms=%.4f mean_ms=%.4f max_ms=%.4f triangles=%llu "
                "pixels=%llu rects=%.2f area=%llu ns_per_pixel=%.2f seconds=%.6f",
                n, median * 1e3, mean * 1e3, u.times[n - 1] * 1e3, static_cast<unsigned long long>(u.tris / n),
                static_cast<unsigned long long>(u.pixels / n), static_cast<double>(u.rects) / n,
                static_cast<unsigned long long>(u.area / n), median * 1e9 * n / static_cast<double>(u.area ? u.area : 1),
                median);
}

// The target: a frame in a material's colours (a texture per vertex,
// walls split) within 1.5x of a plain one. w3 at 640x480 cut from a preset
// block, full frames (best of repeated runs, the texture of every top
// already worked out: a camera change costs no texture) and the update
// sequence of update-w3 (median; each update works out the texture of the
// tops it changed), plain and textured in the same run.
void bench_material_w3(const char* name, const char* preset) {
  static Work plain_w, tex_w;
  make_work(&plain_w, 256, 256, 6, true);
  make_work(&tex_w, 256, 256, 6, true);
  static StockComposition comp;
  const BoxNm box{PointNm{0, 0, 0}, PointNm{255 * kPitch, 255 * kPitch, kStock}};
  material_preset(preset, box, &comp);
  MaterialColours<height_t> mc;
  std::vector<uint8_t> cls(tex_w.top.size());
  std::vector<uint32_t> luts(static_cast<size_t>(kMaxColourClasses) * kShadeLevels), mem(material_texture_bytes(tex_w.g) / 4 + 1);
  material_colours_init(&mc, tex_w.g, comp, cls.data(), luts.data());
  material_colours_texture(&mc, mem.data(), static_cast<uint32_t>(grid_height_of_z(tex_w.g, kStock)));
  static Renderer<height_t> plain_r, tex_r;
  Frame pf, tf;
  setup(&plain_r, &pf, plain_w.g, 640, 480);
  setup(&tex_r, &tf, tex_w.g, 640, 480);
  renderer_set_colours(&tex_r, &mc.colours);
  const CutterPose pose{true, PointNm{128 * kPitch, 128 * kPitch, kStock}};
  double t0 = bench::now_s();
  render_full(&tex_r, &tex_w.g, pose);  // the texture of every top, once
  const double first_s = bench::now_s() - t0;
  double full_s[2];
  Renderer<height_t>* rs[2] = {&plain_r, &tex_r};
  Work* ws[2] = {&plain_w, &tex_w};
  for (int k = 0; k < 2; ++k)
    full_s[k] = bench::best_time_s(
        [&] {
          const double a = bench::now_s();
          render_full(rs[k], &ws[k]->g, pose);
          return bench::now_s() - a;
        },
        0.5, 200);
  const Updates up = run_updates(&plain_w, &plain_r), ut = run_updates(&tex_w, &tex_r);
  bench::result(name,
                "size=640x480 grid=256x256 preset=%s first_ms=%.3f full_plain_ms=%.3f full_material_ms=%.3f "
                "full_ratio=%.2f update_plain_ms=%.4f update_material_ms=%.4f update_ratio=%.2f seconds=%.6f",
                preset, first_s * 1e3, full_s[0] * 1e3, full_s[1] * 1e3, full_s[1] / full_s[0], up.median() * 1e3,
                ut.median() * 1e3, ut.median() / up.median(), full_s[1]);
}

void bench_marble_w3(const char* name) { bench_material_w3(name, "marble"); }
void bench_wood_w3(const char* name) { bench_material_w3(name, "wood"); }
void bench_two_layer_w3(const char* name) { bench_material_w3(name, "two-layer"); }

BENCH(render_w1, "render-w1", bench_w1);
BENCH(render_w2, "render-w2", bench_w2);
BENCH(render_w3, "render-w3", bench_w3);
BENCH(update_w3, "update-w3", bench_update_w3);
BENCH(render_1k, "render-1k", bench_1k);
BENCH(material_w3, "material-w3-marble", bench_marble_w3);
BENCH(material_w3_wood, "material-w3-wood", bench_wood_w3);
BENCH(material_w3_layers, "material-w3-two-layer", bench_two_layer_w3);

}  // namespace
}  // namespace dexmill
