// core/engage/engage_meter.h: each record's engagement and removal.
#include "core/engage/engage_meter.h"

#include "core/canon/arc_chords.h"
#include "core/grid/removals.h"
#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {
namespace {

// The horizontal unit direction of a -> b, q30 (false: no horizontal motion).
bool direction_q30(const PointNm& a, const PointNm& b, int64_t* ex, int64_t* ey) {
  const int64_t dx = b.x_nm - a.x_nm, dy = b.y_nm - a.y_nm;
  if (dx == 0 && dy == 0) return false;
  const int64_t l = hypot_floor(dx, dy);
  if (l == 0) return false;
  *ex = muldiv_round(dx, int64_t{1} << 30, l);
  *ey = muldiv_round(dy, int64_t{1} << 30, l);
  return true;
}

// One sample: the tool at p feeding along (ex, ey).
void sample(EngageMeter* m, const GridGeometry& g, const PointNm& p, int64_t s_nm, int64_t ex, int64_t ey,
            bool clockwise) {
  EngageMove& mv = m->move;
  if (mv.samples >= static_cast<uint32_t>(kEngageMaxSamples)) return;
  EngageAt e;
  // Within 2R of the start, a sample's ring reaches the footprint the tool
  // left there.
  const PointNm& s = m->record.start;
  const int64_t reach = 2 * m->tool.profile.radius_nm;
  const bool near = p.x_nm - s.x_nm < reach && s.x_nm - p.x_nm < reach && p.y_nm - s.y_nm < reach && s.y_nm - p.y_nm < reach;
  engage_at_tops(g, m->shadow, m->tool, p, ex, ey, clockwise, near ? &s : nullptr, &e);
  ++mv.samples;
  mv.ae_max_nm = max_of(mv.ae_max_nm, e.ae_nm);
  mv.ap_max_nm = max_of(mv.ap_max_nm, e.ap_nm);
  if (e.area_um2 > mv.section.area_um2) {
    mv.section = e;
    const int64_t R = m->tool.profile.radius_nm;
    mv.area_at = PointNm{p.x_nm + mul_shift(R, ex, 30), p.y_nm + mul_shift(R, ey, 30), p.z_nm + e.ap_nm / 2};
  }
  if (e.engaged && (!mv.worst.engaged || e.angle_bam() > mv.worst.angle_bam())) {
    mv.worst = e;
    mv.worst_at = p;
  }
  // A straight move's samples kept, for a split at its changes.
  if (m->trace && m->record.kind == CanonKind::kFeed) m->trace[m->ntrace++] = EngageSample{s_nm, e};
}

// The straight piece a -> b of a path sampled every step_nm (horizontal
// length) from its start: *carry_nm is how far past the last sample the
// piece begins (the path's start: step_nm, so that it is sampled); `last`:
// the path's end is sampled too; *s_nm: the path's horizontal length
// before the piece (and after it, on return).
void sample_piece(EngageMeter* m, const GridGeometry& g, const PointNm& a, const PointNm& b, bool clockwise,
                  int64_t step_nm, int64_t* carry_nm, bool last, int64_t* s_nm) {
  int64_t ex, ey;
  if (!direction_q30(a, b, &ex, &ey)) return;  // a plunge: no front to meet
  const int64_t len = hypot_floor(b.x_nm - a.x_nm, b.y_nm - a.y_nm);
  auto at = [&](int64_t t) {
    return PointNm{a.x_nm + muldiv_round(b.x_nm - a.x_nm, t, len), a.y_nm + muldiv_round(b.y_nm - a.y_nm, t, len),
                   a.z_nm + muldiv_round(b.z_nm - a.z_nm, t, len)};
  };
  int64_t t = step_nm - *carry_nm;  // the next sample's distance from a
  if (t < 0) t = 0;
  int64_t sampled = -1;
  for (; t <= len; t += step_nm) {
    sample(m, g, at(t), *s_nm + t, ex, ey, clockwise);
    sampled = t;
  }
  if (last && sampled != len) sample(m, g, b, *s_nm + len, ex, ey, clockwise), sampled = len;
  *carry_nm = sampled >= 0 ? len - sampled : *carry_nm + len;
  *s_nm += len;
}

}  // namespace

