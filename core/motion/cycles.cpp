// Canned-cycle moves; see cycles.h. The order of moves follows
// LinuxCNC's CYCLE_MACRO: the first repeat positions at the current level and
// goes down to R; later repeats position at the clearance level.
#include "core/motion/cycles.h"

#include "core/motion/arc_chords.h"

namespace dexmill {

int64_t cycle_peck_count(int64_t r_c, int64_t bottom_c, int64_t q_nm) {
  // Depths r - q, r - 2q, ... while still above the bottom.
  if (r_c - bottom_c <= q_nm) return 0;
  return (r_c - bottom_c - 1) / q_nm;
}

namespace {

void hole(const CyclePlan& p, int64_t a, int64_t b, CycleOut* out) {
  auto at = [&](int64_t c) { return plane_point(p.plane, a, b, c); };
  switch (p.code) {
    case 810:  // drill: feed down, rapid out
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->move(CanonKind::kTraverse, at(p.clear_c));
      break;
    case 820:  // drill with dwell
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->dwell(p.dwell_ms);
      out->move(CanonKind::kTraverse, at(p.clear_c));
      break;
    case 830:  // peck drill: back out to R after each peck
    case 730: {  // chip break: back off a little after each peck
      int64_t depth = p.r_c - p.q_nm;
      for (; depth > p.bottom_c; depth -= p.q_nm) {
        out->move(CanonKind::kFeed, at(depth));
        if (p.code == 830) out->move(CanonKind::kTraverse, at(p.r_c));
        out->move(CanonKind::kTraverse, at(depth + kPeckBackoffNm));
      }
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->move(CanonKind::kTraverse, at(p.clear_c));
      break;
    }
    case 850:  // bore: feed in, feed out to R
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->move(CanonKind::kFeed, at(p.r_c));
      out->move(CanonKind::kTraverse, at(p.clear_c));
      break;
    case 890:  // bore with dwell: feed in, dwell, feed out to the clearance level
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->dwell(p.dwell_ms);
      out->move(CanonKind::kFeed, at(p.clear_c));
      break;
    default:
      break;
  }
}

}  // namespace

void cycle_emit(const CyclePlan& p, CycleOut* out) {
  if (p.raise_first) out->move(CanonKind::kTraverse, plane_point(p.plane, p.start_a, p.start_b, p.r_c));
  int64_t a = p.a, b = p.b;
  for (int64_t k = 0; k < p.repeats; ++k) {
    a += p.inc_a;
    b += p.inc_b;
    if (k == 0 && p.current_c > p.r_c) {
      out->move(CanonKind::kTraverse, plane_point(p.plane, a, b, p.current_c));
      out->move(CanonKind::kTraverse, plane_point(p.plane, a, b, p.r_c));
    } else {
      out->move(CanonKind::kTraverse, plane_point(p.plane, a, b, p.clear_c));
      if (p.clear_c > p.r_c) out->move(CanonKind::kTraverse, plane_point(p.plane, a, b, p.r_c));
    }
    hole(p, a, b, out);
  }
}

}  // namespace dexmill
