// Exact swept-envelope cutting: past the paper's instances of motion (§2.3).
//
// For every dexel column within reach of a move, the lowest point of the
// tool anywhere along the move is found in closed form and applied once, with
// the figure-2 cases (core/cut/stamp.h). No scallops between instances, and each
// dexel is touched once per move (or per piece of a long move or an arc).
//
// Working units: horizontal lengths in U = 1/4 nm (so tool radii up to 2^28
// nm square within int64), heights in V = lsb / 256 of the grid. A column's
// height is rounded to the nearest LSB at the end.
//
// Ranges (every product of the sweep is bounded from these, and
// each file states the worst case of its own; tests/test_ranges.cpp runs
// their corners under UBSan with the checked helpers of core/config.h):
//   tool (core/tool/tool.h, and here):  R <= 2^28 nm, so R <= 2^30 U, R^2 <=
//     2^60 U^2, reach2 = (R + 2)^2 < 2^61; rc <= R; a V-bit's slope k =
//     cot(a/2) < 2^7 (cot_q30 < 2^37) and its profile k r <= 10 m < 2^36 U;
//     the stick-out <= 10 m, len_v < 2^42 V for lsb >= 1 nm;
//   grid (core/grid/grid.h): lsb in [1 nm, 2^30 nm] (checked here), so V per U
//     = 64 / lsb and v_per_u_q32 in [2^8, 2^38]; pitch <= 1 m < 2^30 nm (2^32
//     U); indices < 2^16; origins within 1 km; tops <= 2^32 - 1 LSB (2^40 V);
//   points: clamped to 2^46 nm (clamp_point), so a tip height above z0 is
//     within 2^46 + 2^40 nm, |z_v| < 2^55 V;
//   pieces (core/cut/sweep_piece.h): at most 2^27 nm = 2^29 U long
//     horizontally, and no steeper than 2^24:1 (else a plunge), so a slope
//     is below 2^24 (m_geo_q30 < 2^54) and 2^24 * 64 / lsb <= 2^30 V per U
//     (slope_v_q32 < 2^62), and a piece's whole rise is under 2^55 V;
//   columns: within R + 1 nm of a piece's box, so their offsets from its
//     ends are below l + R + 4 U < 2^31 U (a wedge's least u: -(4 R + 18)).
// Heights far outside the grid (beyond 2^43 V, 2^35 LSB, where only a
// 2^-16 V fixed-point run would overflow) are cut column by column from
// their exact values, which give the same bits.
//
// Error bound (tests/test_sweep.cpp checks it against a dense double-precision
// oracle): the height written is within 1 LSB of the exact lowest point of the
// tool over the move for a column displaced by at most 1 nm horizontally (a
// backward bound: where the tool's side is vertical, at r = R, the height is
// infinitely sensitive to position, and no finite forward bound exists).
//
// The shaft: where it is below some top, figure 2 needs each column's whole
// interval, [lowest point, shaft top of the highest position over the
// column]: the union of the tool's intervals over a piece, which is one
// interval because the positions over a column are one run of the piece.
// Pieces (a move's, an arc's quarter turns or chords) are applied one after
// another, as stamping applies instances: a piece whose tool sits inside a
// dexel with material above and below it (case d) leaves that dexel whole,
// so a later piece's cut does not reach above it. Only a tool deeper in the
// material than its own length meets this, and no single dexel per column
// can hold what it leaves.
#ifndef DEXMILL_CORE_CUT_SWEEP_H
#define DEXMILL_CORE_CUT_SWEEP_H

#include <stddef.h>
#include <stdint.h>

#include "core/cut/stats.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "core/canon/canon.h"
#include "core/point.h"
#include "core/status.h"
#include "core/tool/tool.h"

