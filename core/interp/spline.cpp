// Spline chords; see spline.h.
#include "core/interp/spline.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

namespace {

// P(u) - P0 = a u + b u^2 + c u^3 for one axis, from the Bernstein form
// (quadratic: 2u(1-u) d1 + u^2 d2; cubic: 3u(1-u)^2 d1 + 3u^2(1-u) d2 +
// u^3 d3, with d_i = P_i - P0).
struct Poly {
  int64_t a, b, c;
};

Poly poly(const SplinePlan& s, const int64_t* v) {
  const int64_t d1 = v[1] - v[0], d2 = v[2] - v[0];
  if (s.points == 3) return Poly{2 * d1, d2 - 2 * d1, 0};
  const int64_t d3 = v[3] - v[0];
  return Poly{3 * d1, 3 * d2 - 6 * d1, 3 * d1 - 3 * d2 + d3};
}

// |(x, y)| rounded up.
int64_t norm_ceil(int64_t x, int64_t y) {
  const U128 v = sum_sq_u128(x, y);
  const uint64_t r = isqrt_u128(v);
  const U128 rr = mul_wide_u64(r, r);
  return static_cast<int64_t>(rr.hi == v.hi && rr.lo == v.lo ? r : r + 1);
}

// P0 + (((c k + b n) k + a n^2) k) / n^3 for u = k / n, rounded once at the
// end: (c k + b n) k / n is rounded (0.5), then (that + a n) k / n^2 (0.5 k
// / n^2 of the first rounding, and 0.5): at most 0.5 + 0.5 / n. Magnitudes
// (spline.h's range: |d| <= 4e10, n <= 2^20): c k, b n < 4e17, a n < 1.3e17.
int64_t eval(const Poly& p, int64_t p0, int64_t k, int64_t n) {
  const int64_t t = p.c * k + p.b * n;
  const int64_t v = muldiv_round(t, k, n) + p.a * n;
  return p0 + muldiv_round(v, k, n * n);
}

}  // namespace

uint32_t spline_chord_count(const SplinePlan& s, int64_t sagitta_nm) {
  if (sagitta_nm < 1) sagitta_nm = 1;
  const Poly px = poly(s, s.x), py = poly(s, s.y);
  // |P''| = |2b + 6c u| is largest at u = 0 or u = 1.
  const int64_t m0 = norm_ceil(2 * px.b, 2 * py.b);
  const int64_t m1 = norm_ceil(2 * px.b + 6 * px.c, 2 * py.b + 6 * py.c);
  const int64_t m = m0 > m1 ? m0 : m1;
  // n^2 >= m / (8 s).
  const int64_t q = div_ceil(m, 8 * sagitta_nm);
  int64_t n = isqrt_u64(static_cast<uint64_t>(q));
  if (n * n < q) ++n;
  if (n < 1) n = 1;
  return n > kSplineMaxChords ? kSplineMaxChords : static_cast<uint32_t>(n);
}

void spline_point(const SplinePlan& s, uint32_t k, int64_t* x, int64_t* y) {
  const int last = s.points - 1;
  if (k == 0 || k >= s.chords) {  // the ends exactly
    *x = s.x[k == 0 ? 0 : last];
    *y = s.y[k == 0 ? 0 : last];
    return;
  }
  *x = eval(poly(s, s.x), s.x[0], k, s.chords);
  *y = eval(poly(s, s.y), s.y[0], k, s.chords);
}

}  // namespace dexmill
