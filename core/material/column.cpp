// The composition along a vertical segment; see column.h.
#include "core/material/column.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int32_t kMaxCuts = 1 + 2 * (kCompositionMaxLayers + kCompositionMaxInserts);

struct Cuts {
  int64_t z[kMaxCuts];
  int32_t n = 0;
};

// z_lo and every layer or insert bound strictly inside (z_lo, z_hi),
// ascending (insertion sort: at most kMaxCuts values).
void collect(const StockComposition& c, int64_t z_lo, int64_t z_hi, Cuts* cuts) {
  auto add = [&](int64_t z) {
    if (z <= z_lo || z >= z_hi) return;
    int32_t i = cuts->n++;
    while (i > 0 && cuts->z[i - 1] > z) {
      cuts->z[i] = cuts->z[i - 1];
      --i;
    }
    cuts->z[i] = z;
  };
  cuts->z[0] = z_lo;
  cuts->n = 1;
  for (int32_t i = 0; i < c.layer_count; ++i) add(c.layers[i].z_lo_nm), add(c.layers[i].z_hi_nm);
  for (int32_t i = 0; i < c.insert_count; ++i) add(c.inserts[i].box.lo.z_nm), add(c.inserts[i].box.hi.z_nm);
}

}  // namespace

uint32_t composition_column(const StockComposition& c, int64_t x_nm, int64_t y_nm, int64_t z_lo_nm, int64_t z_hi_nm,
                            int64_t lengths_nm[kCompositionMaxMaterials]) {
  for (int32_t i = 0; i < kCompositionMaxMaterials; ++i) lengths_nm[i] = 0;
  int64_t lo = clamp(z_lo_nm, -kCoordLimitNm, kCoordLimitNm), hi = clamp(z_hi_nm, -kCoordLimitNm, kCoordLimitNm);
  if (lo >= hi || c.material_count == 0) return 0;
  // The column in the part (the frame keeps Z an axis: a column stays one,
  // perhaps upside down, its lengths the same).
  const PointNm a = composition_part_point(c, PointNm{x_nm, y_nm, lo}), b = composition_part_point(c, PointNm{x_nm, y_nm, hi});
  x_nm = a.x_nm;
  y_nm = a.y_nm;
  lo = min_of(a.z_nm, b.z_nm);
  hi = max_of(a.z_nm, b.z_nm);
  Cuts cuts;
  collect(c, lo, hi, &cuts);
  uint32_t mask = 0;
  for (int32_t i = 0; i < cuts.n; ++i) {
    const int64_t end = i + 1 < cuts.n ? cuts.z[i + 1] : hi;
    if (end == cuts.z[i]) continue;  // a bound shared by two layers or inserts: one lookup
    const uint8_t m = composition_material_in_part(c, PointNm{x_nm, y_nm, cuts.z[i]});
    lengths_nm[m] += end - cuts.z[i];
    mask |= static_cast<uint32_t>(1) << m;
  }
  return mask;
}

uint32_t composition_materials_in(const StockComposition& c, int64_t x_nm, int64_t y_nm, int64_t z_lo_nm, int64_t z_hi_nm) {
  int64_t lengths[kCompositionMaxMaterials];
  return composition_column(c, x_nm, y_nm, z_lo_nm, z_hi_nm, lengths);
}

}  // namespace dexmill
