// A small deterministic random generator for tests (xorshift64*): the same
// inputs on every run and every platform.
#ifndef DEXMILL_TESTS_RNG_H
#define DEXMILL_TESTS_RNG_H

#include <cstdint>

namespace t {

struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed = 1) : s(seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull) {}
  uint64_t next() {
    s ^= s >> 12;
    s ^= s << 25;
    s ^= s >> 27;
    return s * 2685821657736338717ull;
  }
  // Uniform in [lo, hi].
  int64_t range(int64_t lo, int64_t hi) { return lo + static_cast<int64_t>(next() % static_cast<uint64_t>(hi - lo + 1)); }
  // Log-uniform in [1, 2^32): every octave as often.
  uint32_t u32_log() {
    const int bits = 1 + static_cast<int>(next() % 32);
    uint32_t v = static_cast<uint32_t>(next() >> 32);
    v = bits == 32 ? v : (v & ((1u << bits) - 1)) | (1u << (bits - 1));
    return v ? v : 1;
  }
};

}  // namespace t

#endif
