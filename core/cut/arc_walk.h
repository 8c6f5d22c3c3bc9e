// The chords of an arc that can reach a region, in order, skipping the rest
// without generating them: a long arc (thousands of turns of a large radius,
// legal G-code) passing by a small grid costs work for the part near the grid
// only. Depth-first halving of the sweep: a stretch whose bounding box (its
// end points, widened by its bulge) misses the region is dropped whole; a
// reachable stretch of at most 64 chords is cut into equal chords of the
// angle core/canon/arc_chords.h would use. No heap, and small enough for a
// microcontroller's stack: 52 stretches of two angles (832 bytes; the
// halving depth is at most 47 for 10 000 turns), end points recomputed.
#ifndef DEXMILL_CORE_CUT_ARC_WALK_H
#define DEXMILL_CORE_CUT_ARC_WALK_H

#include <stdint.h>

#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/canon/arc_chords.h"
#include "core/canon/canon.h"

namespace dexmill {

// A rectangle of machine x and y, nm, inclusive.
struct RectNm {
  int64_t x0, y0, x1, y1;
};

// Calls chord(from, to) for every chord of sagitta <= sagitta_nm (plus the
// 2 nm + 6e-9 r of core/canon/arc_chords.h) that can reach `reach`, in path order.
template <class F>
void arc_walk(const CanonRecord& arc, int64_t sagitta_nm, const RectNm& reach, F chord) {
  ArcChords geo;
  geo.init(arc, INT64_MAX / 4);  // geometry only; point_at() gives any point
  const int64_t sweep = geo.sweep_bam();
  const uint64_t total = static_cast<uint64_t>(sweep < 0 ? -sweep : sweep);
  const int64_t rmax = geo.radius_max();
  ArcChords fine;
  fine.init(arc, sagitta_nm);
  const uint64_t theta = (total + fine.count() - 1) / fine.count();  // chord angle, >= 1
  struct Stretch {
    uint64_t t0, t1;
  };
  Stretch stack[52];
  int sp = 0;
  stack[sp++] = Stretch{0, total};
  while (sp > 0) {
    const Stretch st = stack[--sp];
    struct {
      uint64_t t0, t1;
      PointNm p0, p1;
    } s{st.t0, st.t1, st.t0 == 0 ? arc.start : geo.point_at(st.t0), geo.point_at(st.t1)};
    const uint64_t span = s.t1 - s.t0;
    // How far the curve leaves the chord p0-p1: r (1 - cos(span / 2)) below
    // half a turn (plus a margin for CORDIC), else anything up to 2r.
    int64_t bulge = 2 * rmax;
    if (span < (static_cast<uint64_t>(1) << 31)) {
      const SinCosQ30 sc = sincos_bam(static_cast<uint32_t>(span / 2));
      bulge = mul_shift(rmax, (static_cast<int64_t>(1) << 30) - sc.cos_q30 + 4, 30) + 2;
    }
    const bool leaf = span <= 64 * theta || sp >= 50;
    const int64_t xl = min_of(s.p0.x_nm, s.p1.x_nm) - bulge, xh = max_of(s.p0.x_nm, s.p1.x_nm) + bulge;
    const int64_t yl = min_of(s.p0.y_nm, s.p1.y_nm) - bulge, yh = max_of(s.p0.y_nm, s.p1.y_nm) + bulge;
    if (xh < reach.x0 || xl > reach.x1 || yh < reach.y0 || yl > reach.y1) continue;
    if (leaf) {
      const uint64_t k = span ? (span + theta - 1) / theta : 1;
      PointNm from = s.p0;
      for (uint64_t i = 1; i <= k; ++i) {
        const PointNm to = i == k ? s.p1 : geo.point_at(s.t0 + span * i / k);
        chord(from, to);
        from = to;
      }
      continue;
    }
    const uint64_t tm = s.t0 + span / 2;
    stack[sp++] = Stretch{tm, s.t1};  // the later half waits
    stack[sp++] = Stretch{s.t0, tm};
  }
}

}  // namespace dexmill

#endif
