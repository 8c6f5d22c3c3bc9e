// The composition along a vertical segment: what the process rules of
// (paper §2.6) need from a cut, which lowers a dexel column at
// (x, y) from one height to another. Exact: the composition is piecewise
// constant along z, changing only at layer and insert z bounds, so the
// segment is split at those and each piece is looked up once (at most
// 1 + 2 x (kCompositionMaxLayers + kCompositionMaxInserts) pieces).
#ifndef DEXMILL_CORE_MATERIAL_COLUMN_H
#define DEXMILL_CORE_MATERIAL_COLUMN_H

#include <stdint.h>

#include "core/material/material.h"

namespace dexmill {

// For z_lo <= z < z_hi at (x, y): the length in nm of the segment in each
// material, lengths_nm[i] for material i (i < material_count; the others
// are set to 0), and the materials present as a bit mask (bit i set when
// lengths_nm[i] > 0). An empty segment (z_lo >= z_hi) gives all zeros and 0.
// Lengths add up to z_hi - z_lo when the composition has a material;
// the segment is clamped to +-kCoordLimitNm first.
uint32_t composition_column(const StockComposition& c, int64_t x_nm, int64_t y_nm, int64_t z_lo_nm, int64_t z_hi_nm,
                            int64_t lengths_nm[kCompositionMaxMaterials]);

// The mask alone (no lengths): bit i set when material i fills some z in
// [z_lo, z_hi) at (x, y).
uint32_t composition_materials_in(const StockComposition& c, int64_t x_nm, int64_t y_nm, int64_t z_lo_nm, int64_t z_hi_nm);

}  // namespace dexmill

#endif
