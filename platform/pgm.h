// Netpbm grey images: 16-bit PGM (P5, maxval 65535, big-endian samples as
// the format requires).
#ifndef DEXMILL_PLATFORM_PGM_H
#define DEXMILL_PLATFORM_PGM_H

#include <cstddef>
#include <cstdint>

namespace dexmill {

// Writes `width` x `height` samples, row 0 first (the top row of the image),
// atomically. On failure returns false with a message in err.
bool write_pgm16(const char* path, int width, int height, const uint16_t* samples, char* err, std::size_t errn);

}  // namespace dexmill

#endif
