// Material in a dexel grid, exactly: the sum over dexels of top - bottom in
// LSB (holes count 0). Each dexel stands for a pitch x pitch column, so the
// volume is that sum times lsb * pitch^2; the difference of two sums (before
// and after cutting) is the volume removed, with no rounding at all.
#ifndef DEXMILL_CORE_GRID_VOLUME_H
#define DEXMILL_CORE_GRID_VOLUME_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/math/fixed.h"

namespace dexmill {

template <class H>
uint64_t grid_material_lsb(const DexelGrid<H>& g) {
  uint64_t sum = 0;
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  for (size_t k = 0; k < n; ++k) sum += static_cast<uint64_t>(g.top[k]) - static_cast<uint64_t>(g.bottom[k]);
  return sum;
}

// Such a sum (or a difference of two) as a volume in cubic micrometres,
// rounded to nearest: lsb_dexels * lsb * pitch^2 / 10^9 for an LSB and
// pitch of at most 1 m (core/grid/grid.h); UINT64_MAX when it does not fit.
inline uint64_t volume_um3(uint64_t lsb_dexels, int64_t lsb_nm, int64_t pitch_nm) {
  constexpr uint64_t kNm3PerUm3 = 1000000000;
  const U128 height = mul_wide_u64(lsb_dexels, static_cast<uint64_t>(lsb_nm));  // LSB dexels to nm dexels
  if (height.hi != 0) return UINT64_MAX;
  U128 v = mul_wide_u64(height.lo, static_cast<uint64_t>(pitch_nm) * static_cast<uint64_t>(pitch_nm));
  const uint64_t lo = v.lo + kNm3PerUm3 / 2;
  v = U128{v.hi + (lo < v.lo ? 1 : 0), lo};
  if (v.hi >= kNm3PerUm3) return UINT64_MAX;
  uint64_t rem = 0;
  return divmod_u128_portable(v, kNm3PerUm3, &rem);
}

}  // namespace dexmill

#endif
