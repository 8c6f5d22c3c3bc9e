// The stock and the dexel grid of `dexmill run`.
//
// Default stock (no --stock), from a first pass over the program
// (core/motion/summary.h), for programs that put Z0 on the stock top as CAM
// programs do:
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
// programs' walls do not alias into stripes, within a million dexels).
// --pitch MM sets it; --grid NXxNY gives the finest pitch that fits the
// stock in NX x NY dexels, keeping its shape. Dexel axes run from the
// stock's X0, Y0 in steps of the pitch, so the stock is rounded up to whole
// pitches (by less than one); one ring of hole dexels around it makes its
// side walls (core/grid/grid.h).
// Heights: 0 is the stock bottom, the LSB the finest 1-2-5 step that holds
// the stock height in 16 bits (core/grid/grid.h lsb_for_range).
#ifndef DEXMILL_TOOLS_RUN_STOCK_H
#define DEXMILL_TOOLS_RUN_STOCK_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/motion/summary.h"

namespace dexmill {
namespace cli {

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

// Most dexels a run may use (2 x 2 bytes each for 16-bit heights).
constexpr int64_t kMaxGridCells = 64LL << 20;

// The default grid's bounds and its pitch per tool (see above).
constexpr int64_t kDefaultMaxAcross = 1024, kDefaultMinAcross = 256, kDefaultDexelsPerTool = 32;
// The default pitch for a stock and the smallest tool diameter (0: none known).
int64_t default_pitch_nm(const StockBox& stock, int64_t smallest_tool_nm);

// Plans the grid for a stock: by grid_nx/ny when given, else by pitch_nm
// (the caller's default_pitch_nm when no option gave one). False with a
// message for a grid beyond kMaxGridCells or a pitch that leaves fewer
// than 2 dexels across.

bool plan_grid(const StockBox& stock, int32_t grid_nx, int32_t grid_ny, int64_t pitch_nm, GridPlan* out,
               std::string* err);

// Fills a grid set up by grid_init with the plan's stock.
template <class H>
void fill_stock(DexelGrid<H>* g, const GridPlan& plan);

// --stock FILE.stl, a pre-machined blank: its triangles (machine mm, read
// once, floats end there) and their bounding box. Returns kExitOk, or the
// exit code after printing the STL reader's error.
int read_stock_stl(const std::string& path, std::vector<TriangleNm>* tris, StockBox* box);

// Carves a grid filled by fill_stock to the blank's shape: each column of the
// stock takes the highest point of the mesh over its axis (core/design's
// rasterizing, within 0.5 LSB + 2 nm), or becomes a hole where the mesh has
// none. kExitOk, or kExitUsage when the stock is wider than that allows.
template <class H>
int carve_stock(DexelGrid<H>* g, const GridPlan& plan, const std::vector<TriangleNm>& tris);

}  // namespace cli
}  // namespace dexmill

#endif
