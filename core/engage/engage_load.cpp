// core/engage/engage_load.h: Kienzle's force, the spindle's power and torque.
#include "core/engage/engage_load.h"

#include "core/math/fixed.h"
#include "core/math/pow_ratio.h"

namespace dexmill {

namespace {
constexpr uint64_t kNmPerMmU = 1000000;
}  // namespace

int64_t kienzle_kc_kpa(const CuttingCoefficients& c, int64_t chip_nm) {
  const uint64_t h = static_cast<uint64_t>(max_of(chip_nm, kKienzleMinChipNm));
  // kc1.1 (h / 1 mm)^-mc: kc1.1 below 2^31, the power below 2^52 (q32) for
  // a chip of a micrometre and mc up to 2.
  const int64_t f_q32 = pow_ratio_q32(h, kNmPerMmU, -c.mc_ppm);
  return mul_shift(static_cast<int64_t>(c.kc11_n_per_mm2) * 1000, f_q32, 32);
}

void engage_load(const EngageTool& t, const CuttingCoefficients& c, EngageMove* m) {
  m->has_load = false;
  if (c.kc11_n_per_mm2 <= 0 || m->spindle_rpm <= 0 || m->fz_nm <= 0 || !m->worst.engaged) return;
  m->has_load = true;
  // Force: kc1.1 a_p h^(1 - mc), a_p in um gives mN.
  const uint64_t h = static_cast<uint64_t>(max_of(m->chip.max_nm, kKienzleMinChipNm));
  const int64_t g_q32 = pow_ratio_q32(h, kNmPerMmU, 1000000 - c.mc_ppm);
  m->force_mn = mul_shift(static_cast<int64_t>(c.kc11_n_per_mm2) * (m->worst.ap_nm / 1000), g_q32, 32);
  // Power: kc (kPa = 10^-3 N/mm^2) x MRR (um^3/min = 10^-9 mm^3/min):
  // 10^-12 N mm/min = 10^-15 / 60 W; in mW, over 6 x 10^13.
  const EngageChip section = engage_chip(t, m->section, m->fz_nm);
  const int64_t kc_kpa = kienzle_kc_kpa(c, section.mean_nm);
  m->power_mw = muldiv_round(m->mrr_um3_per_min, kc_kpa, 60000000000000LL);
  // Torque: P / omega = P 60 / (2 pi n); 2 pi x 10^6 = 6283185.3.
  m->torque_mn_m = muldiv_round(m->power_mw, 60000000, 6283185LL * m->spindle_rpm);
}

}  // namespace dexmill
