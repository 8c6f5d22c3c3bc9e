// Value noise and its fractal sums; see noise.h for formats and bounds.
//
// Everything that can be negative is kept away from shifts: lattice
// coordinates are split into cell and fraction with an unsigned shift of a
// biased value, the blend runs on unsigned 16-bit corner values.
#include "core/material/noise.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

// Lattice coordinates carry this many fraction bits before an octave picks
// its own: octave i uses floor(x * 2^(16 + i) / f), exact for every i below
// kNoiseMaxOctaves by taking the floor of a floor.
constexpr int kUFracBits = 16 + kNoiseMaxOctaves - 1;
// |u| <= 2^46 * 2^23 / 1000 < 2^60: adding 2^62 makes it positive.
constexpr uint64_t kUBias = static_cast<uint64_t>(1) << 62;

inline uint32_t fmix32(uint32_t h) {
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

// floor(u / 2^s) for |u| < 2^62, without shifting a negative value.
inline int64_t floor_shift(int64_t u, int s) {
  return static_cast<int64_t>((static_cast<uint64_t>(u) + kUBias) >> s) - static_cast<int64_t>(kUBias >> s);
}

// The lattice coordinate of one axis, kUFracBits fraction bits.
inline int64_t lattice_u(int64_t x_nm, int64_t feature_nm) {
  return muldiv_floor(clamp(x_nm, -kCoordLimitNm, kCoordLimitNm), static_cast<int64_t>(1) << kUFracBits, feature_nm);
}

// The three stages of noise_lattice_hash.
inline uint32_t hash_i(uint32_t i, uint32_t seed) { return fmix32(seed ^ (i * 0x9e3779b1u)); }
inline uint32_t hash_j(uint32_t h, uint32_t j) { return fmix32(h ^ (j * 0x85ebca77u)); }
inline uint32_t hash_k(uint32_t h, uint32_t k) { return fmix32(h ^ (k * 0xc2b2ae3du)); }

// a + (b - a) w for unsigned 16-bit a, b and w in q16 (0..65536), rounded to
// nearest: never outside [min(a, b), max(a, b)], and below 2^32 throughout.
inline uint32_t blend_u16(uint32_t a, uint32_t b, uint32_t w_q16) {
  return (a * (65536u - w_q16) + b * w_q16 + 32768u) >> 16;
}

// Noise at lattice coordinates with 16 fraction bits, as unsigned 16 bits.
// The eight corner hashes share their first stages (noise_lattice_hash
// mixes i, then j, then k): 2 + 4 + 8 finalisers instead of 24, same bits.
uint32_t noise_u16(int64_t ux, int64_t uy, int64_t uz, uint32_t seed) {
  const uint32_t i = static_cast<uint32_t>(static_cast<uint64_t>(floor_shift(ux, 16)));
  const uint32_t j = static_cast<uint32_t>(static_cast<uint64_t>(floor_shift(uy, 16)));
  const uint32_t k = static_cast<uint32_t>(static_cast<uint64_t>(floor_shift(uz, 16)));
  const uint32_t wx = noise_fade_q16(static_cast<uint32_t>(static_cast<uint64_t>(ux)) & 0xffffu);
  const uint32_t wy = noise_fade_q16(static_cast<uint32_t>(static_cast<uint64_t>(uy)) & 0xffffu);
  const uint32_t wz = noise_fade_q16(static_cast<uint32_t>(static_cast<uint64_t>(uz)) & 0xffffu);
  uint32_t hx[2], hxy[2][2];
  for (uint32_t dx = 0; dx < 2; ++dx) hx[dx] = hash_i(i + dx, seed);
  for (uint32_t dx = 0; dx < 2; ++dx)
    for (uint32_t dy = 0; dy < 2; ++dy) hxy[dx][dy] = hash_j(hx[dx], j + dy);
  uint32_t plane[2];
  for (uint32_t dz = 0; dz < 2; ++dz) {
    const uint32_t y0 = blend_u16(hash_k(hxy[0][0], k + dz) >> 16, hash_k(hxy[1][0], k + dz) >> 16, wx);
    const uint32_t y1 = blend_u16(hash_k(hxy[0][1], k + dz) >> 16, hash_k(hxy[1][1], k + dz) >> 16, wx);
    plane[dz] = blend_u16(y0, y1, wy);
  }
  return blend_u16(plane[0], plane[1], wz);
}

struct LatticeU {
  int64_t x, y, z;
};

LatticeU lattice_point(PointNm p, int64_t feature_nm) {
  const int64_t f = clamp(feature_nm, kNoiseMinFeatureNm, kNoiseMaxFeatureNm);
  return LatticeU{lattice_u(p.x_nm, f), lattice_u(p.y_nm, f), lattice_u(p.z_nm, f)};
}

// Octave i's noise, q15, from the common lattice point.
inline int32_t octave_q15(const LatticeU& u, int32_t i, uint32_t seed) {
  const int s = kUFracBits - 16 - i;
  return static_cast<int32_t>(noise_u16(floor_shift(u.x, s), floor_shift(u.y, s), floor_shift(u.z, s),
                                        seed + static_cast<uint32_t>(i))) -
         kNoiseOne;
}

}  // namespace