template <class H>
Status engage_meter_init(EngageMeter* m, const DexelGrid<H>& g, uint32_t* shadow, size_t shadow_words) {
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  if (!shadow || shadow_words < n) return Status::kBufferTooSmall;
  for (size_t k = 0; k < n; ++k) shadow[k] = g.top[k];
  m->shadow = shadow;
  m->pending = GridRect::none();
  return Status::kOk;
}

void engage_meter_set_tool(EngageMeter* m, const Tool& t, int64_t pitch_nm) {
  engage_tool_init(t, pitch_nm, &m->tool);
  m->spacing_nm = max_of(pitch_nm, m->tool.profile.radius_nm / 2);
}

template <class H>
void engage_meter_before(EngageMeter* m, const DexelGrid<H>&, const CanonRecord& r, bool clockwise,
                         int32_t spindle_rpm) {
  m->move = EngageMove{};
  m->ntrace = 0;
  EngageMove& mv = m->move;
  mv.line = r.line;
  mv.spindle_rpm = spindle_rpm;
  mv.feed = r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
  mv.feed_nm_per_min = r.feed_nm_per_min;
  m->record = r;
  m->clockwise = clockwise;
}

namespace {

// The record's path sampled on the shadow (the tops before it).
void sample_path(EngageMeter* m, const GridGeometry& g) {
  const CanonRecord& r = m->record;
  if (r.kind == CanonKind::kFeed) {
    const int64_t len = hypot_floor(r.end.x_nm - r.start.x_nm, r.end.y_nm - r.start.y_nm);
    int64_t carry = max_of(m->spacing_nm, div_ceil(len, kEngageMaxSamples - 1));
    int64_t s = 0;
    sample_piece(m, g, r.start, r.end, m->clockwise, carry, &carry, true, &s);
    return;
  }
  ArcChords chords;
  chords.init(r, max_of<int64_t>(g.pitch_nm / 4, 1));
  // At most kEngageMaxSamples over the arc: its length in the plane is at
  // most 2 pi r_max a turn (7 r_max per turn, rounded up).
  PointNm a = r.start, b;
  const int64_t turns = max_of<int64_t>(1, r.arc.turns < 0 ? -static_cast<int64_t>(r.arc.turns) : r.arc.turns);
  const int64_t step = max_of(m->spacing_nm, div_ceil(chords.radius_max() * 7 * turns, kEngageMaxSamples - 1));
  int64_t carry = step, s = 0;
  for (uint32_t k = 0; chords.next(&b); ++k) {
    sample_piece(m, g, a, b, m->clockwise, step, &carry, k + 1 == chords.count(), &s);
    a = b;
  }
}

}  // namespace

template <class H>
void engage_meter_measure(EngageMeter* m, const DexelGrid<H>& g, GridRect changed, EngageMove* out) {
  changed.include(m->pending);
  // What it removed (the shadow still the tops before it) ...
  const int32_t i0 = max_of(changed.i0, int32_t{0}), i1 = min_of(changed.i1, g.nx);
  const int32_t j0 = max_of(changed.j0, int32_t{0}), j1 = min_of(changed.j1, g.ny);
  uint64_t removed = 0;
  for (int32_t j = j0; j < j1; ++j) {
    const size_t row = g.index(0, j);
    for (int32_t i = i0; i < i1; ++i) {
      const uint32_t was = m->shadow[row + static_cast<size_t>(i)];
      const uint32_t now = g.top[row + static_cast<size_t>(i)];
      if (now < was) removed += was - now;
    }
  }
  m->move.removed_lsb = removed;
  // ... then, for a feed move that removed something, where it met
  // material, on the stock before it; a move in air meets none.
  EngageMove& mv = m->move;
  if (mv.feed && removed > 0) {
    sample_path(m, GridGeometry{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm});
    if (mv.spindle_rpm > 0)
      mv.fz_nm = div_round(mv.feed_nm_per_min, static_cast<int64_t>(mv.spindle_rpm) * m->tool.flutes);
    mv.chip = engage_chip(m->tool, mv.worst, mv.fz_nm);
    // um^2 x um/min; below 2^63 for a section under 10^10 um^2 (100 mm square) at 20 m/min.
    mv.mrr_um3_per_min = sat_mul_i64(mv.section.area_um2, mv.feed_nm_per_min / 1000);
  }
  *out = m->move;
}

