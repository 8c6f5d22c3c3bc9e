// FNV-1a 64 over explicit little-endian bytes: the golden hashes of grids,
// frames and traces are the same on every CPU, whatever its byte order.
#ifndef DEXMILL_CORE_MATH_HASH_H
#define DEXMILL_CORE_MATH_HASH_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

struct Hash64 {
  uint64_t state_fnv = 14695981039346656037ull;

  void byte(uint8_t b) {
    state_fnv ^= b;
    state_fnv *= 1099511628211ull;
  }
  void bytes(const uint8_t* p, size_t n) {
    for (size_t i = 0; i < n; ++i) byte(p[i]);
  }
  // Unsigned integer of `nbytes` bytes, least significant byte first.
  void uint_le(uint64_t v, int nbytes) {
    for (int i = 0; i < nbytes; ++i) byte(static_cast<uint8_t>(v >> (8 * i)));
  }
  uint64_t value() const { return state_fnv; }
};

}  // namespace dexmill

#endif
