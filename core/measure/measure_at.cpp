// core/measure/measure_at.h: the column under a point.
#include "core/measure/measure_at.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

template <class H>
MeasureAt measure_at(const DexelGrid<H>& g, const uint32_t* lines, const uint8_t* programs, int64_t x_nm, int64_t y_nm) {
  MeasureAt m;
  // The nearest column: its index rounded, the half-pitch beyond the
  // first and last columns still theirs.
  const int64_t fi = div_round(x_nm - g.x0_nm, g.pitch_nm), fj = div_round(y_nm - g.y0_nm, g.pitch_nm);
  if (fi < 0 || fj < 0 || fi >= g.nx || fj >= g.ny) return m;
  m.on_grid = true;
  m.i = static_cast<int32_t>(fi);
  m.j = static_cast<int32_t>(fj);
  m.column_x_nm = g.x0_nm + fi * g.pitch_nm;
  m.column_y_nm = g.y0_nm + fj * g.pitch_nm;
  m.distance_nm = hypot_floor(x_nm - m.column_x_nm, y_nm - m.column_y_nm);
  const size_t k = g.index(m.i, m.j);
  m.material = !g.is_hole(m.i, m.j);
  m.top_nm = g.z0_nm + static_cast<int64_t>(g.top[k]) * g.lsb_nm;
  m.bottom_nm = g.z0_nm + static_cast<int64_t>(g.bottom[k]) * g.lsb_nm;
  m.height_error_nm = g.lsb_nm;
  if (lines) m.line = lines[k];
  if (programs) m.program = programs[k];
  return m;
}

template MeasureAt measure_at<uint8_t>(const DexelGrid<uint8_t>&, const uint32_t*, const uint8_t*, int64_t, int64_t);
template MeasureAt measure_at<uint16_t>(const DexelGrid<uint16_t>&, const uint32_t*, const uint8_t*, int64_t, int64_t);
template MeasureAt measure_at<uint32_t>(const DexelGrid<uint32_t>&, const uint32_t*, const uint8_t*, int64_t, int64_t);

}  // namespace dexmill
