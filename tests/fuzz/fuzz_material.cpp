// libFuzzer target: the material file reader (platform/format/material_file.h)
// and the composition it builds (core/material/). Input: the file's text,
// read for a fixed 100 x 60 x 20 mm stock. A file that reads must give a
// composition whose every material index is in range, whose lookups at a
// lattice of points in and around the stock name a material it holds, and
// whose column lengths (core/material/column.h) add up to each segment's
// length; reading it again gives the same composition (the same counts,
// names, rules, and materials and colours at every lattice point). A file that does not read
// gives one error line naming the file and leaves the composition as it
// was.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/material/column.h"
#include "core/material/material.h"
#include "core/math/fixed.h"
#include "platform/format/material_file.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz_material {

using namespace dexmill;

const BoxNm kFuzzStock{PointNm{0, 0, -20 * kNmPerMm}, PointNm{100 * kNmPerMm, 60 * kNmPerMm, 0}};

// Every index the composition stores names one of its materials.
void check_indices(const StockComposition& c) {
  FUZZ_REQUIRE(c.material_count >= 1 && c.material_count <= kCompositionMaxMaterials);
  FUZZ_REQUIRE(c.default_material < c.material_count);
  FUZZ_REQUIRE(c.layer_count >= 0 && c.layer_count <= kCompositionMaxLayers);
  FUZZ_REQUIRE(c.insert_count >= 0 && c.insert_count <= kCompositionMaxInserts);
  for (int32_t i = 0; i < c.layer_count; ++i) {
    FUZZ_REQUIRE(c.layers[i].material < c.material_count);
    FUZZ_REQUIRE(c.layers[i].z_lo_nm < c.layers[i].z_hi_nm);
  }
  for (int32_t i = 0; i < c.insert_count; ++i) FUZZ_REQUIRE(c.inserts[i].material < c.material_count);
  for (int32_t i = 0; i < c.material_count; ++i) {
    const size_t len = strnlen(c.materials[i].name, kMaterialNameMax + 1);
    FUZZ_REQUIRE(len >= 1 && len <= static_cast<size_t>(kMaterialNameMax));
  }
}

// Lookups and columns on a 7 x 7 lattice reaching 10 mm past the stock.
void check_lookups(const StockComposition& c) {
  const int64_t margin_nm = 10 * kNmPerMm;
  const BoxNm& s = kFuzzStock;
  for (int i = 0; i <= 6; ++i) {
    for (int j = 0; j <= 6; ++j) {
      const int64_t x = s.lo.x_nm - margin_nm + (s.hi.x_nm - s.lo.x_nm + 2 * margin_nm) * i / 6;
      const int64_t y = s.lo.y_nm - margin_nm + (s.hi.y_nm - s.lo.y_nm + 2 * margin_nm) * j / 6;
      for (int k = 0; k <= 6; ++k) {
        const int64_t z = s.lo.z_nm - margin_nm + (s.hi.z_nm - s.lo.z_nm + 2 * margin_nm) * k / 6;
        FUZZ_REQUIRE(composition_material_at(c, x, y, z) < c.material_count);
        (void)composition_colour_at(c, PointNm{x, y, z});
      }
      int64_t lengths_nm[kCompositionMaxMaterials];
      const int64_t z_lo = s.lo.z_nm - margin_nm, z_hi = s.hi.z_nm + margin_nm;
      const uint32_t mask = composition_column(c, x, y, z_lo, z_hi, lengths_nm);
      int64_t sum_nm = 0;
      for (int32_t m = 0; m < kCompositionMaxMaterials; ++m) {
        FUZZ_REQUIRE(lengths_nm[m] >= 0);
        FUZZ_REQUIRE(((mask >> m) & 1u) == (lengths_nm[m] > 0 ? 1u : 0u));
        if (m >= c.material_count) FUZZ_REQUIRE(lengths_nm[m] == 0);
        sum_nm += lengths_nm[m];
      }
      FUZZ_REQUIRE(sum_nm == z_hi - z_lo);
      FUZZ_REQUIRE(composition_materials_in(c, x, y, z_lo, z_hi) == mask);
    }
  }
}

// Two reads of one file: equal in everything a run uses (padding bytes
// aside, which a copy need not keep).
void check_same(const StockComposition& a, const StockComposition& b) {
  FUZZ_REQUIRE(a.material_count == b.material_count && a.layer_count == b.layer_count &&
               a.insert_count == b.insert_count && a.default_material == b.default_material);
  for (int32_t i = 0; i < a.material_count; ++i) {
    const MaterialProcess& p = a.materials[i].process;
    const MaterialProcess& q = b.materials[i].process;
    FUZZ_REQUIRE(std::strcmp(a.materials[i].name, b.materials[i].name) == 0);
    FUZZ_REQUIRE(a.materials[i].texture.kind == b.materials[i].texture.kind);
    FUZZ_REQUIRE(p.max_feed_nm_per_min == q.max_feed_nm_per_min && p.spindle_min_rpm == q.spindle_min_rpm &&
                 p.spindle_max_rpm == q.spindle_max_rpm && p.coolant_allowed == q.coolant_allowed &&
                 p.tolerance_nm == q.tolerance_nm && p.density_mg_per_cm3 == q.density_mg_per_cm3);
  }
  const BoxNm& s = kFuzzStock;
  for (int i = 0; i <= 8; ++i)
    for (int k = 0; k <= 8; ++k) {
      const PointNm p{s.lo.x_nm + (s.hi.x_nm - s.lo.x_nm) * i / 8, s.lo.y_nm + (s.hi.y_nm - s.lo.y_nm) * k / 8,
                      s.lo.z_nm + (s.hi.z_nm - s.lo.z_nm) * ((i + k) % 9) / 8};
      FUZZ_REQUIRE(composition_material_at(a, p.x_nm, p.y_nm, p.z_nm) ==
                   composition_material_at(b, p.x_nm, p.y_nm, p.z_nm));
      const Rgb8 ca = composition_colour_at(a, p), cb = composition_colour_at(b, p);
      FUZZ_REQUIRE(ca.r == cb.r && ca.g == cb.g && ca.b == cb.b);
    }
}

int fuzz_material(const uint8_t* data, size_t size) {
  const char* text = reinterpret_cast<const char*>(data);
  // A sentinel composition: a failed read must leave it byte for byte.
  static StockComposition c, before, again;
  std::memset(static_cast<void*>(&c), 0xA5, sizeof c);
  std::memcpy(static_cast<void*>(&before), &c, sizeof c);
  std::string err;
  if (!material_file_parse("fuzz.mat", text, size, kFuzzStock, &c, &err)) {
    FUZZ_REQUIRE(err.compare(0, 9, "fuzz.mat:") == 0);
    FUZZ_REQUIRE(err.find('\n') == std::string::npos);
    FUZZ_REQUIRE(std::memcmp(&c, &before, sizeof c) == 0);
    return 0;
  }
  FUZZ_REQUIRE(err.empty());
  check_indices(c);
  check_lookups(c);
  std::memset(static_cast<void*>(&again), 0xA5, sizeof again);
  std::string err2;
  FUZZ_REQUIRE(material_file_parse("fuzz.mat", text, size, kFuzzStock, &again, &err2));
  check_same(c, again);
  return 0;
}

}  // namespace fuzz_material

DEXMILL_FUZZ_ENTRY(fuzz_material::fuzz_material)
