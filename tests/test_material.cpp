// core/material/material.h and material_preset.h: the composition's layers,
// inserts and default, their precedence and edges, capacities, and the
// presets.
#include <cstring>

#include "core/material/material.h"
#include "core/material/material_preset.h"
#include "core/math/hash.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kMm = 1000000;

Material mat(const char* name) {
  Material m;
  (void)material_set_name(&m, name);
  return m;
}

// Three materials: 0 default, 1 and 2 for layers and inserts.
StockComposition three() {
  StockComposition c;
  uint8_t i = 9;
  CHECK(ok(composition_add_material(&c, mat("a"), &i)) && i == 0);
  CHECK(ok(composition_add_material(&c, mat("b"), &i)) && i == 1);
  CHECK(ok(composition_add_material(&c, mat("c"), &i)) && i == 2);
  return c;
}

const BoxNm kStock{{0, 0, 0}, {100 * kMm, 70 * kMm, 20 * kMm}};

uint64_t composition_hash(const StockComposition& c) {
  Hash64 h;
  for (int64_t z = 0; z <= 20 * kMm; z += 2 * kMm)
    for (int64_t y = 0; y <= 70 * kMm; y += 7 * kMm)
      for (int64_t x = 0; x <= 100 * kMm; x += 5 * kMm) {
        h.byte(composition_material_at(c, x, y, z));
        const Rgb8 col = composition_colour_at(c, PointNm{x, y, z});
        h.byte(col.r), h.byte(col.g), h.byte(col.b);
      }
  return h.value();
}

}  // namespace

TEST(material_names) {
  Material m;
  CHECK_EQ(std::strcmp(m.name, "stock"), 0);
  CHECK(ok(material_set_name(&m, "0123456789abcdef")));  // 16: the most
  CHECK_EQ(std::strcmp(m.name, "0123456789abcdef"), 0);
  CHECK(material_set_name(&m, "0123456789abcdefg") == Status::kBadArgument);
  CHECK(material_set_name(&m, "") == Status::kBadArgument);
  CHECK_EQ(std::strcmp(m.name, "0123456789abcdef"), 0);  // unchanged on failure
}

TEST(composition_default_and_layers) {
  StockComposition c = three();
  CHECK_EQ(composition_material_at(c, 1, 2, 3), 0);
  CHECK(ok(composition_set_default(&c, 2)));
  CHECK_EQ(composition_material_at(c, 1, 2, 3), 2);
  CHECK(ok(composition_set_default(&c, 0)));
  CHECK(ok(composition_add_layer(&c, 0, 10 * kMm, 1)));
  CHECK(ok(composition_add_layer(&c, 10 * kMm, 20 * kMm, 2)));
  CHECK_EQ(composition_material_at(c, 0, 0, -1), 0);
  CHECK_EQ(composition_material_at(c, 0, 0, 0), 1);            // z_lo is in
  CHECK_EQ(composition_material_at(c, 0, 0, 10 * kMm - 1), 1);
  CHECK_EQ(composition_material_at(c, 0, 0, 10 * kMm), 2);     // z_hi is out, the next layer's z_lo in
  CHECK_EQ(composition_material_at(c, 0, 0, 20 * kMm - 1), 2);
  CHECK_EQ(composition_material_at(c, 0, 0, 20 * kMm), 0);
  // Overlapping layers: the later one wins.
  CHECK(ok(composition_add_layer(&c, 5 * kMm, 15 * kMm, 0)));
  CHECK_EQ(composition_material_at(c, 0, 0, 5 * kMm - 1), 1);
  CHECK_EQ(composition_material_at(c, 0, 0, 5 * kMm), 0);
  CHECK_EQ(composition_material_at(c, 0, 0, 15 * kMm), 2);
}

