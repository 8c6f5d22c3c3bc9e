// The thin-floor colour mode (`--color thin --thin MM`, paper §2.7.2: "thin
// regions where top - bottom is small", the floors that crack or that a
// program fades out of, which the programmer must take care of): every
// dexel whose material, top - bottom, is thinner than a limit highlighted,
// in two bands (under half the limit red, under the limit orange), the rest
// in the workpiece's grey. A class depends on its own dexel alone.
#ifndef DEXMILL_DISPLAY_COLOUR_THIN_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_THIN_COLOURS_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

enum ThinBand : uint8_t { kThinNot = 0, kThinUnder = 1, kThinUnderHalf = 2 };
constexpr int32_t kThinBands = 3;

extern const Rgb kThinBandColour[kThinBands];

// The band of dexel (i, j) of g against limit_nm.
template <class H>
ThinBand thin_band(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t limit_nm);

template <class H>
struct ThinColours {
  const DexelGrid<H>* grid = nullptr;
  int64_t limit_nm = 0;    // thinner than this is highlighted
  SurfaceColours colours;  // what the renderer takes (renderer_set_colours)
};

// Sets t up for grid g and a limit; cls (nx*ny bytes) and luts (kThinBands
// * kShadeLevels words) are caller memory. t must stay where it is while a
// renderer uses t->colours.
template <class H>
void thin_colours_init(ThinColours<H>* t, const DexelGrid<H>& g, int64_t limit_nm, uint8_t* cls, uint32_t* luts);

#define DEXMILL_THIN_COLOURS_EXTERN(H)                                                       \
  extern template ThinBand thin_band<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t); \
  extern template void thin_colours_init<H>(ThinColours<H>*, const DexelGrid<H>&, int64_t, uint8_t*, uint32_t*);
DEXMILL_THIN_COLOURS_EXTERN(uint8_t)
DEXMILL_THIN_COLOURS_EXTERN(uint16_t)
DEXMILL_THIN_COLOURS_EXTERN(uint32_t)
#undef DEXMILL_THIN_COLOURS_EXTERN

}  // namespace dexmill

#endif
