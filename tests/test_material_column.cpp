// core/material/column.h against a brute-force walk of the segment one nm
// at a time, on random compositions with small coordinates.
#include <random>

#include "core/material/column.h"
#include "core/material/material_preset.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

StockComposition random_composition(std::mt19937& rng) {
  StockComposition c;
  const int materials = 1 + static_cast<int>(rng() % kCompositionMaxMaterials);
  uint8_t idx = 0;
  for (int i = 0; i < materials; ++i) (void)composition_add_material(&c, Material{}, &idx);
  (void)composition_set_default(&c, static_cast<uint8_t>(rng() % materials));
  auto z = [&] { return static_cast<int64_t>(rng() % 48) - 4; };
  auto m = [&] { return static_cast<uint8_t>(rng() % materials); };
  const int layers = static_cast<int>(rng() % (kCompositionMaxLayers + 1));
  for (int i = 0; i < layers; ++i) {
    const int64_t a = z(), b = a + 1 + static_cast<int64_t>(rng() % 20);
    (void)composition_add_layer(&c, a, b, m());
  }
  const int inserts = static_cast<int>(rng() % (kCompositionMaxInserts + 1));
  for (int i = 0; i < inserts; ++i) {
    const int64_t a = z(), b = a + 1 + static_cast<int64_t>(rng() % 20);
    if (rng() % 2) {
      (void)composition_add_box(&c, BoxNm{{static_cast<int64_t>(rng() % 8), static_cast<int64_t>(rng() % 8), a}, {9, 9, b}}, m());
    } else {
      (void)composition_add_cylinder(&c, static_cast<int64_t>(rng() % 10), static_cast<int64_t>(rng() % 10),
                                     1 + static_cast<int64_t>(rng() % 6), a, b, m());
    }
  }
  return c;
}

}  // namespace

TEST(column_matches_brute_force) {
  std::mt19937 rng(31);
  for (int it = 0; it < 3000; ++it) {
    const StockComposition c = random_composition(rng);
    const int64_t x = rng() % 12, y = rng() % 12;
    const int64_t lo = static_cast<int64_t>(rng() % 56) - 8, hi = lo + static_cast<int64_t>(rng() % 50) - 5;
    int64_t expect[kCompositionMaxMaterials] = {};
    uint32_t expect_mask = 0;
    for (int64_t z = lo; z < hi; ++z) {
      const uint8_t m = composition_material_at(c, x, y, z);
      ++expect[m];
      expect_mask |= 1u << m;
    }
    int64_t got[kCompositionMaxMaterials];
    const uint32_t mask = composition_column(c, x, y, lo, hi, got);
    bool same = CHECK_EQ(mask, expect_mask) && CHECK_EQ(composition_materials_in(c, x, y, lo, hi), expect_mask);
    for (int i = 0; i < kCompositionMaxMaterials; ++i) same = CHECK_EQ(got[i], expect[i]) && same;
    if (!same) break;
  }
}

TEST(column_wood_on_aluminium) {
  // A 10 mm deep plunge through the glue line of the 20 mm block: 5 mm of
  // each; the top 5 mm only beech; an empty segment nothing.
  StockComposition c;
  CHECK(material_preset("wood-on-aluminium", BoxNm{{0, 0, 0}, {100000000, 70000000, 20000000}}, &c));
  int64_t len[kCompositionMaxMaterials];
  CHECK_EQ(composition_column(c, 50000000, 35000000, 5000000, 15000000, len), 3u);
  CHECK_EQ(len[0], 5000000);  // aluminium
  CHECK_EQ(len[1], 5000000);  // beech
  CHECK_EQ(composition_materials_in(c, 1, 1, 15000000, 20000000), 2u);
  CHECK_EQ(composition_column(c, 1, 1, 7, 7, len), 0u);
  CHECK_EQ(len[0] + len[1], 0);
  // Unbounded ends are clamped, not overflowed.
  CHECK_EQ(composition_column(c, 0, 0, INT64_MIN, INT64_MAX, len), 3u);
  CHECK_EQ(len[0] + len[1], 2 * kCoordLimitNm);
}
