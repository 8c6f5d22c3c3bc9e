// What the simulated part is at a point (`dexmill measure STOCK --at X,Y`):
// the dexel column nearest (x, y) — its top and bottom, whether it holds
// material, and the program line that last lowered it where the stock
// kept lines (core/stock/stock_file.h, kStockLayerLine). A column stands
// for the surface at its centre: its heights are the cut's there, within
// the cut's bound (one LSB, core/cut/README.md), and the point is at most
// half a pitch from the centre along each axis (pitch / sqrt 2 in all),
// the horizontal error stated with every answer. Integer only, no heap:
// the panel's too.
#ifndef DEXMILL_CORE_MEASURE_MEASURE_AT_H
#define DEXMILL_CORE_MEASURE_MEASURE_AT_H

#include <stdint.h>

#include "core/grid/grid.h"

namespace dexmill {

struct MeasureAt {
  bool on_grid = false;               // the point is over the grid (within half a pitch of its columns)
  int32_t i = 0, j = 0;               // the column
  int64_t column_x_nm = 0, column_y_nm = 0;
  int64_t distance_nm = 0;            // from the point to the column's centre (<= pitch / sqrt 2)
  bool material = false;              // it holds material (else cut through: a hole)
  int64_t top_nm = 0, bottom_nm = 0;  // machine Z
  int64_t height_error_nm = 0;        // the heights' bound: one LSB
  uint32_t line = 0;                  // the line that last lowered its top (0: uncut, or not kept)
  uint8_t program = 0;                // and the chain's program it is in
};

// The column at (x_nm, y_nm) of g; lines and programs (nx * ny, or null)
// the stock's layers.
template <class H>
MeasureAt measure_at(const DexelGrid<H>& g, const uint32_t* lines, const uint8_t* programs, int64_t x_nm, int64_t y_nm);

}  // namespace dexmill

#endif
