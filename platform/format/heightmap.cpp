// The heightmap's samples; see heightmap.h.
#include "platform/format/heightmap.h"

#include <cstddef>

namespace dexmill {

void heightmap_samples(const DexelGrid<height_t>& g, uint16_t* img) {
  const std::size_t nx = static_cast<std::size_t>(g.nx);
  for (int32_t j = 0; j < g.ny; ++j) {
    uint16_t* row = img + static_cast<std::size_t>(g.ny - 1 - j) * nx;
    for (int32_t i = 0; i < g.nx; ++i) {
      const uint64_t h = g.top[g.index(i, j)];
      row[i] = static_cast<uint16_t>(h > 65535 ? 65535 : h);
    }
  }
}

}  // namespace dexmill
