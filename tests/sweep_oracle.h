// Double-precision oracle for the lowest point of a tool swept along a
// straight move (tests only): the exact minimum of z(s) + f(r(s)) over the
// part of the move that reaches the column, by interval solve and a long
// ternary search of the convex function.
#ifndef DEXMILL_TESTS_SWEEP_ORACLE_H
#define DEXMILL_TESTS_SWEEP_ORACLE_H

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/tool/tool.h"

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

// The column and its four neighbours one step away (times a slack, nm):
// where core/cut/sweep.h's backward bound looks for the exact height.
constexpr double kNeighbours[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// The part [*s0, *s1] of the move a -> b (s in [0, 1]) where the tool
// reaches the column (px, py); false when it never does.
inline bool reach_on_line(const dexmill::Tool& t, P3 a, P3 b, double px, double py, double* s0, double* s1) {
  const double R = static_cast<double>(t.diameter_nm / 2);
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  if (l2 == 0) {
    *s0 = 0;
    *s1 = 1;
    return std::hypot(px - a.x, py - a.y) <= R;
  }
  // |A + s d - P|^2 <= R^2: a quadratic in s.
  const double fx = a.x - px, fy = a.y - py;
  const double qa = l2, qb = 2 * (fx * dx + fy * dy), qc = fx * fx + fy * fy - R * R;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return false;
  const double sq = std::sqrt(disc);
  *s0 = std::max(0.0, (-qb - sq) / (2 * qa));
  *s1 = std::min(1.0, (-qb + sq) / (2 * qa));
  return *s0 <= *s1;
}

// Lowest tool point over the column (px, py) for the move a -> b, in nm, or
// HUGE_VAL when the tool never reaches it.
inline double lowest_on_line(const dexmill::Tool& t, P3 a, P3 b, double px, double py) {
  const double R = static_cast<double>(t.diameter_nm / 2);
  const double dx = b.x - a.x, dy = b.y - a.y;
  auto g = [&](double s) {  // s in [0, 1]
    const double cx = a.x + s * dx, cy = a.y + s * dy;
    const double r = std::hypot(px - cx, py - cy);
    return a.z + s * (b.z - a.z) + profile_nm(t, std::min(r, R));
  };
  double s0, s1;
  if (!reach_on_line(t, a, b, px, py, &s0, &s1)) return HUGE_VAL;
  if (dx == 0 && dy == 0) return std::min(a.z, b.z) + profile_nm(t, std::hypot(px - a.x, py - a.y));
  double lo = s0, hi = s1;
  for (int it = 0; it < 200; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (g(m1) <= g(m2)) hi = m2; else lo = m1;
  }
  return std::min({g(s0), g(s1), g((lo + hi) / 2)});
}

// Highest tip height over the part of the move that reaches the column
// (the shaft top there is that plus the tool's length), nm, or -HUGE_VAL.
inline double highest_on_line(const dexmill::Tool& t, P3 a, P3 b, double px, double py) {
  double s0, s1;
  if (!reach_on_line(t, a, b, px, py, &s0, &s1)) return -HUGE_VAL;
  return std::max(a.z + s0 * (b.z - a.z), a.z + s1 * (b.z - a.z));
}

// A dexel's material [bottom, top], LSB.
struct Dexel {
  double top, bottom;
};

// Figure 2 (core/cut/stamp.h) in doubles: what the tool interval [cb, ct] (LSB)
// leaves of the material w. False when the case is ambiguous: an end of the
// tool within tol of an end of the material, where 1 LSB of rounding may
// pick either case.
inline bool figure2(Dexel w, double cb, double ct, double tol, Dexel* out) {
  for (double c : {cb, ct})
    for (double e : {w.top, w.bottom})
      if (std::fabs(c - e) <= tol) return false;
  *out = w;
  if (cb >= w.top || ct <= w.bottom) return true;  // a
  if (cb <= w.bottom) {
    *out = ct >= w.top ? Dexel{0, 0} : Dexel{w.top, ct};  // e, c
  } else if (ct >= w.top) {
    out->top = cb;  // b; d leaves w
  }
  return true;
}

// Checks every dexel of an nx x ny grid (dexel (0, 0) at the origin, z0 =
// 0) that held `stock` before one move against figure 2 applied to the
// oracle's interval: lowest(px, py) to highest(px, py) + len_nm, nm, with the
// backward bound of core/cut/sweep.h (1 LSB, the column or its neighbours
// slack_nm away). Columns where the case is ambiguous, or where lowest()
// gives NaN (the oracle cannot tell), are skipped; *cases
// counts the others by the case their material shows (index 0: untouched,
// 1: top cut, 2: bottom cut, 3: hole). Returns the number of bad dexels.
template <class H, class Lo, class Hi>
int check_figure2_grid(int nx, int ny, double pitch_nm, double lsb_nm, const H* top, const H* bottom, Dexel stock,
                       double len_nm, double slack_nm, Lo lowest, Hi highest, int cases[4], const char* what) {
  int bad = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double px = i * pitch_nm, py = j * pitch_nm;
      const double t = top[j * nx + i], b = bottom[j * nx + i];
      Dexel lo{HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL};
      bool clear = true;
      auto inside = [&] { return t >= lo.top - 1 && t <= hi.top + 1 && b >= lo.bottom - 1 && b <= hi.bottom + 1; };
      for (auto& o : kNeighbours) {
        if (&o != &kNeighbours[0] && clear && inside()) break;  // the neighbours only when the column disagrees
        const double x = px + o[0] * slack_nm, y = py + o[1] * slack_nm;
        const double cb = lowest(x, y), ct = highest(x, y);
        Dexel e = stock;
        if (std::isnan(cb) || (cb != HUGE_VAL && !figure2(stock, cb / lsb_nm, (ct + len_nm) / lsb_nm, 1.0, &e)))
          clear = false;
        lo = Dexel{std::min(lo.top, e.top), std::min(lo.bottom, e.bottom)};
        hi = Dexel{std::max(hi.top, e.top), std::max(hi.bottom, e.bottom)};
      }
      if (!clear) continue;
      cases[t == 0 && b == 0 ? 3 : b != stock.bottom ? 2 : t != stock.top ? 1 : 0]++;
      if (!inside()) {
        if (++bad <= 3)
          std::printf("  %s: dexel (%d,%d) [%.0f, %.0f], oracle top [%.2f, %.2f] bottom [%.2f, %.2f]\n", what, i, j, b,
                      t, lo.top, hi.top, lo.bottom, hi.bottom);
      }
    }
  }
  return bad;
}

}  // namespace oracle

#endif
