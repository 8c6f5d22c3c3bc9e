// Counters of a cutting run, and an optional log of the dexel spans it
// visited (the benchmark replays the log to time the lower bound: the same
// dexels in the same order with only a min() of a constant).
#ifndef DEXMILL_CORE_CUT_STATS_H
#define DEXMILL_CORE_CUT_STATS_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

// One visited run of dexels: row j, columns [i0, i1] inclusive.
struct DexelSpan {
  int32_t j, i0, i1;
};

// Caller memory for spans; when full, further spans are counted in `dropped`
// (reported, never silently lost).
struct SpanLog {
  DexelSpan* spans = nullptr;
  size_t capacity = 0;
  size_t count = 0;
  uint64_t dropped = 0;

  void add(int32_t j, int32_t i0, int32_t i1) {
    if (count < capacity) spans[count++] = DexelSpan{j, i0, i1};
    else ++dropped;
  }
};

struct CutStats {
  uint64_t instances = 0;      // cutter placements (stamp) or swept pieces (sweep)
  uint64_t dexel_updates = 0;  // workpiece dexels visited by the cutting loop
  uint64_t floor_skips = 0;    // sweep: of those, left at a test of the ball's floor (no root)
  uint64_t row_skips = 0;      // sweep: bull-nose rows left at a test of their floor (bull_row_above)
  SpanLog* log = nullptr;      // optional
};

}  // namespace dexmill

#endif
