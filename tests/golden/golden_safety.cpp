// Golden section "safety": a program with one offence of each kind the
// safety checks know (core/check/safety.h) cut by core/mill into an m = 16
// grid beside a fixture, with the interpreter's spindle state, each
// finding printed with its line, place, depth and volume: the checks give
// the same findings on every target (issue 20).
#include <stdint.h>
#include <string.h>

#include "core/check/body.h"
#include "core/check/safety.h"
#include "core/check/safety_pass.h"
#include "core/cut/mill.h"
#include "core/grid/grid.h"
#include "core/motion/interp.h"
#include "core/tool/spec.h"
#include "tests/golden/golden.h"

using namespace dexmill;

namespace golden {
namespace {

// Line 5 plunges a nocentre tool 2 mm, 6 another 5 mm under its hole; 7
// runs its shank 2 mm over the flutes, 8 and 9 its holder 1 mm into the
// stock (and the shank 6; line 9, no deeper, goes on their stretch), 11 rapids through it, 13 cuts after M5 (one
// finding, though the next record cuts its end cap), 15 goes into the
// clamp at X30, 16 below the stock, the clamp and the holder into the stock.
const char kProgram[] =
    "G21 G90 G17\n"                // 1
    "M3 S10000\n"                  // 2
    "G0 Z5\n"                      // 3
    "G0 X4 Y4\n"                   // 4
    "G1 Z-2 F100\n"                // 5 plunge
    "G1 Z-7 F300\n"                // 6 plunge deeper
    "G1 X24\n"                     // 7 shank: flutes 5
    "G1 Z-11 Y10\n"                // 8 ramp down: holder, shank
    "G1 X4\n"                      // 9 holder at 10 over the tip
    "G0 Z-1\n"                     // 10
    "G0 X20 Y18\n"                 // 11 rapid through
    "M5\n"                         // 12
    "G1 X4 Y16 F300\n"             // 13 spindle stopped
    "M3\n"                         // 14
    "G1 X34 Y18 Z2\n"              // 15 into the clamp
    "G1 X30 Y10 Z-13\n"            // 16 below the stock (bottom -12), still in the clamp
    "G0 Z5\n"                      // 17
    "M2\n";

class OneTool : public ToolLibrary {
 public:
  explicit OneTool(const Tool& t) : t_(t) {}
  bool tool(int32_t, Tool* out) const override {
    *out = t_;
    return true;
  }

 private:
  Tool t_;
};

SafetyWatch g_watch;  // 4 KB of events: static, not on a panel's stack

}  // namespace

void golden_safety(Out& out) {
  Arena& a = arena();
  a.reset();
  const int64_t mm = kNmPerMm;
  const int32_t nx = 81, ny = 49;  // 40 x 24 mm at 0.5 mm
  const size_t cells = static_cast<size_t>(nx) * ny;
  uint16_t* top = a.take<uint16_t>(cells);
  uint16_t* bottom = a.take<uint16_t>(cells);
  uint32_t* shadow = a.take<uint32_t>(cells);
  DexelGrid<uint16_t> g;
  const GridGeometry geo{nx, ny, 0, 0, 500000, -12 * mm, lsb_for_range(20 * mm, 16)};
  if (!top || !bottom || !shadow || !ok(grid_init(&g, geo, top, bottom, cells))) {
    fail(out, "safety: set-up");
    return;
  }
  grid_block_stock(&g, grid_height_of_z(g, 0));
  const char spec[] = "flat:4,len=5,stick=10,holder=14x6,14-30x8,nocentre";
  Tool tool;
  if (tool_spec_parse(spec, sizeof spec - 1, &tool) != ToolSpecError::kOk) {
    fail(out, "safety: tool");
    return;
  }
  const size_t tiles_n = safety_tile_words(g);
  uint32_t* tiles = a.take<uint32_t>(tiles_n);
  const BoxNm clamp{PointNm{30 * mm, 14 * mm, -12 * mm}, PointNm{40 * mm, 24 * mm, 4 * mm}};
  DexelGrid<uint32_t> f;
  if (!tiles || !fixture_grid_size(g, &clamp, 1, &f)) {
    fail(out, "safety: fixture grid");
    return;
  }
  const size_t fcells = static_cast<size_t>(f.nx) * f.ny;
  f.top = a.take<uint32_t>(fcells);
  f.bottom = a.take<uint32_t>(fcells);
  if (!f.top || !f.bottom || !ok(safety_watch_init(&g_watch, g, shadow, cells, tiles, tiles_n))) {
    fail(out, "safety: memory");
    return;
  }
  fixture_grid_fill(&f, &clamp, 1);
  g_watch.bottom_nm = g.z0_nm;
  g_watch.check_shank = g_watch.check_holder = g_watch.check_plunge = true;
  g_watch.fixtures = &f;
  g_watch.fixture_boxes = &clamp;
  g_watch.nfixture_boxes = 1;
  OneTool lib(tool);
  Mill<uint16_t> mill(&g, CutMode::kSweep, &lib, nullptr, 0);
  (void)mill.set_tool(tool);
  SafetyPass<uint16_t> sink(&mill, &g, &g_watch, &lib, tool);
  InterpOptions opt;
  Interp in(&sink, opt);
  sink.set_interp(&in);
  const uint32_t errors = interp_run_text(&in, kProgram, strlen(kProgram), nullptr);
  sink.finish();
  out.str("safety").kv("events", static_cast<int64_t>(g_watch.nevents)).kv("total", static_cast<int64_t>(g_watch.total));
  out.kv("rapid_lsb", static_cast<int64_t>(g_watch.rapid_removed_lsb)).kv("errors", errors).kx("grid", grid_hash(g)).end();
  for (size_t k = 0; k < g_watch.nevents; ++k) {
    const SafetyEvent& e = g_watch.events[k];
    out.str(safety_kind_name(e.kind)).kv("line", e.line).kv("x", e.at.x_nm).kv("y", e.at.y_nm).kv("z", e.at.z_nm);
    out.kv("depth", e.depth_nm).kv("columns", static_cast<int64_t>(e.columns)).kv("lsb", static_cast<int64_t>(e.removed_lsb));
    out.kv("last_line", e.last_line).end();
  }
}

}  // namespace golden
