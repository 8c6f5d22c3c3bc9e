// The procedural textures of texture.h (paper §2.7.1).
#include "core/material/texture.h"

#include "core/material/noise.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {
namespace {

constexpr int64_t kMinScaleNm = 1000;                     // 1 um
constexpr int64_t kMaxScaleNm = int64_t(1) << 40;         // about 1.1 km
constexpr int64_t kMaxTurnsQ16 = int64_t(16) << 16;       // 16 turns
constexpr int64_t kMaxRadiusNm = (int64_t(1) << 31) - 1;  // hypot_round's domain

int64_t coord(PointNm p, Axis a) { return a == Axis::kX ? p.x_nm : (a == Axis::kY ? p.y_nm : p.z_nm); }

int64_t scale(int64_t nm) { return clamp(nm, kMinScaleNm, kMaxScaleNm); }

// The fraction of a turn v / period mod 1 as a binary angle (floor).
uint32_t turn_bam(int64_t v, int64_t period) {
  const int64_t m = v - period * div_floor(v, period);  // [0, period)
  return static_cast<uint32_t>(muldiv_floor(m, static_cast<int64_t>(1) << 32, period));
}

// (1 + sin(angle)) / 2 raised to 2^sharpness, q16 in [0, 65536]: 1 at the
// crest of a vein or a ring, 0 half a period away.
int32_t crest_weight_q16(uint32_t angle_bam, int32_t sharpness) {
  const int64_t s = sincos_bam(angle_bam).sin_q30;                        // [-2^30, 2^30]
  uint64_t w = static_cast<uint64_t>(s + (int64_t(1) << 30) + (int64_t(1) << 14)) >> 15;  // q16
  for (int32_t k = clamp<int32_t>(sharpness, 0, 4); k > 0; --k) w = (w * w + 32768u) >> 16;
  return static_cast<int32_t>(w);
}

bool same_name(const char* a, const char* b) {
  while (*a && *a == *b) ++a, ++b;
  return *a == *b;
}

const char* const kKindNames[kTextureKindCount] = {"plain", "layers", "marble", "wood", "bronze", "granite"};

}  // namespace

Rgb8 layers_colour(const LayersTexture& t, PointNm p) {
  const int32_t n = clamp<int32_t>(t.boundary_count, 0, kLayersMaxBands - 1);
  int32_t band = 0;
  while (band < n && p.z_nm >= t.boundary_z_nm[band]) ++band;
  return t.colour[band];
}

Rgb8 marble_colour(const MarbleTexture& t, PointNm p) {
  const int64_t c = clamp(coord(p, t.axis), -kCoordLimitNm, kCoordLimitNm);
  const int64_t origin = clamp(t.origin_nm, -kCoordLimitNm, kCoordLimitNm);
  const int64_t turns_q16 = clamp<int64_t>(t.turbulence_turns_q16, 0, kMaxTurnsQ16);
  int64_t bam = turn_bam(c - origin, scale(t.period_nm));
  // turbulence q15 times turns q16 is q31 of a turn; a binary angle is q32.
  if (turns_q16 != 0) bam += 2 * turbulence_q15(p, scale(t.feature_nm), t.octaves, t.seed) * turns_q16;
  const int32_t w = crest_weight_q16(static_cast<uint32_t>(static_cast<uint64_t>(bam)), t.sharpness);
  return rgb_mix(t.base, t.vein, w);
}

Rgb8 wood_colour(const WoodTexture& t, PointNm p) {
  const PointNm q = clamp_point(p);
  const int64_t coords[3] = {q.x_nm, q.y_nm, q.z_nm};
  const int ax = static_cast<int>(t.axis) % 3;
  const int ia = ax == 0 ? 1 : 0, ib = ax == 2 ? 1 : 2;  // the other two, in x, y, z order
  const int64_t da = clamp(coords[ia] - clamp(t.centre_a_nm, -kCoordLimitNm, kCoordLimitNm), -kMaxRadiusNm, kMaxRadiusNm);
  const int64_t db = clamp(coords[ib] - clamp(t.centre_b_nm, -kCoordLimitNm, kCoordLimitNm), -kMaxRadiusNm, kMaxRadiusNm);
  int64_t r = hypot_round(da, db);
  const int64_t wobble = clamp<int64_t>(t.wobble_nm, 0, kMaxScaleNm);
  if (wobble != 0) r += muldiv_floor(wobble, fbm_q15(p, scale(t.feature_nm), t.octaves, t.seed), kNoiseOne);
  return rgb_mix(t.light, t.dark, crest_weight_q16(turn_bam(r, scale(t.ring_pitch_nm)), t.sharpness));
}

Rgb8 bronze_colour(const BronzeTexture& t, PointNm p) {
  const int32_t sheen = noise3_q15(p, scale(t.sheen_feature_nm), t.seed + 101u) + kNoiseOne;  // q16 0..65535
  const int32_t fbm = fbm_q15(p, scale(t.patina_feature_nm), t.octaves, t.seed);
  const int64_t ramp = t.patina_ramp_q15 < 1 ? 1 : t.patina_ramp_q15;
  const int64_t patina = clamp<int64_t>(muldiv_floor(static_cast<int64_t>(fbm) - t.patina_threshold_q15, 65536, ramp), 0, 65536);
  return rgb_mix(rgb_mix(t.base, t.highlight, sheen), t.patina, static_cast<int32_t>(patina));
}

Rgb8 granite_colour(const GraniteTexture& t, PointNm p) {
  const int64_t grain = scale(t.grain_nm);
  const int32_t n = noise3_q15(p, grain, t.seed);
  if (n > t.dark_above_q15) return t.dark;
  if (n < t.light_below_q15) return t.light;
  if (noise3_q15(p, grain, t.seed + 1u) > t.feldspar_above_q15) return t.feldspar;
  return t.base;
}

Rgb8 texture_colour(const Texture& t, PointNm p) {
  switch (t.kind) {
    case TextureKind::kPlain: return t.plain;
    case TextureKind::kLayers: return layers_colour(t.layers, p);
    case TextureKind::kMarble: return marble_colour(t.marble, p);
    case TextureKind::kWood: return wood_colour(t.wood, p);
    case TextureKind::kBronze: return bronze_colour(t.bronze, p);
    case TextureKind::kGranite: return granite_colour(t.granite, p);
  }
  return t.plain;
}

const char* texture_kind_name(TextureKind k) {
  const int i = static_cast<int>(k);
  return i < kTextureKindCount ? kKindNames[i] : "?";
}

bool texture_kind_from_name(const char* name, TextureKind* out) {
  for (int i = 0; i < kTextureKindCount; ++i)
    if (same_name(name, kKindNames[i])) {
      *out = static_cast<TextureKind>(i);
      return true;
    }
  return false;
}

}  // namespace dexmill