namespace dexmill {

constexpr int64_t kSweepUnitsPerNm = 4;  // U per nm
constexpr int kSweepVBits = 8;           // V = LSB / 2^8

// A tool prepared for sweeping on grids with a given LSB.
struct SweepTool {
  ToolKind kind;
  int64_t r_u, r2_u;       // R in U, R^2 in U^2
  int64_t a_u, rc_u;       // bull nose: flat radius a = R - rc, corner radius rc
  int64_t rc2_u;           // rc^2
  // Bull nose on ramps (core/cut/bull_flank.h): a / R, rc / R and the
  // quartic's tool-only coefficients (rc / R)^2, 2 a rc / R^2, (a / R)^2,
  // each q52.
  int64_t bull_a_q52, bull_rc_q52, bull_rc2_q52, bull_2arc_q52, bull_a2_q52;
  int64_t bull_inv_r_q62;  // floor(2^62 / R), R in U
  int64_t cot_q30;         // V-bit: k = cot(a/2), the profile's slope dh/dr
  int64_t len_v;           // shaft top above the tip, V
  int64_t v_per_u_q32;     // U -> V: 2^32 * U / V = 2^(32+8) / (4 * lsb)
  int64_t u_per_v_q30;     // V -> U: 2^30 * V / U, rounded up
  // Ball: the paraboloid r^2 / (2R) under the sphere in V, rounded down, as
  // ((r^2 >> bowl_pre) * bowl_q) >> bowl_post: a 32 x 32-bit product.
  uint32_t bowl_q;
  int bowl_pre, bowl_post;
  int64_t lsb_nm;          // the LSB this was prepared for
};

// Fails with kBadArgument when R exceeds 2^28 nm (268.435456 mm: a diameter
// of 536.87 mm) or lsb is outside [1, 2^30] nm: the sweep's ranges above.
Status sweep_tool_prepare(const ToolProfile& p, int64_t lsb_nm, SweepTool* out);

// Height of the tool's lower surface above its tip at r^2 (U^2, r <= R), V.
// Inline: it is the inner loop of every sweep.
inline int64_t sweep_profile_v(const SweepTool& t, int64_t r2) {
  int64_t f_u = 0;
  switch (t.kind) {
    case ToolKind::kFlat:
      return 0;
    case ToolKind::kBall:  // R - sqrt(R^2 - r^2)
      f_u = t.r_u - static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(t.r2_u - r2)));
      break;
    case ToolKind::kBullNose: {  // flat to a, then the torus of radius rc
      // floor(sqrt(r2)) <= a exactly when r2 < (a + 1)^2: the flat needs no root.
      if (r2 < (t.a_u + 1) * (t.a_u + 1)) return 0;
      const int64_t r = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(r2)));
      const int64_t d = min_of(r - t.a_u, t.rc_u);
      f_u = t.rc_u - static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(t.rc2_u - d * d)));
      break;
    }
    case ToolKind::kVBit:  // k * r
      f_u = mul_shift_fit(static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(r2))), t.cot_q30, 30);
      break;
  }
  // f_u <= 2^36 U (the profile's height, at most the stick-out's 10 m; and k
  // < 2^7 with r <= 2^30 U), v_per_u_q32 <= 2^38: below 2^42 V after the
  // shift. Ball and bull: f_u <= R <= 2^30 U.
  return mul_shift_fit(f_u, t.v_per_u_q32, 32);
}

// The ball's paraboloid r2 / (2R) in V (r2 <= R^2 in U^2), rounded down.
inline int64_t sweep_bowl_v(const SweepTool& t, int64_t r2) {
  const uint64_t r2_hi = static_cast<uint64_t>(r2) >> t.bowl_pre;  // < 2^32
  return static_cast<int64_t>((static_cast<uint64_t>(static_cast<uint32_t>(r2_hi)) * t.bowl_q) >> t.bowl_post);
}

// A straight move of the tool tip from a to b (any direction: lines, ramps,
// plunges). Moves longer than 2^27 nm are cut as consecutive pieces.
//
// start_cap = false leaves out the columns where the lowest point is the
// tool standing at a (behind the move's start). Pass it when the previous
// move, cut with the same tool, ended at a: its sweep holds the whole tool
// at a already (every column of it is either in that move's sweep at the
// tool's own height or lower), so the union is unchanged and the work at
// polyline joints is done once.
template <class H>
void sweep_line(DexelGrid<H>* g, const SweepTool& t, PointNm a, PointNm b, CutStats* st, bool start_cap = true);

// The size of SweepChain::parts (below).
constexpr size_t kSweepChainPartsBytes = 4736;

