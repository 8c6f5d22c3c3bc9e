// core/math/trig.h against double precision: the bounds stated in trig.h.
#include <cmath>
#include <random>

#include "core/math/trig.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
const double kTwoPi = 6.283185307179586476925286766559;
const double kBamPerRad = 4294967296.0 / kTwoPi;
}  // namespace

TEST(trig_atan_table_matches_double) {
  // Re-derive the CORDIC table: a wrong digit would bias every angle.
  SinCosQ30 s = sincos_bam(0);
  CHECK_NEAR(s.cos_q30, 1 << 30, 2);
  for (int i = 0; i <= 30; ++i) {
    double a = std::atan(std::ldexp(1.0, -i)) * kBamPerRad;
    uint32_t got = atan2_bam(int64_t(1) << 20, (int64_t(1) << 20) << i);
    CHECK_NEAR(static_cast<double>(got), a, 2.0);
  }
}

TEST(trig_sincos_bound) {
  std::mt19937 rng(11);
  for (int it = 0; it < 200000; ++it) {
    uint32_t a = it < 64 ? static_cast<uint32_t>(it) * 0x04000000u : static_cast<uint32_t>(rng());
    SinCosQ30 s = sincos_bam(a);
    double rad = a / kBamPerRad;
    if (!CHECK_NEAR(static_cast<double>(s.cos_q30), std::cos(rad) * 1073741824.0, 2.0)) break;
    if (!CHECK_NEAR(static_cast<double>(s.sin_q30), std::sin(rad) * 1073741824.0, 2.0)) break;
  }
}

TEST(trig_atan2_bound) {
  std::mt19937_64 rng(12);
  for (int it = 0; it < 200000; ++it) {
    int sh = static_cast<int>(rng() % 62);
    int64_t x = static_cast<int64_t>(rng()) >> (sh + 1), y = static_cast<int64_t>(rng()) >> (rng() % 62 + 1);
    if (x == 0 && y == 0) continue;
    double exact = std::atan2(static_cast<double>(y), static_cast<double>(x));
    if (exact < 0) exact += kTwoPi;
    double got = atan2_bam(y, x);
    double diff = std::fabs(got - exact * kBamPerRad);
    if (diff > 2147483648.0) diff = 4294967296.0 - diff;  // wrap at the full turn
    if (!CHECK_LE(diff, 2.0)) break;
  }
  CHECK_EQ(atan2_bam(0, 0), 0u);
  CHECK_EQ(atan2_bam(0, 5), 0u);
  CHECK_NEAR(static_cast<double>(atan2_bam(5, 0)), 1073741824.0, 2.0);
  CHECK_NEAR(static_cast<double>(atan2_bam(0, -5)), 2147483648.0, 2.0);
}

TEST(trig_degrees) {
  CHECK_EQ(bam_from_mdeg(90000), kBamQuarterTurn);
  CHECK_EQ(bam_from_mdeg(-90000), 3u * kBamQuarterTurn);
  CHECK_EQ(bam_from_mdeg(720000), 0u);
  CHECK_EQ(bam_from_mdeg(45000), 0x20000000u);
}
