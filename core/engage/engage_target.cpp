// core/engage/engage_target.h: the feed that meets a load target.
#include "core/engage/engage_target.h"

#include "core/math/fixed.h"
#include "core/math/pow_ratio.h"

namespace dexmill {

namespace {

// F x num / den, rounded down, saturating.
int64_t scaled_feed(int64_t f, int64_t num, int64_t den) {
  if (den <= 0) return INT64_MAX;
  return muldiv_floor(f, num, den);
}

// F (P* / P)^(1 / (1 - mc)), one part in 10^4 below: P = kc(h) A F and
// h linear in F.
int64_t power_feed(int64_t f, int64_t want_mw, int64_t got_mw, int32_t mc_ppm) {
  if (got_mw <= 0) return INT64_MAX;
  const int32_t exp_ppm = static_cast<int32_t>(muldiv_round(1000000, 1000000, 1000000 - mc_ppm));
  const int64_t k_q32 = pow_ratio_q32(static_cast<uint64_t>(want_mw), static_cast<uint64_t>(got_mw), exp_ppm);
  if (k_q32 == INT64_MAX) return INT64_MAX;
  return mul_shift(muldiv_floor(f, 9999, 10000), k_q32, 32);
}

}  // namespace

int64_t engage_target_feed(const EngageTarget& t, const EngageMove& m, const CuttingCoefficients& c,
                           int64_t max_chip_nm, int64_t material_max_feed_nm_per_min, EngageFeedWhy* why) {
  const int64_t hi = min_of(t.max_feed_nm_per_min, material_max_feed_nm_per_min);
  const int64_t f = m.feed_nm_per_min;
  *why = EngageFeedWhy::kKept;
  if (m.removed_lsb == 0) {
    *why = EngageFeedWhy::kAir;
    return hi;
  }
  int64_t want = INT64_MAX;
  if (m.worst.engaged) {
    switch (t.kind) {
      case EngageTargetKind::kChip: {
        const int64_t h = t.chip_nm > 0 ? t.chip_nm : max_chip_nm;
        if (h > 0 && m.chip.max_nm > 0) want = scaled_feed(f, h, m.chip.max_nm);
        break;
      }
      case EngageTargetKind::kPower:
        if (m.has_load && c.mc_ppm < 1000000) want = power_feed(f, t.power_mw, m.power_mw, c.mc_ppm);
        break;
      case EngageTargetKind::kMrr:
        if (m.mrr_um3_per_min > 0) want = scaled_feed(f, t.mrr_um3_per_min, m.mrr_um3_per_min);
        break;
    }
  }
  if (want == INT64_MAX) return f;  // the engagement cannot say: as programmed
  // Whatever the target, the material's chip limit holds.
  if (max_chip_nm > 0 && m.chip.max_nm > 0) want = min_of(want, scaled_feed(f, max_chip_nm, m.chip.max_nm));
  *why = EngageFeedWhy::kTarget;
  return max_of(min_of(want, hi), min_of(t.min_feed_nm_per_min, hi));
}

void engage_line_feeds_clear(EngageLineFeeds* f) {
  for (size_t k = 0; k < f->n; ++k) {
    f->feed_nm_per_min[k] = INT64_MAX;
    f->kept[k] = 0;
  }
}

void engage_line_feeds_add(EngageLineFeeds* f, uint32_t line, int64_t feed_nm_per_min, EngageFeedWhy why) {
  if (line >= f->n) return;
  f->feed_nm_per_min[line] = min_of(f->feed_nm_per_min[line], feed_nm_per_min);
  if (why == EngageFeedWhy::kKept) f->kept[line] = 1;
}

}  // namespace dexmill
