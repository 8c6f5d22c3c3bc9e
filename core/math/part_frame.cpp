// core/math/part_frame.h: points between the machine and the part.
#include "core/math/part_frame.h"

#include "core/math/fixed.h"

namespace dexmill {

PartFrame part_frame_identity() {
  PartFrame f{};
  f.turn[0] = f.turn[4] = f.turn[8] = 1;
  return f;
}

bool part_frame_is_identity(const PartFrame& f) {
  for (int k = 0; k < 9; ++k)
    if (f.turn[k] != (k % 4 == 0 ? 1 : 0)) return false;
  return f.offset_half_nm[0] == 0 && f.offset_half_nm[1] == 0 && f.offset_half_nm[2] == 0;
}

bool part_frame_keeps_z(const PartFrame& f) {
  return f.turn[2] == 0 && f.turn[5] == 0 && f.turn[6] == 0 && f.turn[7] == 0 && f.turn[8] != 0;
}

PointNm part_frame_to_part(const PartFrame& f, const PointNm& m) {
  const int64_t v[3] = {2 * m.x_nm, 2 * m.y_nm, 2 * m.z_nm};
  int64_t p[3];
  for (int r = 0; r < 3; ++r)
    p[r] = div_floor(f.turn[3 * r] * v[0] + f.turn[3 * r + 1] * v[1] + f.turn[3 * r + 2] * v[2] + f.offset_half_nm[r], 2);
  return PointNm{p[0], p[1], p[2]};
}

PointNm part_frame_to_machine(const PartFrame& f, const PointNm& p) {
  // The turn's inverse is its transpose: 2 m = turn^T (2 p - offset).
  const int64_t v[3] = {2 * p.x_nm - f.offset_half_nm[0], 2 * p.y_nm - f.offset_half_nm[1], 2 * p.z_nm - f.offset_half_nm[2]};
  int64_t m[3];
  for (int r = 0; r < 3; ++r) m[r] = div_floor(f.turn[r] * v[0] + f.turn[3 + r] * v[1] + f.turn[6 + r] * v[2], 2);
  return PointNm{m[0], m[1], m[2]};
}

}  // namespace dexmill
