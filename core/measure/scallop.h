// The highest scallop in a region of the simulated part (`dexmill measure
// STOCK --scallop [--region X0,Y0,X1,Y1]`): the tops scanned along every
// row (X) and every column (Y) of the region; along a scan, the profile's
// local maxima (a plateau counts once) are crests and its local minima
// valleys; a crest's scallop is its height over the higher of the two
// valleys beside it (the lowest tops between it and the crests before
// and after it), and the highest scallop is the largest over the region,
// per axis and in all. A crest needs a valley on both sides within the
// region; a hole ends the scan there (a through-cut is no valley).
//
// Bound: the tops are the cut's within one LSB each, and between samples
// the surface can rise above a sampled crest or dip below a sampled
// valley. A ball-nose's scallop has a cusp at its crest and a round
// valley; the true cusp lies within a pitch of the sampled crest, and is
// at most one sample step higher than it (the surface beside a cusp is
// concave: it does not rise faster than the step from the crest's lower
// neighbour). So the bound stated is two LSB plus the larger of the
// crest's two steps to its neighbours, plus the valley's (one dexel's
// worth of height at the crest and at the valley). The crest's place is
// its column's centre (the cusp within a pitch along the scan).
// Integer only, no heap.
#ifndef DEXMILL_CORE_MEASURE_SCALLOP_H
#define DEXMILL_CORE_MEASURE_SCALLOP_H

#include <stdint.h>

#include "core/grid/grid.h"

namespace dexmill {

struct Scallop {
  bool found = false;            // some crest with valleys on both sides
  int32_t i = 0, j = 0;          // the crest's column
  int64_t x_nm = 0, y_nm = 0;
  int64_t height_nm = 0;         // crest - max(left valley, right valley)
  int64_t crest_nm = 0, valley_nm = 0;  // machine Z of the crest and of the higher valley
  int64_t error_nm = 0;          // the bound above
  int32_t crests = 0;            // crests with valleys on both sides, scanned
};

struct ScallopAnswer {
  Scallop along_x, along_y;  // scans along rows (stepover in X) and columns
  const Scallop& highest() const { return along_y.height_nm > along_x.height_nm ? along_y : along_x; }
};

// Over the columns [r.i0, r.i1) x [r.j0, r.j1) of g (clipped to the grid).
template <class H>
ScallopAnswer scallop(const DexelGrid<H>& g, GridRect r);

}  // namespace dexmill

#endif
