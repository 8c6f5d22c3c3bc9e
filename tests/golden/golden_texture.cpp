// Golden section "texture": the material layer (core/material, paper
// §2.6-2.7) pinned bit for bit: value noise and its fractal sums, each
// procedural texture, and each preset's composition (material index and
// colour, and the lengths of each material along vertical segments), hashed
// over a grid of points around a 100 x 70 x 20 mm block.
#include <stdint.h>

#include "core/material/column.h"
#include "core/material/material.h"
#include "core/material/material_preset.h"
#include "core/material/noise.h"
#include "core/material/texture.h"
#include "core/math/hash.h"
#include "tests/golden/golden.h"
#include "tests/golden/golden_programs.h"

using namespace dexmill;

namespace golden {
namespace {

// 13 x 8 x 5 points from 10 mm outside the block, off the noises' lattices
// by odd amounts of nm.
template <class F>
void each_point(F f) {
  for (int64_t k = 0; k < 5; ++k)
    for (int64_t j = 0; j < 8; ++j)
      for (int64_t i = 0; i < 13; ++i) f(PointNm{mm(10 * i - 10) + 1234 * j, mm(10 * j) - 777 * k, mm(5 * k) + 31 * i});
}

void colour_bytes(Hash64& h, Rgb8 c) {
  h.byte(c.r);
  h.byte(c.g);
  h.byte(c.b);
}

void noise_lines(Out& out) {
  const int64_t features[] = {um(1500), mm(12)};
  for (int64_t f : features) {
    Hash64 hn, hf, ht;
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    each_point([&](PointNm p) {
      const int32_t n = noise3_q15(p, f, 7u);
      lo = n < lo ? n : lo;
      hi = n > hi ? n : hi;
      hn.uint_le(static_cast<uint32_t>(n), 4);
      hf.uint_le(static_cast<uint32_t>(fbm_q15(p, f, 5, 7u)), 4);
      ht.uint_le(static_cast<uint32_t>(turbulence_q15(p, f, 5, 7u)), 4);
    });
    out.str("noise").kv("feature_nm", f).kv("min", lo).kv("max", hi).kx("noise", hn.value()).kx("fbm", hf.value());
    out.kx("turbulence", ht.value()).end();
  }
}

}  // namespace

void golden_texture(Out& out) {
  noise_lines(out);
  for (int32_t k = 0; k < kTextureKindCount; ++k) {
    Texture t;
    t.kind = static_cast<TextureKind>(k);
    Hash64 h;
    Rgb8 first{0, 0, 0};
    bool have_first = false;
    each_point([&](PointNm p) {
      const Rgb8 c = texture_colour(t, p);
      if (!have_first) first = c, have_first = true;
      colour_bytes(h, c);
    });
    out.str("texture ").str(texture_kind_name(t.kind));
    out.kx("first", (static_cast<uint32_t>(first.r) << 16) | (static_cast<uint32_t>(first.g) << 8) | first.b, 6);
    out.kx("colours", h.value()).end();
  }
  const BoxNm stock{{0, 0, 0}, {mm(100), mm(70), mm(20)}};
  for (int32_t i = 0; i < material_preset_count(); ++i) {
    StockComposition c;
    if (!material_preset(material_preset_name(i), stock, &c)) {
      fail(out, "material_preset");
      continue;
    }
    Hash64 hm, hc;
    each_point([&](PointNm p) {
      hm.byte(composition_material_at(c, p.x_nm, p.y_nm, p.z_nm));
      colour_bytes(hc, composition_colour_at(c, p));
    });
    out.str("preset ").str(material_preset_name(i)).kv("materials", c.material_count);
    out.kx("material", hm.value()).kx("colours", hc.value()).end();
  }
  // Each grid column's segment from 5 mm below the block to near its top,
  // the length in every material (core/material/column.h: what a cut
  // removes), for the presets of more than one material.
  for (int32_t i = 0; i < material_preset_count(); ++i) {
    StockComposition c;
    if (!material_preset(material_preset_name(i), stock, &c) || c.material_count < 2) continue;
    Hash64 hl;
    uint32_t any = 0;
    for (int64_t cj = 0; cj < 8; ++cj)
      for (int64_t ci = 0; ci < 13; ++ci) {
        int64_t len[kCompositionMaxMaterials];
        const uint32_t mask = composition_column(c, mm(10 * ci - 10), mm(10 * cj) + 3, mm(-5), mm(20) - 17 * ci, len);
        any |= mask;
        hl.uint_le(mask, 4);
        for (int64_t l : len) hl.uint_le(static_cast<uint64_t>(l), 8);
      }
    out.str("columns ").str(material_preset_name(i)).kx("mask", any, 2).kx("lengths", hl.value()).end();
  }
}

}  // namespace golden
