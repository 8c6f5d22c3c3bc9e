// Safety checks; see safety.h.
#include "core/check/safety.h"

#include "core/math/fixed.h"
#include "core/motion/arc_chords.h"

namespace dexmill {

const char* safety_kind_name(SafetyKind k) {
  switch (k) {
    case SafetyKind::kRapidIntoStock: return "rapid";
    case SafetyKind::kSpindleStopped: return "spindle_stopped";
    case SafetyKind::kBelowStock: return "below_stock";
    case SafetyKind::kIntoTable: return "table";
  }
  return "";
}

namespace {

// The event of (line, kind): one this call began or the last before them
// (a line's removals go on into the next record with its end cap), else a
// new one (counted; null when the list is full).
SafetyEvent* event_for(SafetyWatch* w, size_t first_of_call, uint32_t line, SafetyKind kind, bool* added) {
  for (size_t k = first_of_call > 0 ? first_of_call - 1 : 0; k < w->nevents; ++k)
    if (w->events[k].line == line && w->events[k].kind == kind) return &w->events[k];
  ++w->total;
  *added = true;
  if (w->nevents >= kSafetyEventsMax) return nullptr;
  SafetyEvent* e = &w->events[w->nevents++];
  *e = SafetyEvent{};
  e->line = line;
  e->kind = kind;
  return e;
}

// The lowest point of the tool tip along a motion record: an end, or for
// an arc whose plane is upright (G18, G19) the lowest of its chord points.
PointNm lowest_tip(const CanonRecord& r) {
  PointNm low = r.start.z_nm <= r.end.z_nm ? r.start : r.end;
  if (r.kind != CanonKind::kArc || r.arc.plane == Plane::kXY) return low;
  ArcChords chords;
  chords.init(r, kArcChordSagittaNm);
  PointNm p;
  while (chords.next(&p))
    if (p.z_nm < low.z_nm) low = p;
  return low;
}

void check_below(SafetyWatch* w, size_t first, const CanonRecord& r, SafetyKind kind, int64_t limit_nm, bool* added) {
  const PointNm low = lowest_tip(r);
  if (low.z_nm >= limit_nm) return;
  // A move that only rises from where the last one went down is the way
  // out, not a second offence.
  if (low.z_nm == r.start.z_nm && r.end.z_nm > r.start.z_nm && r.kind != CanonKind::kArc) return;
  SafetyEvent* e = event_for(w, first, r.line, kind, added);
  if (!e) return;
  if (limit_nm - low.z_nm > e->depth_nm) {
    e->depth_nm = limit_nm - low.z_nm;
    e->at = low;
  }
}

}  // namespace

template <class H>
Status safety_watch_init(SafetyWatch* w, const DexelGrid<H>& g, uint32_t* shadow, size_t shadow_words) {
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  if (!shadow || shadow_words < n) return Status::kBufferTooSmall;
  for (size_t k = 0; k < n; ++k) shadow[k] = g.top[k];
  w->shadow = shadow;
  w->nevents = 0;
  w->total = 0;
  w->rapid_removed_lsb = 0;
  w->spindle_stretch = kSafetyEventsMax;
  w->spindle_stretch_open = false;
  return Status::kOk;
}

template <class H>
bool safety_watch_record(SafetyWatch* w, const DexelGrid<H>& g, GridRect changed, const CanonRecord& r,
                         const SafetyMove& m, const SafetyOrigin* prev) {
  const size_t first = w->nevents;
  const uint64_t total_before = w->total;
  bool added = false;
  const bool move = r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
  if (move && m.spindle_on) w->spindle_stretch_open = false;  // M3/M4 ended the stretch
  if (move && w->check_below) check_below(w, first, r, SafetyKind::kBelowStock, w->bottom_nm, &added);
  if (move && w->check_table) check_below(w, first, r, SafetyKind::kIntoTable, w->table_nm, &added);
  const int32_t i0 = max_of(changed.i0, int32_t{0}), i1 = min_of(changed.i1, g.nx);
  const int32_t j0 = max_of(changed.j0, int32_t{0}), j1 = min_of(changed.j1, g.ny);
  // Most moves are feeds with the spindle on after a move like them: what
  // they remove is no finding whoever it is charged to, so the shadow just
  // follows the grid (a widening copy the compiler vectorizes).
  const auto quiet = [w](const SafetyMove& x) {
    return !x.rapid && (x.spindle_on || !w->check_spindle) && x.start_known;
  };
  if (quiet(m) && (!prev || quiet(prev->move))) {
    for (int32_t j = j0; j < j1; ++j) {
      const size_t row = g.index(0, j);
      const H* top = g.top + row;
      uint32_t* was = w->shadow + row;
      for (int32_t i = i0; i < i1; ++i) was[i] = top[i];
    }
    return added;
  }
  for (int32_t j = j0; j < j1; ++j) {
    const size_t row = g.index(0, j);
    for (int32_t i = i0; i < i1; ++i) {
      uint32_t& was = w->shadow[row + static_cast<size_t>(i)];
      const uint32_t now = g.top[row + static_cast<size_t>(i)];
      if (now >= was) {
        was = now;
        continue;
      }
      const uint64_t removed = was - now;
      was = now;
      const int64_t x = g.x0_nm + i * g.pitch_nm, y = g.y0_nm + j * g.pitch_nm, z = g.z0_nm + now * g.lsb_nm;
      const bool before = prev && prev->tool && profile_explains_cut(*prev->tool, prev->end, x, y, z, g.lsb_nm);
      const SafetyMove& by = before ? prev->move : m;
      if (by.rapid) w->rapid_removed_lsb += removed;
      if (!by.start_known) continue;
      SafetyEvent* e;
      if (by.rapid && w->check_rapid) {
        e = event_for(w, first, by.line, SafetyKind::kRapidIntoStock, &added);
      } else if (!by.spindle_on && w->check_spindle) {
        // One event a stretch: the open one, else a new one on this line.
        if (!w->spindle_stretch_open) {
          w->spindle_stretch_open = true;
          ++w->total;
          added = true;
          w->spindle_stretch = w->nevents;
          e = nullptr;
          if (w->nevents < kSafetyEventsMax) {
            e = &w->events[w->nevents++];
            *e = SafetyEvent{};
            e->kind = SafetyKind::kSpindleStopped;
            e->line = by.line;
          }
        } else {
          e = w->spindle_stretch < w->nevents ? &w->events[w->spindle_stretch] : nullptr;
        }
        if (e) e->last_line = max_of(e->last_line, by.line);
      } else {
        continue;
      }
      if (!e) continue;
      ++e->columns;
      e->removed_lsb += removed;
      const int64_t depth_nm = static_cast<int64_t>(removed) * g.lsb_nm;
      if (e->columns == 1 || depth_nm > e->depth_nm) {  // the deepest cut column marks the event
        e->depth_nm = depth_nm;
        e->at = PointNm{x, y, z};
      }
    }
  }
  return added || w->total != total_before;
}

#define DEXMILL_SAFETY_INSTANTIATE(H)                                                                            \
  template Status safety_watch_init<H>(SafetyWatch*, const DexelGrid<H>&, uint32_t*, size_t);                    \
  template bool safety_watch_record<H>(SafetyWatch*, const DexelGrid<H>&, GridRect, const CanonRecord&,          \
                                       const SafetyMove&, const SafetyOrigin*);
DEXMILL_SAFETY_INSTANTIATE(uint8_t)
DEXMILL_SAFETY_INSTANTIATE(uint16_t)
DEXMILL_SAFETY_INSTANTIATE(uint32_t)

}  // namespace dexmill
