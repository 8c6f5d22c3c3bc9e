// The sweep's internals (core/cut/sweep.h is its interface): the prepared
// piece, the chain's memos, the test switches, and the entry points with
// the column loops' word width and the switches as parameters. Only the
// sweep's own files (core/cut/sweep_*.cpp, core/cut/bull_flank.h) and the
// tests include it.
#ifndef DEXMILL_CORE_CUT_SWEEP_INTERNAL_H
#define DEXMILL_CORE_CUT_SWEEP_INTERNAL_H

#include <stdint.h>

#include <new>

#include "core/config.h"
#include "core/cut/stats.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/canon/canon.h"
#include "core/point.h"

namespace dexmill {

// The bull nose's w* for the last few (piece, |v|) of a chain
// (core/cut/bull_flank.h): a cache of a pure function of the tool, the
// piece's slope and |v|, so the bits are those of computing it. A chained
// piece along x meets the previous piece's w* on every row, at the same
// offsets (its collinear wedge), and finds it here. 128 slots (3 KB): the
// rows of two pieces of a tool some 60 rows wide. Only bull-nose pieces
// read and fill it.
//
// Which slot: with the grid's pitch known (row_inv_q32, set by the chain),
// slot 2 k + way for |v| in [k, k + 1) half pitches, way the piece's
// (SweepLine::bull_way, alternating along the chain). A row's |v| is a
// whole number of U, v0 + n p or (p - v0) + n p on the two sides of the
// track (v0 in [0, p)), one below half a pitch and one above: distinct
// rows, distinct slots (for tools up to 64 half pitches, 32 rows, in
// radius), and the last piece's w* on each row waits in the other way for
// the next piece's wedge (a lookup tries both ways: pieces often repeat the
// last one's slope). Without the pitch, a hash of |v| and the slope.
// Any slot may hold any key (it is checked): the choice only costs hits.
struct BullFlankMemo {
  static constexpr int kSlotBits = 7;
  struct Slot {
    int64_t m_q30, sin_q30;  // the piece's slope (SweepLine::m_geo_q30, ball_sin_q30)
    uint32_t v_plus1;        // |v| + 1, U (|v| <= R + 1 < 2^31); 0: empty
    int32_t w_u;             // w*, U, with its sign
  };
  Slot slot[1 << kSlotBits] = {};
  int64_t r_u = 0, rc_u = 0;  // the tool the slots hold (another empties them)
  uint64_t row_inv_q32 = 0;   // ceil(2^32 / half a pitch in U), or 0: hashed slots
  uint8_t next_way = 0;       // the next piece's way
};

// A straight piece prepared for sweeping (core/cut/sweep_piece.h,
// setup_piece; a SweepChain holds the last one).
struct SweepLine {
  int64_t len_u;             // horizontal length l, U
  int64_t ex_q30, ey_q30;    // unit direction e
  int64_t za_v, zb_v;        // tip heights above the grid's z0, V
  int64_t slope_v_q32;       // dz/ds in V per U, q32
  int64_t m_geo_q30;         // dz/ds, dimensionless, q30
  int64_t ball_sin_q30;      // ball: m / sqrt(1 + m^2)
  int64_t ball_k_q30;        // ball: sqrt(1 + m^2)
  int64_t vbit_c1_q30;       // V-bit: m / sqrt(k^2 - m^2), valid when vbit_inside
  bool vbit_inside;          // V-bit: |m| < k
  bool level;                // dz == 0
  bool plunge;               // no horizontal motion (or steeper than 2^24:1)
  uint8_t bull_way;          // bull nose in a chain (bull_memo set): its memo way (BullFlankMemo), 0 or 1
  BullFlankMemo* bull_memo = nullptr;  // bull nose in a chain: the chain's memo
};

// floor(sqrt(x)) for the last few x: a cache of a pure function, so the bits
// are those of computing it. The moves of one x-parallel stripe meet the same
// rows at the same cross offsets v, and each row's root rho(v) is the most
// expensive part of its set-up; the chain keeps one for its moves. 128
// slots (1.5 KB): a tool 30 rows wide meets 31 offsets, which 32 slots
// hashed into with about half of them colliding.
struct RootMemo {
  static constexpr int kSlotBits = 7;
  uint64_t key[1 << kSlotBits] = {};   // zeroes are true entries: sqrt(0) = 0
  uint32_t root[1 << kSlotBits] = {};
};

// What a SweepChain keeps of its moves besides where it ended
// (SweepChain::parts): the last piece, and the memos of its roots and of
// the bull nose's w*.
struct SweepChainParts {
  SweepLine last{};
  RootMemo roots;
  BullFlankMemo bull_memo;
};
static_assert(sizeof(SweepChainParts) <= kSweepChainPartsBytes && alignof(SweepChainParts) <= 8,
              "SweepChain::parts holds a SweepChainParts");

// The parts of chain c: an implicit-lifetime aggregate whose empty state is
// all zero bytes, what SweepChain::parts starts as.
inline SweepChainParts* chain_parts(SweepChain* c) { return std::launder(reinterpret_cast<SweepChainParts*>(c->parts)); }

// Switches of exact shortcuts, each giving the same bits as without it: the
// public entry points (core/cut/sweep.h) take every one (kSweepDefaults);
// tests turn one off to check exactly that.
struct SweepTuning {
  // Ball pieces in a general direction and level ball arcs leave out the
  // columns whose top is under every height they compute there
  // (core/cut/sweep_piece.h, ball_floor_of; core/cut/sweep_arc.cpp,
  // level_piece): no square roots for most of a pocket's columns.
  bool skip_under_floor = true;
  // Rows along x visit a collinear wedge (SweepChain) from the flank
  // outwards and stop at its edge (core/cut/sweep_piece.h) instead of
  // testing every column.
  bool wedge_stops = true;
  // Bull-nose chains keep their pieces' w* in row slots of their memo
  // (BullFlankMemo), so that the next piece finds the last one's on every
  // row, instead of the hashed slots (or no memo).
  bool bull_row_shortcuts = true;
  // Bull-nose ramps along x leave the rows at either end of their range
  // whose every top is at or under the least height the piece computes on
  // them (core/cut/sweep_piece.h, bull_row_above, bull_trim_rows): no
  // contact solve, no roots, the same visit counts too.
  bool bull_row_floor = true;
};
constexpr SweepTuning kSweepDefaults{};

// The entry points of core/cut/sweep.h with the switches k and the column
// loops in W-bit words (32 or 64; the program's is kSweepWordBits,
// core/config.h): the same bits for every W and k. Tests run both widths.
template <class H, int W>
void sweep_line_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& k, PointNm a, PointNm b, CutStats* st,
                  bool start_cap);
