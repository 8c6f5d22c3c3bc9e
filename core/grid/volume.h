// Material in a dexel grid, exactly: the sum over dexels of top - bottom in
// LSB (holes count 0). Each dexel stands for a pitch x pitch column, so the
// volume is that sum times lsb * pitch^2; the difference of two sums (before
// and after cutting) is the volume removed, with no rounding at all.
#ifndef DEXMILL_CORE_GRID_VOLUME_H
#define DEXMILL_CORE_GRID_VOLUME_H

#include <stdint.h>

#include "core/grid/grid.h"

namespace dexmill {

template <class H>
uint64_t grid_material_lsb(const DexelGrid<H>& g) {
  uint64_t sum = 0;
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  for (size_t k = 0; k < n; ++k) sum += static_cast<uint64_t>(g.top[k]) - static_cast<uint64_t>(g.bottom[k]);
  return sum;
}

}  // namespace dexmill

#endif
