// The Cortex-M panel demo (`make panel`): what a controller panel does with
// dexmill, on an emulated MPS2 AN386 board (Cortex-M4F), built freestanding
// with semihosting only for printing. The same file built for the host gives
// the reference output; tools/scripts/panel.sh requires every line that does
// not start with "info" to be identical.
//
// Pipeline: G-code text in flash -> the simulation (core/sim/simulation.h:
// interpreter, canonical records, Mill with exact sweeps, the dexel grid,
// the safety observer) in a static block -> renderer (display/surface/render.h) ->
// a 480x272 RGB565 frame in a static framebuffer -> its hash.
//
// Everything lives in static memory sized at compile time. No heap, no
// stdio, integer only.
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "core/assess/assess.h"
#include "core/safety/safety.h"
#include "core/sim/simulation.h"
#include "core/sim/stock_state.h"
#include "core/stock/stock_file.h"
#include "core/stock/stock_transform.h"
#include "core/config.h"
#include "core/cut/mill.h"
#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "core/cut/sweep.h"
#include "core/material/material_preset.h"
#include "display/api/dexmill.h"
#include "display/colour/error_colours.h"
#include "display/colour/material_colours.h"
#include "display/overlay/marker.h"
#include "display/overlay/overlay.h"
#include "display/surface/render.h"
#include "tools/panel/board.h"
#include "tools/panel/text_out.h"

using namespace dexmill;

