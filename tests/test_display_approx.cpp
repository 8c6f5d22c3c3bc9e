// display/raster/approx.h against a double-precision oracle: the stated bounds.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>

#include "display/raster/approx.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using t::Rng;

double value(ScaledRecip r) { return std::ldexp(static_cast<double>(r.m), -r.shift); }

}  // namespace

TEST(recip_u32_within_bound) {
  Rng rng;
  double worst = 0;
  auto check = [&](uint32_t v) {
    const double exact = 1.0 / v, got = value(recip_u32(v));
    const double rel = std::fabs(got - exact) * v;  // error in units of 1/v
    worst = rel > worst ? rel : worst;
    CHECK_LE(rel, std::ldexp(1.0, -28));
  };
  for (uint32_t v = 1; v < 70000; ++v) check(v);
  for (int k = 0; k < 2000000; ++k) check(rng.u32_log());
  for (uint32_t v : {0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFFu, 0xFFFFFFFEu}) check(v);
  std::printf("recip_u32: worst relative error %.3g (bound 2^-28 = %.3g)\n", worst, std::ldexp(1.0, -28));
}

TEST(rsqrt_within_bounds) {
  Rng rng;
  double worst = 0, worst_fast = 0;
  auto check = [&](uint32_t v) {
    const double exact = 1.0 / std::sqrt(static_cast<double>(v));
    const double rel = std::fabs(value(rsqrt_u32(v)) - exact) / exact;
    const double rel_fast = std::fabs(value(rsqrt_fast_u32(v)) - exact) / exact;
    worst = rel > worst ? rel : worst;
    worst_fast = rel_fast > worst_fast ? rel_fast : worst_fast;
    CHECK_LE(rel, std::ldexp(1.0, -28));
    CHECK_LE(rel_fast, std::ldexp(1.0, -15));
  };
  for (uint32_t v = 1; v < 70000; ++v) check(v);
  for (int k = 0; k < 2000000; ++k) check(rng.u32_log());
  for (uint32_t v : {0x3FFFFFFFu, 0x40000000u, 0xFFFFFFFFu}) check(v);
  std::printf("rsqrt_u32: worst %.3g (bound %.3g); rsqrt_fast_u32: worst %.3g (bound %.3g)\n", worst,
              std::ldexp(1.0, -28), worst_fast, std::ldexp(1.0, -15));
}

TEST(scale_recip_divides) {
  Rng rng;
  for (int k = 0; k < 200000; ++k) {
    const uint32_t v = rng.u32_log();
    const int64_t x = static_cast<int64_t>(rng.next() % (1ull << 32)) - (int64_t(1) << 31);
    const int64_t got = scale_recip(x, recip_u32(v));
    // 1/v carries relative error 2^-28: |x/v| < 2^31 adds at most 2^3 to
    // the rounding's 1/2.
    CHECK_NEAR(static_cast<double>(got), static_cast<double>(x) / v, 0.5 + std::ldexp(std::fabs(static_cast<double>(x) / v), -28) + 1e-9);
  }
}

TEST(normal_unit_q14_within_bound) {
  Rng rng;
  double worst = 0;
  for (int k = 0; k < 500000; ++k) {
    // Magnitudes from 1 to 2^60 per component, any sign, some zeros.
    int64_t c[3];
    for (int64_t& v : c) {
      const int bits = static_cast<int>(rng.next() % 61);
      v = bits == 0 ? 0 : static_cast<int64_t>(rng.next() >> (64 - bits));
      if (rng.next() & 1) v = -v;
    }
    if (c[0] == 0 && c[1] == 0 && c[2] == 0) c[2] = 1;
    const UnitQ14 u = normal_unit_q14(c[0], c[1], c[2]);
    const double len = std::sqrt(double(c[0]) * c[0] + double(c[1]) * c[1] + double(c[2]) * c[2]);
    const int32_t got[3] = {u.x, u.y, u.z};
    for (int a = 0; a < 3; ++a) {
      const double err = std::fabs(got[a] - 16384.0 * c[a] / len);
      worst = err > worst ? err : worst;
      CHECK_LE(err, 2.0);
    }
  }
  const UnitQ14 z = normal_unit_q14(0, 0, 0);
  CHECK_EQ(z.z, 16384);
  std::printf("normal_unit_q14: worst component error %.3f q14 LSB (bound 2)\n", worst);
}
