// Golden section "frame": the golden mill program's kind of part (a pocketed
// block with a through hole, cut by sweeps) rendered by display/render.h at
// 120x90 in both pixel formats and both z formats, in the iso and top views,
// plus one incremental update after a further cut; one frame hash a line
// (display's frame_hash: pixel values as little-endian bytes, any stride).
#include <stdint.h>

#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "display/render.h"
#include "tests/golden/golden.h"

using namespace dexmill;

namespace golden {
namespace {

constexpr int32_t kW = 120, kH = 90, kNx = 48, kNy = 40;

Tool ball6() {
  Tool t;
  t.kind = ToolKind::kBall;
  t.diameter_nm = 6 * kNmPerMm;
  t.flute_length_nm = 20 * kNmPerMm;
  t.length_nm = 50 * kNmPerMm;
  return t;
}

void one(Out& out, PixelFormat pf, ZFormat zf, ViewPreset view) {
  Arena& a = arena();
  a.reset();
  const size_t cells = static_cast<size_t>(kNx) * kNy;
  uint16_t* top = a.take<uint16_t>(cells);
  uint16_t* bottom = a.take<uint16_t>(cells);
  const int bpp = pf == PixelFormat::kRgb565 ? 2 : 4;
  uint32_t* pixels = a.take<uint32_t>(static_cast<size_t>(kW) * kH);
  DexelGrid<uint16_t> g;
  const GridGeometry geo{kNx, kNy, 0, 0, 500000, 0, 500};
  if (!top || !bottom || !pixels || !ok(grid_init(&g, geo, top, bottom, cells))) {
    fail(out, "frame: grid");
    return;
  }
  grid_block_stock(&g, 40000);  // 20 mm
  const Tool tool = ball6();
  const ToolProfile prof = tool_profile(tool);
  SweepTool st_tool;
  sweep_tool_prepare(prof, g.lsb_nm, &st_tool);
  CutStats st;
  const int64_t mm = kNmPerMm;
  sweep_line(&g, st_tool, PointNm{5 * mm, 5 * mm, 15 * mm}, PointNm{18 * mm, 6 * mm, 13 * mm}, &st);
  sweep_line(&g, st_tool, PointNm{18 * mm, 6 * mm, 13 * mm}, PointNm{18 * mm, 14 * mm, 12 * mm}, &st, false);
  sweep_line(&g, st_tool, PointNm{10 * mm, 14 * mm, 25 * mm}, PointNm{10 * mm, 14 * mm, -mm}, &st);  // hole
  RenderOptions opt;
  opt.zformat = zf;
  const size_t need = renderer_scratch_bytes(g, kW, kH, zf);
  void* scratch = a.take<uint64_t>((need + 7) / 8);
  static Renderer<uint16_t> r;
  FrameView fb{pixels, kW, kH, kW * bpp, pf};
  if (!scratch || !ok(renderer_init(&r, g, fb, opt, scratch, need))) {
    fail(out, "frame: renderer");
    return;
  }
  renderer_set_tool(&r, &prof);
  renderer_set_camera(&r, renderer_fit(r, view));
  render_full(&r, &g, CutterPose{true, PointNm{18 * mm, 14 * mm, 12 * mm}});
  out.str("frame").kv("view", static_cast<int64_t>(view)).str(pf == PixelFormat::kRgb565 ? " rgb565" : " xrgb8888");
  out.str(zf == ZFormat::kZ16 ? " z16" : " z32").kx("full", frame_hash(fb));
  sweep_line(&g, st_tool, PointNm{18 * mm, 14 * mm, 12 * mm}, PointNm{6 * mm, 15 * mm, 14 * mm}, &st, false);
  const RenderResult res = render_update(&r, &g, CutterPose{true, PointNm{6 * mm, 15 * mm, 14 * mm}});
  out.kx("update", frame_hash(fb)).kv("rects", res.nrects).end();
}

}  // namespace

void golden_frame(Out& out) {
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso);
  one(out, PixelFormat::kRgb565, ZFormat::kZ16, ViewPreset::kIso);
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ16, ViewPreset::kTop);
  one(out, PixelFormat::kRgb565, ZFormat::kZ32, ViewPreset::kFront);
}

}  // namespace golden
