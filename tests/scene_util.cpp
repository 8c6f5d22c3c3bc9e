// Test scenes for the display (see scene_util.h).
#include "tests/scene_util.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace t {

using namespace dexmill;

template <class H>
void make_block(TestGrid<H>* tg, int32_t nx, int32_t ny, int64_t pitch_nm, int64_t height_nm) {
  GridGeometry geo{};
  geo.nx = nx;
  geo.ny = ny;
  geo.x0_nm = -pitch_nm / 2;
  geo.y0_nm = -pitch_nm / 2;
  geo.pitch_nm = pitch_nm;
  geo.z0_nm = 0;
  geo.lsb_nm = lsb_for_range(height_nm + height_nm / 4, static_cast<int>(sizeof(H) * 8));
  tg->top.assign(static_cast<size_t>(nx) * ny, 0);
  tg->bottom.assign(tg->top.size(), 0);
  grid_init(&tg->g, geo, tg->top.data(), tg->bottom.data(), tg->top.size());
  grid_block_stock(&tg->g, grid_height_of_z(tg->g, height_nm));
}

template <class H>
void make_cutter(const DexelGrid<H>& g, const Tool& tool, TestCutter* out) {
  out->tool = tool;
  out->profile = tool_profile(tool);
  out->words.resize(cutter_storage_words(cutter_reach_dex(out->profile, g.pitch_nm)));
  cutter_build(out->profile, g.pitch_nm, g.lsb_nm, out->words.data(), out->words.size(), &out->c);
}

Tool ball_tool(int64_t d) { return Tool{ToolKind::kBall, d, 0, 0, 0, 8 * d}; }
Tool flat_tool(int64_t d) { return Tool{ToolKind::kFlat, d, 0, 0, 0, 8 * d}; }
Tool bull_tool(int64_t d, int64_t rc) { return Tool{ToolKind::kBullNose, d, rc, 0, 0, 8 * d}; }
Tool vbit_tool(int64_t d, int32_t a) { return Tool{ToolKind::kVBit, d, 0, a, 0, 8 * d}; }

template <class H>
void make_pocketed(TestGrid<H>* tg) {
  const int64_t mm = kNmPerMm;
  make_block(tg, 62, 42, mm, 20 * mm);
  DexelGrid<H>& g = tg->g;
  TestCutter flat, ball, vbit;
  make_cutter(g, flat_tool(6 * mm), &flat);
  make_cutter(g, ball_tool(8 * mm), &ball);
  make_cutter(g, vbit_tool(6 * mm, 90000), &vbit);
  CutStats st;
  // Pocket: 14 mm floor, zig-zag 3 mm stepover.
  for (int64_t y = 8 * mm; y <= 20 * mm; y += 3 * mm)
    stamp_line(&g, flat.c, PointNm{8 * mm, y, 14 * mm}, PointNm{28 * mm, y, 14 * mm}, &st);
  // Ball channel, diagonal and sloping.
  stamp_line(&g, ball.c, PointNm{34 * mm, 6 * mm, 18 * mm}, PointNm{54 * mm, 24 * mm, 12 * mm}, &st);
  // V groove across.
  stamp_line(&g, vbit.c, PointNm{6 * mm, 30 * mm, 18 * mm}, PointNm{56 * mm, 34 * mm, 18 * mm}, &st);
  // Through hole in the pocket floor.
  stamp_line(&g, flat.c, PointNm{18 * mm, 14 * mm, 25 * mm}, PointNm{18 * mm, 14 * mm, -mm}, &st);
  stamp_line(&g, flat.c, PointNm{18 * mm, 14 * mm, -mm}, PointNm{22 * mm, 16 * mm, -mm}, &st);
}

void make_frame(TestFrame* f, int32_t w, int32_t h, PixelFormat fmt) {
  f->pixels.assign(static_cast<size_t>(w) * h, 0);
  f->fb.pixels = f->pixels.data();
  f->fb.width = w;
  f->fb.height = h;
  f->fb.stride_bytes = w * pixel_bytes(fmt);
  f->fb.format = fmt;
}

template <class H>
bool init_renderer(Renderer<H>* r, const DexelGrid<H>& g, TestFrame* f, const RenderOptions& opt) {
  const size_t n = renderer_scratch_bytes(g, f->fb.width, f->fb.height, opt.zformat);
  f->scratch.assign((n + 7) / 8, 0);
  return ok(renderer_init(r, g, f->fb, opt, f->scratch.data(), n));
}

void dump_frame(const FrameView& fb, const char* name) {
  const char* dir = std::getenv("DEXMILL_TEST_IMAGES");
  if (!dir || !*dir) return;
  char path[1024];
  std::snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
  FILE* fp = std::fopen(path, "wb");
  if (!fp) return;
  std::fprintf(fp, "P6\n%d %d\n255\n", fb.width, fb.height);
  for (int32_t y = 0; y < fb.height; ++y) {
    for (int32_t x = 0; x < fb.width; ++x) {
      const Rgb c = pixel_unpack(fb.format, frame_pixel(fb, x, y));
      const unsigned char px[3] = {c.r, c.g, c.b};
      std::fwrite(px, 1, 3, fp);
    }
  }
  std::fclose(fp);
}

#define SCENE_INSTANTIATE(H)                                                                  \
  template void make_block<H>(TestGrid<H>*, int32_t, int32_t, int64_t, int64_t);             \
  template void make_cutter<H>(const DexelGrid<H>&, const Tool&, TestCutter*);               \
  template void make_pocketed<H>(TestGrid<H>*);                                              \
  template bool init_renderer<H>(Renderer<H>*, const DexelGrid<H>&, TestFrame*, const RenderOptions&);
SCENE_INSTANTIATE(uint8_t)
SCENE_INSTANTIATE(uint16_t)
SCENE_INSTANTIATE(uint32_t)

int uncovered_changes(const FrameView& now, const FrameView& before, const RenderResult& res) {
  int n = 0;
  for (int32_t y = 0; y < now.height; ++y)
    for (int32_t x = 0; x < now.width; ++x) {
      if (frame_pixel(now, x, y) == frame_pixel(before, x, y)) continue;
      bool in = false;
      for (int k = 0; k < res.nrects; ++k)
        in |= x >= res.rects[k].x0 && x < res.rects[k].x1 && y >= res.rects[k].y0 && y < res.rects[k].y1;
      n += !in;
    }
  return n;
}

void report_first_difference(const char* what, int step, const FrameView& incremental, const FrameView& full,
                             const char* prefix) {
  int32_t fx = -1, fy = -1;
  for (int32_t y = 0; y < incremental.height && fx < 0; ++y)
    for (int32_t x = 0; x < incremental.width; ++x)
      if (frame_pixel(incremental, x, y) != frame_pixel(full, x, y)) {
        fx = x;
        fy = y;
        break;
      }
  if (fx < 0) return;
  std::printf("%s: step %d: first differing pixel (%d, %d): incremental %08x, full %08x\n", what, step, fx, fy,
              frame_pixel(incremental, fx, fy), frame_pixel(full, fx, fy));
  const std::string base(prefix);
  dump_frame(incremental, (base + "_actual").c_str());
  dump_frame(full, (base + "_expected").c_str());
}

}  // namespace t
