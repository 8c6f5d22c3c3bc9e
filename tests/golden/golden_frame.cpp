// Golden section "frame": the golden mill program's kind of part (a pocketed
// block with a through hole, cut by sweeps) rendered by display/surface/render.h at
// 120x90 in both pixel formats and both z formats, in the iso and top views,
// plus one incremental update after a further cut; one frame hash a line
// (display's frame_hash: pixel values as little-endian bytes, any stride).
// The same scene against a design part (a plane 6 mm below the top with a
// pyramid on it) in the error view (paper §2.5, figure 10), with the
// assessment's figures: E, sum of design tops, the band counts. And once,
// the scene held in a vice with a clamp on its top (display/surface/fixture_draw.h).
// And the colour modes tool (the cuts by T1, the hole by T2, the update's by
// T3), slope, and thin (under 16 mm: the cut floors).
#include <stdint.h>
#include <string.h>

#include "core/assess/assess.h"
#include "core/cut/sweep.h"
#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "core/material/material_preset.h"
#include "display/colour/error_colours.h"
#include "display/colour/material_colours.h"
#include "display/overlay/backplot.h"
#include "display/overlay/marker.h"
#include "display/overlay/overlay.h"
#include "display/surface/render.h"
#include "display/colour/slope_colours.h"
#include "display/colour/thin_colours.h"
#include "display/colour/tool_colours.h"
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

// The error view's state: the design and its colour mode.
struct ErrorView {
  DesignGrid design;
  AssessOptions opt;
  ErrorColours<uint16_t> colours;
};

// Sets up the design and the error colours for grid g; false when the arena is short.
bool error_view(Arena& a, const DexelGrid<uint16_t>& g, ErrorView* e, Out& out) {
  const size_t cells = static_cast<size_t>(g.nx) * g.ny;
  int32_t* tops = a.take<int32_t>(cells);
  uint8_t* cls = a.take<uint8_t>(cells);
  uint32_t* luts = a.take<uint32_t>(static_cast<size_t>(kErrorBands) * kShadeLevels);
  const GridGeometry geo{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm};
  if (!tops || !cls || !luts || !ok(design_init(&e->design, geo, tops, cells))) return false;
  const int64_t mm = kNmPerMm, z = 14 * mm;
  const PointNm c0{0, 0, z}, c1{24 * mm, 0, z}, c2{24 * mm, 20 * mm, z}, c3{0, 20 * mm, z}, apex{16 * mm, 12 * mm, 19 * mm};
  const TriangleNm tris[6] = {{{c0, c1, c2}}, {{c0, c2, c3}},
                              {{PointNm{12 * mm, 8 * mm, z}, PointNm{20 * mm, 8 * mm, z}, apex}},
                              {{PointNm{20 * mm, 8 * mm, z}, PointNm{20 * mm, 16 * mm, z}, apex}},
                              {{PointNm{20 * mm, 16 * mm, z}, PointNm{12 * mm, 16 * mm, z}, apex}},
                              {{PointNm{12 * mm, 16 * mm, z}, PointNm{12 * mm, 8 * mm, z}, apex}}};
  for (const TriangleNm& t : tris) (void)design_add_triangle(&e->design, t);
  e->opt.region = GridRect{1, 1, g.nx - 1, g.ny - 1};
  e->opt.tol_nm = 100000;
  error_colours_init(&e->colours, g, e->design, e->opt, cls, luts);
  AssessResult res;
  if (!ok(assess(g, e->design, e->opt, &res))) return false;
  out.str("assess").kx("E_lsb2_lo", res.e_lsb2.lo).kx("E_lsb2_hi", res.e_lsb2.hi).kv("sum_top", static_cast<int64_t>(res.sum_design_top_lsb));
  out.kv("within", static_cast<int64_t>(res.within_tol_columns)).kv("gouge", static_cast<int64_t>(res.gouge_columns));
  out.kv("max_gouge", res.max_gouge_lsb).kv("left", static_cast<int64_t>(res.leftover_columns));
  out.kv("max_left", res.max_leftover_lsb).end();
  return true;
}

