// A colour mode's classes (paper §2.7: colours "created on the fly during
// surface building"): every dexel belongs to one of a few classes, each
// class has its own ramp, and a face takes the ramp of one corner: a top
// triangle its lowest corner's (a slope the colour of the floor it drops
// to), a side face its own dexel's (a wall the colour of its top). The error view (§2.5.1, figure 10) is the
// first mode; tool, slope and material colours are others. Off (null): one
// ramp for the whole workpiece, as before, at the cost of one test a cell.
#ifndef DEXMILL_DISPLAY_SURFACE_COLOURS_H
#define DEXMILL_DISPLAY_SURFACE_COLOURS_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "display/framebuffer.h"
#include "display/raster.h"

namespace dexmill {

constexpr int32_t kMaxColourClasses = 8;

struct SurfaceColours {
  uint8_t* cls = nullptr;     // per dexel (nx*ny, row-major), caller memory; each < nclasses
  uint32_t* luts = nullptr;   // nclasses * kShadeLevels pixel values, caller memory (the renderer fills them)
  int32_t nclasses = 0;       // 1..kMaxColourClasses
  Rgb colour[kMaxColourClasses];
  // Recomputes cls over r after the grid changed there; the renderer calls
  // it for every rectangle it is about to redraw, before drawing.
  void (*classify)(void* ctx, GridRect r, uint8_t* cls) = nullptr;
  void* ctx = nullptr;
};

}  // namespace dexmill

#endif
