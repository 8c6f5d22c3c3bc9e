// core/safety/travel_watch.h: soft limits, each move at its line.
#include "core/safety/travel_watch.h"

#include "core/canon/arc_chords.h"
#include "core/math/fixed.h"

namespace dexmill {

namespace {

int64_t coord(const PointNm& p, int axis) { return axis == 0 ? p.x_nm : axis == 1 ? p.y_nm : p.z_nm; }

// The axis an arc's plane is about (0 X, 1 Y, 2 Z).
int plane_axis(Plane p) { return p == Plane::kXY ? 2 : p == Plane::kZX ? 1 : 0; }

// How far each side of each axis the move went past, at its farthest.
struct Excess {
  int64_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  int64_t lo_at[3] = {0, 0, 0}, hi_at[3] = {0, 0, 0};

  void point(const MachineAxis* ax, const PointNm& p) {
    for (int a = 0; a < 3; ++a) {
      if (!ax[a].limited) continue;
      const int64_t v = coord(p, a);
      if (v > ax[a].max_nm + kTravelSlackNm && v - ax[a].max_nm > hi[a]) hi[a] = v - ax[a].max_nm, hi_at[a] = v;
      if (v < ax[a].min_nm - kTravelSlackNm && ax[a].min_nm - v > lo[a]) lo[a] = ax[a].min_nm - v, lo_at[a] = v;
    }
  }
};

void keep(TravelWatch* w, uint32_t line, int axis, bool above, int64_t excess, int64_t at) {
  ++w->total;
  if (w->nkept >= kTravelKept) return;
  TravelFinding& f = w->kept[w->nkept++];
  f.line = line;
  f.axis = static_cast<uint8_t>(axis);
  f.above = above;
  f.excess_nm = excess;
  f.at_nm = at;
  f.limit_nm = above ? w->axis[axis].max_nm : w->axis[axis].min_nm;
}

// The arc's box (centre +- its largest radius in the plane, its ends along
// the axis) inside every limit: no chord to walk.
bool arc_box_inside(const MachineAxis* ax, const CanonRecord& r, const ArcChords& chords, int64_t tlo_nm) {
  const int64_t rad = chords.radius_max() + 8;  // the chords' points' bound, rounded up
  const Plane pl = r.arc.plane;
  const int64_t ca = plane_a(pl, r.arc.centre), cb = plane_b(pl, r.arc.centre);
  const int64_t c0 = plane_c(pl, r.start), c1 = plane_c(pl, r.end);
  const PointNm lo = plane_point(pl, ca - rad, cb - rad, min_of(c0, c1));
  const PointNm hi = plane_point(pl, ca + rad, cb + rad, max_of(c0, c1));
  for (int a = 0; a < 3; ++a) {
    if (!ax[a].limited) continue;
    const int64_t off = a == 2 ? tlo_nm : 0;
    int64_t l = coord(lo, a) + off, h = coord(hi, a) + off;
    if (l > h) {  // plane_point may hand an axis its coordinates in either order
      const int64_t t = l;
      l = h;
      h = t;
    }
    if (l < ax[a].min_nm || h > ax[a].max_nm) return false;
  }
  return true;
}

}  // namespace

void travel_watch_init(TravelWatch* w, const MachineSpec& m) {
  *w = TravelWatch{};
  w->kind = m.kind;
  for (int a = 0; a < 3; ++a) w->axis[a] = m.axis[a];
}

bool travel_watch_check(TravelWatch* w, const CanonRecord& r) {
  if (r.kind != CanonKind::kTraverse && r.kind != CanonKind::kFeed && r.kind != CanonKind::kArc) return false;
  const int64_t tlo = r.tool_length_offset_nm;
  auto machine = [tlo](const PointNm& p) { return PointNm{p.x_nm, p.y_nm, p.z_nm + tlo}; };
  // Where the move goes: its end, and an arc's points on the way; a side
  // counts where the move goes farther past it than its start already
  // was (the move before it, which took it there, was the finding).
  Excess from, e;
  bool first[3];
  for (int a = 0; a < 3; ++a) {
    const bool moves = coord(r.start, a) != coord(r.end, a) ||
                       (r.kind == CanonKind::kArc && a != static_cast<int>(plane_axis(r.arc.plane)));
    first[a] = !w->known[a] && moves;
    w->known[a] = w->known[a] || moves;
  }
  from.point(w->axis, machine(r.start));
  e.point(w->axis, machine(r.end));
  if (r.kind == CanonKind::kArc) {
    ArcChords c;
    c.init(r, kArcChordSagittaNm);
    PointNm p;
    if (!arc_box_inside(w->axis, r, c, tlo))
      while (c.next(&p)) e.point(w->axis, machine(p));
  }
  bool any = false;
  for (int a = 0; a < 3; ++a) {
    if (!w->known[a]) continue;  // not moved yet: where it is is the machine's
    if (first[a]) from.hi[a] = from.lo[a] = 0;  // its first move: from wherever the machine was
    if (e.hi[a] > from.hi[a]) keep(w, r.line, a, true, e.hi[a], e.hi_at[a]), any = true;
    if (e.lo[a] > from.lo[a]) keep(w, r.line, a, false, e.lo[a], e.lo_at[a]), any = true;
  }
  return any;
}

}  // namespace dexmill