namespace {

constexpr int64_t um(int64_t v) { return v * kNmPerUm; }
constexpr int64_t mm(int64_t v) { return v * kNmPerMm; }

// ---- the workpiece: a 48 x 32 x 20 mm block at 0.25 mm ---------------------
constexpr int32_t kNx = 192, kNy = 128;
constexpr int64_t kPitchNm = um(250);
constexpr int64_t kStockTopNm = mm(20);
constexpr int64_t kRangeNm = mm(25);  // material range the m-bit heights cover
// The simulation's block: the grid, the interpreter's memory, the
// observers' shadows (core/sim/simulation.h sizes it; checked at start).
constexpr size_t kSimBytes = 640 * 1024;
alignas(8) unsigned char g_sim_mem[kSimBytes];

// ---- the tool table (T1..T4) ------------------------------------------------
struct PanelTool {
  ToolKind kind;
  int64_t diameter_nm, corner_nm;
  int32_t tip_mdeg;
};
constexpr PanelTool kTools[] = {
    {ToolKind::kFlat, mm(6), 0, 0},          // T1 roughing end mill
    {ToolKind::kBall, mm(4), 0, 0},          // T2 finishing ball
    {ToolKind::kVBit, mm(6), 0, 90000},      // T3 engraving V-bit
    {ToolKind::kBullNose, mm(8), mm(1), 0},  // T4 contouring bull nose
};
constexpr int kToolCount = static_cast<int>(sizeof kTools / sizeof kTools[0]);
constexpr int64_t kToolLengthNm = mm(40);

// ---- the demo program: G-code text in flash ---------------------------------
// T1 ramps into a pocket and zig-zags it, cuts an inner pocket with arcs,
// drills four through holes with a canned cycle; T4 contours the pocket;
// T2 finishes with ramps and a helix; T3 engraves the top face.
const char kProgram[] =
    "%\n"
    "(dexmill panel demo: 48 x 32 x 20 mm block)\n"
    "G21 G90 G17 G94\n"
    "T1 M6\n"
    "S12000 M3\n"
    "G0 X10 Y8 Z25\n"
    "G1 Z21 F400\n"
    "G1 X20 Z16 F900\n"
    "G1 X38\n"
    "Y12\n"
    "X10\n"
    "Y16\n"
    "X38\n"
    "Y20\n"
    "X10\n"
    "Y24\n"
    "X38\n"
    "G0 Z25\n"
    "G0 X18 Y13\n"
    "G1 Z13 F400\n"
    "G1 X30 F900\n"
    "G3 X30 Y19 R3\n"
    "G1 X18\n"
    "G3 X18 Y13 R3\n"
    "G0 Z25\n"
    "G98 G81 X4 Y4 Z-1 R22 F300\n"
    "X44\n"
    "Y28\n"
    "X4\n"
    "G80\n"
    "T4 M6\n"
    "G0 X7 Y5 Z25\n"
    "G1 Z15 F400\n"
    "G1 X41 F900\n"
    "Y27\n"
    "X7\n"
    "Y5\n"
    "G0 Z25\n"
    "T2 M6\n"
    "G0 X12 Y14\n"
    "G1 Z16 F400\n"
    "G1 X36 Y18 Z13.5 F900\n"
    "G1 X12 Y22 Z14.5\n"
    "G0 Z25\n"
    "G0 X34 Y16\n"
    "G1 Z15 F400\n"
    "G2 X34 Y16 I-2 J0 Z13 P2\n"
    "G0 Z25\n"
    "T3 M6\n"
    "G0 X9 Y30\n"
    "G1 Z19.2 F300\n"
    "G1 X15\n"
    "X17 Y28.6\n"
    "X19 Y31\n"
    "X21 Y28.6\n"
    "X23 Y31\n"
    "X39 Y30.5 Z19.4\n"
    "X46 Y33.5 Z19.2\n"
    "G0 Z25\n"
    "M30\n"
    "%\n";

class PanelLibrary final : public ToolLibrary {
 public:
  bool tool(int32_t number, Tool* out) const override {
    if (number < 1 || number > kToolCount) return false;
    const PanelTool& p = kTools[number - 1];
    Tool t;
    t.kind = p.kind;
    t.diameter_nm = p.diameter_nm;
    t.corner_radius_nm = p.corner_nm;
    t.tip_angle_mdeg = p.tip_mdeg;
    t.flute_length_nm = mm(20);
    t.length_nm = kToolLengthNm;
    *out = t;
    return true;
  }
};

// The four tools, for the Mill's memory.
Tool g_tools[kToolCount];

// The block as the panel holds it: 48 x 32 mm at 0.25 mm, its top at 20 mm
// over every column; the program in flash, the panel's tools.
SimJob panel_job(const PanelLibrary& lib) {
  SimJob j;
  const int bits = static_cast<int>(sizeof(height_t) * 8);
  j.plan.geo = GridGeometry{kNx, kNy, kPitchNm / 2, kPitchNm / 2, kPitchNm, 0, lsb_for_range(kRangeNm, bits)};
  j.plan.top_lsb = div_round(kStockTopNm, j.plan.geo.lsb_nm);
  j.plan.stock_nx = kNx - 1;
  j.plan.stock_ny = kNy - 1;
  for (int k = 0; k < kToolCount; ++k) (void)lib.tool(k + 1, &g_tools[k]);
  j.tool = g_tools[0];
  j.library = &lib;
  j.tools = g_tools;
  j.ntools = kToolCount;
  j.input_buffer_bytes = 1024;
  j.time_estimate = false;  // what the cut costs is what this panel measures
  return j;
}

// Runs a program (the demo's by default) through a simulation of `job` in
// the static block (null: the block is too small).
Simulation* play_program(const SimJob& job, const char* text = kProgram) {
  Simulation* sim = sim_create(job, g_sim_mem, sizeof g_sim_mem);
  if (!sim) return nullptr;
  sim->feed(text, strlen(text));
  sim->close_input();
  while (sim->step(SimBudget()) == SimState::kReady) {
  }
  return sim;
}

uint32_t program_lines() {
  uint32_t lines = 0;
  for (const char* p = kProgram; *p; ++p) lines += *p == '\n';
  return lines;
}

// ==== FRAME: render + frame hash ==============================================
// The panel is a 480x272 RGB565 TFT (a common 4.3" controller display): a
// static framebuffer and the renderer's scratch (16-bit z-buffer, shade
// cache, block table, tiles) sized at compile time, an iso camera fitted to
// the block, the last tool drawn at its last position.
constexpr int32_t kFrameW = 480, kFrameH = 272;
uint16_t g_frame[kFrameW * kFrameH];
constexpr size_t kScratchWords = (kFrameW * kFrameH * 2 + kNx * kNy * 2 + 64 * 1024) / 8;
uint64_t g_scratch[kScratchWords];
Renderer<height_t> g_renderer;

bool render_frame(golden::Out& out, DexelGrid<height_t>* g, const ToolProfile& tool, PointNm tip) {
  FrameView fb{g_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  RenderOptions opt;
  opt.zformat = ZFormat::kZ16;
  const size_t need = renderer_scratch_bytes(*g, kFrameW, kFrameH, opt.zformat);
  if (need > sizeof g_scratch || !ok(renderer_init(&g_renderer, *g, fb, opt, g_scratch, sizeof g_scratch))) {
    out.str("panel FAIL renderer set-up").kv("scratch_needed", static_cast<int64_t>(need)).end();
    return false;
  }
  renderer_set_tool(&g_renderer, &tool);
  renderer_set_camera(&g_renderer, renderer_fit(g_renderer, ViewPreset::kIso));
  const RenderResult res = render_full(&g_renderer, g, CutterPose{true, tip});
  out.str("panel frame").kv("w", kFrameW).kv("h", kFrameH).str(" rgb565").kx("hash", frame_hash(fb));
  out.kv("rects", res.nrects).kv("scratch_bytes", static_cast<int64_t>(need)).end();
  return true;
}

// ==== ASSESS: the cut against the part it is meant to make (paper §2.5) =====
// The design: the block's top at Z20 with a 42 x 30 mm pocket at Z15 (what
// T4's contour leaves), as ten triangles (a panel gets them from its CAM
// system). T1's floor is left 1 mm high (green), the inner pocket, the
// finishing ramps and the drilled holes go below it (red).
int32_t g_design_tops[kNx * kNy];
uint8_t g_bands[kNx * kNy];
uint32_t g_band_luts[kErrorBands * kShadeLevels];
DesignGrid g_design;
ErrorColours<height_t> g_error_colours;

bool assess_and_draw(golden::Out& out, DexelGrid<height_t>* g, PointNm tip) {
  if (!ok(design_init(&g_design, GridGeometry{g->nx, g->ny, g->x0_nm, g->y0_nm, g->pitch_nm, g->z0_nm, g->lsb_nm},
                      g_design_tops, static_cast<size_t>(kNx) * kNy))) {
    out.str("panel FAIL design set-up").end();
    return false;
  }
  const int64_t x0 = 0, y0 = 0, x1 = mm(48), y1 = mm(32), px0 = mm(3), py0 = mm(1), px1 = mm(45), py1 = mm(31);
  const int64_t top = mm(20), floor = mm(15);
  // Rectangles (x0, y0, x1, y1, z) as two triangles each: the pocket's
  // floor, then the top around it.
  const int64_t rects[5][5] = {{px0, py0, px1, py1, floor}, {x0, y0, x1, py0, top}, {x0, py1, x1, y1, top},
                               {x0, py0, px0, py1, top},    {px1, py0, x1, py1, top}};
  for (const auto& q : rects) {
    const PointNm a{q[0], q[1], q[4]}, b{q[2], q[1], q[4]}, c{q[2], q[3], q[4]}, d{q[0], q[3], q[4]};
    (void)design_add_triangle(&g_design, TriangleNm{{a, b, c}});
    (void)design_add_triangle(&g_design, TriangleNm{{a, c, d}});
  }
  AssessOptions opt;
  opt.region = GridRect{1, 1, g->nx - 1, g->ny - 1};
  opt.tol_nm = um(100);
  AssessResult res;
  if (!ok(assess(*g, g_design, opt, &res))) return false;
  out.str("panel assess").kx("E_lsb2_lo", res.e_lsb2.lo).kx("E_lsb2_hi", res.e_lsb2.hi);
  out.kv("design_columns", static_cast<int64_t>(res.design_columns)).kv("within", static_cast<int64_t>(res.within_tol_columns));
  out.kv("gouge", static_cast<int64_t>(res.gouge_columns)).kv("max_gouge_lsb", res.max_gouge_lsb);
  out.kv("left", static_cast<int64_t>(res.leftover_columns)).kv("max_left_lsb", res.max_leftover_lsb).end();
  // The error view (figure 10) in the same frame, from the same renderer.
  error_colours_init(&g_error_colours, *g, g_design, opt, g_bands, g_band_luts);
  renderer_set_colours(&g_renderer, &g_error_colours.colours);
  const RenderResult r = render_full(&g_renderer, g, CutterPose{true, tip});
  FrameView fb{g_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  out.str("panel error frame").kx("hash", frame_hash(fb)).kv("rects", r.nrects).end();
  return true;
}

// ==== OVERLAY: the design translucent over the cut (paper figure 9) ==========
// The design as a grid of its own, drawn by a second renderer through the
// same view, blended over the plain frame of the cut where it is nearer:
// what went below the design shows in the design's colour.
height_t g_design_top[kNx * kNy];
height_t g_design_bottom[kNx * kNy];
uint16_t g_design_frame[kFrameW * kFrameH];
uint64_t g_design_scratch[kScratchWords];
Renderer<height_t> g_design_renderer;
uint8_t g_design_cls[kNx * kNy];
uint32_t g_design_lut[kShadeLevels];

bool overlay_frame(golden::Out& out, DexelGrid<height_t>* g, PointNm tip) {
  DexelGrid<height_t> dg;
  const GridGeometry geo{g->nx, g->ny, g->x0_nm, g->y0_nm, g->pitch_nm, g->z0_nm, g->lsb_nm};
  FrameView dfb{g_design_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  RenderOptions opt;
  opt.zformat = ZFormat::kZ16;
  if (!ok(grid_init(&dg, geo, g_design_top, g_design_bottom, static_cast<size_t>(kNx) * kNy)) ||
      !ok(renderer_init(&g_design_renderer, dg, dfb, opt, g_design_scratch, sizeof g_design_scratch))) {
    out.str("panel FAIL overlay set-up").end();
    return false;
  }
  design_to_grid(g_design, GridRect{1, 1, g->nx - 1, g->ny - 1}, &dg);
  SurfaceColours blue;
  blue.cls = g_design_cls;  // all class 0 (static zeros)
  blue.luts = g_design_lut;
  blue.nclasses = 1;
  blue.colour[0] = Rgb{80, 140, 230};
  renderer_set_colours(&g_design_renderer, &blue);
  renderer_share_frame(&g_design_renderer, g_renderer);
  renderer_set_camera(&g_design_renderer, g_renderer.cam);
  render_full(&g_design_renderer, &dg, CutterPose{});
  // The cut's plain frame again (the error view replaced it), then the blend.
  renderer_set_colours(&g_renderer, nullptr);
  render_full(&g_renderer, g, CutterPose{true, tip});
  FrameView fb{g_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  const DepthView cz{g_renderer.target.z, g_renderer.target.z_stride, g_renderer.target.zformat};
  const DepthView dz{g_design_renderer.target.z, g_design_renderer.target.z_stride, g_design_renderer.target.zformat};
  overlay_blend(fb, cz, dfb, dz, ScreenRect{0, 0, kFrameW, kFrameH});
  out.str("panel overlay frame").kx("design", frame_hash(dfb)).kx("design_over_cut", frame_hash(fb)).end();
  return true;
}

// ==== SAFETY: the program again, with the checks a panel runs before the
// machine does (core/safety/safety.h): rapids into material, the spindle, the
// tool below the block, the shank above the flutes, a clamp beside the block.
// The grid comes out as the plain cut's; each finding is printed with its
// line and marked in red on the frame.
bool safety_pass(golden::Out& out, const PanelLibrary& lib, uint64_t plain_hash, Simulation** done) {
  SimJob job = panel_job(lib);
  SimChecks& c = job.checks;
  c.rapid = c.spindle = c.below = c.shank = c.holder = c.plunge = true;
  Simulation* sim = play_program(job);
  if (!sim) {
    out.str("panel FAIL safety set-up").end();
    return false;
  }
  *done = sim;
  DexelGrid<height_t>* g = &sim->grid();
  const SafetyWatch& g_watch = *sim->safety();
  const int errors = static_cast<int>(sim->errors());
  const PointNm tip = sim->mill().position();
  out.str("panel safety").kv("findings", static_cast<int64_t>(g_watch.total)).kv("errors", errors);
  out.kv("same_grid", grid_hash(*g) == plain_hash ? 1 : 0).end();
  FrameView fb{g_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  renderer_set_colours(&g_renderer, nullptr);
  render_full(&g_renderer, g, CutterPose{true, tip});
  for (size_t k = 0; k < g_watch.nevents; ++k) {
    const SafetyEvent& e = g_watch.events[k];
    out.str("panel finding ").str(safety_kind_name(e.kind)).kv("line", e.line).kv("depth_um", e.depth_nm / kNmPerUm).end();
    (void)marker_draw(fb, g_renderer.view, e.at, 6, pixel_pack(fb.format, Rgb{255, 32, 24}));
  }
  out.str("panel safety frame").kx("hash", frame_hash(fb)).end();
  return errors == 0 && grid_hash(*g) == plain_hash;
}

// ==== MATERIAL: the frame in marble (paper §2.7.1) ===========================
// The same cut drawn in the marble preset's colours (a texture per vertex,
// walls split), its hash equal to the host's; and the cost against plain
// frames on the board: full frames (the texture of every top worked out on
// the first, kept after), and one cut's incremental update each way (the
// grid put back between the two).
StockComposition g_marble;
MaterialColours<height_t> g_marble_colours;
uint8_t g_marble_cls[kNx * kNy];
uint32_t g_marble_luts[kMaxColourClasses * kShadeLevels];
uint32_t g_marble_texture[kNx * kNy * (sizeof(uint32_t) + sizeof(height_t)) / 4 + 1];
height_t g_saved_top[kNx * kNy], g_saved_bottom[kNx * kNy];

struct MaterialCost {
  uint64_t first = 0, full = 0, plain_full = 0, plain_update = 0, update = 0;
};

bool material_frames(golden::Out& out, DexelGrid<height_t>* g, const ToolProfile& tool, PointNm tip, MaterialCost* cost) {
  const BoxNm box{PointNm{0, 0, 0}, PointNm{kNx * kPitchNm, kNy * kPitchNm, kStockTopNm}};
  if (!material_preset("marble", box, &g_marble) || material_texture_bytes(*g) > sizeof g_marble_texture) {
    out.str("panel FAIL material set-up").end();
    return false;
  }
  material_colours_init(&g_marble_colours, *g, g_marble, g_marble_cls, g_marble_luts);
  material_colours_texture(&g_marble_colours, g_marble_texture, static_cast<uint32_t>(grid_height_of_z(*g, kStockTopNm)));
  FrameView fb{g_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  const CutterPose pose{true, tip};
  uint64_t t = golden::board_instructions();
  auto lap = [&t]() {
    const uint64_t now = golden::board_instructions();
    const uint64_t d = now - t;
    t = now;
    return d;
  };
  renderer_set_colours(&g_renderer, &g_marble_colours.colours);
  render_full(&g_renderer, g, pose);
  cost->first = lap();
  const uint64_t marble_hash = frame_hash(fb);
  render_full(&g_renderer, g, pose);
  cost->full = lap();
  renderer_set_colours(&g_renderer, nullptr);
  render_full(&g_renderer, g, pose);
  cost->plain_full = lap();
  // One finishing move, plain and then in marble from the same grid.
  SweepTool st;
  if (!ok(sweep_tool_prepare(tool, g->lsb_nm, &st))) return false;
  memcpy(g_saved_top, g->top, sizeof g_saved_top);
  memcpy(g_saved_bottom, g->bottom, sizeof g_saved_bottom);
  const PointNm a{mm(9), mm(9), mm(17)}, b{mm(39), mm(23), mm(15)};
  CutStats cs;
  sweep_line(g, st, a, b, &cs);
  const GridRect changed = g->dirty;
  (void)lap();
  render_update(&g_renderer, g, CutterPose{true, b});
  cost->plain_update = lap();
  memcpy(g->top, g_saved_top, sizeof g_saved_top);
  memcpy(g->bottom, g_saved_bottom, sizeof g_saved_bottom);
  g->dirty = changed;
  renderer_set_colours(&g_renderer, &g_marble_colours.colours);
  render_full(&g_renderer, g, pose);
  sweep_line(g, st, a, b, &cs);
  (void)lap();
  render_update(&g_renderer, g, CutterPose{true, b});
  cost->update = lap();
  out.str("panel marble frame").kx("hash", marble_hash).kx("after_cut", frame_hash(fb)).end();
  return true;
}

// ==== API: the same program through the embedding API (display/api/dexmill.h)
// as a controller would drive it: the text read in 256-byte blocks (an SD
// card's), steps of 8 moves, the view redrawn after each into the panel's
// framebuffer (only what changed); the removed volume, the moves and the
// last frame's hash, equal on the board and the host.
// The finished part as a 240x136 thumbnail (a program list's preview),
// drawn once aliased and once anti-aliased (DM_VIEW_ANTIALIAS: the scene at
// 480x272 averaged 2x2) in the memory the preview's view had: what the
// switch costs on the board, in bytes and instructions, at the same size.
constexpr int32_t kThumbW = 240, kThumbH = 136;
uint16_t g_thumb[kThumbW * kThumbH];
// The larger of the preview's view and the anti-aliased thumbnail's: the
// scene at twice the size (2 bytes a pixel and a 4-byte depth), the grid's
// shading and the renderer's tables.
constexpr size_t kViewMemBytes = kThumbW * kThumbH * 4 * 6 + kNx * kNy * 4 + 128 * 1024;
static_assert(kViewMemBytes >= kFrameW * kFrameH * 6 + kNx * kNy * 4, "the preview's view fits too");
alignas(8) unsigned char g_view_mem[kViewMemBytes];

struct ThumbCost {
  uint64_t aliased = 0, antialiased = 0;  // instructions of a whole frame each
};

// One thumbnail of the finished simulation with view flags `flags`.
bool thumbnail(golden::Out& out, dm_sim* sim, uint32_t flags, const char* name, uint64_t* cost) {
  dm_frame frame{g_thumb, kThumbW, kThumbH, kThumbW * 2, DM_RGB565};
  size_t need = 0;
  dm_view* view = nullptr;
  if (dm_view_bytes_flags(sim, kThumbW, kThumbH, DM_RGB565, flags, &need) != DM_OK || need > sizeof g_view_mem ||
      dm_view_create_flags(sim, &frame, nullptr, flags, g_view_mem, sizeof g_view_mem, &view) != DM_OK) {
    out.str("panel FAIL thumbnail view").str(name).kv("bytes", static_cast<int64_t>(need)).end();
    return false;
  }
  const uint64_t t0 = golden::board_instructions();
  dm_rect all;
  int32_t n = 0;
  (void)dm_render(view, &all, 1, &n);
  *cost = golden::board_instructions() - t0;
  const FrameView fb{g_thumb, kThumbW, kThumbH, kThumbW * 2, PixelFormat::kRgb565};
  out.str("panel thumbnail ").str(name).kv("w", kThumbW).kv("h", kThumbH).kx("hash", frame_hash(fb)).end();
  // The handle holds pointers: its size differs between the host and the board.
  out.str("info thumbnail ").str(name).kv("view_bytes", static_cast<int64_t>(need)).end();
  dm_view_destroy(view);
  return true;
}

bool api_preview(golden::Out& out, uint64_t* steps_out, ThumbCost* thumbs) {
  dm_job job;
  if (dm_job_init(&job, DEXMILL_API_VERSION) != DM_OK) return false;
  job.stock = dm_box{{0, 0, 0}, {mm(48), mm(32), kStockTopNm}};
  job.pitch_nm = kPitchNm;
  const char* specs[kToolCount] = {"flat:6,len=20,stick=40", "ball:4,len=20,stick=40", "vbit:6:90,len=20,stick=40",
                                   "bull:8:1,len=20,stick=40"};
  job.tool.spec = specs[0];
  for (int k = 0; k < kToolCount; ++k) {
    job.tools[k].spec = specs[k];
    job.tools[k].number = k + 1;
  }
  job.ntools = kToolCount;
  job.input_buffer_bytes = DM_INPUT_MIN_BYTES;
  size_t need = 0;
  dm_sim* sim = nullptr;
  if (dm_required_bytes(&job, &need) != DM_OK || need > sizeof g_sim_mem ||
      dm_create(&job, g_sim_mem, sizeof g_sim_mem, &sim) != DM_OK) {
    out.str("panel FAIL api set-up").kv("bytes", static_cast<int64_t>(need)).end();
    return false;
  }
  dm_frame frame{g_frame, kFrameW, kFrameH, kFrameW * 2, DM_RGB565};
  dm_camera cam{DM_VIEW_ISO, 0, 0, 0};
  size_t view_need = 0;
  dm_view* view = nullptr;
  if (dm_view_bytes(sim, kFrameW, kFrameH, &view_need) != DM_OK || view_need > sizeof g_view_mem ||
      dm_view_create(sim, &frame, &cam, g_view_mem, sizeof g_view_mem, &view) != DM_OK) {
    out.str("panel FAIL api view").kv("bytes", static_cast<int64_t>(view_need)).end();
    dm_destroy(sim);
    return false;
  }
  const size_t len = strlen(kProgram);
  size_t at = 0;
  dm_budget budget{8, 0, 0, nullptr, nullptr};
  int32_t state = DM_READY;
  uint64_t steps = 0;
  while (state == DM_READY || state == DM_NEED_INPUT) {
    if (state == DM_NEED_INPUT) {
      const size_t n = len - at < 256 ? len - at : 256;
      if (n) (void)dm_feed(sim, kProgram + at, n);
      else (void)dm_end_input(sim);
      at += n;
    }
    if (dm_step(sim, &budget, &state) != DM_OK) break;
    dm_rect rects[8];
    int32_t nrects = 0;
    (void)dm_render(view, rects, 8, &nrects);
    ++steps;
  }
  dm_progress p;
  (void)dm_get_progress(sim, &p);
  const FrameView fb{g_frame, kFrameW, kFrameH, kFrameW * 2, PixelFormat::kRgb565};
  out.str("panel api").kv("state", state).kv("moves", static_cast<int64_t>(p.moves)).kv("errors", p.errors);
  out.kv("removed_um3", static_cast<int64_t>(p.removed_um3)).kx("frame", frame_hash(fb)).end();
  dm_view_destroy(view);
  const bool thumbs_ok = thumbnail(out, sim, 0, "aliased", &thumbs->aliased) &&
                         thumbnail(out, sim, DM_VIEW_ANTIALIAS, "antialiased", &thumbs->antialiased);
  dm_destroy(sim);
  *steps_out = steps;
  return state == DM_DONE && p.errors == 0 && thumbs_ok;
}

// ==== TWO SIDES: a stock kept between two programs, flipped ===================
// What a panel at the machine does for a second side: the first side's
// stock saved (to a buffer standing for its flash or SD card, through the
// stock file's writer), read back in 512-byte pieces into a new simulation,
// turned over about X (core/stock/stock_transform.h), and the second side
// cut on it. Host and board must agree on every bit.
const char kSide1[] =
    "G21 G90 G17 G94\nT1 M6\nS12000 M3\nG0 X12 Y10 Z25\nG1 Z17 F400\nG1 X36 F900\nY22\nX12\nY10\nG0 Z25\n"
    "G98 G81 X6 Y6 Z-1 R22 F300\nX42\nG80\nM30\n";
const char kSide2[] =
    "G21 G90 G17 G94\nT2 M6\nS12000 M3\nG0 X4 Y20 Z25\nG1 Z18 F400\nG1 X44 F900\nY28\nX4\nY20\nG0 Z25\nM30\n";
constexpr size_t kStockFileMax = kStockHeaderBytes + 4 * kNx * kNy + 4 * kNy + kStockTrailerBytes;
alignas(4) unsigned char g_stock_flash[kStockFileMax];
size_t g_stock_flash_n = 0;

bool to_flash(void*, const uint8_t* p, size_t n) {
  if (g_stock_flash_n + n > sizeof g_stock_flash) return false;
  memcpy(g_stock_flash + g_stock_flash_n, p, n);
  g_stock_flash_n += n;
  return true;
}

bool two_sides(golden::Out& out, const PanelLibrary& lib, uint64_t* cost_save, uint64_t* cost_load) {
  SimJob side1 = panel_job(lib);
  Simulation* sim = play_program(side1, kSide1);
  if (!sim || sim->errors() != 0) return false;
  StockMeta m;
  if (sim_stock_meta(*sim, "side1", &m) != StockStateError::kOk) return false;
  const uint64_t t0 = golden::board_instructions();
  g_stock_flash_n = 0;
  const StockError we = stock_write(m, sim->stock_columns(m.layers), to_flash, nullptr);
  *cost_save = golden::board_instructions() - t0;
  out.str("panel side1").kx("hash", grid_hash(sim->grid())).kv("removed_lsb", static_cast<int64_t>(sim->removed_lsb()));
  out.kv("stock_bytes", static_cast<int64_t>(g_stock_flash_n)).kv("write", static_cast<int64_t>(we)).end();
  sim_destroy(sim);
  if (we != StockError::kOk) return false;
  // The second side: the saved stock read from "flash", turned over about X.
  static StockReader reader;  // 4.6 KB: static, not on the board's stack
  reader = StockReader();
  size_t at = 0, used = 0;
  StockError re = reader.feed(g_stock_flash, g_stock_flash_n, &used);  // stops at the header's end
  at += used;
  if (re != StockError::kOk || !reader.header_done()) return false;
  StockMeta turned = reader.meta();
  StockSetup flip;
  flip.flip_x = true;
  if (stock_setup_meta(flip, &turned) != StockSetupError::kOk) return false;
  SimJob side2 = panel_job(lib);
  side2.plan = sim_plan_of_stock(turned);
  side2.resume = &turned;
  sim = sim_create(side2, g_sim_mem, sizeof g_sim_mem);
  if (!sim) return false;
  const uint64_t t1 = golden::board_instructions();
  StockMeta as_read = reader.meta();
  if (!reader.bind(sim->stock_columns(as_read.layers))) return false;
  while (at < g_stock_flash_n && re == StockError::kOk) {  // as from an SD card, a sector at a time
    const size_t piece = g_stock_flash_n - at < 512 ? g_stock_flash_n - at : 512;
    re = reader.feed(g_stock_flash + at, piece, &used);
    at += used;
  }
  if (re == StockError::kOk) re = reader.finish();
  const StockSetupError se = stock_apply_setup(flip, &as_read, sim->stock_columns(as_read.layers), nullptr, 0);
  *cost_load = golden::board_instructions() - t1;
  out.str("panel side2 stock").kv("read", static_cast<int64_t>(re)).kv("flip", static_cast<int64_t>(se));
  out.kx("hash", grid_hash(sim->grid())).end();
  if (re != StockError::kOk || se != StockSetupError::kOk) return false;
  sim->feed(kSide2, strlen(kSide2));
  sim->close_input();
  while (sim->step(SimBudget()) == SimState::kReady) {
  }
  StockMeta chain;
  const bool ok_chain = sim_stock_meta(*sim, "side2", &chain) == StockStateError::kOk;
  out.str("panel side2").kv("errors", static_cast<int64_t>(sim->errors())).kx("hash", grid_hash(sim->grid()));
  out.kv("removed_lsb", static_cast<int64_t>(sim->removed_lsb()));
  out.kv("chain_programs", ok_chain ? chain.nprograms : -1);
  out.kv("chain_removed_lsb", ok_chain ? static_cast<int64_t>(chain.removed_lsb_dexels) : -1).end();
  const bool good = sim->errors() == 0 && ok_chain;
  sim_destroy(sim);
  return good;
}

void info_instructions(golden::Out& out, const char* what, uint64_t n, uint64_t per) {
  out.str("info instructions ").str(what).kv("n", static_cast<int64_t>(n));
  if (per) out.kv("per_dexel_update_x100", static_cast<int64_t>(n * 100u / per));
  out.end();
}

}  // namespace

int main(int, char**) {
  golden::Out out(golden::board_write);
  const uint64_t t0 = golden::board_instructions();

  const PanelLibrary lib;
  const SimJob plain = panel_job(lib);
  const size_t need = sim_required_bytes(plain);
  Simulation* sim = need && need <= sizeof g_sim_mem ? sim_create(plain, g_sim_mem, sizeof g_sim_mem) : nullptr;
  if (!sim) {
    out.str("panel FAIL set-up").kv("sim_bytes", static_cast<int64_t>(need)).end();
    return 1;
  }
  DexelGrid<height_t>& g = sim->grid();
  const int bits = static_cast<int>(sizeof(height_t) * 8);
  out.str("panel grid").kv("nx", kNx).kv("ny", kNy).kv("m", bits).kv("pitch_nm", g.pitch_nm).kv("lsb_nm", g.lsb_nm);
  out.kv("grid_bytes", static_cast<int64_t>(2 * sizeof(height_t) * kNx * kNy)).end();
  out.str("info sim_bytes").kv("n", static_cast<int64_t>(need)).end();
  sim->start();  // the untouched stock taken (its material, for the volume removed)
  const uint64_t t1 = golden::board_instructions();

  sim->feed(kProgram, strlen(kProgram));
  sim->close_input();
  while (sim->step(SimBudget()) == SimState::kReady) {
  }
  const Mill<height_t>& mill = sim->mill();
  const int errors = static_cast<int>(sim->errors());
  const uint64_t t2 = golden::board_instructions();

  const uint64_t hash = grid_hash(g);
  out.str("panel program").kv("lines", program_lines()).kv("errors", errors).kv("status", static_cast<int64_t>(mill.status())).end();
  out.str("panel cut").kv("pieces", static_cast<int64_t>(mill.stats().instances));
  out.kv("dexel_updates", static_cast<int64_t>(mill.stats().dexel_updates)).end();
  out.str("panel grid").kx("hash", hash).end();
  const uint64_t t3 = golden::board_instructions();

  const ToolProfile prof = tool_profile(mill.tool());
  const PointNm end = mill.position();
  const uint64_t cut_updates = mill.stats().dexel_updates;
  const bool drawn = render_frame(out, &g, prof, end);
  const uint64_t t4 = golden::board_instructions();
  const bool assessed = drawn && assess_and_draw(out, &g, end);
  const uint64_t t5 = golden::board_instructions();
  const bool overlaid = assessed && overlay_frame(out, &g, end);
  const uint64_t t6 = golden::board_instructions();
  sim_destroy(sim);  // the safety pass cuts the program again in the same block
  Simulation* checked_sim = nullptr;
  const bool checked = overlaid && safety_pass(out, lib, hash, &checked_sim);
  const uint64_t t7 = golden::board_instructions();
  MaterialCost mcost;
  const bool marbled = checked && material_frames(out, &checked_sim->grid(), prof, checked_sim->mill().position(), &mcost);
  const uint64_t t8 = golden::board_instructions();
  sim_destroy(checked_sim);
  checked_sim = nullptr;
  uint64_t api_steps = 0;
  ThumbCost thumbs;
  const bool api = marbled && api_preview(out, &api_steps, &thumbs);
  const uint64_t t9 = golden::board_instructions();
  uint64_t save_cost = 0, load_cost = 0;
  const bool sides = api && two_sides(out, lib, &save_cost, &load_cost);

  if (t3 != 0) {
    out.str("info clock: ").str(golden::board_clock_name()).end();
    info_instructions(out, "setup(grid)", t1 - t0, 0);
    info_instructions(out, "cut", t2 - t1, cut_updates);
    info_instructions(out, "render(480x272)", t4 - t3, 0);
    info_instructions(out, "assess+error_frame(480x272)", t5 - t4, 0);
    info_instructions(out, "overlay(2 frames+blend)", t6 - t5, 0);
    info_instructions(out, "cut+safety checks+frame", t7 - t6, 0);
    info_instructions(out, "marble first frame(textures of all tops)", mcost.first, 0);
    info_instructions(out, "marble full frame", mcost.full, 0);
    info_instructions(out, "plain full frame", mcost.plain_full, 0);
    info_instructions(out, "marble update(one cut)", mcost.update, 0);
    info_instructions(out, "plain update(one cut)", mcost.plain_update, 0);
    info_instructions(out, "api: cut in 8-move steps, a redraw after each, two thumbnails", t9 - t8, 0);
    info_instructions(out, "thumbnail(240x136) aliased", thumbs.aliased, 0);
    info_instructions(out, "thumbnail(240x136) anti-aliased", thumbs.antialiased, 0);
    out.str("info api steps").kv("n", static_cast<int64_t>(api_steps)).end();
    info_instructions(out, "stock saved to flash (192x128, 16-bit)", save_cost, 0);
    info_instructions(out, "stock read back in 512-byte pieces and flipped", load_cost, 0);
  }
  return (errors == 0 && drawn && assessed && overlaid && checked && marbled && api && sides) ? 0 : 1;
}
