// CRC-32 by slicing by four: table k holds the register after byte b
// followed by k zero bytes, so four bytes fold into the register with four
// independent look-ups (core/math/crc32.h).
#include "core/math/crc32.h"

namespace dexmill {
namespace {

// 0x04C11DB7 with its bits reversed: the CRC works on bits least
// significant first, so the tables are built for the reflected polynomial.
constexpr uint32_t kCrc32PolynomialReflected = 0xEDB88320u;

struct Crc32Tables {
  uint32_t t[4][256];
};

constexpr Crc32Tables make_tables() {
  Crc32Tables s{};
  for (uint32_t byte = 0; byte < 256; ++byte) {
    uint32_t c = byte;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1) ? kCrc32PolynomialReflected ^ (c >> 1) : c >> 1;
    s.t[0][byte] = c;
  }
  for (uint32_t byte = 0; byte < 256; ++byte)
    for (int k = 1; k < 4; ++k) s.t[k][byte] = s.t[0][s.t[k - 1][byte] & 0xFFu] ^ (s.t[k - 1][byte] >> 8);
  return s;
}

constexpr Crc32Tables kTables = make_tables();

}  // namespace

uint32_t crc32_update(uint32_t crc, const uint8_t* p, size_t n) {
  // The register is kept inverted between calls, so a running value of 0
  // means "no data yet" and the result is the finished CRC.
  uint32_t c = ~crc;
  size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    c ^= static_cast<uint32_t>(p[i]) | static_cast<uint32_t>(p[i + 1]) << 8 | static_cast<uint32_t>(p[i + 2]) << 16 |
         static_cast<uint32_t>(p[i + 3]) << 24;
    c = kTables.t[3][c & 0xFFu] ^ kTables.t[2][(c >> 8) & 0xFFu] ^ kTables.t[1][(c >> 16) & 0xFFu] ^ kTables.t[0][c >> 24];
  }
  for (; i < n; ++i) c = kTables.t[0][(c ^ p[i]) & 0xFFu] ^ (c >> 8);
  return ~c;
}

}  // namespace dexmill
