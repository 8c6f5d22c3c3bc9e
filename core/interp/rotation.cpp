#include "core/interp/rotation.h"

#include "core/gcode/gvalue.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

XyRotation xy_rotation(int64_t deg_e9) {
  constexpr int64_t kTurnE9 = 360LL * 1000000000;
  XyRotation r{false, 1 << 30, 0};
  if (deg_e9 % kTurnE9 == 0) return r;
  const SinCosQ30 sc = sincos_bam(bam_of_degrees(deg_e9));
  r.on = true;
  r.cos_q30 = sc.cos_q30;
  r.sin_q30 = sc.sin_q30;
  return r;
}

XyRotation xy_rotation_inverse(const XyRotation& r) { return XyRotation{r.on, r.cos_q30, -r.sin_q30}; }

PointNm rotate_about(const XyRotation& r, const PointNm& p, int64_t ox_nm, int64_t oy_nm) {
  if (!r.on) return p;
  const int64_t dx = p.x_nm - ox_nm, dy = p.y_nm - oy_nm;
  // Each product floored at q29 (one half nm), the sum rounded to the nm.
  const int64_t x2 = mul_shift(dx, r.cos_q30, 29) - mul_shift(dy, r.sin_q30, 29);
  const int64_t y2 = mul_shift(dx, r.sin_q30, 29) + mul_shift(dy, r.cos_q30, 29);
  return PointNm{ox_nm + ((x2 + 1) >> 1), oy_nm + ((y2 + 1) >> 1), p.z_nm};
}

}  // namespace dexmill