template <class H, int W>
void sweep_chain_line_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& k, PointNm a, PointNm b,
                        CutStats* st, SweepChain* c);
template <class H, int W>
void sweep_chain_end_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& k, CutStats* st, SweepChain* c);
template <class H, int W>
void sweep_arc_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& k, const CanonRecord& arc, CutStats* st,
                 bool start_cap);
template <class H, int W>
void sweep_chain_arc_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& k, const CanonRecord& arc,
                       CutStats* st, SweepChain* c);

#define DEXMILL_SWEEP_W_EXTERN(H, W)                                                                           \
  extern template void sweep_line_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, PointNm, PointNm, \
                                          CutStats*, bool);                                                      \
  extern template void sweep_chain_line_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, PointNm,    \
                                                PointNm, CutStats*, SweepChain*);                                \
  extern template void sweep_chain_end_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, CutStats*,   \
                                               SweepChain*);                                                     \
  extern template void sweep_arc_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, const CanonRecord&, \
                                         CutStats*, bool);                                                       \
  extern template void sweep_chain_arc_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&,             \
                                               const CanonRecord&, CutStats*, SweepChain*);
#define DEXMILL_SWEEP_W_EXTERN_BOTH(H) DEXMILL_SWEEP_W_EXTERN(H, 32) DEXMILL_SWEEP_W_EXTERN(H, 64)
DEXMILL_SWEEP_W_EXTERN_BOTH(uint8_t)
DEXMILL_SWEEP_W_EXTERN_BOTH(uint16_t)
DEXMILL_SWEEP_W_EXTERN_BOTH(uint32_t)
#undef DEXMILL_SWEEP_W_EXTERN_BOTH
#undef DEXMILL_SWEEP_W_EXTERN

}  // namespace dexmill

#endif
