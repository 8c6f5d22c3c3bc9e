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
#include "display/render.h"
#include "tools/bench.h"

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

void bench_update_w3(const char* name) {
  static Work w;
  make_work(&w, 256, 256, 6, true);
  Frame f;
  setup(&g_renderer, &f, w.g, 640, 480);
  renderer_set_tool(&g_renderer, &w.profile);
  render_full(&g_renderer, &w.g, CutterPose{true, PointNm{0, 0, kStock}});
  // One instance of motion per update: a finishing pass along stripes that
  // follows the relief 0.5 mm below the milled surface, so every instance
  // cuts, as the paper's local update does.
  const int64_t sx = 255 * kPitch, sy = 255 * kPitch;
  std::vector<double> times;
  uint64_t tris = 0, pixels = 0, rects = 0, area = 0;
  CutStats st;
  for (int32_t j = 60; j < 240; j += 60) {
    for (int32_t i = 8; i < 248; ++i) {
      const int64_t x = i * kPitch, y = j * kPitch, z = relief_nm(x, y, sx, sy) - kNmPerMm / 2;
      stamp_instance(&w.g, w.c, i, j, grid_height_of_z(w.g, z), &st);
      const CutterPose pose{true, PointNm{x, y, z}};
      const double t0 = bench::now_s();
      const RenderResult res = render_update(&g_renderer, &w.g, pose);
      times.push_back(bench::now_s() - t0);
      tris += res.stats.triangles;
      pixels += res.stats.pixels_written;
      rects += static_cast<uint64_t>(res.nrects);
      for (int k = 0; k < res.nrects; ++k) area += static_cast<uint64_t>(res.rects[k].area());
    }
  }
  // Each update is different, so the median stands for the typical one (a
  // shared machine's interruptions go to the mean and the maximum).
  const int n = static_cast<int>(times.size());
  double total = 0;
  for (double t : times) total += t;
  std::sort(times.begin(), times.end());
  const double median = times[n / 2], mean = total / n;
  bench::result(name,
                "size=640x480 grid=256x256 tool=ball:6dex updates=%d ms=%.4f mean_ms=%.4f max_ms=%.4f triangles=%llu "
                "pixels=%llu rects=%.2f area=%llu ns_per_pixel=%.2f seconds=%.6f",
                n, median * 1e3, mean * 1e3, times[n - 1] * 1e3, static_cast<unsigned long long>(tris / n),
                static_cast<unsigned long long>(pixels / n), static_cast<double>(rects) / n,
                static_cast<unsigned long long>(area / n), median * 1e9 * n / static_cast<double>(area ? area : 1), median);
}

BENCH(render_w1, "render-w1", bench_w1);
BENCH(render_w2, "render-w2", bench_w2);
BENCH(render_w3, "render-w3", bench_w3);
BENCH(update_w3, "update-w3", bench_update_w3);
BENCH(render_1k, "render-1k", bench_1k);

}  // namespace
}  // namespace dexmill
