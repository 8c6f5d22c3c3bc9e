// CRC-32 of ISO 3309 (the PNG specification's, section 5.5: reflected
// polynomial 0xEDB88320, register preset to all ones and inverted at the
// end): PNG's chunks (platform/format/png.cpp) and the stock file's header
// and tiles (core/stock/stock_file.h) are checked with it.
#ifndef DEXMILL_CORE_MATH_CRC32_H
#define DEXMILL_CORE_MATH_CRC32_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

// Start with crc = 0; data in pieces may be fed by passing each call's
// result to the next. crc32_update(0, "123456789", 9) == 0xCBF43926.
// Four table look-ups per four bytes (slicing by four, 4 KiB of tables),
// same value as a byte at a time: 0.76 ns a byte against 2.2 on this
// project's build machine (64 MiB, g++ -O2).
uint32_t crc32_update(uint32_t crc, const uint8_t* p, size_t n);

}  // namespace dexmill

#endif
