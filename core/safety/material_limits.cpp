// The process rules of an inhomogeneous stock; see process.h.
#include "core/safety/material_limits.h"

#include "core/grid/removals.h"
#include "core/material/column.h"

namespace dexmill {

const char* process_rule_name(ProcessRule r) {
  switch (r) {
    case ProcessRule::kFeed: return "feed";
    case ProcessRule::kSpindle: return "spindle";
    case ProcessRule::kCoolant: return "coolant";
  }
  return "";
}

namespace {

// True the first time (line, rule, material) is met (process.h: exact for
// the tracked lines, the last kProcessRecentMax past them).
bool first_finding(ProcessWatch* w, uint32_t line, ProcessRule rule, uint8_t material) {
  if (line < w->seen_lines) {
    uint8_t& b = w->seen[static_cast<size_t>(line) * kProcessRules + static_cast<size_t>(rule)];
    const uint8_t bit = static_cast<uint8_t>(1u << material);
    if (b & bit) return false;
    b = static_cast<uint8_t>(b | bit);
    return true;
  }
  const uint64_t key = (static_cast<uint64_t>(line) * kProcessRules + static_cast<uint64_t>(rule)) * 8u + material + 1u;
  for (uint64_t k : w->recent)
    if (k == key) return false;
  w->recent[w->recent_next] = key;
  w->recent_next = (w->recent_next + 1) % kProcessRecentMax;
  return true;
}

// One finding per (line, rule, material): counted and (while there is
// room) kept the first time only.
void violate(ProcessWatch* w, const ProcessState& s, ProcessRule rule, uint8_t material, int64_t value, PointNm at,
             bool* added) {
  if (!first_finding(w, s.line, rule, material)) return;
  ++w->tally[material].violations;
  ++w->total;
  *added = true;
  if (w->nkept >= kProcessViolationsMax) return;
  ProcessViolation& v = w->kept[w->nkept++];
  v.rule = rule;
  v.line = s.line;
  v.material = material;
  v.value = value;
  v.at = at;
}

}  // namespace

template <class H>
Status process_watch_init(ProcessWatch* w, const DexelGrid<H>& g, const StockComposition* comp, uint32_t* shadow,
                          size_t shadow_words) {
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  if (!shadow || shadow_words < n) return Status::kBufferTooSmall;
  for (size_t k = 0; k < n; ++k) shadow[k] = g.top[k];
  w->comp = comp;
  w->shadow = shadow;
  w->nkept = 0;
  w->total = 0;
  for (MaterialTally& t : w->tally) t = MaterialTally{};
  w->line_feed_limit = nullptr;
  w->line_feed_limits = 0;
  w->seen = nullptr;
  w->seen_lines = 0;
  for (uint64_t& k : w->recent) k = 0;
  w->recent_next = 0;
  return Status::kOk;
}

void process_watch_track_findings(ProcessWatch* w, uint8_t* seen, size_t n) {
  for (size_t k = 0; k < process_seen_bytes(n); ++k) seen[k] = 0;
  w->seen = seen;
  w->seen_lines = seen ? n : 0;
}

void process_watch_track_lines(ProcessWatch* w, int64_t* limits, size_t n) {
  for (size_t k = 0; k < n; ++k) limits[k] = kNoFeedLimit;
  w->line_feed_limit = limits;
  w->line_feed_limits = limits ? n : 0;
}

template <class H>
bool process_watch_record(ProcessWatch* w, const DexelGrid<H>& g, GridRect changed, const ProcessState& s,
                          const ProcessOrigin* prev) {
  bool added = false;
  uint32_t mask_now = 0;  // the materials this record removed, for the time tallies
  const StockComposition& c = *w->comp;
  int64_t lengths[kCompositionMaxMaterials];
  each_removal(w->shadow, g, changed, [&](int32_t i, int32_t j, uint32_t was, uint32_t now) {
    const int64_t x = g.x0_nm + i * g.pitch_nm, y = g.y0_nm + j * g.pitch_nm;
    const int64_t z_lo = g.z0_nm + static_cast<int64_t>(now) * g.lsb_nm, z_hi = g.z0_nm + static_cast<int64_t>(was) * g.lsb_nm;
    const bool before = prev && prev->tool && profile_explains_cut(*prev->tool, prev->end, x, y, z_lo, g.lsb_nm);
    const ProcessState& by = before ? prev->state : s;
    const uint32_t mask = composition_column(c, x, y, z_lo, z_hi, lengths);
    if (!before) mask_now |= mask;
    for (int32_t m = 0; m < c.material_count; ++m) {
      if (!(mask >> m & 1u)) continue;
      w->tally[m].removed_nm_columns += static_cast<uint64_t>(lengths[m]);
      const MaterialProcess& p = c.materials[m].process;
      const uint8_t mi = static_cast<uint8_t>(m);
      const PointNm at{x, y, z_lo};
      // Every feed move's lowest limit, over it or not: the same materials,
      // charged to the same line, as the feed rule below sees.
      if (by.feed_move && by.line < w->line_feed_limits)
        w->line_feed_limit[by.line] = min_of(w->line_feed_limit[by.line], p.max_feed_nm_per_min);
      if (by.feed_move && by.feed_nm_per_min > p.max_feed_nm_per_min)
        violate(w, by, ProcessRule::kFeed, mi, by.feed_nm_per_min, at, &added);
      if (by.spindle_on && (by.spindle_rpm < p.spindle_min_rpm || by.spindle_rpm > p.spindle_max_rpm))
        violate(w, by, ProcessRule::kSpindle, mi, by.spindle_rpm, at, &added);
      if (by.coolant && !p.coolant_allowed) violate(w, by, ProcessRule::kCoolant, mi, by.coolant, at, &added);
    }
  });
  // Cutting time: a record's whole time to each material it removed (an
  // end cap's material, cut with the next record, adds no time).
  for (int32_t m = 0; m < c.material_count; ++m)
    if (mask_now >> m & 1u) w->tally[m].cut_time_us += s.time_us;
  return added;
}

#define DEXMILL_PROCESS_INSTANTIATE(H)                                                                           \
  template Status process_watch_init<H>(ProcessWatch*, const DexelGrid<H>&, const StockComposition*, uint32_t*, \
                                        size_t);                                                               \
  template bool process_watch_record<H>(ProcessWatch*, const DexelGrid<H>&, GridRect, const ProcessState&,     \
                                        const ProcessOrigin*);
DEXMILL_PROCESS_INSTANTIATE(uint8_t)
DEXMILL_PROCESS_INSTANTIATE(uint16_t)
DEXMILL_PROCESS_INSTANTIATE(uint32_t)

}  // namespace dexmill
