// core/material/noise.h against a double-precision evaluation of the same
// algorithm (the same lattice hash and values, the exact cell fraction and
// the exact quintic fade): the bounds stated in noise.h, and the field's
// statistics.
#include <cmath>
#include <cstdlib>
#include <random>

#include "core/material/noise.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// The lattice hash written out again from its definition (murmur3's 32-bit
// finaliser after mixing in each coordinate times an odd constant).
uint32_t fmix(uint32_t h) {
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  return h ^ (h >> 16);
}
uint32_t oracle_hash(uint32_t i, uint32_t j, uint32_t k, uint32_t seed) {
  return fmix(fmix(fmix(seed ^ (i * 0x9e3779b1u)) ^ (j * 0x85ebca77u)) ^ (k * 0xc2b2ae3du));
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// One octave of the oracle: lattice coordinates x * 2^octave / f, exactly.
double oracle_octave(PointNm p, int64_t f, int octave, uint32_t seed) {
  const double scale = std::ldexp(1.0, octave) / static_cast<double>(f);
  const double u[3] = {static_cast<double>(p.x_nm) * scale, static_cast<double>(p.y_nm) * scale,
                       static_cast<double>(p.z_nm) * scale};
  int64_t c[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    const double fl = std::floor(u[a]);
    c[a] = static_cast<int64_t>(fl);
    w[a] = fade(u[a] - fl);
  }
  const uint32_t s = seed + static_cast<uint32_t>(octave);
  double plane[2];
  for (int dz = 0; dz < 2; ++dz) {
    double row[2];
    for (int dy = 0; dy < 2; ++dy) {
      const double a = noise_lattice_value_q15(c[0], c[1] + dy, c[2] + dz, s);
      const double b = noise_lattice_value_q15(c[0] + 1, c[1] + dy, c[2] + dz, s);
      row[dy] = a + (b - a) * w[0];
    }
    plane[dz] = row[0] + (row[1] - row[0]) * w[1];
  }
  return plane[0] + (plane[1] - plane[0]) * w[2];
}

double oracle_sum(PointNm p, int64_t f, int n, uint32_t seed, bool absolute) {
  double acc = 0, wsum = 0;
  for (int i = 0; i < n; ++i) {
    const double v = oracle_octave(p, f, i, seed);
    const double w = std::ldexp(1.0, -i);
    acc += w * (absolute ? std::fabs(v) : v);
    wsum += w;
  }
  return acc / wsum;
}

PointNm random_point(std::mt19937_64& rng, int64_t span_nm) {
  auto coord = [&] { return static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * span_nm + 1)) - span_nm; };
  const int64_t x = coord(), y = coord(), z = coord();
  return PointNm{x, y, z};
}

}  // namespace

TEST(noise_hash_matches_its_definition) {
  std::mt19937 rng(18);
  for (int it = 0; it < 10000; ++it) {
    const uint32_t i = rng(), j = rng(), k = rng(), seed = rng();
    if (!CHECK_EQ(noise_lattice_hash(i, j, k, seed), oracle_hash(i, j, k, seed))) break;
  }
  // Known answers: a change of the hash changes every texture's colours.
  CHECK_EQ(noise_lattice_hash(0, 0, 0, 0), oracle_hash(0, 0, 0, 0));
  CHECK_EQ(noise_lattice_hash(1, 2, 3, 4), 0xaf20004bu);
}

TEST(noise_hash_is_the_lattice_value) {
  // The value at a lattice point is the hash's top 16 bits, centred.
  for (int64_t i = -3; i <= 3; ++i) {
    const uint32_t h = noise_lattice_hash(static_cast<uint32_t>(i), 7u, static_cast<uint32_t>(-i), 5u);
    CHECK_EQ(noise_lattice_value_q15(i, 7, -i, 5u), static_cast<int32_t>(h >> 16) - 32768);
  }
  // At a lattice point the noise is that point's value, exactly.
  const int64_t f = 2000000;
  for (int64_t i = -4; i <= 4; ++i) {
    const PointNm p{i * f, (i + 2) * f, (3 - i) * f};
    CHECK_EQ(noise3_q15(p, f, 9u), noise_lattice_value_q15(i, i + 2, 3 - i, 9u));
  }
  // Neighbouring cells and seeds differ.
  CHECK_NE(noise_lattice_hash(0, 0, 0, 0), noise_lattice_hash(1, 0, 0, 0));
  CHECK_NE(noise_lattice_hash(0, 0, 0, 0), noise_lattice_hash(0, 1, 0, 0));
  CHECK_NE(noise_lattice_hash(0, 0, 0, 0), noise_lattice_hash(0, 0, 1, 0));
  CHECK_NE(noise_lattice_hash(0, 0, 0, 0), noise_lattice_hash(0, 0, 0, 1));
}

TEST(noise_fade_bound) {
  double worst = 0;
  for (uint32_t t = 0; t < 65536; ++t) {
    const double exact = fade(t / 65536.0) * 65536.0;
    const double d = std::fabs(noise_fade_q16(t) - exact);
    if (d > worst) worst = d;
  }
  CHECK_LE(worst, 0.51);  // noise.h; measured 0.5000
  CHECK_EQ(noise_fade_q16(0), 0u);
  CHECK_EQ(noise_fade_q16(32768), 32768u);  // s(1/2) = 1/2
}

