// The stock and the dexel grid of `dexmill run`: the plan is core's
// (core/sim/stock_plan.h); here are its messages and the STL blank's file.
#ifndef DEXMILL_TOOLS_RUN_RUN_STOCK_H
#define DEXMILL_TOOLS_RUN_RUN_STOCK_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/sim/stock_plan.h"
#include "core/stock/stock_file.h"

namespace dexmill {
namespace cli {

// The budget of a run's grid from --max-memory (max_memory_bytes; 0: not
// given): by default half the machine's physical memory (half leaves the
// rest to the images, the design and the other programs), 4 GiB where the
// OS does not say. A dexel costs the plan its heights (kGridDexelBytes);
// the planes the engine keeps beside them are counted once the job says
// which (engine_within_budget).
GridBudget run_grid_budget(uint64_t max_memory_bytes);

// core's plan_grid, with its error as the message a user reads.
bool plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, const GridBudget& budget,
               GridPlan* out, std::string* err);

// A grid that comes planned (a saved stock's) against the budget: true, or
// false with the message.
bool plan_within_budget(const GridPlan& plan, const GridBudget& budget, std::string* err);

// The engine's whole block (sim_required_bytes: the grid and the planes
// its job keeps per dexel, core/sim/simulation_impl.h layout) against the
// budget: true, or false with the message.
bool engine_within_budget(uint64_t engine_bytes, const GridPlan& plan, const GridBudget& budget, std::string* err);

// --stock FILE.stl, a pre-machined blank: its triangles (machine mm, read
// once, floats end there) and their bounding box. Returns kExitOk, or the
// exit code after printing the STL reader's error.
int read_stock_stl(const std::string& path, std::vector<TriangleNm>* tris, StockBox* box);

// Carves a grid filled by fill_stock to the blank's shape (core/sim/stock_plan.h
// carve_stock, the triangles rasterized here). kExitOk, or kExitUsage when
// the stock is wider than the design grid allows.
template <class H>
int carve_stock(DexelGrid<H>* g, const GridPlan& plan, const std::vector<TriangleNm>& tris);

// A saved stock's heights against this build's (its m at byte 17): kExitOk,
// or kExitInput after saying so at the file.
int stock_heights_fit(const StockMeta& m, const std::string& path);

}  // namespace cli
}  // namespace dexmill

#endif
