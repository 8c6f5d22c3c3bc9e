// The thinnest floor of the simulated part (`dexmill measure STOCK
// --thickness`): the least top - bottom over the columns that hold
// material, and the column where (the first in row-major order among
// equals). Each column's top and bottom are the cut's within one LSB
// (core/measure/measure_at.h), so the thickness is within two LSB; the
// column stands for the surface within half a pitch of its centre along X
// and Y (pitch / sqrt 2 in all).
// Integer only, no heap.
#ifndef DEXMILL_CORE_MEASURE_THIN_FLOOR_H
#define DEXMILL_CORE_MEASURE_THIN_FLOOR_H

#include <stdint.h>

#include "core/grid/grid.h"

namespace dexmill {

struct ThinFloor {
  bool found = false;              // some column holds material
  int32_t i = 0, j = 0;            // the thinnest column
  int64_t x_nm = 0, y_nm = 0;      // its centre
  int64_t thickness_nm = 0;        // top - bottom there
  int64_t top_nm = 0, bottom_nm = 0;
  int64_t thickness_error_nm = 0;  // two LSB
};

template <class H>
ThinFloor thin_floor(const DexelGrid<H>& g);

}  // namespace dexmill

#endif
