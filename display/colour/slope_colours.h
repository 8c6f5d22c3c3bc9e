// The slope colour mode (`--color slope`, paper §2.7.2: a physically based
// texture from the derivative of the height, which accentuates edges):
// every dexel in the band of its surface's angle from the horizontal,
// from the central differences of the tops (core/grid/grid.h
// grid_gradient, the gradient the normals start from): flat, gentle,
// steep, wall. A class depends on the four neighbours, so classify
// recomputes the dexels one past the rectangle it is given (kClassReach
// allows two).
#ifndef DEXMILL_DISPLAY_COLOUR_SLOPE_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_SLOPE_COLOURS_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

enum SlopeBand : uint8_t { kSlopeFlat = 0, kSlopeGentle = 1, kSlopeSteep = 2, kSlopeWall = 3 };
constexpr int32_t kSlopeBands = 4;

// Band k + 1 starts at kSlopeLimitDeg[k] degrees (inclusive).
extern const int32_t kSlopeLimitDeg[kSlopeBands - 1];
// Light to dark, grey to deep red: the steeper, the darker, so edges read
// as lines.
extern const Rgb kSlopeBandColour[kSlopeBands];

// The band of dexel (i, j) of g (holes next to it count as height 0, as
// they do for the normals: a dexel beside a hole is a wall's top).
template <class H>
SlopeBand slope_band(const DexelGrid<H>& g, int32_t i, int32_t j);

template <class H>
struct SlopeColours {
  const DexelGrid<H>* grid = nullptr;
  SurfaceColours colours;  // what the renderer takes (renderer_set_colours)
};

// Sets s up for grid g; cls (nx*ny bytes) and luts (kSlopeBands *
// kShadeLevels words) are caller memory. s must stay where it is while a
// renderer uses s->colours.
template <class H>
void slope_colours_init(SlopeColours<H>* s, const DexelGrid<H>& g, uint8_t* cls, uint32_t* luts);

#define DEXMILL_SLOPE_COLOURS_EXTERN(H)                                               \
  extern template SlopeBand slope_band<H>(const DexelGrid<H>&, int32_t, int32_t); \
  extern template void slope_colours_init<H>(SlopeColours<H>*, const DexelGrid<H>&, uint8_t*, uint32_t*);
DEXMILL_SLOPE_COLOURS_EXTERN(uint8_t)
DEXMILL_SLOPE_COLOURS_EXTERN(uint16_t)
DEXMILL_SLOPE_COLOURS_EXTERN(uint32_t)
#undef DEXMILL_SLOPE_COLOURS_EXTERN

}  // namespace dexmill

#endif
