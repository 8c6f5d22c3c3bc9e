// core/engage/engage_split.h: a move's pieces at its load's changes.
#include "core/engage/engage_split.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

namespace {

// |a - b| over the lower of the two, more than the change that starts a piece.
bool differ(int64_t a, int64_t b) {
  const int64_t lo = min_of(a, b), hi = max_of(a, b);
  if (lo <= 0) return hi > lo;
  return hi - lo > muldiv_floor(lo, kEngageSplitChangePpm, 1000000);
}

// A piece while the runs are found (16 bytes: a move's 128 on the stack).
struct Run {
  int64_t end_nm, feed_nm_per_min;
};

// Merges piece k with piece k + 1 (the lower feed).
void merge(Run* seg, int32_t* count, int32_t k) {
  seg[k].end_nm = seg[k + 1].end_nm;
  seg[k].feed_nm_per_min = min_of(seg[k].feed_nm_per_min, seg[k + 1].feed_nm_per_min);
  for (int32_t j = k + 1; j + 1 < *count; ++j) seg[j] = seg[j + 1];
  --*count;
}

// How far apart the feeds of pieces a and b are.
int64_t gap(const Run& a, const Run& b) {
  return max_of(a.feed_nm_per_min, b.feed_nm_per_min) - min_of(a.feed_nm_per_min, b.feed_nm_per_min);
}

// min over the neighbours of k (the load between samples is covered by both).
int64_t covered(const int64_t* feed, int32_t n, int32_t k) {
  int64_t f = feed[k];
  if (k > 0) f = min_of(f, feed[k - 1]);
  if (k + 1 < n) f = min_of(f, feed[k + 1]);
  return f;
}

// The time of a piece of length l at feed f, in units of nm^2 / (nm/min)
// scaled: l * 2^20 / f (only compared with each other).
int64_t time_of(int64_t l, int64_t f) { return f > 0 ? muldiv_floor(l, int64_t{1} << 20, f) : INT64_MAX / 4; }

}  // namespace

int32_t engage_split(const int64_t* s_nm, const int64_t* feed_nm_per_min, int32_t n, int64_t length_nm,
                     const EngageSplitRule& rule, EngageSegment* out) {
  int64_t lowest = INT64_MAX;
  for (int32_t k = 0; k < n; ++k) lowest = min_of(lowest, feed_nm_per_min[k]);
  out[0] = EngageSegment{length_nm, lowest};
  const int32_t most = min_of(rule.max_segments, kEngageMaxSegments);
  if (n < 2 || most < 2 || length_nm <= 0) return 1;
  // Runs of samples whose covered feeds stay within the change of the
  // run's lowest (a gradual fall stays one run at its lowest), a piece a
  // run.
  Run seg[kEngageMaxSamples];
  int32_t count = 0;
  int64_t run_lo = covered(feed_nm_per_min, n, 0);
  for (int32_t k = 1; k < n; ++k) {
    const int64_t f = covered(feed_nm_per_min, n, k);
    if (differ(f, run_lo) && count + 2 < kEngageMaxSamples) {
      // Rising load (the next is slower): the slow piece starts at the
      // last light sample; falling: the slow one ends at the first light.
      const int64_t at = f < run_lo ? s_nm[k - 1] : s_nm[k];
      seg[count++] = Run{at, run_lo};
      run_lo = f;
    } else {
      run_lo = min_of(run_lo, f);
    }
  }
  seg[count++] = Run{length_nm, run_lo};
  // No piece shorter than the minimum: the shortest merged into the
  // neighbour nearer its feed, until none is.
  for (;;) {
    int32_t shortest = -1;
    int64_t len_min = rule.min_segment_nm;
    for (int32_t k = 0; k < count && count > 1; ++k) {
      const int64_t l = seg[k].end_nm - (k ? seg[k - 1].end_nm : 0);
      if (l < len_min) len_min = l, shortest = k;
    }
    if (shortest < 0) break;
    const int32_t k = shortest;
    const bool with_next = k == 0 || (k + 1 < count && gap(seg[k], seg[k + 1]) <= gap(seg[k], seg[k - 1]));
    merge(seg, &count, with_next ? k : k - 1);
  }
  // Neighbours with the same feed are one piece; then at most `most`:
  // the pair of the closest feeds merged first.
  for (int32_t k = 0; k + 1 < count;)
    if (!differ(seg[k].feed_nm_per_min, seg[k + 1].feed_nm_per_min)) merge(seg, &count, k);
    else ++k;
  while (count > most) {
    int32_t best = 0;
    int64_t best_gap = INT64_MAX;
    for (int32_t k = 0; k + 1 < count; ++k) {
      const int64_t d = gap(seg[k], seg[k + 1]);
      if (d < best_gap) best_gap = d, best = k;
    }
    merge(seg, &count, best);
  }
  if (count < 2) return 1;
  // Worth it only when it saves a part of the move's time at one feed.
  int64_t whole = time_of(length_nm, lowest), split = 0;
  for (int32_t k = 0; k < count; ++k) split += time_of(seg[k].end_nm - (k ? seg[k - 1].end_nm : 0), seg[k].feed_nm_per_min);
  if (whole - split < muldiv_floor(whole, kEngageSplitGainPpm, 1000000)) return 1;
  for (int32_t k = 0; k < count; ++k) out[k] = EngageSegment{seg[k].end_nm, seg[k].feed_nm_per_min, PointNm{0, 0, 0}};
  return count;
}

