// The thinnest wall of the simulated part (`dexmill measure STOCK
// --thickness --wall-height MM`), found by scans of the tops along the
// grid's rows, columns and both diagonals.
//
// What a wall is: along a scan, a run of consecutive columns a..b that
// hold material and whose every top stands at least H (wall_height_nm)
// above the floor on both sides of the run: the tops of the columns just
// before a and just after b. A hole (cut through) or the grid's edge beside
// the run is air, lower than any floor, so a wall at the stock's edge or
// standing between through-cuts counts. The run must be across the wall:
// at both its ends the face must run crosswise to the scan, within 26.6
// degrees (6 steps crosswise to either side it is within 3 steps of the
// end along the scan, thin_wall.cpp face_crosswise), so a wall is found
// away from its own ends (6 steps); else a scan across a convex corner's
// tip or along a chord near a round island's edge would find a short run
// where the material is thick.
// Its width is the run's length
// (b - a + 1) times the scan's step (the pitch along rows and columns,
// pitch * sqrt 2 along the diagonals); for each run start the shortest
// run that qualifies is taken, and the thinnest wall is the least width
// over every scan (ties: the first in the order rows, columns, diagonal
// up, diagonal down, then along the scan).
//
// Bounds: along its scan the width is within one step of the wall's true
// width there (its faces lie between sampled columns, each within a step).
// A straight wall crosswise to a scan direction is measured at its true
// width; one at an angle to it (counted up to 26.6 degrees) at most
// 1 / cos 26.6 = 1.12 times its width, plus the step; a round one (an
// island) at least cos 26.6 = 0.894 times its diameter, less the step.
// Heights (H against the tops) are within one LSB. Tops only: a wall
// under an overhang (a bottom raised by a second setup) is judged by its
// top. Integer only, no heap; O(columns) per scan but for runs that start
// at a step up and reach far (a plateau's length each).
#ifndef DEXMILL_CORE_MEASURE_THIN_WALL_H
#define DEXMILL_CORE_MEASURE_THIN_WALL_H

#include <stdint.h>

#include "core/grid/grid.h"

namespace dexmill {

enum class WallScan : uint8_t { kRow = 0, kColumn = 1, kDiagonalUp = 2, kDiagonalDown = 3 };
const char* wall_scan_name(WallScan s);  // "X", "Y", "XY", "X-Y": the scan's direction

struct ThinWall {
  bool found = false;
  WallScan scan = WallScan::kRow;
  int32_t i0 = 0, j0 = 0, i1 = 0, j1 = 0;  // the run's first and last columns
  int64_t x_nm = 0, y_nm = 0;              // its middle (machine XY)
  int64_t width_nm = 0;                    // run length x step
  int64_t width_error_nm = 0;              // one step
  int64_t top_nm = 0;                      // the run's lowest top
  bool floor_air = false;                  // both sides are air (holes or the grid's edge)
  int64_t floor_nm = 0;                    // else the higher of the two sides' tops
};

template <class H>
ThinWall thin_wall(const DexelGrid<H>& g, int64_t wall_height_nm);

}  // namespace dexmill

#endif
