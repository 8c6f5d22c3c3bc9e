// LinuxCNC's G5.2/G5.3 NURBS in the XY plane, as chords of bounded sagitta.
//
// The curve (LinuxCNC 2.9: interp_convert.cc convert_nurbs, its knot vector
// nurbs_G5_knot_vector_creator): control points P0..Pn, P0 the point where
// G5.2 began, weights w (P words), order k (L, at least 3): a rational
// B-spline of degree k - 1 on the clamped integer knot vector
// 0 (k times), 1, 2, ..., n - k + 1, n - k + 2 (k times), so u runs over
// [0, n - k + 2] and span s is u in [s, s + 1]. The machine follows it by
// biarcs through 4 points per control point (emccanon.cc NURBS_FEED) and
// LinuxCNC's preview by 15 chords per control point; dexmill follows the
// curve itself.
//
// Integer only. de Boor's algorithm with a parameter per level (which gives
// the blossom, so also each piece's Bezier points), parameters in q48, is
// run on the basis: each control point's coefficient (q48), then its
// rational share b_i w_i / sum b_j w_j (q62) weighs the points relative to
// P0. Weights are ratios to the largest, in q40 (so at least 2^28).
//
// Chords: each span is cut into m = 2^j pieces of equal parameter step, the
// least m for which every piece passes the hull test: the piece's rational
// Bezier points (positive weights), projected, lie within the sagitta s of
// the chord between its ends. The curve lies in the convex hull of those
// points, so the whole piece is within s of its chord (a bound, not a
// sample). Each point is within 2 nm of the exact curve (plus the weights'
// rounding: at most 2^-29 times the control points' spread, 64 nm for 18 m
// with weights 4096 apart; 0.01 nm for 1 m and weights within 16), so the
// polyline is within s + 3 nm of the curve (tests/test_nurbs.cpp checks both against a
// double oracle). The first chord starts at P0, the last ends at Pn exactly.
//
// Limits: 64 control points, order 10, weights within a ratio of 4096 of
// one another (their product with a coordinate must fit; a larger ratio is
// an error, not a loss of precision), at most 65536 chords a span.
#ifndef DEXMILL_CORE_INTERP_NURBS_H
#define DEXMILL_CORE_INTERP_NURBS_H

#include <stdint.h>

namespace dexmill {

constexpr int32_t kNurbsMaxPoints = 64;
constexpr int32_t kNurbsMaxOrder = 10;
constexpr int64_t kNurbsMaxWeightRatio = 4096;
constexpr uint32_t kNurbsMaxPiecesLog2 = 16;

struct NurbsCurve {
  int32_t count;  // control points so far (P0 included)
  int32_t order;  // k
  int64_t x_nm[kNurbsMaxPoints], y_nm[kNurbsMaxPoints];
  int64_t weight[kNurbsMaxPoints];  // P in 1e-9 while collected; q24 of the largest after nurbs_prepare
};

// True when the weights (1e-9, all positive) are within kNurbsMaxWeightRatio.
bool nurbs_weights_ok(const NurbsCurve& c);
// Weights to q24 ratios of the largest (call once, after nurbs_weights_ok).
void nurbs_prepare(NurbsCurve* c);
// Spans: n - k + 2 (n + 1 = count).
inline int32_t nurbs_spans(const NurbsCurve& c) { return c.count - c.order + 1; }
// Pieces of span s for sagitta s_nm (>= 1; a power of two; at most 2^16).
uint32_t nurbs_pieces(const NurbsCurve& c, int32_t span, int64_t sagitta_nm);
// The curve at u = span + i / m (m a power of two), to the nearest nm.
void nurbs_point(const NurbsCurve& c, int32_t span, uint32_t i, uint32_t m, int64_t* x_nm, int64_t* y_nm);

}  // namespace dexmill

#endif
