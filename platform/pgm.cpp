#include "platform/pgm.h"

#include <cstdio>
#include <vector>

#include "platform/atomic_file.h"

namespace dexmill {

bool write_pgm16(const char* path, int width, int height, const uint16_t* samples, char* err, std::size_t errn) {
  AtomicFile f;
  if (f.open(path)) {
    f.printf("P5\n%d %d\n65535\n", width, height);
    std::vector<uint8_t> row(static_cast<std::size_t>(width) * 2);
    for (int y = 0; y < height; ++y) {
      const uint16_t* s = samples + static_cast<std::size_t>(y) * width;
      for (int x = 0; x < width; ++x) {
        row[2 * x] = static_cast<uint8_t>(s[x] >> 8);
        row[2 * x + 1] = static_cast<uint8_t>(s[x]);
      }
      f.write(row.data(), row.size());
    }
    if (f.commit()) return true;
  }
  std::snprintf(err, errn, "%s", f.error());
  return false;
}

}  // namespace dexmill
