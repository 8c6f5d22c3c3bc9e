// A point of the tool path: the tool tip in machine coordinates, nm.
#ifndef DEXMILL_CORE_POINT_H
#define DEXMILL_CORE_POINT_H

#include <stdint.h>

#include "core/math/fixed.h"

namespace dexmill {

struct PointNm {
  int64_t x_nm, y_nm, z_nm;
};

// An axis-aligned box in machine coordinates, nm.
struct BoxNm {
  PointNm lo, hi;
};

// Cutting code accepts any coordinates but saturates them to +-2^46 nm
// (about 70 km) first, so no intermediate can overflow; the G-code reader
// rejects anything beyond its own, much smaller, range before that.
constexpr int64_t kCoordLimitNm = static_cast<int64_t>(1) << 46;
inline PointNm clamp_point(PointNm p) {
  p.x_nm = clamp(p.x_nm, -kCoordLimitNm, kCoordLimitNm);
  p.y_nm = clamp(p.y_nm, -kCoordLimitNm, kCoordLimitNm);
  p.z_nm = clamp(p.z_nm, -kCoordLimitNm, kCoordLimitNm);
  return p;
}

inline bool operator==(const PointNm& a, const PointNm& b) {
  return a.x_nm == b.x_nm && a.y_nm == b.y_nm && a.z_nm == b.z_nm;
}

}  // namespace dexmill

#endif
