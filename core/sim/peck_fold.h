// One line's vertical moves at one X and Y, held and cut as one plunge: a
// peck cycle (G73, G83) of a million pecks is then one cut instead of a
// million (`dexmill bench worst-g83`: 32 s before, each peck re-cutting the whole
// footprint to go 11 nm deeper).
//
// Why the grid is the same to the last bit: a vertical move's cut lowers
// each dexel to the tool standing at the move's lowest point (a cutter's
// radius never shrinks upwards, so higher positions lie inside it; the
// cut's integer heights are monotone in the tip's height), and successive
// cuts keep the lowest of them. So any run of vertical moves that joins up
// into one span [lo, hi] of Z at that X and Y cuts what one move down to lo
// cuts, in whatever order and however many (tests/test_peck_fold.cpp
// compares the two for every tool shape and both cut modes).
//
// What may watch the fold: the line's removals are charged to that line
// either way (provenance, core/sim/provenance.h), and the time, travel and
// status still see every record. Watchers that judge each move by what it
// removed (safety, process rules, engagement, gouge events) see the moves
// one by one, so the engine folds only when they are off
// (core/sim/simulation_impl.h, SimulationT::fold_on_).
#ifndef DEXMILL_CORE_SIM_PECK_FOLD_H
#define DEXMILL_CORE_SIM_PECK_FOLD_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/math/fixed.h"
#include "core/point.h"

namespace dexmill {

struct PeckFold {
  bool active = false;
  uint32_t line = 0;
  PointNm start{0, 0, 0};         // where the first held move began (the cut's position then)
  PointNm at{0, 0, 0};            // where the last held move ended
  int64_t lo_nm = 0, hi_nm = 0;   // the span of Z the held moves swept
};

// A straight move with no X or Y motion.
inline bool peck_fold_vertical(const CanonRecord& r) {
  return (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed) && r.start.x_nm == r.end.x_nm &&
         r.start.y_nm == r.end.y_nm;
}

inline void peck_fold_span(PeckFold* f, const CanonRecord& r) {
  f->lo_nm = min_of(f->lo_nm, min_of(r.start.z_nm, r.end.z_nm));
  f->hi_nm = max_of(f->hi_nm, max_of(r.start.z_nm, r.end.z_nm));
  f->at = r.end;
}

// Starts holding r if it is a vertical move from where the cut stands.
inline bool peck_fold_begin(PeckFold* f, const CanonRecord& r, const PointNm& cut_at) {
  if (!peck_fold_vertical(r) || !(r.start == cut_at)) return false;
  f->active = true;
  f->line = r.line;
  f->start = r.start;
  f->lo_nm = f->hi_nm = r.start.z_nm;
  peck_fold_span(f, r);
  return true;
}

// Holds r too if it is the same line's vertical move on from the last one
// (then the span stays one interval: r starts inside it).
inline bool peck_fold_add(PeckFold* f, const CanonRecord& r) {
  if (!f->active || r.line != f->line || !peck_fold_vertical(r) || !(r.start == f->at)) return false;
  peck_fold_span(f, r);
  return true;
}

// The moves that cut what the held ones cut, to end where they ended: down
// from the start to the span's bottom, up to its top, back to the end (the
// cut skips the ones its covered span already holds, core/cut/mill.h).
inline int peck_fold_moves(const PeckFold& f, CanonRecord out[3]) {
  const PointNm lo{f.start.x_nm, f.start.y_nm, f.lo_nm}, hi{f.start.x_nm, f.start.y_nm, f.hi_nm};
  const PointNm via[4] = {f.start, lo, hi, f.at};
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    if (via[k] == via[k + 1]) continue;
    CanonRecord r{};
    r.kind = CanonKind::kFeed;
    r.line = f.line;
    r.start = via[k];
    r.end = via[k + 1];
    out[n++] = r;
  }
  return n;
}

}  // namespace dexmill

#endif
