// The load classes of `--color engagement` (display/colour/engage_colours.h):
// every feed move that met material falls in one of kEngageBands bands,
// and the columns it lowered take that band. Two scales, fixed for a run
// so that a legend can name them before the program's peak is known:
// - by the engagement angle (the arc of the edge in material, 0 to a half
//   turn; what a machinist reads as the radial load, with or without a
//   material): 30-degree bands, the last 150 to 180 (a full slot);
// - with load limits (`--check load`: the material's largest chip per
//   tooth, the spindle's power): the larger of chip / max_chip and power /
//   spindle power, in fifths of the limit, the last band over it.
// Integer only: it runs on the panel.
#ifndef DEXMILL_CORE_ENGAGE_ENGAGE_BAND_H
#define DEXMILL_CORE_ENGAGE_ENGAGE_BAND_H

#include <stdint.h>

#include "core/engage/engage_meter.h"

namespace dexmill {

constexpr int32_t kEngageBands = 6;  // classes 1..6 (0: never cut by a measured move)
// The class of a feed move that removed material where no engagement was
// measured: a plunge (straight down, no feed direction to sample along).
constexpr uint8_t kEngageBandUnmeasured = kEngageBands + 1;

// The upper edges of the bands but the last: degrees, or percent of the limit.
extern const int32_t kEngageBandAngleDeg[kEngageBands - 1];
extern const int32_t kEngageBandLimitPct[kEngageBands - 1];

// m's band (1..kEngageBands; a move that removed material its samples did
// not see engaged, within an LSB of the surface, is in the first);
// kEngageBandUnmeasured for a feed move that removed material with no
// samples; 0 for the others (removed nothing, or not a feed move).
// by_limits: against spindle_power_mw (0: none; needs m.has_load) and
// max_chip_nm (0: none); else by the engagement angle.
uint8_t engage_band(const EngageMove& m, bool by_limits, int64_t spindle_power_mw, int64_t max_chip_nm);

}  // namespace dexmill

#endif
