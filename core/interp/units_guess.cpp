// The "looks like inches" rule; see units_guess.h.
//
// Its margins on the corpus it was chosen on (numbers as written):
//   inch programs: at most 14.2 across (LinuxCNC's mmount.ngc), top Z at
//   most 1.6 but for one test at 3.5 (inside-corners, whose feeds are 8),
//   feeds at most 1000 (blur_torus, a planner test);
//   mm programs under 20 across (FreeCAD's metric post test, tux.ngc,
//   PathDxf2GCode's part): top Z 4 or more and feeds 140 or more; the
//   ones with a top under 2.5 are 33 across or more (bCNC's sample).
// A pcb-gcode program that writes G21 over inch-sized numbers has no F at
// all, and is not judged.
#include "core/interp/units_guess.h"

namespace dexmill {

int64_t UnitsEvidence::extent_nm() const {
  if (!moved) return 0;
  const int64_t x = x_hi_nm - x_lo_nm, y = y_hi_nm - y_lo_nm;
  return x > y ? x : y;
}

namespace {

void take_point(UnitsEvidence* e, const PointNm& p) {
  if (!e->moved) {
    e->moved = true;
    e->x_lo_nm = e->x_hi_nm = p.x_nm;
    e->y_lo_nm = e->y_hi_nm = p.y_nm;
    e->top_nm = p.z_nm;
    return;
  }
  if (p.x_nm < e->x_lo_nm) e->x_lo_nm = p.x_nm;
  if (p.x_nm > e->x_hi_nm) e->x_hi_nm = p.x_nm;
  if (p.y_nm < e->y_lo_nm) e->y_lo_nm = p.y_nm;
  if (p.y_nm > e->y_hi_nm) e->y_hi_nm = p.y_nm;
  if (p.z_nm > e->top_nm) e->top_nm = p.z_nm;
}

}  // namespace

void units_evidence_add(UnitsEvidence* e, const CanonRecord& r, bool programmed_feed) {
  const bool feed = r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
  if (!feed && r.kind != CanonKind::kTraverse) return;
  take_point(e, r.start);
  take_point(e, r.end);
  if (!feed || !programmed_feed) return;
  if (!e->fed || r.feed_nm_per_min > e->feed_max_nm_per_min) e->feed_max_nm_per_min = r.feed_nm_per_min;
  e->fed = true;
}

bool units_look_like_inch(const UnitsEvidence& e) {
  if (!e.fed) return false;
  if (e.extent_nm() >= kInchLookExtentNm) return false;
  if (e.feed_max_nm_per_min >= kInchLookFastFeedNmPerMin) return false;
  return e.top_nm < kInchLookTopNm || e.feed_max_nm_per_min < kInchLookSlowFeedNmPerMin;
}

}  // namespace dexmill