TEST(composition_inserts_precedence) {
  StockComposition c = three();
  CHECK(ok(composition_add_layer(&c, 0, 20 * kMm, 1)));
  const BoxNm box{{10 * kMm, 10 * kMm, 5 * kMm}, {30 * kMm, 20 * kMm, 15 * kMm}};
  CHECK(ok(composition_add_box(&c, box, 2)));
  // The box beats the layer; its lo faces are in, its hi faces out.
  CHECK_EQ(composition_material_at(c, 10 * kMm, 10 * kMm, 5 * kMm), 2);
  CHECK_EQ(composition_material_at(c, 10 * kMm - 1, 15 * kMm, 10 * kMm), 1);
  CHECK_EQ(composition_material_at(c, 30 * kMm - 1, 20 * kMm - 1, 15 * kMm - 1), 2);
  CHECK_EQ(composition_material_at(c, 30 * kMm, 15 * kMm, 10 * kMm), 1);
  CHECK_EQ(composition_material_at(c, 20 * kMm, 20 * kMm, 10 * kMm), 1);
  CHECK_EQ(composition_material_at(c, 20 * kMm, 15 * kMm, 15 * kMm), 1);
  // A later cylinder over the box's corner wins there; on its radius is in.
  CHECK(ok(composition_add_cylinder(&c, 10 * kMm, 10 * kMm, 3 * kMm, 0, 20 * kMm, 0)));
  CHECK_EQ(composition_material_at(c, 10 * kMm, 10 * kMm, 10 * kMm), 0);
  CHECK_EQ(composition_material_at(c, 13 * kMm, 10 * kMm, 10 * kMm), 0);
  CHECK_EQ(composition_material_at(c, 13 * kMm + 1, 10 * kMm, 10 * kMm), 2);  // outside: the box again
  CHECK_EQ(composition_material_at(c, 10 * kMm, 7 * kMm, 10 * kMm), 0);
  CHECK_EQ(composition_material_at(c, 10 * kMm, 7 * kMm - 1, 10 * kMm), 1);    // outside both: the layer
  // 3-4-5: (3, 4) mm from the axis of a 5 mm cylinder is on it; 1 nm more is not.
  CHECK(ok(composition_add_cylinder(&c, 50 * kMm, 50 * kMm, 5 * kMm, 0, 20 * kMm, 2)));
  CHECK_EQ(composition_material_at(c, 53 * kMm, 54 * kMm, 0), 2);
  CHECK_EQ(composition_material_at(c, 53 * kMm, 54 * kMm + 1, 0), 1);
  CHECK_EQ(composition_material_at(c, 53 * kMm, 54 * kMm, 20 * kMm), 0);       // above: default
  // An earlier box is beaten by a later one that overlaps it.
  CHECK(ok(composition_add_box(&c, BoxNm{{20 * kMm, 12 * kMm, 0}, {25 * kMm, 14 * kMm, 20 * kMm}}, 1)));
  CHECK_EQ(composition_material_at(c, 22 * kMm, 13 * kMm, 10 * kMm), 1);
  CHECK_EQ(composition_material_at(c, 26 * kMm, 13 * kMm, 10 * kMm), 2);
  // Far away coordinates are defined (UBSan): the default or a layer.
  CHECK_EQ(composition_material_at(c, INT64_MIN, INT64_MAX, 1), 1);
  CHECK_EQ(composition_material_at(c, INT64_MAX, INT64_MIN, INT64_MIN), 0);
}

TEST(composition_capacities_and_bad_arguments) {
  StockComposition c;
  uint8_t i = 0;
  for (int k = 0; k < kCompositionMaxMaterials; ++k) CHECK(ok(composition_add_material(&c, mat("m"), &i)));
  CHECK(composition_add_material(&c, mat("m"), &i) == Status::kBufferTooSmall);
  CHECK_EQ(c.material_count, kCompositionMaxMaterials);
  CHECK(composition_add_layer(&c, 5, 5, 0) == Status::kBadArgument);
  CHECK(composition_add_layer(&c, 0, 5, kCompositionMaxMaterials) == Status::kBadArgument);
  CHECK(composition_set_default(&c, kCompositionMaxMaterials) == Status::kBadArgument);
  CHECK(composition_add_box(&c, BoxNm{{0, 0, 0}, {1, 0, 1}}, 0) == Status::kBadArgument);
  CHECK(composition_add_cylinder(&c, 0, 0, 0, 0, 1, 0) == Status::kBadArgument);
  CHECK(composition_add_cylinder(&c, 0, 0, kCompositionMaxRadiusNm + 1, 0, 1, 0) == Status::kBadArgument);
  CHECK(composition_add_cylinder(&c, 0, 0, 5, 1, 1, 0) == Status::kBadArgument);
  CHECK_EQ(c.layer_count, 0);
  CHECK_EQ(c.insert_count, 0);
  for (int k = 0; k < kCompositionMaxLayers; ++k) CHECK(ok(composition_add_layer(&c, k, k + 1, 1)));
  CHECK(composition_add_layer(&c, 0, 1, 1) == Status::kBufferTooSmall);
  for (int k = 0; k < kCompositionMaxInserts; ++k) CHECK(ok(composition_add_cylinder(&c, 0, 0, 5, k, k + 1, 2)));
  CHECK(composition_add_box(&c, BoxNm{{0, 0, 0}, {1, 1, 1}}, 0) == Status::kBufferTooSmall);
  CHECK_EQ(c.insert_count, kCompositionMaxInserts);
  composition_clear(&c);
  CHECK_EQ(c.material_count + c.layer_count + c.insert_count, 0);
  CHECK(composition_colour_at(c, PointNm{0, 0, 0}) == Texture{}.plain);  // empty: grey, index 0
  CHECK_EQ(composition_material_at(c, 0, 0, 0), 0);
}