// A polyline of straight moves cut with one tool, move by move.
//
// Why: for one move, a column's lowest point is either inside the move (its
// band) or the tool standing at an end (a cap). Along a polyline of short
// moves the caps are most of the work (a 0.3 mm move of a 3 mm ball: the
// band is 30x3 dexels, each cap a half disc of 350). But the union of the
// moves' sweeps needs the tool standing at an inner vertex B only on the
// columns where both moves meeting at B have their lowest point at B: where
// one of them has it inside, its band is at least as low (it includes B);
// where the next has it at its own far end, that cap is lower still. So a
// chained move cuts its band, its start cap only on that wedge (tested in
// the previous move's frame), and leaves its end cap pending until the next
// move or sweep_chain_end. The result is the same union as move-by-move
// sweep_line with full caps.
//
// Error: where a band and a cap round apart, the chain's top is within 1
// LSB of the exact sweep plus, at an LSB of a nanometre or two, a few nm on
// moves a tenth of a millimetre long: 2 nm measured for an arc's 1 um chords
// at 1 nm (tests/test_sweep_chain_arcs.cpp); the same chords given as G1
// lines were seen 12 nm out. At 16-bit heights' LSBs (0.1 um and up) within
// 1 LSB (tests/test_sweep_chain.cpp).
//
// Only moves whose shaft reaches above every top are chained (their cut is
// then a min() per column, so leaving out dominated heights changes
// nothing); others cut their caps at once. Call sweep_chain_end before
// reading the grid, before changing the tool, and at the end.
struct SweepChain {
  enum class State : uint8_t {
    kFresh,    // no move before: cut the whole start cap
    kCovered,  // the tool at `end` is cut already: skip the start cap
    kPending,  // the end cap of the last piece at `end` is pending
  };
  State state = State::kFresh;
  PointNm end{0, 0, 0};
  // The last piece and the chain's memos (SweepChainParts, internal to the
  // sweep: core/cut/sweep_internal.h), held here so that a chain needs no
  // heap; zero bytes are their empty state. kSweepChainPartsBytes is their
  // size with 64-bit pointers, and sweep_internal.h checks that they fit.
  alignas(8) unsigned char parts[kSweepChainPartsBytes] = {};
};

// Cuts a -> b as the next move of chain c (a move that does not start at
// c->end first ends the chain).
template <class H>
void sweep_chain_line(DexelGrid<H>* g, const SweepTool& t, PointNm a, PointNm b, CutStats* st, SweepChain* c);
// Cuts the pending end cap, if any; the chain stays joined at c->end.
template <class H>
void sweep_chain_end(DexelGrid<H>* g, const SweepTool& t, CutStats* st, SweepChain* c);
// Cuts an arc (sweep_arc) as the next move of chain c. An exact arc cuts
// both its caps: the pending line cap goes first, and the arc's start cap
// only when nothing ended at its start; the chain goes on covered at the
// arc's end. A chorded arc (sweep_arc_exact false) puts its chords on the
// chain as straight moves, its end cap pending.
template <class H>
void sweep_chain_arc(DexelGrid<H>* g, const SweepTool& t, const CanonRecord& arc, CutStats* st, SweepChain* c);

// An arc or helix (a kArc record). Exact per column for level XY arcs with a
// ball or flat end and radius <= 2^27 nm; otherwise chords of sagitta <=
// kArcChordSagittaNm, each swept exactly (see core/cut/sweep_arc.cpp).
// start_cap as for sweep_line.
template <class H>
void sweep_arc(DexelGrid<H>* g, const SweepTool& t, const CanonRecord& arc, CutStats* st, bool start_cap = true);

// Whether sweep_arc cuts an arc of at most one turn exactly per column (a
// level XY arc, or a helix about Z no tighter than the tool, with a ball or
// flat end), else as chords of sagitta <= kArcChordSagittaNm.
bool sweep_arc_exact(const SweepTool& t, const CanonRecord& arc);

#define DEXMILL_SWEEP_EXTERN(H)                                                                             \
  extern template void sweep_line<H>(DexelGrid<H>*, const SweepTool&, PointNm, PointNm, CutStats*, bool); \
  extern template void sweep_arc<H>(DexelGrid<H>*, const SweepTool&, const CanonRecord&, CutStats*, bool); \
  extern template void sweep_chain_line<H>(DexelGrid<H>*, const SweepTool&, PointNm, PointNm, CutStats*,    \
                                           SweepChain*);                                                     \
  extern template void sweep_chain_end<H>(DexelGrid<H>*, const SweepTool&, CutStats*, SweepChain*);          \
  extern template void sweep_chain_arc<H>(DexelGrid<H>*, const SweepTool&, const CanonRecord&, CutStats*,  \
                                          SweepChain*);
DEXMILL_SWEEP_EXTERN(uint8_t)
DEXMILL_SWEEP_EXTERN(uint16_t)
DEXMILL_SWEEP_EXTERN(uint32_t)
#undef DEXMILL_SWEEP_EXTERN

}  // namespace dexmill

#endif
