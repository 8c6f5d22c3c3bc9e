// Golden section "safety": a program with one offence of each kind the
// safety checks know (core/safety/safety.h) cut by the simulation
// (core/sim/simulation.h) into an m = 16 grid beside a fixture, each
// finding printed with its line, place, depth and volume: the checks give
// the same findings on every target.
#include <stdint.h>
#include <string.h>

#include "core/safety/safety.h"
#include "core/grid/grid.h"
#include "core/sim/simulation.h"
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

}  // namespace

void golden_safety(Out& out) {
  Arena& a = arena();
  a.reset();
  const int64_t mm = kNmPerMm;
  const char spec[] = "flat:4,len=5,stick=10,holder=14x6,14-30x8,nocentre";
  SimJob job;
  if (tool_spec_parse(spec, sizeof spec - 1, &job.tool) != ToolSpecError::kOk) {
    fail(out, "safety: tool");
    return;
  }
  // 40 x 24 mm at 0.5 mm, the block's top at Z0 over every column.
  const int32_t nx = 81, ny = 49;
  job.plan.geo = GridGeometry{nx, ny, 0, 0, 500000, -12 * mm, lsb_for_range(20 * mm, 16)};
  job.plan.top_lsb = div_round(12 * mm, job.plan.geo.lsb_nm);
  job.plan.stock_nx = nx - 1;
  job.plan.stock_ny = ny - 1;
  const BoxNm clamp{PointNm{30 * mm, 14 * mm, -12 * mm}, PointNm{40 * mm, 24 * mm, 4 * mm}};
  SimChecks& c = job.checks;
  c.rapid = c.spindle = c.below = c.shank = c.holder = c.plunge = true;
  c.fixtures = &clamp;
  c.nfixtures = 1;
  job.input_buffer_bytes = 4096;
  const size_t bytes = SimulationT<uint16_t>::required_bytes(job);
  void* mem = a.take<uint64_t>(bytes / 8 + 1);
  SimulationT<uint16_t>* sim = mem ? SimulationT<uint16_t>::create(job, mem, bytes + 8) : nullptr;
  if (!sim) {
    fail(out, "safety: set-up");
    return;
  }
  sim->feed(kProgram, strlen(kProgram));
  sim->close_input();
  while (sim->step(SimBudget()) == SimState::kReady) {
  }
  const SafetyWatch& g_watch = *sim->safety();
  const uint32_t errors = sim->errors();
  out.str("safety").kv("events", static_cast<int64_t>(g_watch.nevents)).kv("total", static_cast<int64_t>(g_watch.total));
  out.kv("rapid_lsb", static_cast<int64_t>(g_watch.rapid_removed_lsb)).kv("errors", errors).kx("grid", grid_hash(sim->grid())).end();
  for (size_t k = 0; k < g_watch.nevents; ++k) {
    const SafetyEvent& e = g_watch.events[k];
    out.str(safety_kind_name(e.kind)).kv("line", e.line).kv("x", e.at.x_nm).kv("y", e.at.y_nm).kv("z", e.at.z_nm);
    out.kv("depth", e.depth_nm).kv("columns", static_cast<int64_t>(e.columns)).kv("lsb", static_cast<int64_t>(e.removed_lsb));
    out.kv("last_line", e.last_line).end();
  }
  SimulationT<uint16_t>::destroy(sim);
}

}  // namespace golden