TEST(material_presets_exist_and_differ) {
  const char* expected[] = {"two-layer", "marble", "wood", "bronze", "aluminium", "granite", "wood-on-aluminium"};
  CHECK_EQ(material_preset_count(), 7);
  uint64_t hashes[7];
  for (int i = 0; i < material_preset_count(); ++i) {
    CHECK_EQ(std::strcmp(material_preset_name(i), expected[i]), 0);
    StockComposition c;
    CHECK(material_preset(expected[i], kStock, &c));
    CHECK_GE(c.material_count, 1);
    for (int m = 0; m < c.material_count; ++m) {
      const MaterialProcess& p = c.materials[m].process;
      CHECK_GT(p.max_feed_nm_per_min, 0);
      CHECK_LT(p.spindle_min_rpm, p.spindle_max_rpm);
      CHECK_GT(p.tolerance_nm, 0);
      CHECK_GT(p.density_mg_per_cm3, 0);
    }
    hashes[i] = composition_hash(c);
    for (int j = 0; j < i; ++j) CHECK_NE(hashes[i], hashes[j]);
  }
  CHECK_EQ(std::strcmp(material_preset_name(7), "?"), 0);
  StockComposition c;
  c.material_count = 3;
  CHECK(!material_preset("steel", kStock, &c));
  CHECK(!material_preset("", kStock, &c));
  CHECK(!material_preset("wood-on", kStock, &c));
  CHECK_EQ(c.material_count, 3);  // untouched
}

TEST(material_presets_values) {
  StockComposition c;
  CHECK(material_preset("bronze", kStock, &c));
  CHECK_EQ(c.materials[0].process.max_feed_nm_per_min, 400 * kMm);  // 400 mm/min
  CHECK_EQ(std::strcmp(c.materials[0].name, "bronze"), 0);
  CHECK(material_preset("wood", kStock, &c));
  CHECK(!c.materials[0].process.coolant_allowed);
  // The paper's equation 4: black above half the height, yellow below.
  CHECK(material_preset("two-layer", kStock, &c));
  CHECK(composition_colour_at(c, PointNm{5, 5, 10 * kMm}) == (Rgb8{24, 24, 24}));
  CHECK(composition_colour_at(c, PointNm{5, 5, 10 * kMm - 1}) == (Rgb8{232, 192, 24}));
  // Wood over aluminium, the glue line at mid height: coolant allowed below,
  // forbidden above.
  CHECK(material_preset("wood-on-aluminium", kStock, &c));
  CHECK_EQ(c.material_count, 2);
  const uint8_t below = composition_material_at(c, 50 * kMm, 35 * kMm, 10 * kMm - 1);
  const uint8_t above = composition_material_at(c, 50 * kMm, 35 * kMm, 10 * kMm);
  CHECK_NE(below, above);
  CHECK_EQ(std::strcmp(c.materials[below].name, "aluminium"), 0);
  CHECK_EQ(std::strcmp(c.materials[above].name, "beech"), 0);
  CHECK(c.materials[below].process.coolant_allowed);
  CHECK(!c.materials[above].process.coolant_allowed);
  CHECK_EQ(composition_material_at(c, 0, 0, 20 * kMm), above);   // the top face is wood
  CHECK_EQ(composition_material_at(c, 0, 0, -kMm), below);       // under the block: the default
}
