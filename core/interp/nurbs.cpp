#include "core/interp/nurbs.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {
namespace {

constexpr int kWeightBits = 40;  // weights as ratios to the largest, which is 2^40
constexpr int kParamBits = 48;   // parameters and basis values
constexpr int kShareBits = 62;   // a control point's share of a point
constexpr int kFineBits = 10;    // sums in 2^-10 nm before the last rounding

// Knot t_i of the clamped integer knot vector (nurbs_G5_knot_vector_creator).
int64_t knot(const NurbsCurve& c, int32_t i) {
  const int32_t n = c.count - 1, k = c.order;
  return i < k ? 0 : i <= n ? i - k + 1 : n - k + 2;
}

// The point of span `span` for the parameters u[0..d-1] (q48, each within
// the span; all equal: the curve point, else its blossom, a Bezier point
// of a piece). de Boor's algorithm with level r using u[r - 1], run on the
// basis (each control point's coefficient, q48: non-negative, summing to
// one), then the rational shares b_i w_i / sum b_j w_j (q62) weigh the
// points, relative to P0 so that every product fits.
void point_of(const NurbsCurve& c, int32_t span, const int64_t* u, int64_t* x, int64_t* y) {
  const int32_t d = c.order - 1, j = span + d;  // t_j = span <= u < t_{j+1}
  int64_t coef[kNurbsMaxOrder][kNurbsMaxOrder];  // coef[i][m]: point j - d + m's part in slot i
  for (int32_t i = 0; i <= d; ++i)
    for (int32_t m = 0; m <= d; ++m) coef[i][m] = i == m ? static_cast<int64_t>(1) << kParamBits : 0;
  for (int32_t r = 1; r <= d; ++r) {
    for (int32_t i = d; i >= r; --i) {
      const int32_t g = j - d + i;
      const int64_t ti = knot(c, g), tr = knot(c, g + d + 1 - r);
      // (u - t_i) / (t_{i+d+1-r} - t_i): within [0, 1] for u in the span.
      const int64_t alpha = (u[r - 1] - (ti << kParamBits)) / (tr - ti);
      for (int32_t m = 0; m <= d; ++m)
        coef[i][m] = coef[i - 1][m] + mul_shift(coef[i][m] - coef[i - 1][m], alpha, kParamBits);
    }
  }
  int64_t bw[kNurbsMaxOrder], sum = 0;
  for (int32_t m = 0; m <= d; ++m) {
    bw[m] = mul_shift(coef[d][m], c.weight[j - d + m], 32);  // <= 2^56
    sum += bw[m];                                             // <= 2^60
  }
  int64_t fx = 0, fy = 0;
  for (int32_t m = 0; m <= d; ++m) {
    if (bw[m] == 0) continue;
    const int64_t share = muldiv_round(bw[m], static_cast<int64_t>(1) << kShareBits, sum);
    const int32_t g = j - d + m;
    fx += mul_shift(share, c.x_nm[g] - c.x_nm[0], kShareBits - kFineBits);
    fy += mul_shift(share, c.y_nm[g] - c.y_nm[0], kShareBits - kFineBits);
  }
  const int64_t half = static_cast<int64_t>(1) << (kFineBits - 1);
  *x = c.x_nm[0] + ((fx + half) >> kFineBits);
  *y = c.y_nm[0] + ((fy + half) >> kFineBits);
}

// q48 of span + i / m (m = 2^log2m).
int64_t param(int32_t span, uint32_t i, uint32_t log2m) {
  return (static_cast<int64_t>(span) << kParamBits) + (static_cast<int64_t>(i) << (kParamBits - log2m));
}

// Whether the projected Bezier points of the piece [a, b] lie within s of
// the chord between its ends (and within 2^30 nm of its start, so that the
// products below fit).
bool piece_flat(const NurbsCurve& c, int32_t span, int64_t a, int64_t b, int64_t s_nm) {
  const int32_t d = c.order - 1;
  int64_t px[kNurbsMaxOrder], py[kNurbsMaxOrder];
  int64_t u[kNurbsMaxOrder] = {};  // (zeroed: GCC 12 cannot see that order >= 3 fills it)
  for (int32_t m = 0; m <= d; ++m) {
    for (int32_t r = 0; r < d; ++r) u[r] = r < d - m ? a : b;
    point_of(c, span, u, &px[m], &py[m]);
  }
  constexpr int64_t kNear = static_cast<int64_t>(1) << 30;
  const int64_t bx = px[d] - px[0], by = py[d] - py[0];
  if (bx <= -kNear || bx >= kNear || by <= -kNear || by >= kNear) return false;
  const U128 s2 = sq_u128(s_nm);
  const int64_t ab2 = bx * bx + by * by;
  for (int32_t m = 1; m < d; ++m) {
    const int64_t qx = px[m] - px[0], qy = py[m] - py[0];
    if (qx <= -kNear || qx >= kNear || qy <= -kNear || qy >= kNear) return false;
    const int64_t dot = qx * bx + qy * by;
    if (dot <= 0) {
      if (u128_less(s2, sum_sq_u128(qx, qy))) return false;
    } else if (dot >= ab2) {
      if (u128_less(s2, sum_sq_u128(qx - bx, qy - by))) return false;
    } else {
      // The distance to the line is |cross| / |AB|: cross^2 <= s^2 |AB|^2
      // (|cross| < 2^61, s <= 2^30, |AB|^2 < 2^61).
      const int64_t cross = bx * qy - by * qx;
      if (u128_less(mul_wide_u64(static_cast<uint64_t>(s_nm * s_nm), static_cast<uint64_t>(ab2)), sq_u128(cross)))
        return false;
    }
  }
  return true;
}

}  // namespace

