// Cutting by instances of motion, paper §2.3: the cutter dexel set is placed
// at evenly spaced points along a move and intersected with the workpiece at
// each, matching every cutter dexel with the nearest workpiece dexel.
#ifndef DEXMILL_CORE_CUT_STAMP_H
#define DEXMILL_CORE_CUT_STAMP_H

#include <stdint.h>

#include "core/cut/stats.h"
#include "core/grid/grid.h"
#include "core/point.h"
#include "core/tool/cutter.h"

namespace dexmill {

// What one cutter dexel c does to one workpiece dexel w (figure 2).
enum class CutCase : uint8_t {
  kA = 0,  // no overlap (w.top <= c.bottom, or c above/below w): nothing
  kB = 1,  // c.bottom inside w, c.top at or above w.top: w.top = c.bottom
  kC = 2,  // c.top inside w, c.bottom at or below w.bottom: w.bottom = c.top
  kD = 3,  // c strictly inside w: would split w; impossible in 3 axes, ignored
  kE = 4,  // c covers w: w becomes a hole, top = bottom = 0
};

// The figure-2 classification, with ties resolved so that a dexel never
// keeps zero thickness unless it becomes a hole:
//   a: cb >= wt or ct <= wb      b: wb < cb < wt <= ct
//   c: cb <= wb < ct < wt        d: wb < cb and ct < wt
//   e: cb <= wb and wt <= ct
template <class W>
inline CutCase classify_cut(W wt, W wb, W cb, W ct) {
  if (cb >= wt || ct <= wb) return CutCase::kA;
  if (cb <= wb) return ct >= wt ? CutCase::kE : CutCase::kC;
  return ct >= wt ? CutCase::kB : CutCase::kD;
}

// Applies one case to w and returns it (w changed for b, c and e). cb and
// ct may lie outside [0, 2^m - 1]: the comparisons then still pick the right
// case and only in-range values are ever stored.
template <class H, class W>
inline CutCase apply_cut(H* wt, H* wb, W cb, W ct) {
  const CutCase c = classify_cut<W>(*wt, *wb, cb, ct);
  switch (c) {
    case CutCase::kB: *wt = static_cast<H>(cb); break;
    case CutCase::kC: *wb = static_cast<H>(ct); break;
    case CutCase::kE: *wt = 0; *wb = 0; break;
    default: break;
  }
  return c;
}
inline bool cut_changed(CutCase c) { return c == CutCase::kB || c == CutCase::kC || c == CutCase::kE; }

// One instance of motion: the cutter's axis on workpiece dexel (ci, cj)
// (may be outside the grid), its tip at height tip_lsb (any int64). Only
// dexels inside the grid are touched; the dirty rectangle grows by the
// footprint when anything changed.
template <class H>
void stamp_instance(DexelGrid<H>* g, const CutterDexels& c, int64_t ci, int64_t cj, int64_t tip_lsb, CutStats* st);

// A straight move from `a` to `b` (tool tip, machine nm): instances at
// p_k = a + (b - a) * k / n, k = 0..n, with n = max(ceil(|dx| / pitch),
// ceil(|dy| / pitch), 1) so that consecutive instances are at most one
// pitch apart in x and y and no dexel is skipped (a plunge gives its two
// ends; a move of zero length one instance). Instances whose cutter
// cannot reach the grid are not computed (nor counted), so a move far
// outside the grid costs O(1). With include_start = false the instance at
// k = 0 is left out: a move that continues from the previous one's end does
// not stamp that point twice.
template <class H>
void stamp_line(DexelGrid<H>* g, const CutterDexels& c, PointNm a, PointNm b, CutStats* st, bool include_start = true);

#define DEXMILL_STAMP_EXTERN(H)                                                                          \
  extern template void stamp_instance<H>(DexelGrid<H>*, const CutterDexels&, int64_t, int64_t, int64_t, \
                                         CutStats*);                                                     \
  extern template void stamp_line<H>(DexelGrid<H>*, const CutterDexels&, PointNm, PointNm, CutStats*, bool);
DEXMILL_STAMP_EXTERN(uint8_t)
DEXMILL_STAMP_EXTERN(uint16_t)
DEXMILL_STAMP_EXTERN(uint32_t)
#undef DEXMILL_STAMP_EXTERN

}  // namespace dexmill

#endif
