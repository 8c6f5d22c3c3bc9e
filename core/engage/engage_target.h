// Feeds set by the load (`dexmill optimize --target`): the feed at which a
// measured move (core/engage/engage_meter.h) meets a target, raised in
// light cuts and lowered in heavy ones (Fussell, Jerard and Hemmett, J.
// Manuf. Sci. Eng. 123(2), 2001: a discrete height model picks a feed per
// move). At the move's measured engagement and spindle speed:
// - chip: the thickest chip is the feed per tooth times sin(phi) at the
//   arc's widest point, linear in the feed: F' = F h* / h;
// - power: P = kc(h_mean) A F with kc = kc1.1 h^-mc and h_mean linear in
//   F, so P grows as F^(1 - mc): F' = F (P* / P)^(1 / (1 - mc));
// - removal rate: A F, linear: F' = F Q* / Q.
// Rounded down (the power's within pow_ratio_q32's error, then one part in
// 10^4 below it), so the move measured again at F' is at most the
// target. A move that removed nothing runs at the highest feed; a move
// whose engagement cannot say (a plunge: no horizontal front; no spindle
// speed for a chip or power target; no coefficients for power) keeps its
// programmed feed. Then bounded: at most the feed at the material's chip
// limit (any target), at most max_feed, at least min_feed.
// Each line gets the lowest of its moves' feeds (an F word is the line's).
// Integer only, caller memory.
#ifndef DEXMILL_CORE_ENGAGE_ENGAGE_TARGET_H
#define DEXMILL_CORE_ENGAGE_ENGAGE_TARGET_H

#include <stddef.h>
#include <stdint.h>

#include "core/engage/engage_load.h"
#include "core/engage/engage_meter.h"

namespace dexmill {

enum class EngageTargetKind : uint8_t { kChip = 0, kPower = 1, kMrr = 2 };

struct EngageTarget {
  EngageTargetKind kind = EngageTargetKind::kChip;
  int64_t chip_nm = 0;          // kChip: the chip thickness wanted (0: each material's max_chip)
  int64_t power_mw = 0;         // kPower
  int64_t mrr_um3_per_min = 0;  // kMrr
  int64_t min_feed_nm_per_min = 0;
  int64_t max_feed_nm_per_min = 0;  // the machine's (> 0)
};

enum class EngageFeedWhy : uint8_t {
  kTarget = 0,  // set by the target (then bounded)
  kAir = 1,     // removed nothing: the highest feed
  kKept = 2,    // the engagement cannot say: the programmed feed
};

// The feed for m (whose material's chip limit and coefficients are given:
// a kChip target of 0 takes max_chip_nm, and without one the move keeps
// its feed), bounded by the target's feeds and the material's max feed.
int64_t engage_target_feed(const EngageTarget& t, const EngageMove& m, const CuttingCoefficients& c,
                           int64_t max_chip_nm, int64_t material_max_feed_nm_per_min, EngageFeedWhy* why);

// Each line's feed, the lowest of its moves' (caller memory, lines
// 0 .. n - 1, INT64_MAX where none was set), and whether one of them kept
// its programmed feed.
struct EngageLineFeeds {
  int64_t* feed_nm_per_min = nullptr;
  uint8_t* kept = nullptr;  // 1: a move of the line kept its programmed feed (a plunge, ...)
  size_t n = 0;
};
void engage_line_feeds_clear(EngageLineFeeds* f);
void engage_line_feeds_add(EngageLineFeeds* f, uint32_t line, int64_t feed_nm_per_min, EngageFeedWhy why);

}  // namespace dexmill

#endif