template <class H>
void engage_meter_commit(EngageMeter* m, const DexelGrid<H>& g, GridRect changed, uint8_t* cls, uint8_t band) {
  changed.include(m->pending);
  m->pending = GridRect::none();
  if (cls) {
    each_removal(m->shadow, g, changed, [&](int32_t i, int32_t j, uint32_t, uint32_t now) {
      cls[g.index(i, j)] = band;
      class_hole_walls(cls, g, i, j, now, band);
    });
    return;
  }
  // Not colouring: the shadow follows the grid, a plain copy.
  const int32_t i0 = max_of(changed.i0, int32_t{0}), i1 = min_of(changed.i1, g.nx);
  const int32_t j0 = max_of(changed.j0, int32_t{0}), j1 = min_of(changed.j1, g.ny);
  for (int32_t j = j0; j < j1; ++j) {
    const size_t row = g.index(0, j);
    for (int32_t i = i0; i < i1; ++i) m->shadow[row + static_cast<size_t>(i)] = g.top[row + static_cast<size_t>(i)];
  }
}

template <class H>
void engage_meter_after(EngageMeter* m, const DexelGrid<H>& g, GridRect changed, EngageMove* out) {
  engage_meter_measure(m, g, changed, out);
  engage_meter_commit(m, g, changed, nullptr, 0);
}

void engage_meter_note(EngageMeter* m, GridRect changed) { m->pending.include(changed); }

void engage_summary_add(EngageSummary* s, const EngageMove& m) {
  if (!m.feed) return;
  ++s->moves;
  if (!m.worst.engaged && m.removed_lsb == 0) return;
  ++s->engaged;
  if (m.spindle_rpm <= 0) ++s->no_speed;
  if (m.worst.angle_bam() > s->angle.worst.angle_bam()) s->angle = m;
  if (m.ae_max_nm > s->ae.ae_max_nm) s->ae = m;
  if (m.ap_max_nm > s->ap.ap_max_nm) s->ap = m;
  if (m.chip.max_nm > s->chip.chip.max_nm) s->chip = m;
  if (m.mrr_um3_per_min > s->rate.mrr_um3_per_min) s->rate = m;
  if (m.has_load && m.force_mn > s->force.force_mn) s->force = m;
  if (m.has_load && m.power_mw > s->power.power_mw) s->power = m;
}

#define DEXMILL_ENGAGE_METER_INSTANTIATE(H)                                                                \
  template Status engage_meter_init<H>(EngageMeter*, const DexelGrid<H>&, uint32_t*, size_t);           \
  template void engage_meter_before<H>(EngageMeter*, const DexelGrid<H>&, const CanonRecord&, bool, int32_t); \
  template void engage_meter_measure<H>(EngageMeter*, const DexelGrid<H>&, GridRect, EngageMove*);       \
  template void engage_meter_commit<H>(EngageMeter*, const DexelGrid<H>&, GridRect, uint8_t*, uint8_t);  \
  template void engage_meter_after<H>(EngageMeter*, const DexelGrid<H>&, GridRect, EngageMove*);
DEXMILL_ENGAGE_METER_INSTANTIATE(uint8_t)
DEXMILL_ENGAGE_METER_INSTANTIATE(uint16_t)
DEXMILL_ENGAGE_METER_INSTANTIATE(uint32_t)

}  // namespace dexmill