bool nurbs_weights_ok(const NurbsCurve& c) {
  int64_t lo = c.weight[0], hi = c.weight[0];
  for (int32_t i = 1; i < c.count; ++i) {
    lo = min_of(lo, c.weight[i]);
    hi = max_of(hi, c.weight[i]);
  }
  return lo > 0 && hi / lo < kNurbsMaxWeightRatio;
}

void nurbs_prepare(NurbsCurve* c) {
  int64_t hi = 0;
  for (int32_t i = 0; i < c->count; ++i) hi = max_of(hi, c->weight[i]);
  for (int32_t i = 0; i < c->count; ++i)
    c->weight[i] = muldiv_round(c->weight[i], static_cast<int64_t>(1) << kWeightBits, hi);
}

uint32_t nurbs_pieces(const NurbsCurve& c, int32_t span, int64_t sagitta_nm) {
  const int64_t s = clamp(sagitta_nm, int64_t{1}, static_cast<int64_t>(1) << 30);
  for (uint32_t log2m = 0;; ++log2m) {
    const uint32_t m = 1u << log2m;
    bool flat = true;
    for (uint32_t i = 0; flat && i < m; ++i) flat = piece_flat(c, span, param(span, i, log2m), param(span, i + 1, log2m), s);
    if (flat || log2m == kNurbsMaxPiecesLog2) return m;
  }
}

void nurbs_point(const NurbsCurve& c, int32_t span, uint32_t i, uint32_t m, int64_t* x_nm, int64_t* y_nm) {
  uint32_t log2m = 0;
  while ((1u << log2m) < m) ++log2m;
  if (span == nurbs_spans(c) - 1 && i == m) {  // the clamped end: the last control point itself
    *x_nm = c.x_nm[c.count - 1];
    *y_nm = c.y_nm[c.count - 1];
    return;
  }
  if (span == 0 && i == 0) {
    *x_nm = c.x_nm[0];
    *y_nm = c.y_nm[0];
    return;
  }
  int64_t u[kNurbsMaxOrder] = {};  // (zeroed: GCC 12 cannot see that order >= 3 fills it)
  // u = span + 1 belongs to the next span's formula as well; this span's
  // gives the same point (the curve is continuous).
  const int64_t at = param(span, i, log2m);
  for (int32_t r = 0; r < c.order - 1; ++r) u[r] = at;
  point_of(c, span, u, x_nm, y_nm);
}

}  // namespace dexmill
