// The heightmap image of a grid (`dexmill run --heightmap`): the final tops
// as 16-bit grey samples, what the PGM and PNG heightmaps both hold.
#ifndef DEXMILL_PLATFORM_FORMAT_HEIGHTMAP_H
#define DEXMILL_PLATFORM_FORMAT_HEIGHTMAP_H

#include <cstdint>

#include "core/config.h"
#include "core/grid/grid.h"

namespace dexmill {

// Fills img (g.nx * g.ny samples, row 0 the top of the picture) from the
// grid: row 0 is the grid's last row (north up); a sample is the top height
// in LSB (the report gives the LSB), 65535 for any higher, holes 0.
void heightmap_samples(const DexelGrid<height_t>& g, uint16_t* img);

}  // namespace dexmill

#endif