uint32_t noise_lattice_hash(uint32_t i, uint32_t j, uint32_t k, uint32_t seed) {
  return hash_k(hash_j(hash_i(i, seed), j), k);
}

int32_t noise_lattice_value_q15(int64_t i, int64_t j, int64_t k, uint32_t seed) {
  const uint32_t h = noise_lattice_hash(static_cast<uint32_t>(static_cast<uint64_t>(i)), static_cast<uint32_t>(static_cast<uint64_t>(j)),
                                        static_cast<uint32_t>(static_cast<uint64_t>(k)), seed);
  return static_cast<int32_t>(h >> 16) - kNoiseOne;
}

uint32_t noise_fade_q16(uint32_t t_q16) {
  // s = t^3 (6t^2 - 15t + 10); the quadratic is >= 1 on [0, 1), so it is
  // formed unsigned: 6t^2 + 10 - 15t in q32 (< 10 * 2^32), then q28 so that
  // its product with t^3 (q32, < 2^32) fits 64 bits.
  const uint64_t t = t_q16 & 0xffffu;
  const uint64_t t2 = t * t;                                          // q32
  const uint64_t quad_q32 = 6 * t2 + (static_cast<uint64_t>(10) << 32) - 15 * (t << 16);
  const uint64_t t3_q32 = (t2 * t) >> 16;
  return static_cast<uint32_t>((t3_q32 * (quad_q32 >> 4) + (static_cast<uint64_t>(1) << 43)) >> 44);
}

int32_t noise3_q15(PointNm p, int64_t feature_nm, uint32_t seed) {
  return octave_q15(lattice_point(p, feature_nm), 0, seed);
}

int32_t fbm_q15(PointNm p, int64_t feature_nm, int32_t octaves, uint32_t seed) {
  const int32_t n = clamp<int32_t>(octaves, 1, kNoiseMaxOctaves);
  const LatticeU u = lattice_point(p, feature_nm);
  int64_t acc = 0;  // sum n_i 2^(n-1-i): the weights as integers
  for (int32_t i = 0; i < n; ++i) acc += static_cast<int64_t>(octave_q15(u, i, seed)) * (static_cast<int64_t>(1) << (n - 1 - i));
  return static_cast<int32_t>(div_floor(acc, (static_cast<int64_t>(1) << n) - 1));
}

int32_t turbulence_q15(PointNm p, int64_t feature_nm, int32_t octaves, uint32_t seed) {
  const int32_t n = clamp<int32_t>(octaves, 1, kNoiseMaxOctaves);
  const LatticeU u = lattice_point(p, feature_nm);
  int64_t acc = 0;
  for (int32_t i = 0; i < n; ++i) {
    const int32_t v = octave_q15(u, i, seed);
    acc += static_cast<int64_t>(v < 0 ? -v : v) * (static_cast<int64_t>(1) << (n - 1 - i));
  }
  return static_cast<int32_t>(div_floor(acc, (static_cast<int64_t>(1) << n) - 1));
}

}  // namespace dexmill
