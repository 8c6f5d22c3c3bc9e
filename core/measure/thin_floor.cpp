// core/measure/thin_floor.h: the thinnest floor.
#include "core/measure/thin_floor.h"

namespace dexmill {

template <class H>
ThinFloor thin_floor(const DexelGrid<H>& g) {
  ThinFloor f;
  int64_t least_lsb = 0;
  for (int32_t j = 0; j < g.ny; ++j)
    for (int32_t i = 0; i < g.nx; ++i) {
      if (g.is_hole(i, j)) continue;
      const size_t k = g.index(i, j);
      const int64_t t = static_cast<int64_t>(g.top[k]) - static_cast<int64_t>(g.bottom[k]);
      if (f.found && t >= least_lsb) continue;
      f.found = true;
      least_lsb = t;
      f.i = i;
      f.j = j;
    }
  if (!f.found) return f;
  const size_t k = g.index(f.i, f.j);
  f.x_nm = g.x0_nm + static_cast<int64_t>(f.i) * g.pitch_nm;
  f.y_nm = g.y0_nm + static_cast<int64_t>(f.j) * g.pitch_nm;
  f.top_nm = g.z0_nm + static_cast<int64_t>(g.top[k]) * g.lsb_nm;
  f.bottom_nm = g.z0_nm + static_cast<int64_t>(g.bottom[k]) * g.lsb_nm;
  f.thickness_nm = least_lsb * g.lsb_nm;
  f.thickness_error_nm = 2 * g.lsb_nm;
  return f;
}

template ThinFloor thin_floor<uint8_t>(const DexelGrid<uint8_t>&);
template ThinFloor thin_floor<uint16_t>(const DexelGrid<uint16_t>&);
template ThinFloor thin_floor<uint32_t>(const DexelGrid<uint32_t>&);

}  // namespace dexmill