TEST(noise_against_double_oracle) {
  std::mt19937_64 rng(19);
  const int64_t features[] = {1000, 7777, 2500000, 8000000, 123456789};
  double worst = 0, bias = 0;
  const int n = 60000;
  for (int it = 0; it < n; ++it) {
    const int64_t f = features[it % 5];
    const PointNm p = random_point(rng, it % 3 == 0 ? 500000000 : 40 * f);
    const uint32_t seed = static_cast<uint32_t>(rng());
    const double e = noise3_q15(p, f, seed) - oracle_octave(p, f, 0, seed);
    bias += e;
    if (std::fabs(e) > worst) worst = std::fabs(e);
    if (!CHECK_LE(std::fabs(e), 9.0)) break;  // noise.h
  }
  // The blends round to nearest: no drift (a floor would make it -1.5).
  CHECK_LE(std::fabs(bias / n), 0.25);
  std::printf("  noise3_q15 max |error| = %.3f LSB q15 (bound 9), mean error %.3f\n", worst, bias / n);
}

TEST(noise_fbm_turbulence_against_double_oracle) {
  std::mt19937_64 rng(20);
  double worst = 0;
  for (int it = 0; it < 20000; ++it) {
    const int64_t f = 1000000 + static_cast<int64_t>(rng() % 20000000);
    const int n = 1 + it % kNoiseMaxOctaves;
    const PointNm p = random_point(rng, 200000000);
    const uint32_t seed = static_cast<uint32_t>(rng());
    const double df = std::fabs(fbm_q15(p, f, n, seed) - oracle_sum(p, f, n, seed, false));
    const double dt = std::fabs(turbulence_q15(p, f, n, seed) - oracle_sum(p, f, n, seed, true));
    worst = std::fmax(worst, std::fmax(df, dt));
    if (!CHECK_LE(df, 10.0) || !CHECK_LE(dt, 10.0)) break;  // noise.h
  }
  std::printf("  fbm/turbulence max |error| = %.3f LSB q15 (bound 10)\n", worst);
}

TEST(noise_statistics) {
  // Mean near 0, spread well inside [-1, 1), not constant; turbulence >= 0.
  std::mt19937_64 rng(21);
  const int64_t f = 5000000;
  double sum = 0, sum2 = 0;
  int32_t lo = 32767, hi = -32768, tlo = 32768;
  const int n = 40000;
  for (int it = 0; it < n; ++it) {
    const PointNm p = random_point(rng, 1000000000);
    const int32_t v = noise3_q15(p, f, 3u);
    sum += v;
    sum2 += static_cast<double>(v) * v;
    lo = v < lo ? v : lo;
    hi = v > hi ? v : hi;
    const int32_t fb = fbm_q15(p, f, 5, 3u), tu = turbulence_q15(p, f, 5, 3u);
    CHECK(fb >= -32768 && fb <= 32767);
    CHECK(tu >= 0 && tu <= 32768);
    tlo = tu < tlo ? tu : tlo;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  CHECK_LE(std::fabs(mean), 1000.0);  // 3% of full scale; the standard error is about 100
  CHECK_GE(sd, 6000.0);               // trilinear value noise: about 0.3 of full scale
  CHECK_LE(lo, -25000);
  CHECK_GE(hi, 25000);
  CHECK_GE(tlo, 0);
  std::printf("  noise3_q15 mean %.1f sd %.1f range %d..%d\n", mean, sd, lo, hi);
}

TEST(noise_extremes_are_defined) {
  // The largest coordinates and features, both signs: no overflow (the
  // UBSan build would stop here), results in range.
  const int64_t big = kCoordLimitNm;
  const int64_t feats[] = {1, kNoiseMinFeatureNm, kNoiseMaxFeatureNm, INT64_MAX};
  const int64_t coords[] = {-big, -big + 1, -1, 0, 1, big - 1, big, INT64_MIN, INT64_MAX};
  for (int64_t f : feats)
    for (int64_t c : coords) {
      const PointNm p{c, c / -2, c / 3};
      const int32_t v = noise3_q15(p, f, 1u);
      CHECK(v >= -32768 && v <= 32767);
      const int32_t fb = fbm_q15(p, f, kNoiseMaxOctaves, 1u);
      CHECK(fb >= -32768 && fb <= 32767);
      CHECK(turbulence_q15(p, f, 99, 1u) >= 0);
    }
}

TEST(noise_continuous_across_cells) {
  // One nm either side of a cell face changes the noise by at most a few LSB
  // (the fade's derivative is 0 at the faces).
  const int64_t f = 3000000;
  for (int64_t i = -5; i <= 5; ++i) {
    const PointNm a{i * f - 1, 1234567, -7654321}, b{i * f, 1234567, -7654321};
    CHECK_LE(std::abs(noise3_q15(a, f, 4u) - noise3_q15(b, f, 4u)), 1);
  }
}
