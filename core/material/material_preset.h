// The built-in materials (`--material NAME` without a file): each
// a StockComposition placed on a given stock box. Process values are typical
// ones for a small 3-axis mill with carbide cutters (material_preset.cpp
// says where each number comes from); a material file overrides them.
//
//   two-layer          engraving laminate (ABS): black over yellow at half the
//                      block's height, the paper's equation 4 and figure 12
//   marble             white marble with blue veins (figures 14-15)
//   wood               beech, rings around a pith below the block, no coolant
//   bronze             cast bearing bronze with patina (figure 16), max feed 400 mm/min
//   aluminium          6061 aluminium, plain colour
//   granite            grey granite, speckled
//   wood-on-aluminium  beech glued over aluminium at half the height: the
//                      paper's metal-and-wood case (coolant forbidden in the wood)
#ifndef DEXMILL_CORE_MATERIAL_MATERIAL_PRESET_H
#define DEXMILL_CORE_MATERIAL_MATERIAL_PRESET_H

#include <stdint.h>

#include "core/material/material.h"
#include "core/point.h"

namespace dexmill {

// Fills *out with the preset `name` on `stock` (machine coordinates, nm);
// false (out untouched) for an unknown name.
bool material_preset(const char* name, BoxNm stock, StockComposition* out);

// The preset's place in the order above, -1 for an unknown name.
int32_t material_preset_index(const char* name);

// The preset names in the order above, for help texts: i in 0..count-1.
int32_t material_preset_count();
const char* material_preset_name(int32_t i);

// The single materials the presets are made of, placed on `stock`.
Material material_abs_laminate(BoxNm stock);
Material material_marble(BoxNm stock);
Material material_beech(BoxNm stock);
Material material_bronze(BoxNm stock);
Material material_aluminium(BoxNm stock);
Material material_granite(BoxNm stock);

}  // namespace dexmill

#endif