namespace {

uint64_t gcd_u64(uint64_t a, uint64_t b) {
  while (b) {
    const uint64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

uint64_t abs_u(int64_t v) { return v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v); }

}  // namespace

int32_t engage_split_snap(const PointNm& start, const PointNm& end, EngageSegment* seg, int32_t count) {
  const int64_t dx = end.x_nm - start.x_nm, dy = end.y_nm - start.y_nm, dz = end.z_nm - start.z_nm;
  const int64_t len = hypot_floor(dx, dy);
  const int64_t g = static_cast<int64_t>(gcd_u64(gcd_u64(abs_u(dx), abs_u(dy)), abs_u(dz)));
  if (count < 2 || len <= 0 || g < 2) {
    seg[0] = EngageSegment{len, seg[0].feed_nm_per_min, end};
    for (int32_t k = 1; k < count; ++k) seg[0].feed_nm_per_min = min_of(seg[0].feed_nm_per_min, seg[k].feed_nm_per_min);
    return 1;
  }
  int64_t step[kEngageMaxSegments];
  for (int32_t k = 0; k + 1 < count; ++k) {
    // Towards the faster side: back when the next piece is slower.
    const bool back = seg[k + 1].feed_nm_per_min < seg[k].feed_nm_per_min;
    const int64_t j = back ? muldiv_floor(seg[k].end_nm, g, len) : -muldiv_floor(-seg[k].end_nm, g, len);
    step[k] = clamp(j, int64_t{0}, g);
  }
  step[count - 1] = g;
  // Empty pieces (an end at or before the one before it, or at the start)
  // merge with the next, at the lower feed.
  int32_t n = 0;
  int64_t prev = 0;
  for (int32_t k = 0; k < count; ++k) {
    if (step[k] <= prev) {
      if (n > 0) {
        seg[n - 1].feed_nm_per_min = min_of(seg[n - 1].feed_nm_per_min, seg[k].feed_nm_per_min);
        if (k + 1 == count) seg[n - 1].end_nm = len, seg[n - 1].end_at = end;  // it now ends the move
      } else if (k + 1 < count) seg[k + 1].feed_nm_per_min = min_of(seg[k + 1].feed_nm_per_min, seg[k].feed_nm_per_min);
      continue;
    }
    const int64_t j = step[k];
    seg[n] = EngageSegment{muldiv_floor(len, j, g), seg[k].feed_nm_per_min,
                           PointNm{start.x_nm + dx / g * j, start.y_nm + dy / g * j, start.z_nm + dz / g * j}};
    prev = j;
    ++n;
  }
  // Neighbours that came to the same feed are one piece.
  int32_t m = 0;
  for (int32_t k = 0; k < n; ++k) {
    if (m > 0 && seg[m - 1].feed_nm_per_min == seg[k].feed_nm_per_min) {
      seg[m - 1].end_nm = seg[k].end_nm;
      seg[m - 1].end_at = seg[k].end_at;
      continue;
    }
    seg[m++] = seg[k];
  }
  return m;
}

int64_t engage_sample_feed(const EngageTarget& target, const EngageTool& tool, const EngageMove& m,
                           const EngageAt& at, const CuttingCoefficients& c, int64_t max_chip_nm,
                           int64_t material_max_feed_nm_per_min, int64_t move_feed_nm_per_min) {
  EngageMove s = m;
  s.worst = at;
  s.section = at;
  s.ae_max_nm = at.ae_nm;
  s.ap_max_nm = at.ap_nm;
  s.chip = engage_chip(tool, at, m.fz_nm);
  s.mrr_um3_per_min = sat_mul_i64(at.area_um2, m.feed_nm_per_min / 1000);
  // A sample that met nothing is in air: the move's highest feed.
  if (!at.engaged) s.removed_lsb = 0;
  s.has_load = false;
  engage_load(tool, c, &s);
  EngageFeedWhy why;
  const int64_t f = engage_target_feed(target, s, c, max_chip_nm, material_max_feed_nm_per_min, &why);
  // A sample the target cannot read (a graze at the arc's very end: no
  // chip) takes the move's own feed.
  return why == EngageFeedWhy::kKept ? move_feed_nm_per_min : f;
}

bool engage_splits_add(EngageSplits* s, uint32_t line, const EngageSegment* seg, int32_t count) {
  if (count < 2) return true;
  if (s->n + static_cast<size_t>(count) > s->cap) {
    ++s->left;
    return false;
  }
  for (int32_t k = 0; k < count; ++k) s->pieces[s->n++] = EngageSplitPiece{line, k + 1 == count, seg[k]};
  ++s->moves;
  return true;
}

}  // namespace dexmill
