// Gouges charged to their line; see gouge_watch.h.
#include "core/assess/gouge_watch.h"

#include "core/math/fixed.h"

namespace dexmill {

Status gouge_watch_init(GougeWatch* w, const DesignGrid* d, const AssessOptions& o, uint8_t* seen, size_t seen_bytes) {
  if (!d || !d->top_lsb || !seen || seen_bytes < gouge_watch_seen_bytes(d->geo.nx, d->geo.ny)) return Status::kBufferTooSmall;
  w->design = d;
  w->opt = o;
  w->seen = seen;
  for (size_t k = 0; k < seen_bytes; ++k) seen[k] = 0;
  w->nevents = 0;
  w->total = 0;
  return Status::kOk;
}

namespace {

// The event of `line`: one this call began, or the one before them when it
// has that line (a line's gouges go on over several records: its end cap
// comes with the next), else a new one (counted; null when the list is full).
GougeEvent* event_for(GougeWatch* w, size_t first_of_call, uint32_t line, bool* counted_new) {
  for (size_t k = first_of_call > 0 ? first_of_call - 1 : 0; k < w->nevents; ++k)
    if (w->events[k].line == line) return &w->events[k];
  ++w->total;
  *counted_new = true;
  if (w->nevents >= kGougeEventsMax) return nullptr;
  GougeEvent* e = &w->events[w->nevents++];
  *e = GougeEvent{};
  e->line = line;
  return e;
}

}  // namespace

template <class H>
bool gouge_watch_check(GougeWatch* w, const DexelGrid<H>& g, GridRect changed, uint32_t line, const PointNm& tool,
                       const GougeOrigin* prev) {
  const DesignGrid& d = *w->design;
  const GridRect& reg = w->opt.region;
  const int32_t i0 = max_of(max_of(changed.i0, reg.i0), int32_t{0}), i1 = min_of(min_of(changed.i1, reg.i1), g.nx);
  const int32_t j0 = max_of(max_of(changed.j0, reg.j0), int32_t{0}), j1 = min_of(min_of(changed.j1, reg.j1), g.ny);
  // No column with depth <= the least tolerance of any box can gouge: one
  // subtraction and a compare a column (kNoDesign, INT32_MIN, never passes).
  int64_t tol_min_nm = w->opt.tol_nm;
  for (size_t b = 0; b < w->opt.nboxes; ++b) tol_min_nm = min_of(tol_min_nm, w->opt.boxes[b].tol_nm);
  const int64_t tol_min = tol_min_nm / g.lsb_nm, tol_all = w->opt.tol_nm / g.lsb_nm;
  const size_t first = w->nevents;
  bool found = false;
  for (int32_t j = j0; j < j1; ++j) {
    const size_t row = g.index(0, j);
    const int32_t* dr = d.top_lsb + row;
    const H* tr = g.top + row;
    for (int32_t i = i0; i < i1; ++i) {
      if (static_cast<int64_t>(dr[i]) - tr[i] <= tol_min) continue;
      const size_t k = row + static_cast<size_t>(i);
      const int64_t depth = static_cast<int64_t>(dr[i]) - tr[i];
      if ((w->seen[k >> 3] >> (k & 7)) & 1) continue;
      const int64_t tol = w->opt.nboxes ? assess_tolerance_nm(w->opt, d.geo, i, j) / g.lsb_nm : tol_all;
      if (depth <= tol) continue;
      w->seen[k >> 3] = static_cast<uint8_t>(w->seen[k >> 3] | (1u << (k & 7)));
      found = true;
      const int64_t x = g.x0_nm + i * g.pitch_nm, y = g.y0_nm + j * g.pitch_nm;
      const bool before = prev && prev->tool && profile_explains_cut(*prev->tool, prev->end, x, y, g.z0_nm + tr[i] * g.lsb_nm, g.lsb_nm);
      bool is_new = false;
      GougeEvent* e = event_for(w, first, before ? prev->line : line, &is_new);
      if (!e) continue;
      if (is_new) e->tool = before ? prev->end : tool;
      else if (!before) e->tool = tool;
      ++e->columns;
      if (depth > e->depth_lsb) {
        e->depth_lsb = depth;
        e->design_lsb = dr[i];
        e->i = i;
        e->j = j;
      }
    }
  }
  return found;
}

#define DEXMILL_GOUGE_INSTANTIATE(H) \
  template bool gouge_watch_check<H>(GougeWatch*, const DexelGrid<H>&, GridRect, uint32_t, const PointNm&, const GougeOrigin*);
DEXMILL_GOUGE_INSTANTIATE(uint8_t)
DEXMILL_GOUGE_INSTANTIATE(uint16_t)
DEXMILL_GOUGE_INSTANTIATE(uint32_t)

}  // namespace dexmill
