// The material colour mode (`--color material`, paper §2.7):
// every dexel takes the colour of the material just under its top
// (core/material/material.h), so a cut through a two-layer block shows the
// lower layer where it went through and the upper one elsewhere.
//
// Two ways, the caller's choice:
// - flat (material_colours_init alone): one class per material (per band of
//   a layers texture), one ramp each; no memory beyond the class bytes.
// - textured (then material_colours_texture): each material's 3-D texture
//   (veins, rings, speckles) evaluated at every vertex (paper §2.7.1,
//   display/colour/surface_colours.h SurfaceTexture), side faces split at a
//   lattice of a 16th of the stock's height and at the composition's and
//   the layers' z boundaries. A dexel's top colour is kept with the top it
//   was worked out for and recomputed only when that top changes, so
//   turning the camera costs no texture evaluation. Tops the cut never
//   lowered (at or above `uncut_top_lsb`) are tinted towards grey, so that
//   stock left uncut stands apart from machined faces.
#ifndef DEXMILL_DISPLAY_COLOUR_MATERIAL_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_MATERIAL_COLOURS_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/material/material.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

// A material's colour as one swatch: its plain colour, or its texture's
// base (marble's white, wood's light wood, bronze's base, granite's grey,
// layers' bottom band).
Rgb material_swatch(const Material& m);

template <class H>
struct MaterialColours {
  const DexelGrid<H>* grid = nullptr;
  const StockComposition* comp = nullptr;
  // Material k's first class; a layers texture has one class a band (the
  // paper's two-layer block is one material, black over yellow).
  uint8_t first_class[kCompositionMaxMaterials] = {};
  SurfaceColours colours;  // what the renderer takes (renderer_set_colours)
  // Textured (material_colours_texture):
  SurfaceTexture texture;
  uint32_t* top_rgb = nullptr;  // per dexel, the colour under its top
  H* rgb_top = nullptr;         // per dexel, the top top_rgb is for
  bool rgb_valid = false;       // rgb_top filled
  uint32_t uncut_top_lsb = 0;   // tops at or above it are stock left uncut (0: none)
};

// The colour of a texture's tint for uncut stock: halfway to a neutral grey.
uint32_t material_uncut_tint(uint32_t rgb);

// Sets m up for grid g made of c (at most kMaxColourClasses classes: more
// share the last one's colour); cls (nx*ny bytes) and luts
// (kMaxColourClasses * kShadeLevels words) are caller memory. m must stay
// where it is while a renderer uses m->colours.
template <class H>
void material_colours_init(MaterialColours<H>* m, const DexelGrid<H>& g, const StockComposition& c, uint8_t* cls,
                           uint32_t* luts);

// Bytes of caller memory material_colours_texture needs for grid g.
template <class H>
size_t material_texture_bytes(const DexelGrid<H>& g) {
  return static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny) * (sizeof(uint32_t) + sizeof(H));
}

// Turns m (set up by material_colours_init) to colours per vertex: mem is
// material_texture_bytes(g) bytes of caller memory, 4-byte aligned;
// uncut_top_lsb as above (the stock's top, or 0 for no tint). The next
// classify works every dexel out.
template <class H>
void material_colours_texture(MaterialColours<H>* m, void* mem, uint32_t uncut_top_lsb);

extern template void material_colours_texture<uint8_t>(MaterialColours<uint8_t>*, void*, uint32_t);
extern template void material_colours_texture<uint16_t>(MaterialColours<uint16_t>*, void*, uint32_t);
extern template void material_colours_texture<uint32_t>(MaterialColours<uint32_t>*, void*, uint32_t);

extern template void material_colours_init<uint8_t>(MaterialColours<uint8_t>*, const DexelGrid<uint8_t>&,
                                                    const StockComposition&, uint8_t*, uint32_t*);
extern template void material_colours_init<uint16_t>(MaterialColours<uint16_t>*, const DexelGrid<uint16_t>&,
                                                     const StockComposition&, uint8_t*, uint32_t*);
extern template void material_colours_init<uint32_t>(MaterialColours<uint32_t>*, const DexelGrid<uint32_t>&,
                                                     const StockComposition&, uint8_t*, uint32_t*);

}  // namespace dexmill

#endif
