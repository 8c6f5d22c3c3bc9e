// Procedural 3-D textures T(x, y, z) -> colour (paper §2.7.1): evaluated at a
// point of the stock in machine coordinates (nm), integer only, the same
// colour on every CPU (tests/golden "texture").
//
// Each texture has a small parameter struct whose defaults are usable as
// they are (scales for a block of about 100 mm); the presets of
// material_preset.h place them on a given stock. Every colour a texture
// returns is one of its palette colours or a per-channel blend of them, as
// stated per struct (tests/test_texture.cpp checks it).
#ifndef DEXMILL_CORE_MATERIAL_TEXTURE_H
#define DEXMILL_CORE_MATERIAL_TEXTURE_H

#include <stdint.h>

#include "core/material/colour.h"
#include "core/point.h"

namespace dexmill {

enum class Axis : uint8_t { kX = 0, kY = 1, kZ = 2 };

// Paper equation 4, figure 12: colour by height bands. Band i is
// boundary_z[i-1] <= z < boundary_z[i]; a point exactly on a boundary
// belongs to the band above it. Boundaries ascend. Palette: colour[0..count].
constexpr int32_t kLayersMaxBands = 8;
struct LayersTexture {
  int32_t boundary_count = 1;                              // bands = boundary_count + 1, 0..7
  int64_t boundary_z_nm[kLayersMaxBands - 1] = {0};        // ascending, machine z, nm
  Rgb8 colour[kLayersMaxBands] = {{232, 192, 24}, {24, 24, 24}};  // bottom band first: yellow, black
};

// Marble (figures 14-15): parallel veins, a sine of the coordinate along
// `axis` plus turbulence, vein = sin near +1:
//   phase (turns) = (c - origin) / period + turbulence_turns * turbulence(p)
//   w = ((1 + sin(2 pi phase)) / 2)^(2^sharpness), colour = mix(base, vein, w)
// With turbulence_turns_q16 = 0 the colour repeats exactly every period.
// Palette: the per-channel blends of base and vein.
struct MarbleTexture {
  Rgb8 base{236, 236, 230};              // white
  Rgb8 vein{36, 72, 168};                // blue
  Axis axis = Axis::kX;
  int64_t origin_nm = 0;                 // a vein's crest lies a quarter period after it
  int64_t period_nm = 25000000;          // vein spacing, 25 mm
  int64_t feature_nm = 20000000;         // turbulence's largest feature, 20 mm
  int32_t octaves = 5;
  int32_t turbulence_turns_q16 = 98304;  // 1.5 turns of phase at full turbulence
  int32_t sharpness = 2;                 // 0..4: w raised to 2^sharpness (thinner veins)
  uint32_t seed = 1;
};

// Wood: growth rings around a line parallel to `axis` through (centre_a,
// centre_b), the other two coordinates in x, y, z order (axis y: a = x,
// b = z). The radius is perturbed by fBm so the rings wander:
//   r' = r + wobble * fbm(p), phase = r' / ring_pitch,
//   w = ((1 + sin(2 pi phase)) / 2)^(2^sharpness), colour = mix(light, dark, w)
// The radius saturates at 2^31 nm (2.1 m) from the axis.
// Palette: the per-channel blends of light and dark.
struct WoodTexture {
  Rgb8 light{226, 188, 136};
  Rgb8 dark{136, 86, 42};
  Axis axis = Axis::kY;
  int64_t centre_a_nm = 0;
  int64_t centre_b_nm = -60000000;       // the pith 60 mm below the origin: flat-sawn arcs
  int64_t ring_pitch_nm = 4000000;       // a growth ring every 4 mm
  int64_t wobble_nm = 1500000;           // ring wander amplitude, 1.5 mm
  int64_t feature_nm = 30000000;         // wander's largest feature, 30 mm
  int32_t octaves = 3;
  int32_t sharpness = 1;                 // thin dark late wood
  uint32_t seed = 2;
};

// Bronze (figure 16): a warm metallic base with a brighter sheen from
// fine noise and a green patina where coarse fBm rises above a threshold:
//   colour = mix(mix(base, highlight, sheen), patina, clamp((fbm - threshold) / ramp))
// Palette: per channel between the least and the greatest of base,
// highlight and patina.
struct BronzeTexture {
  Rgb8 base{168, 112, 50};
  Rgb8 highlight{226, 172, 96};
  Rgb8 patina{70, 142, 116};
  int64_t sheen_feature_nm = 2000000;    // 2 mm
  int64_t patina_feature_nm = 12000000;  // 12 mm
  int32_t octaves = 4;                   // of the patina's fBm
  int32_t patina_threshold_q15 = 6000;   // fbm above this starts the patina
  int32_t patina_ramp_q15 = 8000;        // and reaches full patina this much higher (>= 1)
  uint32_t seed = 3;
};

// Granite: speckles by thresholds on two noises at grain scale: dark mica
// where the first is above dark_above, light quartz where it is below
// light_below, else pink feldspar where the second is above feldspar_above,
// else the grey base. Palette: exactly those four colours.
struct GraniteTexture {
  Rgb8 base{152, 148, 144};
  Rgb8 dark{36, 34, 40};
  Rgb8 light{232, 228, 222};
  Rgb8 feldspar{198, 150, 138};
  int64_t grain_nm = 900000;             // 0.9 mm
  int32_t dark_above_q15 = 12000;
  int32_t light_below_q15 = -14000;
  int32_t feldspar_above_q15 = 13000;
  uint32_t seed = 4;
};

enum class TextureKind : uint8_t { kPlain = 0, kLayers = 1, kMarble = 2, kWood = 3, kBronze = 4, kGranite = 5 };
constexpr int32_t kTextureKindCount = 6;

// A material's colour: `kind` picks which member is used (the others keep
// their defaults and are ignored).
struct Texture {
  TextureKind kind = TextureKind::kPlain;
  Rgb8 plain{168, 168, 168};  // kPlain: one colour everywhere
  LayersTexture layers;
  MarbleTexture marble;
  WoodTexture wood;
  BronzeTexture bronze;
  GraniteTexture granite;
};

Rgb8 layers_colour(const LayersTexture& t, PointNm p);
Rgb8 marble_colour(const MarbleTexture& t, PointNm p);
Rgb8 wood_colour(const WoodTexture& t, PointNm p);
Rgb8 bronze_colour(const BronzeTexture& t, PointNm p);
Rgb8 granite_colour(const GraniteTexture& t, PointNm p);
// The colour of texture t at p (dispatches on t.kind).
Rgb8 texture_colour(const Texture& t, PointNm p);

// "plain", "layers", "marble", "wood", "bronze", "granite"; "?" when out of range.
const char* texture_kind_name(TextureKind k);
// The kind named `name` (the names above); false when there is none.
bool texture_kind_from_name(const char* name, TextureKind* out);

}  // namespace dexmill

#endif
