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

// core's plan_grid, with its error as the message a user reads.
bool plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, GridPlan* out,
               std::string* err);

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
