// Canned-cycle moves; see cycles.h. The order of moves follows
// LinuxCNC's CYCLE_MACRO: the first repeat positions at the current level and
// goes down to R; later repeats position at the clearance level.
#include "core/interp/cycles.h"

#include "core/canon/arc_chords.h"

namespace dexmill {

int64_t cycle_peck_count(int64_t r_c, int64_t bottom_c, int64_t q_nm) {
  // Depths r - q, r - 2q, ... while still above the bottom.
  if (r_c - bottom_c <= q_nm) return 0;
  return (r_c - bottom_c - 1) / q_nm;
}

namespace {

// The tapping feeds of G74/G84. LinuxCNC 2.9's convert_cycle_g74_g84 hands
// cycle_feed the coordinates in the order of the other vertical plane when
// G18 or G19 is in force, so the tap goes to the point whose plane
// coordinates are (a, b, c) in G19's axes (in G18) or G18's (in G19). That
// is the move its canonical output gives and the machine makes; dexmill
// follows it (and warns, interp_moves.cpp).
PointNm cycle_tap_point(Plane pl, int64_t a, int64_t b, int64_t c) {
  const Plane used = pl == Plane::kZX ? Plane::kYZ : pl == Plane::kYZ ? Plane::kZX : Plane::kXY;
  return plane_point(used, a, b, c);
}

// G87 back boring (convert_cycle_g87): in beside the hole with the spindle
// stopped, under the part, over to the hole's axis, feed up to the top of
// the counterbore and back, then out the same way.
void back_bore(const CyclePlan& p, int64_t a, int64_t b, CycleOut* out) {
  auto at = [&](int64_t pa, int64_t pb, int64_t c) { return plane_point(p.plane, pa, pb, c); };
  const int64_t oa = a + p.off_a, ob = b + p.off_b;
  out->move(CanonKind::kTraverse, at(oa, ob, p.r_c));
  out->spindle(0);  // LinuxCNC also orients the spindle here (ORIENT_SPINDLE)
  out->move(CanonKind::kTraverse, at(oa, ob, p.bottom_c));
  out->move(CanonKind::kTraverse, at(a, b, p.bottom_c));
  out->spindle(p.spindle_rpm);
  out->move(CanonKind::kFeed, at(a, b, p.middle_c));
  out->move(CanonKind::kFeed, at(a, b, p.bottom_c));
  out->spindle(0);
  out->move(CanonKind::kTraverse, at(oa, ob, p.bottom_c));
  out->move(CanonKind::kTraverse, at(oa, ob, p.clear_c));
  out->move(CanonKind::kTraverse, at(a, b, p.clear_c));
  out->spindle(p.spindle_rpm);
}

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
    case 840:    // right-hand tap: in at F, reverse the spindle, dwell, out at F to
    case 740: {  // the clearance level, restore the spindle (G74: the other way round)
      out->move(CanonKind::kFeed, cycle_tap_point(p.plane, a, b, p.bottom_c));
      out->spindle(0);
      out->spindle(-p.spindle_rpm);
      out->dwell(p.dwell_ms);
      out->move(CanonKind::kFeed, cycle_tap_point(p.plane, a, b, p.clear_c));
      out->spindle(0);
      out->spindle(p.spindle_rpm);
      break;
    }
    case 850:  // bore: feed in, feed out to R
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->move(CanonKind::kFeed, at(p.r_c));
      out->move(CanonKind::kTraverse, at(p.clear_c));
      break;
    case 860:  // bore, dwell, stop the spindle, rapid out, restart it
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->dwell(p.dwell_ms);
      out->spindle(0);
      out->move(CanonKind::kTraverse, at(p.clear_c));
      out->spindle(p.spindle_rpm);
      break;
    case 870:
      back_bore(p, a, b, out);
      break;
    case 880:  // bore, dwell, stop the spindle, program stop (the operator
               // retracts by hand), restart it; no retract move
      out->move(CanonKind::kFeed, at(p.bottom_c));
      out->dwell(p.dwell_ms);
      out->spindle(0);
      out->pause();
      out->spindle(p.spindle_rpm);
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
  PolarSeries polar = p.series;
  for (int64_t k = 0; k < p.repeats; ++k) {
    if (p.polar) {
      char word;
      polar.next(&a, &b, &word);  // planning checked every hole
      a += p.polar_off_a;
      b += p.polar_off_b;
    } else {
      a += p.inc_a;
      b += p.inc_b;
    }
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

void cycle_last_hole(const CyclePlan& p, int64_t* a, int64_t* b) {
  *a = p.polar ? p.last_a : p.a + p.inc_a * p.repeats;
  *b = p.polar ? p.last_b : p.b + p.inc_b * p.repeats;
}

PointNm cycle_last_point(const CyclePlan& p) {
  int64_t a, b;
  cycle_last_hole(p, &a, &b);
  if (p.code == 880) return plane_point(p.plane, a, b, p.bottom_c);
  if (p.code == 840 || p.code == 740) return cycle_tap_point(p.plane, a, b, p.clear_c);
  return plane_point(p.plane, a, b, p.clear_c);
}

}  // namespace dexmill
