// A colour mode's classes (paper §2.7: colours "created on the fly during
// surface building"): every dexel belongs to one of a few classes, each
// class has its own ramp, and a face takes the ramp of one corner: a top
// triangle its lowest corner's (a slope the colour of the floor it drops
// to), a side face its own dexel's (a wall the colour of its top). The error view (§2.5.1, figure 10) is the
// first mode; tool, slope, thin and material colours are others. Off (null): one
// ramp for the whole workpiece, as before, at the cost of one test a cell.
#ifndef DEXMILL_DISPLAY_COLOUR_SURFACE_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_SURFACE_COLOURS_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "display/raster/framebuffer.h"
#include "display/raster/raster.h"

namespace dexmill {

constexpr int32_t kMaxColourClasses = 8;
constexpr int32_t kTextureBreaksMax = 16;
// Figure 11's bound: a side face is split into at most this many strips
// between lattice heights (plus one more per break it crosses), and into
// no more than one per kWallStripPx pixels of its height on the screen.
constexpr int32_t kWallSplitsMax = 16;
constexpr int32_t kWallStripPx = 12;

// Colour per vertex (paper §2.7.1): a 3-D texture T(x, y, z) evaluated at
// the surface's vertices and interpolated (Gouraud) times the lighting. The
// side faces, long thin polygons from a top down to a bottom, would take
// only two colours each way; they are split at heights (figure 11: "badly
// behaved" polygons made "well behaved"): on a lattice of split_lsb (set
// by the colour mode: material_colours, a 16th of the stock's height; 0:
// none) and at breaks, heights where the colour
// jumps (a layer's boundary), each drawn with the colour below it under it
// and the colour above it over it. The split heights of a column depend on
// that column alone, so two faces sharing a vertical edge share its
// vertices (no cracks).
struct SurfaceTexture {
  const uint32_t* top_rgb = nullptr;  // per dexel: the colour under its top (0x00RRGGBB), kept by classify
  // The colour of the one-LSB slab under height h_lsb in dexel (i, j)'s column.
  uint32_t (*colour_at)(const void* ctx, int32_t i, int32_t j, uint32_t h_lsb) = nullptr;
  const void* ctx = nullptr;
  uint32_t split_lsb = 0;
  uint32_t breaks_lsb[kTextureBreaksMax] = {};  // ascending; the colour changes between h - 1 and h
  int32_t nbreaks = 0;
};

struct SurfaceColours {
  uint8_t* cls = nullptr;     // per dexel (nx*ny, row-major), caller memory; each < nclasses
  uint32_t* luts = nullptr;   // nclasses * kShadeLevels pixel values, caller memory (the renderer fills them)
  int32_t nclasses = 0;       // 1..kMaxColourClasses
  Rgb colour[kMaxColourClasses];
  // Recomputes cls over r after the grid changed there; the renderer calls
  // it for every rectangle it is about to redraw, before drawing.
  // A class may depend on the dexels up to kClassReach away (a slope's
  // central differences): the callback recomputes r grown by its own reach
  // (clipped to the grid), and the renderer redraws the cells that far past
  // a change anyway (the normals' gradient and blur reach two dexels).
  void (*classify)(void* ctx, GridRect r, uint8_t* cls) = nullptr;
  void* ctx = nullptr;
  // Colours per vertex instead of one ramp per class (null: ramps).
  const SurfaceTexture* texture = nullptr;
};

// How far a class may look from its dexel (see classify above).
constexpr int32_t kClassReach = 2;

// Sets c to n classes of the given colours over caller memory (cls: a byte
// a dexel; luts: n * kShadeLevels words), classified by fn(ctx, ...) (null:
// the caller writes cls itself).
inline void surface_colours_set(SurfaceColours* c, uint8_t* cls, uint32_t* luts, const Rgb* colour, int32_t n,
                                void (*fn)(void*, GridRect, uint8_t*), void* ctx) {
  c->cls = cls;
  c->luts = luts;
  c->nclasses = n < kMaxColourClasses ? n : kMaxColourClasses;
  for (int32_t k = 0; k < c->nclasses; ++k) c->colour[k] = colour[k];
  c->classify = fn;
  c->ctx = ctx;
}

// r within g's dexels.
template <class H>
GridRect clip_to_grid(const DexelGrid<H>& g, GridRect r) {
  return GridRect{r.i0 > 0 ? r.i0 : 0, r.j0 > 0 ? r.j0 : 0, r.i1 < g.nx ? r.i1 : g.nx, r.j1 < g.ny ? r.j1 : g.ny};
}

}  // namespace dexmill

#endif
