// Golden section "demo": the paper's loop (paper §3) for each of its four
// workpieces, in core and display alone, pinned bit for bit on every
// target: the built-in design (core/design/builtin.h) -> zig positions
// (core/cam/zig.h: stripes one dexel apart, a position on every dexel, the
// paper's ball) -> swept cut from a block (core/cut/sweep.h; the plunge
// from above the block, the lifted return not cut) -> the assessment (§2.5:
// E, gouge and leftover columns, the deepest gouge, which the path keeps
// within 1 LSB) -> a frame in the material's textured colours. One line
// each: positions, the grid's hash, the assessment, the frame's hash.
#include <stdint.h>

#include "core/assess/assess.h"
#include "core/cam/zig.h"
#include "core/cut/sweep.h"
#include "core/design/builtin.h"
#include "core/grid/grid.h"
#include "core/material/material_preset.h"
#include "core/tool/tool.h"
#include "display/colour/material_colours.h"
#include "display/surface/render.h"
#include "tests/golden/golden.h"

using namespace dexmill;

namespace golden {
namespace {

constexpr int32_t kW = 160, kH = 120;

// Cuts the zig path of b into g; returns the positions (0: out of memory).
uint64_t cut_zig(Arena& a, const BuiltinDesign& b, const DesignGrid& d, DexelGrid<uint16_t>* g) {
  Tool tool;
  tool.kind = ToolKind::kBall;
  tool.diameter_nm = b.ball_dexels * b.pitch_nm;
  tool.length_nm = b.stock_height_nm + 20 * kNmPerMm;
  const ToolProfile p = tool_profile(tool);
  SweepTool st;
  ZigTool zt;
  const size_t words = zig_tool_words(p, d.geo);
  int32_t* w = a.take<int32_t>(words);
  if (!w || !ok(zig_tool_build(p, d.geo, w, words, &zt)) || !ok(sweep_tool_prepare(p, g->lsb_nm, &st))) return 0;
  const ZigOptions o;
  const size_t scratch_words = zig_stripe_scratch(d, zt, o);
  int64_t* scratch = a.take<int64_t>(scratch_words);
  int64_t* z = a.take<int64_t>(static_cast<size_t>(zig_positions(d, o)));
  if (!scratch || !z) return 0;
  const int64_t above = d.geo.z0_nm + b.stock_height_nm + kNmPerMm;
  CutStats cs;
  uint64_t n = 0;
  for (int32_t s = 0; s < zig_stripe_count(d, o); ++s) {
    if (!ok(zig_stripe(d, zt, o, s, 0, scratch, scratch_words, z))) return 0;
    const int64_t y = d.geo.y0_nm + static_cast<int64_t>(zig_stripe_row(d, o, s)) * d.geo.pitch_nm;
    PointNm at{d.geo.x0_nm, y, above};
    for (int32_t k = 0; k < zig_positions(d, o); ++k, ++n) {
      const PointNm next{d.geo.x0_nm + static_cast<int64_t>(zig_position_u(d, o, k)) * d.geo.pitch_nm, y,
                         d.geo.z0_nm + z[k] * d.geo.lsb_nm};
      sweep_line(g, st, at, next, &cs);
      at = next;
    }
  }
  return n;
}

void one_demo(Out& out, const BuiltinDesign& b) {
  Arena& a = arena();
  a.reset();
  const GridGeometry geo = builtin_geometry(b, 16);
  const size_t cells = static_cast<size_t>(geo.nx) * geo.ny;
  int32_t* tops = a.take<int32_t>(cells);
  uint16_t* top = a.take<uint16_t>(cells);
  uint16_t* bottom = a.take<uint16_t>(cells);
  DesignGrid d;
  DexelGrid<uint16_t> g;
  if (!tops || !top || !bottom || !ok(design_init(&d, geo, tops, cells)) || !ok(builtin_design_fill(b, &d)) ||
      !ok(grid_init(&g, geo, top, bottom, cells))) {
    fail(out, "demo: set-up");
    return;
  }
  grid_block_stock(&g, grid_height_of_z(g, b.stock_height_nm));
  const uint64_t positions = cut_zig(a, b, d, &g);
  if (!positions) {
    fail(out, "demo: zig");
    return;
  }
  AssessOptions ao;
  ao.region = GridRect{1, 1, geo.nx - 1, geo.ny - 1};  // grid_block_stock leaves the border ring a hole
  AssessResult res;
  if (!ok(assess(g, d, ao, &res))) {
    fail(out, "demo: assess");
    return;
  }
  out.str("demo ").str(b.name).kv("positions", static_cast<int64_t>(positions)).kx("grid", grid_hash(g));
  out.kx("E_lsb2_lo", res.e_lsb2.lo).kv("gouge", static_cast<int64_t>(res.gouge_columns)).kv("max_gouge_lsb", res.max_gouge_lsb);
  out.kv("left", static_cast<int64_t>(res.leftover_columns)).kv("within", static_cast<int64_t>(res.within_tol_columns));
  // The frame, in the material's colours.
  static StockComposition comp;
  const BoxNm box{PointNm{0, 0, 0}, PointNm{(geo.nx - 1) * geo.pitch_nm, (geo.ny - 1) * geo.pitch_nm, b.stock_height_nm}};
  uint32_t* pixels = a.take<uint32_t>(static_cast<size_t>(kW) * kH);
  RenderOptions opt;
  const size_t need = renderer_scratch_bytes(g, kW, kH, opt.zformat);
  void* scratch = a.take<uint64_t>((need + 7) / 8);
  uint8_t* cls = a.take<uint8_t>(cells);
  uint32_t* luts = a.take<uint32_t>(static_cast<size_t>(kMaxColourClasses) * kShadeLevels);
  uint32_t* tex = a.take<uint32_t>(material_texture_bytes(g) / 4 + 1);
  static Renderer<uint16_t> r;
  static MaterialColours<uint16_t> mc;
  FrameView fb{pixels, kW, kH, kW * 4, PixelFormat::kXrgb8888};
  if (!pixels || !scratch || !cls || !luts || !tex || !material_preset(b.material, box, &comp) ||
      !ok(renderer_init(&r, g, fb, opt, scratch, need))) {
    fail(out, "demo: frame");
    return;
  }
  material_colours_init(&mc, g, comp, cls, luts);
  material_colours_texture(&mc, tex, static_cast<uint32_t>(grid_height_of_z(g, b.stock_height_nm)));
  renderer_set_colours(&r, &mc.colours);
  renderer_set_camera(&r, renderer_fit(r, ViewPreset::kIso));
  render_full(&r, &g, CutterPose{});
  out.kx("frame", frame_hash(fb)).end();
}

}  // namespace

void golden_demo(Out& out) {
  for (int32_t k = 0; k < builtin_design_count(); ++k) one_demo(out, builtin_design_at(k));
}

}  // namespace golden
