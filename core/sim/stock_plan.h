// The stock and its dexel grid, planned before a run (the CLI's defaults
// and the embedding API's explicit boxes go through the same plan).
//
// Default stock (no box given), from a first pass over the program
// (core/sim/scan.h, core/canon/summary.h), for programs that put Z0 on
// the stock top as CAM programs do:
//   top    Z = 0 when any feed reaches below 0; otherwise (a program zeroed on
//          the table) the highest level a feed reaches: the highest of the
//          lower ends of the feed moves (a plunge from a safe height counts
//          at its bottom);
//   bottom Z = the deepest feed, less a quarter of the cut depth (at least
//          1 mm), and at least 2 mm below the top;
//   X, Y   = the box of the feed moves that reach below the top (all feeds,
//          or all motion, when there are none), widened on every side by
//          the largest tool radius the program uses plus 2 mm.
// A program with no motion gets a 50 x 50 x 10 mm block under the origin.
//
// The grid: one pitch for x and y, by default from the job: a 32nd of the
// smallest tool the program uses, but no finer than 1024 dexels and no
// coarser than 256 across the stock's longer side (fine enough that real
// programs' walls do not alias into stripes, within a million dexels). A
// pitch can be given; or a most-dexels-each-way, which gives the finest
// pitch that fits the stock, keeping its shape. Dexel axes run from the
// stock's X0, Y0 in steps of the pitch, so the stock is rounded up to whole
// pitches (by less than one); one ring of hole dexels around it makes its
// side walls (core/grid/grid.h).
// Heights: 0 is the stock bottom, the LSB the finest 1-2-5 step that holds
// the stock height in m bits (core/grid/grid.h lsb_for_range).
//
// Ranges (what the cut's proofs start from, core/cut/sweep.h): a
// stock box within +-kStockCoordMaxNm (1 km: the embedding API's limit;
// `dexmill run` takes +-10 m, the interpreter's) with lo < hi on every
// axis; its height at most 2^m - 1 LSBs of at most 1 m (65 km for 16-bit
// heights, 255 m for 8); a pitch from 1 nm to 1 m; at most 65535 dexels a
// side (the grid's int32 sides and index, core/grid/grid.h); the grid's
// geometry within grid_check_geometry's bounds. Outside, plan_grid refuses
// with the error below that names it.
//
// Memory: no fixed count of dexels, a budget of bytes (GridBudget): the
// caller says what a dexel costs it and how many bytes its run may use
// (`dexmill run --max-memory`, by default a share of the machine's memory,
// tools/run/run_stock.cpp); the plan refuses a grid that needs more, before
// anything is allocated.
#ifndef DEXMILL_CORE_SIM_STOCK_PLAN_H
#define DEXMILL_CORE_SIM_STOCK_PLAN_H

#include <stddef.h>
#include <stdint.h>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/canon/summary.h"
#include "core/point.h"

namespace dexmill {

struct StockBox {
  PointNm lo, hi;
};

StockBox default_stock(const MotionSummary& s, int64_t max_tool_radius_nm);

struct GridPlan {
  GridGeometry geo;
  int32_t stock_nx, stock_ny;  // dexels holding stock: i in [1, stock_nx], j in [1, stock_ny]
  int64_t top_lsb;             // stock top height
  StockBox stock;              // the stock as the grid holds it (rounded up to whole pitches)
};

// The bytes a dexel of the grid holds: its top and bottom.
constexpr uint64_t kGridDexelBytes = 2 * sizeof(height_t);
// The budget of a caller that gives none (the embedding API, the panel, the
// benches): the 64 M dexels of heights the plan took before it had a budget.
constexpr uint64_t kGridDefaultBudgetBytes = (uint64_t{64} << 20) * kGridDexelBytes;

// What a grid may cost.
struct GridBudget {
  uint64_t max_bytes = kGridDefaultBudgetBytes;  // the most the dexels may take, bytes
  // What one dexel costs the caller, bytes: the grid's heights, and the
  // planes it keeps per dexel beside them (at least kGridDexelBytes).
  uint64_t dexel_bytes = kGridDexelBytes;
};

// What a refused plan would have been.
struct PlanRefusal {
  int64_t nx = 0, ny = 0;    // the grid's size, dexels
  uint64_t need_bytes = 0;   // nx * ny * the budget's dexel_bytes (saturated at UINT64_MAX)
  uint64_t max_bytes = 0;    // the budget's
};
// The farthest a stock box's corner may be from the origin, nm.
constexpr int64_t kStockCoordMaxNm = 1000LL * 1000 * 1000000;

// The default grid's bounds and its pitch per tool (see above).
constexpr int64_t kDefaultMaxAcross = 1024, kDefaultMinAcross = 256, kDefaultDexelsPerTool = 32;
// The default pitch for a stock and the smallest tool diameter (0: none known).
int64_t default_pitch_nm(const StockBox& stock, int64_t smallest_tool_nm);

enum class PlanError : uint8_t {
  kOk = 0,
  kGridTooSmall,   // a most-dexels-each-way below 4 x 4
  kTooManyDexels,  // beyond 65535 a side (the refusal's nx, ny say how many)
  kBadGeometry,    // pitch, size or position out of the grid's range
  kBadStock,       // a box corner beyond kStockCoordMaxNm, lo >= hi, or taller than the heights hold
  kOverBudget,     // the dexels need more bytes than the budget (the refusal says how many)
};

// Plans the grid for a stock: by grid_nx/ny when given (> 0), else by
// pitch_nm (the caller's default_pitch_nm when nothing gave one), within
// the budget. Allocates nothing. On kTooManyDexels and kOverBudget, *why
// (when not null) says what the grid would have been.
PlanError plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, GridPlan* out,
                    const GridBudget& budget = GridBudget{}, PlanRefusal* why = nullptr);

// kOk when an nx x ny grid fits the budget, else kOverBudget with *why
// (when not null) filled: the check plan_grid makes, for a grid that comes
// planned (a saved stock's).
PlanError plan_check_budget(int64_t nx, int64_t ny, const GridBudget& budget, PlanRefusal* why = nullptr);

// Fills a grid set up by grid_init with the plan's stock.
template <class H>
void fill_stock(DexelGrid<H>* g, const GridPlan& plan);

// Carves a grid filled by fill_stock to a pre-machined blank's shape, given
// as a design grid on the plan's geometry (its triangles rasterized by
// core/design, within 0.5 LSB + 2 nm): each column of the stock takes the
// blank's highest point over its axis, or becomes a hole where the blank
// has none.
template <class H>
void carve_stock(DexelGrid<H>* g, const GridPlan& plan, const DesignGrid& blank);

}  // namespace dexmill

#endif
