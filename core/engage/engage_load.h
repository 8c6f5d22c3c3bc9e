// The load a move puts on the tool and the spindle, from its engagement
// (core/engage/engage_meter.h) and the material's cutting coefficients
// (Kienzle: the specific cutting force kc = kc1.1 h^-mc, h the uncut chip
// in mm, kc1.1 the force per mm^2 of a 1 mm x 1 mm chip).
//
// - Force: the largest tangential force on a tooth, at the thickest chip
//   of the widest sample: F = kc1.1 b h_max^(1 - mc), the edge's engaged
//   length b taken as the axial depth a_p (exact for a flat's straight
//   edge; a ball's or bull's curved edge is longer and its chip thinner
//   along it, so there F is the straight edge's).
// - Power: at the largest cross-section A, P = kc(h_mean) A v_f, the
//   removal rate times the specific force at the mean chip (Sandvik's and
//   Kienzle's milling power).
// - Torque: T = P / omega, omega = 2 pi n / 60.
// Error: pow_ratio_q32's (core/math/pow_ratio.h) and one unit of each
// result, over the engagement's own (engage.h); a chip under a micrometre
// is taken as one (Kienzle's law is not measured below it).
#ifndef DEXMILL_CORE_ENGAGE_ENGAGE_LOAD_H
#define DEXMILL_CORE_ENGAGE_ENGAGE_LOAD_H

#include <stdint.h>

#include "core/engage/engage_meter.h"

namespace dexmill {

struct CuttingCoefficients {
  int32_t kc11_n_per_mm2 = 0;  // 0: not known (no load)
  int32_t mc_ppm = 0;          // the exponent mc, millionths (0.25: 250000)
};

constexpr int64_t kKienzleMinChipNm = 1000;

// The specific cutting force at chip h, kPa (kN/m^2 = mN/mm^2).
int64_t kienzle_kc_kpa(const CuttingCoefficients& c, int64_t chip_nm);
// m's force, torque and power (has_load: a spindle speed, a feed per tooth
// and coefficients given; otherwise the load is left unset).
void engage_load(const EngageTool& t, const CuttingCoefficients& c, EngageMove* m);

}  // namespace dexmill

#endif