// Paper figure 9: the design as a grid of its own, drawn through the same
// view, blended over the cut where it is the nearer (display/overlay/overlay.h).
void overlay(Out& out, Arena& a, const DexelGrid<uint16_t>& g, const ErrorView& ev, Renderer<uint16_t>& r,
             const FrameView& fb, const RenderOptions& opt) {
  const size_t cells = static_cast<size_t>(g.nx) * g.ny;
  uint16_t* top = a.take<uint16_t>(cells);
  uint16_t* bottom = a.take<uint16_t>(cells);
  uint8_t* pixels = a.take<uint8_t>(static_cast<size_t>(fb.stride_bytes) * fb.height);
  const size_t need = renderer_scratch_bytes(g, fb.width, fb.height, opt.zformat);
  void* scratch = a.take<uint64_t>((need + 7) / 8);
  const GridGeometry geo{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm};
  DexelGrid<uint16_t> dg;
  static Renderer<uint16_t> rd;
  FrameView dfb = fb;
  dfb.pixels = pixels;
  if (!top || !bottom || !pixels || !scratch || !ok(grid_init(&dg, geo, top, bottom, cells)) ||
      !ok(renderer_init(&rd, dg, dfb, opt, scratch, need))) {
    fail(out, "frame: overlay");
    return;
  }
  design_to_grid(ev.design, ev.opt.region, &dg);
  renderer_share_frame(&rd, r);
  renderer_set_camera(&rd, r.cam);
  render_full(&rd, &dg, CutterPose{});
  const ScreenRect all{0, 0, fb.width, fb.height};
  const DepthView rz{r.target.z, r.target.z_stride, r.target.zformat}, dz{rd.target.z, rd.target.z_stride, rd.target.zformat};
  out.str("overlay").kx("design", frame_hash(dfb));
  // Both ways: the cut over the design into the design's frame first (its
  // own pixels are not needed after), then the design over the cut from a
  // copy of the design's frame taken before.
  const size_t bytes = static_cast<size_t>(fb.stride_bytes) * fb.height;
  uint8_t* design_copy = a.take<uint8_t>(bytes);
  if (!design_copy) {
    fail(out, "frame: overlay copy");
    return;
  }
  memcpy(design_copy, pixels, bytes);
  FrameView copy = dfb;
  copy.pixels = design_copy;
  overlay_blend(dfb, dz, fb, rz, all);
  out.kx("cut_over_design", frame_hash(dfb));
  overlay_blend(fb, rz, copy, dz, all);
  out.kx("design_over_cut", frame_hash(fb)).end();
}

// The toolpath over the frame (display/overlay/backplot.h): the four cuts done,
// then a lift and a rapid still to come; then the lift done, the renderer
// repainting where it lies and the path redrawn there (as dexmill run does).
void backplot(Out& out, Renderer<uint16_t>& r, DexelGrid<uint16_t>& g, const FrameView& fb, const CutterPose& pose) {
  const int64_t mm = kNmPerMm;
  const PathSegment path[] = {
      {PointNm{5 * mm, 5 * mm, 15 * mm}, PointNm{18 * mm, 6 * mm, 13 * mm}, PathKind::kFeed},
      {PointNm{18 * mm, 6 * mm, 13 * mm}, PointNm{18 * mm, 14 * mm, 12 * mm}, PathKind::kFeed},
      {PointNm{10 * mm, 14 * mm, 25 * mm}, PointNm{10 * mm, 14 * mm, -mm}, PathKind::kFeed},
      {PointNm{18 * mm, 14 * mm, 12 * mm}, PointNm{6 * mm, 15 * mm, 14 * mm}, PathKind::kFeed},
      {PointNm{6 * mm, 15 * mm, 14 * mm}, PointNm{6 * mm, 15 * mm, 25 * mm}, PathKind::kRapid},
      {PointNm{6 * mm, 15 * mm, 25 * mm}, PointNm{30 * mm, 2 * mm, 25 * mm}, PathKind::kRapid},
  };
  const DepthView z{r.target.z, r.target.z_stride, r.target.zformat};
  const BackplotColours colours;
  backplot_draw(fb, z, r.view, path, 6, 4, ScreenRect{0, 0, fb.width, fb.height}, colours);
  out.str("backplot").kx("full", frame_hash(fb));
  renderer_invalidate(&r, backplot_bounds(fb, r.view, path, 4, 5));
  const RenderResult res = render_update(&r, &g, pose);
  for (int k = 0; k < res.nrects; ++k) backplot_draw(fb, z, r.view, path, 6, 5, res.rects[k], colours);
  out.kx("turned", frame_hash(fb)).kv("rects", res.nrects).kv("bias", backplot_depth_bias(r.view)).end();
}

