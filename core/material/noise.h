// Hashed integer lattice value noise in 3-D and its fractal sums (paper §2.7.1:
// the stochastic textures, marble and bronze, are built from it).
//
// Value noise: every lattice point (i, j, k) of a cubic lattice of pitch
// `feature_nm` gets a pseudo-random value from an unsigned 32-bit hash of
// (i, j, k, seed); between lattice points the eight corner values are blended
// trilinearly with Perlin's quintic fade s(t) = 6t^5 - 15t^4 + 10t^3, so the
// field and its first two derivatives are continuous.
//
// Formats (all integer; the same bits on every CPU, tests/golden "texture"):
//   positions   int64 nm, clamped to +-kCoordLimitNm (core/point.h)
//   feature_nm  the lattice pitch, clamped to [kNoiseMinFeatureNm, kNoiseMaxFeatureNm]
//   lattice t   q16 fraction of the cell, floor((x mod f) * 2^16 / f)
//   fade        q16, rounded to nearest
//   noise       q15: an int32 in [-32768, 32767], value / 32768 in [-1, 1)
//
// Error bound (enforced by tests/test_noise.cpp against a double-precision
// evaluation of the same lattice values with the exact, unquantised cell
// fraction and the exact quintic fade): |noise3_q15 - oracle| <= 9 LSB of
// q15 (2.7e-4): per blend level, t's quantisation (< 2^-16, times the fade's
// slope <= 1.875) and the fade's rounding (0.51 LSB q16) move the weight by
// < 2.39 / 65536 of a difference < 65536, plus 0.5 for rounding the blend;
// three levels give < 8.67. fbm_q15 and turbulence_q15 (weighted means of
// such octaves, then a floor division) are within 10 LSB of theirs.
#ifndef DEXMILL_CORE_MATERIAL_NOISE_H
#define DEXMILL_CORE_MATERIAL_NOISE_H

#include <stdint.h>

#include "core/point.h"

namespace dexmill {

constexpr int64_t kNoiseMinFeatureNm = 1000;               // 1 um
constexpr int64_t kNoiseMaxFeatureNm = int64_t(1) << 40;   // about 1.1 km
constexpr int32_t kNoiseMaxOctaves = 8;
constexpr int32_t kNoiseOne = 32768;                       // 1.0 in q15

// The unsigned hash of a lattice point: the same function seeds every
// noise of the material layer (murmur3's 32-bit finaliser after each word,
// so neighbouring cells are uncorrelated). Exposed for the tests' oracle.
uint32_t noise_lattice_hash(uint32_t i, uint32_t j, uint32_t k, uint32_t seed);
// The value at a lattice point, q15 in [-32768, 32767]: the hash's top 16 bits.
int32_t noise_lattice_value_q15(int64_t i, int64_t j, int64_t k, uint32_t seed);

// Perlin's quintic fade of t (q16, 0..65535), q16 rounded to nearest:
// within 0.51 LSB of the exact value.
uint32_t noise_fade_q16(uint32_t t_q16);

// Value noise at p, q15 in [-32768, 32767] (never outside the range of the
// eight corner values).
int32_t noise3_q15(PointNm p, int64_t feature_nm, uint32_t seed);

// Fractal sums of `octaves` (clamped to 1..kNoiseMaxOctaves) noises, octave i
// at feature / 2^i with weight 2^-i and seed + i, normalised by the sum of
// the weights (floor division):
//   fbm_q15        sum w_i n_i / sum w_i, q15 in [-32768, 32767]
//   turbulence_q15 sum w_i |n_i| / sum w_i, q15 in [0, 32768]
int32_t fbm_q15(PointNm p, int64_t feature_nm, int32_t octaves, uint32_t seed);
int32_t turbulence_q15(PointNm p, int64_t feature_nm, int32_t octaves, uint32_t seed);

}  // namespace dexmill

#endif
