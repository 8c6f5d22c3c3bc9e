// The load classes of --color engagement; see engage_band.h.
#include "core/engage/engage_band.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

const int32_t kEngageBandAngleDeg[kEngageBands - 1] = {30, 60, 90, 120, 150};
const int32_t kEngageBandLimitPct[kEngageBands - 1] = {20, 40, 60, 80, 100};

namespace {

// value / limit in parts per million, saturated far above 1 (limit > 0).
int64_t ratio_ppm(int64_t value, int64_t limit) {
  if (value <= 0) return 0;
  if (value >= limit * 4) return 4000000;
  return value * 1000000 / limit;  // value < 4 limit: no overflow for any limit below 2^41
}

}  // namespace

uint8_t engage_band(const EngageMove& m, bool by_limits, int64_t spindle_power_mw, int64_t max_chip_nm) {
  if (!m.feed) return 0;
  if (m.removed_lsb == 0) return 0;
  // Not sampled: no feed direction (a plunge).
  if (m.samples == 0) return kEngageBandUnmeasured;
  if (!by_limits) {
    // Bands of a sixth of a half turn; a full slot (a half turn, the
    // last step's 179.99 degrees) in the last.
    const uint64_t k = static_cast<uint64_t>(m.worst.angle_bam()) * kEngageBands / kBamHalfTurn;
    return static_cast<uint8_t>(1 + min_of<uint64_t>(k, kEngageBands - 1));
  }
  int64_t f = 0;
  if (max_chip_nm > 0) f = ratio_ppm(m.chip.max_nm, max_chip_nm);
  if (spindle_power_mw > 0 && m.has_load) f = max_of(f, ratio_ppm(m.power_mw, spindle_power_mw));
  if (f > 1000000) return kEngageBands;
  // Fifths of the limit, the limit itself in the fifth.
  return static_cast<uint8_t>(1 + min_of<int64_t>(f * (kEngageBands - 1) / 1000000, kEngageBands - 2));
}

}  // namespace dexmill
