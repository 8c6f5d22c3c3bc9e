// Default stock and grid planning; see run_stock.h.
#include "tools/run/run_stock.h"

#include <cstdio>

#include "core/config.h"
#include "core/sim/stock_state.h"
#include "platform/format/stl_read.h"
#include "platform/os/machine_memory.h"
#include "platform/os/memory.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {

namespace {

// The machine's memory this share of is a run's default budget.
constexpr uint64_t kMachineMemoryShareDivisor = 2;
constexpr uint64_t kUnknownMachineBudgetBytes = uint64_t{4} << 30;

// "... need 977 MiB (1024384036 bytes), more than --max-memory's 512 MiB
// (536870912 bytes); give ..." after what: the words every refusal ends in.
std::string over_budget_text(const char* what, uint64_t need_bytes, uint64_t max_bytes) {
  char b[400];
  std::snprintf(b, sizeof b, "%s need %s (%llu bytes), more than --max-memory's %s (%llu bytes); give a coarser "
                "--pitch or --grid, or a larger --max-memory", what, size_text(need_bytes).c_str(),
                static_cast<unsigned long long>(need_bytes), size_text(max_bytes).c_str(),
                static_cast<unsigned long long>(max_bytes));
  return b;
}

std::string grid_over_budget_text(const PlanRefusal& r) {
  char what[120];
  std::snprintf(what, sizeof what, "the grid would be %lldx%lld dexels, whose heights", static_cast<long long>(r.nx),
                static_cast<long long>(r.ny));
  return over_budget_text(what, r.need_bytes, r.max_bytes);
}

}  // namespace

GridBudget run_grid_budget(uint64_t max_memory_bytes) {
  GridBudget b;
  const uint64_t machine_bytes = machine_memory_bytes();
  b.max_bytes = max_memory_bytes     ? max_memory_bytes
                : machine_bytes == 0 ? kUnknownMachineBudgetBytes
                                     : machine_bytes / kMachineMemoryShareDivisor;
  return b;
}

bool plan_within_budget(const GridPlan& plan, const GridBudget& budget, std::string* err) {
  PlanRefusal r;
  if (plan_check_budget(plan.geo.nx, plan.geo.ny, budget, &r) == PlanError::kOk) return true;
  *err = grid_over_budget_text(r);
  return false;
}

bool engine_within_budget(uint64_t engine_bytes, const GridPlan& plan, const GridBudget& budget, std::string* err) {
  if (engine_bytes <= budget.max_bytes) return true;
  char what[160];
  std::snprintf(what, sizeof what, "the %dx%d grid and the engine that cuts it (with the planes this run keeps per dexel)",
                static_cast<int>(plan.geo.nx), static_cast<int>(plan.geo.ny));
  *err = over_budget_text(what, engine_bytes, budget.max_bytes);
  return false;
}

bool plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, const GridBudget& budget,
               GridPlan* out, std::string* err) {
  PlanRefusal r;
  switch (dexmill::plan_grid(stock, grid_nx, grid_ny, pitch_nm, out, budget, &r)) {
    case PlanError::kOk: return true;
    case PlanError::kGridTooSmall: *err = "--grid needs at least 4x4 dexels"; return false;
    case PlanError::kTooManyDexels: {
      char b[200];
      std::snprintf(b, sizeof b, "the grid would be %lldx%lld dexels, more than the 65535 a side a grid holds; "
                    "give a coarser --pitch or --grid", static_cast<long long>(r.nx), static_cast<long long>(r.ny));
      *err = b;
      return false;
    }
    case PlanError::kOverBudget: *err = grid_over_budget_text(r); return false;
    case PlanError::kBadGeometry: break;
    case PlanError::kBadStock: {
      char b[200];
      std::snprintf(b, sizeof b, "the stock must lie within 1 km of the origin, with X0<X1, Y0<Y1, Z0<Z1, and be at "
                    "most %lld m tall (its heights' 2^%d - 1 steps of at most 1 m)",
                    static_cast<long long>(height_max<height_t>()), DEXMILL_HEIGHT_BITS);
      *err = b;
      return false;
    }
  }
  *err = "the stock and grid give a geometry the dexel grid cannot hold (pitch 1 nm to 1 m, at most 65535 dexels a "
         "side, within 1 km of the origin)";
  return false;
}

int read_stock_stl(const std::string& path, std::vector<TriangleNm>* tris, StockBox* box) {
  std::string err;
  StlReadInfo info;
  const StlRead r = stl_read(path, PointNm{0, 0, 0},
                             [tris](const PointNm* v, std::string*) {
                               tris->push_back(TriangleNm{{v[0], v[1], v[2]}});
                               return true;
                             },
                             &info, &err);
  if (r != StlRead::kOk) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return r == StlRead::kIoError ? kExitIo : kExitInput;
  }
  BoxAccum b;
  for (const TriangleNm& t : *tris)
    for (const PointNm& p : t.v) b.add(p);
  if (b.lo.x_nm >= b.hi.x_nm || b.lo.y_nm >= b.hi.y_nm || b.lo.z_nm >= b.hi.z_nm) {
    std::fprintf(stderr, "%s: error: the blank is flat (its box has no width, depth or height)\n", path.c_str());
    return kExitInput;
  }
  *box = StockBox{b.lo, b.hi};
  return kExitOk;
}

template <class H>
int carve_stock(DexelGrid<H>* g, const GridPlan& plan, const std::vector<TriangleNm>& tris) {
  const size_t cells = static_cast<size_t>(g->nx) * static_cast<size_t>(g->ny);
  std::vector<int32_t> tops(cells);
  DesignGrid d;
  if (!ok(design_init(&d, plan.geo, tops.data(), cells)))
    return fail(kExitUsage, "a blank wider than %.2f m cannot be read from STL", static_cast<double>(kDesignRangeNm) * 1e-9);
  for (const TriangleNm& t : tris) (void)design_add_triangle(&d, t);  // within the box: in range
  dexmill::carve_stock(g, plan, d);
  return kExitOk;
}

template int carve_stock<uint8_t>(DexelGrid<uint8_t>*, const GridPlan&, const std::vector<TriangleNm>&);
template int carve_stock<uint16_t>(DexelGrid<uint16_t>*, const GridPlan&, const std::vector<TriangleNm>&);
template int carve_stock<uint32_t>(DexelGrid<uint32_t>*, const GridPlan&, const std::vector<TriangleNm>&);

int stock_heights_fit(const StockMeta& m, const std::string& path) {
  if (sim_stock_fits<height_t>(m) == StockStateError::kOk) return kExitOk;
  std::fprintf(stderr, "%s:1:17: error: a stock of %d-bit heights; this dexmill is built for %d-bit ones\n", path.c_str(),
               m.height_bits, DEXMILL_HEIGHT_BITS);
  return kExitInput;
}

}  // namespace cli
}  // namespace dexmill