// The fixtures of the safety checks: vice jaws along both y sides of the
// stock (x -2 to 26, y -4 to 0.5 and 19 to 23.5, z 2 to 16 mm; the material
// spans x and y 0.5 to 23 mm) and a toe clamp on the top (x 20 to 26, y 7 to
// 13, z 20 to 22.5 mm); the update's cutter stands in front of the far jaw.
const BoxNm kFixtures[3] = {
    {PointNm{-2 * kNmPerMm, -4 * kNmPerMm, 2 * kNmPerMm}, PointNm{26 * kNmPerMm, kNmPerMm / 2, 16 * kNmPerMm}},
    {PointNm{-2 * kNmPerMm, 19 * kNmPerMm, 2 * kNmPerMm}, PointNm{26 * kNmPerMm, 23 * kNmPerMm + kNmPerMm / 2, 16 * kNmPerMm}},
    {PointNm{20 * kNmPerMm, 7 * kNmPerMm, 20 * kNmPerMm}, PointNm{26 * kNmPerMm, 13 * kNmPerMm, 22 * kNmPerMm + kNmPerMm / 2}},
};

// What colours the frame: the workpiece colour, the error view, or the
// colour modes (--color tool|slope|thin|material).
enum class Colours { kPlain, kError, kTool, kSlope, kThin, kMaterial };

// A material preset's textured colours over g (display/colour/material_colours.h),
// memory from the arena; false when it is short.
bool material_view(Arena& a, const DexelGrid<uint16_t>& g, const char* preset, MaterialColours<uint16_t>* m) {
  static StockComposition comp;
  const size_t cells = static_cast<size_t>(g.nx) * g.ny;
  const BoxNm box{PointNm{0, 0, 0}, PointNm{(g.nx - 1) * g.pitch_nm, (g.ny - 1) * g.pitch_nm, 20 * kNmPerMm}};
  uint8_t* cls = a.take<uint8_t>(cells);
  uint32_t* luts = a.take<uint32_t>(static_cast<size_t>(kMaxColourClasses) * kShadeLevels);
  uint32_t* mem = a.take<uint32_t>(material_texture_bytes(g) / 4 + 1);
  if (!cls || !luts || !mem || !material_preset(preset, box, &comp)) return false;
  material_colours_init(m, g, comp, cls, luts);
  material_colours_texture(m, mem, 40000);  // the stock's top: uncut tops tinted
  return true;
}

// The colour modes' state and memory (the error view has its own).
struct ModeColours {
  ToolProvenance<uint16_t> tool;
  SurfaceColours tool_colours;
  SlopeColours<uint16_t> slope;
  ThinColours<uint16_t> thin;
  MaterialColours<uint16_t> material;
  const SurfaceColours* colours = nullptr;
  // Sets mode c up over g as it is now (the stock, for tool); false when the arena is short.
  bool init(Arena& a, Colours c, const DexelGrid<uint16_t>& g, const char* preset) {
    colours = nullptr;
    if (c == Colours::kPlain || c == Colours::kError) return true;  // no memory taken: the overlay needs it
    if (c == Colours::kMaterial) {
      colours = &material.colours;
      return material_view(a, g, preset, &material);
    }
    const size_t cells = static_cast<size_t>(g.nx) * g.ny;
    uint8_t* cls = a.take<uint8_t>(cells);
    uint32_t* luts = a.take<uint32_t>(static_cast<size_t>(kMaxColourClasses) * kShadeLevels);
    uint32_t* shadow = c == Colours::kTool ? a.take<uint32_t>(cells) : luts;
    if (!cls || !luts || !shadow) return false;
    if (c == Colours::kTool) {
      provenance_init(&tool, g, 1, kToolColourSlots, cls, shadow, nullptr);
      tool_colours_init(&tool_colours, tool, luts);
      colours = &tool_colours;
    } else if (c == Colours::kSlope) {
      slope_colours_init(&slope, g, cls, luts);
      colours = &slope.colours;
    } else if (c == Colours::kThin) {
      thin_colours_init(&thin, g, 16 * kNmPerMm, cls, luts);
      colours = &thin.colours;
    }
    return true;
  }
  // The cut pass's report of a record by tool `number` (tool mode only).
  void record(Colours c, int32_t number, const DexelGrid<uint16_t>& g) {
    if (c != Colours::kTool) return;
    provenance_set_tool(&tool, number);
    provenance_record(&tool, g.dirty, 1);
  }
};

const char* frame_name(Colours c, bool with_fixtures) {
  switch (c) {
    case Colours::kError: return "frame-error";
    case Colours::kTool: return "frame-tool";
    case Colours::kSlope: return "frame-slope";
    case Colours::kThin: return "frame-thin";
    case Colours::kMaterial: return "frame-material";
    default: return with_fixtures ? "frame-fixture" : "frame";
  }
}

