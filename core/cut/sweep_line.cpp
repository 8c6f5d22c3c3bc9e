// Swept envelope of a straight move (core/cut/sweep.h): its entry points,
// with the column loops in the program's word width (core/config.h,
// kSweepWordBits) and every shortcut on. The piece set-up and the row
// kernels are core/cut/sweep_piece.h; the other width is
// core/cut/sweep_line_w.cpp (one width a file: GCC's inlining, which is
// bounded by a file's growth, then treats each as it would alone).
#include "core/config.h"
#include "core/cut/sweep.h"
#include "core/cut/sweep_internal.h"
#include "core/cut/sweep_piece.h"

namespace dexmill {

template <class H>
void sweep_line(DexelGrid<H>* g, const SweepTool& t, PointNm a, PointNm b, CutStats* st, bool start_cap) {
  sweep_line_w<H, kSweepWordBits>(g, t, kSweepDefaults, a, b, st, start_cap);
}

template <class H>
void sweep_chain_end(DexelGrid<H>* g, const SweepTool& t, CutStats* st, SweepChain* c) {
  sweep_chain_end_w<H, kSweepWordBits>(g, t, kSweepDefaults, st, c);
}

template <class H>
void sweep_chain_line(DexelGrid<H>* g, const SweepTool& t, PointNm a, PointNm b, CutStats* st, SweepChain* c) {
  sweep_chain_line_w<H, kSweepWordBits>(g, t, kSweepDefaults, a, b, st, c);
}

DEXMILL_SWEEP_LINE_W_INSTANTIATE_ALL(kSweepWordBits)

#define DEXMILL_SWEEP_INSTANTIATE(H)                                                                             \
  template void sweep_line<H>(DexelGrid<H>*, const SweepTool&, PointNm, PointNm, CutStats*, bool);              \
  template void sweep_chain_line<H>(DexelGrid<H>*, const SweepTool&, PointNm, PointNm, CutStats*, SweepChain*); \
  template void sweep_chain_end<H>(DexelGrid<H>*, const SweepTool&, CutStats*, SweepChain*);
DEXMILL_SWEEP_INSTANTIATE(uint8_t)
DEXMILL_SWEEP_INSTANTIATE(uint16_t)
DEXMILL_SWEEP_INSTANTIATE(uint32_t)

}  // namespace dexmill
