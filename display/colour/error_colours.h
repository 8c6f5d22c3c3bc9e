// The error view's colour mode (paper §2.5.1, figure 10): the classes are
// core/assess's error bands of each dexel against the design, the ramps
// the bands' colours (white within tolerance; greens for material left, reds
// for gouges, light to dark; the workpiece's grey where there is no design).
// One set-up for every user: `dexmill run --color error`, the panel, the
// golden frames.
#ifndef DEXMILL_DISPLAY_COLOUR_ERROR_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_ERROR_COLOURS_H

#include <stdint.h>

#include "core/assess/assess.h"
#include "core/design/design.h"
#include "core/grid/grid.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

// The bands' colours, indexed by ErrorBand.
extern const Rgb kErrorBandColour[kErrorBands];

template <class H>
struct ErrorColours {
  const DexelGrid<H>* grid = nullptr;
  const DesignGrid* design = nullptr;
  AssessOptions opt;
  SurfaceColours colours;  // what the renderer takes (renderer_set_colours)
};

// Sets e up for grid g against design d; cls (nx*ny bytes) and luts
// (kErrorBands * kShadeLevels words) are caller memory. e must stay where it
// is while a renderer uses e->colours.
template <class H>
void error_colours_init(ErrorColours<H>* e, const DexelGrid<H>& g, const DesignGrid& d, const AssessOptions& o,
                        uint8_t* cls, uint32_t* luts);

extern template void error_colours_init<uint8_t>(ErrorColours<uint8_t>*, const DexelGrid<uint8_t>&, const DesignGrid&,
                                                 const AssessOptions&, uint8_t*, uint32_t*);
extern template void error_colours_init<uint16_t>(ErrorColours<uint16_t>*, const DexelGrid<uint16_t>&,
                                                  const DesignGrid&, const AssessOptions&, uint8_t*, uint32_t*);
extern template void error_colours_init<uint32_t>(ErrorColours<uint32_t>*, const DexelGrid<uint32_t>&,
                                                  const DesignGrid&, const AssessOptions&, uint8_t*, uint32_t*);

}  // namespace dexmill

#endif
