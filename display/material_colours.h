// The material colour mode (`--color material`, paper §2.7, issue 19, first
// step): every dexel takes the colour of the material just under its top
// (core/material/material.h), one class per material, so a cut through a
// two-layer block shows the lower layer where it went through and the upper
// one elsewhere. Flat per material: the textures' veins, rings and speckles
// are the next step (colour per vertex).
#ifndef DEXMILL_DISPLAY_MATERIAL_COLOURS_H
#define DEXMILL_DISPLAY_MATERIAL_COLOURS_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/material/material.h"
#include "display/surface_colours.h"

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
};

// Sets m up for grid g made of c (at most kMaxColourClasses classes: more
// share the last one's colour); cls (nx*ny bytes) and luts
// (kMaxColourClasses * kShadeLevels words) are caller memory. m must stay
// where it is while a renderer uses m->colours.
template <class H>
void material_colours_init(MaterialColours<H>* m, const DexelGrid<H>& g, const StockComposition& c, uint8_t* cls,
                           uint32_t* luts);

extern template void material_colours_init<uint8_t>(MaterialColours<uint8_t>*, const DexelGrid<uint8_t>&,
                                                    const StockComposition&, uint8_t*, uint32_t*);
extern template void material_colours_init<uint16_t>(MaterialColours<uint16_t>*, const DexelGrid<uint16_t>&,
                                                     const StockComposition&, uint8_t*, uint32_t*);
extern template void material_colours_init<uint32_t>(MaterialColours<uint32_t>*, const DexelGrid<uint32_t>&,
                                                     const StockComposition&, uint8_t*, uint32_t*);

}  // namespace dexmill

#endif
