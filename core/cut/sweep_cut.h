// The sweep's last step at one dexel, shared by lines and arcs: the lowest
// tool height in V (core/cut/sweep.h) rounded to an LSB and applied with the
// figure-2 cases (core/cut/stamp.h). Internal to the sweep.
#ifndef DEXMILL_CORE_CUT_SWEEP_CUT_H
#define DEXMILL_CORE_CUT_SWEEP_CUT_H

#include <stdint.h>

#include "core/cut/stamp.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"

namespace dexmill {

// r^2 (U^2) up to which a column counts as reached: 2 U (0.5 nm) beyond the
// rim, so that the rounding of derived coordinates never drops a column an
// exact test keeps (r <= R).
inline int64_t sweep_reach2(const SweepTool& t) { return t.r2_u + 4 * t.r_u + 4; }

// The dexels a tool may reach from anywhere in the box [x0, x1] x [y0, y1]
// (nm, of the tool axis): axes within its radius + 1 nm of the box, clipped
// to the grid. False when there are none.
struct SweepColumns {
  int64_t i_first, i_last, j_first, j_last;
};
template <class H>
inline bool sweep_columns(const DexelGrid<H>& g, const SweepTool& t, int64_t x0, int64_t x1, int64_t y0, int64_t y1,
                          SweepColumns* c) {
  const int64_t p = g.pitch_nm, r_nm = t.r_u / kSweepUnitsPerNm + 1;
  c->i_first = max_of<int64_t>(0, div_ceil(x0 - r_nm - g.x0_nm, p));
  c->i_last = min_of<int64_t>(g.nx - 1, div_floor(x1 + r_nm - g.x0_nm, p));
  c->j_first = max_of<int64_t>(0, div_ceil(y0 - r_nm - g.y0_nm, p));
  c->j_last = min_of<int64_t>(g.ny - 1, div_floor(y1 + r_nm - g.y0_nm, p));
  return c->i_first <= c->i_last && c->j_first <= c->j_last;
}

// z (nm) as V above the grid's z0, rounded to nearest, ties away from zero
// (muldiv_round's result): one inline division while the offset fits, which
// is always for clamped points (clamp_point: 2^46 nm) on a checked grid
// (|z0| <= 10^12 nm), the wide muldiv beyond.
template <class H>
inline int64_t sweep_height_v(const DexelGrid<H>& g, int64_t z_nm) {
  constexpr int64_t kFits = static_cast<int64_t>(1) << (62 - kSweepVBits);
  const int64_t dz = z_nm - g.z0_nm;
  if (dz > -kFits && dz < kFits) return div_round(dz * (static_cast<int64_t>(1) << kSweepVBits), g.lsb_nm);
  return muldiv_round(dz, static_cast<int64_t>(1) << kSweepVBits, g.lsb_nm);
}

// The least height in V that sweep_cut_dexel rounds to top_lsb or above:
// where the shaft is above every top (a min()), a tool at or above it leaves
// the dexel as it is. The floor tests of core/cut/sweep_piece.h and
// core/cut/sweep_arc.cpp compare with it.
inline int64_t sweep_keep_v(int64_t top_lsb) {
  return (top_lsb << kSweepVBits) - (static_cast<int64_t>(1) << (kSweepVBits - 1));
}

// round(acc / 2^30) (ties up) for acc = acc0, acc0 + d, acc0 + 2 d, ...: a
// column's along- or cross-track offset in U from its q30 accumulator, for
// walks whose every value read fits int32 (the caller's range argument).
// RoundWalk30Acc<int64_t> serves walks whose values may not fit. For those
// that do, two forms with the same values: a 64-bit accumulator, and for
// 32-bit CPUs (where a 64-bit add, round and shift is six instructions and
// two registers) the biased accumulator acc + 2^29 split into its whole part
// (mod 2^32: a value read fits, one past the last may wrap unread) and
// its 30-bit fraction kept in the top bits of a word, so that the fraction's
// carry is the add's own (adds, adc). The sweep's 32-bit column loops
// (core/cut/sweep_piece.h, general_row) take the split form on every CPU,
// so that a host's tests run what a 32-bit CPU does. Forced inline: -Os
// calls them otherwise, at twice their cost, once a column.
template <class I>
struct RoundWalk30Acc {
  int64_t acc = 0, d = 0;
  void start(int64_t acc0, int64_t step) {
    acc = acc0 + (static_cast<int64_t>(1) << 29);
    d = step;
  }
  __attribute__((always_inline)) I value() const { return static_cast<I>(acc >> 30); }
  __attribute__((always_inline)) void next() { acc += d; }
};
struct RoundWalk30Split {
  uint32_t whole = 0, frac = 0, dwhole = 0, dfrac = 0;  // value = whole + frac / 2^32
  void start(int64_t acc0, int64_t step) {
    const int64_t b = acc0 + (static_cast<int64_t>(1) << 29);
    whole = static_cast<uint32_t>(b >> 30);  // floor, mod 2^32
    frac = static_cast<uint32_t>(b) << 2;    // b mod 2^30, times 4
    dwhole = static_cast<uint32_t>(step >> 30);
    dfrac = static_cast<uint32_t>(step) << 2;
  }
  __attribute__((always_inline)) int32_t value() const { return static_cast<int32_t>(whole); }
  __attribute__((always_inline)) void next() {
    const uint32_t f = frac + dfrac;
    whole += dwhole + (f < frac ? 1u : 0u);  // the fractions' carry
    frac = f;
  }
};

// Applies the lowest tool height h_v (V above z0) at one dexel; ct_lsb is the
// shaft top, shaft_above when it is above every possible top (then only
// cases a, b and e remain). Returns true when the dexel changed.
template <class H>
inline bool sweep_cut_dexel(DexelGrid<H>* g, H* wt, H* wb, int64_t h_v, int64_t ct_lsb, bool shaft_above) {
  const int64_t cb = (h_v + (static_cast<int64_t>(1) << (kSweepVBits - 1))) >> kSweepVBits;
  if (shaft_above) {
    if (cb >= static_cast<int64_t>(*wt)) return false;
    if (cb > static_cast<int64_t>(*wb)) {
      *wt = static_cast<H>(cb);  // case b
    } else {
      *wt = 0;  // case e
      *wb = 0;
    }
    return true;
  }
  const CutCase c = apply_cut<H, int64_t>(wt, wb, cb, ct_lsb);
  if (c == CutCase::kC) g->bottoms_zero = false;
  return cut_changed(c);
}

}  // namespace dexmill

#endif
