// Double-precision oracle for the lowest point of a tool swept along a
// straight move (tests only): the exact minimum of z(s) + f(r(s)) over the
// part of the move that reaches the column, by interval solve and a long
// ternary search of the convex function.
#ifndef DEXMILL_TESTS_SWEEP_ORACLE_H
#define DEXMILL_TESTS_SWEEP_ORACLE_H

#include <algorithm>
#include <cmath>

#include "core/tool.h"

namespace oracle {

inline double profile_nm(const dexmill::Tool& t, double r) {
  const double R = static_cast<double>(t.diameter_nm / 2);
  if (r > R) return HUGE_VAL;
  switch (t.kind) {
    case dexmill::ToolKind::kFlat: return 0;
    case dexmill::ToolKind::kBall: return R - std::sqrt(std::max(0.0, R * R - r * r));
    case dexmill::ToolKind::kBullNose: {
      const double rc = static_cast<double>(t.corner_radius_nm), f = R - rc;
      if (r <= f) return 0;
      return rc - std::sqrt(std::max(0.0, rc * rc - (r - f) * (r - f)));
    }
    case dexmill::ToolKind::kVBit:
      return r / std::tan(t.tip_angle_mdeg / 2000.0 * 3.14159265358979323846 / 180.0);
  }
  return HUGE_VAL;
}

struct P3 {
  double x, y, z;
};

// Lowest tool point over the column (px, py) for the move a -> b, in nm, or
// HUGE_VAL when the tool never reaches it.
inline double lowest_on_line(const dexmill::Tool& t, P3 a, P3 b, double px, double py) {
  const double R = static_cast<double>(t.diameter_nm / 2);
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  auto g = [&](double s) {  // s in [0, 1]
    const double cx = a.x + s * dx, cy = a.y + s * dy;
    const double r = std::hypot(px - cx, py - cy);
    return a.z + s * (b.z - a.z) + profile_nm(t, std::min(r, R));
  };
  if (l2 == 0) {
    const double r = std::hypot(px - a.x, py - a.y);
    if (r > R) return HUGE_VAL;
    return std::min(a.z, b.z) + profile_nm(t, r);
  }
  // |A + s d - P|^2 <= R^2: a quadratic in s.
  const double fx = a.x - px, fy = a.y - py;
  const double qa = l2, qb = 2 * (fx * dx + fy * dy), qc = fx * fx + fy * fy - R * R;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return HUGE_VAL;
  const double sq = std::sqrt(disc);
  double s0 = std::max(0.0, (-qb - sq) / (2 * qa)), s1 = std::min(1.0, (-qb + sq) / (2 * qa));
  if (s0 > s1) return HUGE_VAL;
  double lo = s0, hi = s1;
  for (int it = 0; it < 200; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (g(m1) <= g(m2)) hi = m2; else lo = m1;
  }
  return std::min({g(s0), g(s1), g((lo + hi) / 2)});
}

}  // namespace oracle

#endif
