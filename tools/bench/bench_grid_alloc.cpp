// `dexmill bench grid-256m`: what a grid beyond the 64 M dexels the plan
// once capped costs before the first move: 0.005 mm over an 80 x 80 mm
// stock, 16003 x 16003 dexels, planned within a budget
// (core/sim/stock_plan.h), its engine's block asked of the OS (calloc:
// pages only promised) and then made (sim_create fills the stock: the
// first touch of every page of heights). About 1 GiB; the planes a saved
// or provenance-coloured run keeps beside the heights are counted, not
// allocated.
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "core/gcode/line_reader.h"
#include "core/sim/simulation.h"
#include "core/tool/spec.h"
#include "platform/os/memory.h"
#include "tools/bench/bench.h"

namespace dexmill {
namespace {

constexpr int64_t kSideNm = 80 * kNmPerMm, kDepthNm = 10 * kNmPerMm, kPitchNm = 5000;

void run_grid_alloc(const char* name) {
  SimJob j;
  GridBudget budget;
  budget.max_bytes = UINT64_MAX;  // the bench asks what it costs, not whether it may
  const StockBox box{PointNm{0, 0, -kDepthNm}, PointNm{kSideNm, kSideNm, 0}};
  const char* spec = "flat:6";
  if (plan_grid(box, 0, 0, kPitchNm, &j.plan, budget) != PlanError::kOk ||
      tool_spec_parse(spec, std::strlen(spec), &j.tool) != ToolSpecError::kOk) {
    std::fprintf(stderr, "%s: no grid\n", name);
    return;
  }
  j.input_buffer_bytes = LineReader::kStartBytes;
  const uint64_t dexels = static_cast<uint64_t>(j.plan.geo.nx) * static_cast<uint64_t>(j.plan.geo.ny);
  const size_t bytes = sim_required_bytes(j);
  SimJob kept = j;  // what --save-stock keeps per dexel (tools/run/run_setup.cpp start_engine)
  kept.provenance = kept.provenance_lines = kept.provenance_programs = true;
  const size_t kept_bytes = sim_required_bytes(kept);
  double alloc_s = 0, touch_s = 0;
  {
    ZeroedBlock mem;
    const double t0 = bench::now_s();
    const bool got = mem.allocate(bytes);
    alloc_s = bench::now_s() - t0;
    if (!got) {
      std::fprintf(stderr, "%s: cannot allocate %s\n", name, size_text(bytes).c_str());
      return;
    }
    const double t1 = bench::now_s();
    Simulation* s = sim_create(j, mem.data(), mem.size());
    touch_s = bench::now_s() - t1;
    if (!s) return;
    sim_destroy(s);
  }
  bench::result(name, "grid=%dx%d dexels=%llu bytes=%zu bytes_per_dexel=%.2f kept_bytes_per_dexel=%.2f alloc_s=%.6f "
                "first_touch_s=%.4f ns_per_dexel=%.2f seconds=%.4f",
                j.plan.geo.nx, j.plan.geo.ny, static_cast<unsigned long long>(dexels), bytes,
                static_cast<double>(bytes) / static_cast<double>(dexels),
                static_cast<double>(kept_bytes) / static_cast<double>(dexels), alloc_s, touch_s,
                touch_s * 1e9 / static_cast<double>(dexels), alloc_s + touch_s);
}

}  // namespace
}  // namespace dexmill

BENCH(grid_alloc, "grid-256m", dexmill::run_grid_alloc);