void one(Out& out, PixelFormat pf, ZFormat zf, ViewPreset view, Colours colour = Colours::kPlain, bool with_fixtures = false,
         const char* preset = nullptr) {
  const bool with_error_view = colour == Colours::kError;
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
  static ModeColours mc;
  if (!mc.init(a, colour, g, preset)) {
    fail(out, "frame: colour mode");
    return;
  }
  const Tool tool = ball6();
  const ToolProfile prof = tool_profile(tool);
  SweepTool st_tool;
  sweep_tool_prepare(prof, g.lsb_nm, &st_tool);
  CutStats st;
  const int64_t mm = kNmPerMm;
  sweep_line(&g, st_tool, PointNm{5 * mm, 5 * mm, 15 * mm}, PointNm{18 * mm, 6 * mm, 13 * mm}, &st);
  sweep_line(&g, st_tool, PointNm{18 * mm, 6 * mm, 13 * mm}, PointNm{18 * mm, 14 * mm, 12 * mm}, &st, false);
  mc.record(colour, 1, g);
  sweep_line(&g, st_tool, PointNm{10 * mm, 14 * mm, 25 * mm}, PointNm{10 * mm, 14 * mm, -mm}, &st);  // hole
  mc.record(colour, 2, g);
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
  static ErrorView ev;
  renderer_set_colours(&r, nullptr);
  if (with_error_view) {
    if (!error_view(a, g, &ev, out)) {
      fail(out, "frame: error view");
      return;
    }
    renderer_set_colours(&r, &ev.colours.colours);
  }
  if (mc.colours) renderer_set_colours(&r, mc.colours);
  if (!ok(renderer_set_fixtures(&r, kFixtures, with_fixtures ? 3 : 0))) {
    fail(out, "frame: fixtures");
    return;
  }
  render_full(&r, &g, CutterPose{true, PointNm{18 * mm, 14 * mm, 12 * mm}});
  out.str(frame_name(colour, with_fixtures));
  if (preset) out.str(" ").str(preset);
  out.kv("view", static_cast<int64_t>(view));
  out.str(pf == PixelFormat::kRgb565 ? " rgb565" : " xrgb8888");
  out.str(zf == ZFormat::kZ16 ? " z16" : " z32").kx("full", frame_hash(fb));
  sweep_line(&g, st_tool, PointNm{18 * mm, 14 * mm, 12 * mm}, PointNm{6 * mm, 15 * mm, 14 * mm}, &st, false);
  mc.record(colour, 3, g);
  const RenderResult res = render_update(&r, &g, CutterPose{true, PointNm{6 * mm, 15 * mm, 14 * mm}});
  out.kx("update", frame_hash(fb)).kv("rects", res.nrects).end();
  if (with_error_view) overlay(out, a, g, ev, r, fb, opt);
  else if (!with_fixtures && colour == Colours::kPlain) backplot(out, r, g, fb, CutterPose{true, PointNm{6 * mm, 15 * mm, 14 * mm}});
  if (with_fixtures) {  // a safety finding marked on the clamp, as `run` marks one (magenta, over everything)
    const ScreenRect m = marker_draw(fb, r.view, kFixtures[0].hi, 6, pixel_pack(fb.format, Rgb{255, 40, 255}));
    out.str("frame-fixture-mark").kx("marked", frame_hash(fb)).kv("w", m.x1 - m.x0).kv("h", m.y1 - m.y0).end();
  }
}

}  // namespace

void golden_frame(Out& out) {
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso);
  one(out, PixelFormat::kRgb565, ZFormat::kZ16, ViewPreset::kIso);
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ16, ViewPreset::kTop);
  one(out, PixelFormat::kRgb565, ZFormat::kZ32, ViewPreset::kFront);
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso, Colours::kError);
  one(out, PixelFormat::kRgb565, ZFormat::kZ16, ViewPreset::kTop, Colours::kError);
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso, Colours::kPlain, true);
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso, Colours::kTool);
  one(out, PixelFormat::kRgb565, ZFormat::kZ16, ViewPreset::kTop, Colours::kSlope);
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ16, ViewPreset::kIso, Colours::kThin);
  // Material colours: a texture per vertex, walls split (paper §2.7.1, figure 11).
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kIso, Colours::kMaterial, false, "marble");
  one(out, PixelFormat::kRgb565, ZFormat::kZ16, ViewPreset::kIso, Colours::kMaterial, false, "two-layer");
  one(out, PixelFormat::kRgb565, ZFormat::kZ32, ViewPreset::kFront, Colours::kMaterial, false, "wood");
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ16, ViewPreset::kIso, Colours::kMaterial, false, "bronze");
  one(out, PixelFormat::kXrgb8888, ZFormat::kZ32, ViewPreset::kTop, Colours::kMaterial, false, "granite");
}

}  // namespace golden
