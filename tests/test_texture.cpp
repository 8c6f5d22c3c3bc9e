// core/material/texture.h: determinism, each texture's palette, the layers'
// band edges, marble's period and vein crests, wood's rings, against double
// precision where the texture is a formula of a sine.
#include <cmath>
#include <cstdlib>
#include <random>

#include "core/material/noise.h"
#include "core/material/texture.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kMm = 1000000;

// Points over a 100 x 70 x 20 mm block (the demo's), plus random ones.
template <class F>
void each_point(F f) {
  for (int64_t z = 0; z <= 20 * kMm; z += 2500000)
    for (int64_t y = 0; y <= 70 * kMm; y += 3500000)
      for (int64_t x = 0; x <= 100 * kMm; x += 2500000) f(PointNm{x, y, z});
  std::mt19937_64 rng(7);
  for (int i = 0; i < 3000; ++i) {
    const int64_t x = static_cast<int64_t>(rng() % (400 * kMm)) - 200 * kMm;
    const int64_t y = static_cast<int64_t>(rng() % (400 * kMm)) - 200 * kMm;
    const int64_t z = static_cast<int64_t>(rng() % (400 * kMm)) - 200 * kMm;
    f(PointNm{x, y, z});
  }
}

bool between(uint8_t v, uint8_t a, uint8_t b) { return (a <= v && v <= b) || (b <= v && v <= a); }
bool blend_of(Rgb8 c, Rgb8 a, Rgb8 b) { return between(c.r, a.r, b.r) && between(c.g, a.g, b.g) && between(c.b, a.b, b.b); }
bool within3(uint8_t v, uint8_t a, uint8_t b, uint8_t c) {
  const uint8_t lo = a < b ? (a < c ? a : c) : (b < c ? b : c), hi = a > b ? (a > c ? a : c) : (b > c ? b : c);
  return lo <= v && v <= hi;
}

Texture of_kind(TextureKind k) {
  Texture t;
  t.kind = k;
  return t;
}

// mix(a, b, w) per channel in double, for the sine-formula oracles.
bool near_mix(Rgb8 got, Rgb8 a, Rgb8 b, double w, double tol) {
  auto ch = [&](int g, int x, int y) { return std::fabs(g - (x + (y - x) * w)) <= tol; };
  return ch(got.r, a.r, b.r) && ch(got.g, a.g, b.g) && ch(got.b, a.b, b.b);
}

}  // namespace

TEST(texture_deterministic_without_state) {
  // Every texture gives the same colour at a point whatever was evaluated
  // before it (forward, then again in reverse order).
  for (int k = 0; k < kTextureKindCount; ++k) {
    const Texture t = of_kind(static_cast<TextureKind>(k));
    Rgb8 first[64];
    for (int i = 0; i < 64; ++i) first[i] = texture_colour(t, PointNm{i * 1700001, i * -900007, i * 310003});
    for (int i = 63; i >= 0; --i)
      CHECK(texture_colour(t, PointNm{i * 1700001, i * -900007, i * 310003}) == first[i]);
  }
}

TEST(texture_names_round_trip) {
  for (int k = 0; k < kTextureKindCount; ++k) {
    TextureKind got = TextureKind::kPlain;
    CHECK(texture_kind_from_name(texture_kind_name(static_cast<TextureKind>(k)), &got));
    CHECK_EQ(static_cast<int>(got), k);
  }
  TextureKind got = TextureKind::kWood;
  CHECK(!texture_kind_from_name("marbles", &got));
  CHECK(!texture_kind_from_name("", &got));
  CHECK(got == TextureKind::kWood);
}

TEST(texture_layers_band_edges_exact) {
  LayersTexture t;
  t.boundary_count = 2;
  t.boundary_z_nm[0] = 5 * kMm;
  t.boundary_z_nm[1] = 12 * kMm;
  t.colour[0] = Rgb8{1, 2, 3};
  t.colour[1] = Rgb8{4, 5, 6};
  t.colour[2] = Rgb8{7, 8, 9};
  CHECK(layers_colour(t, PointNm{0, 0, -INT64_MAX}) == t.colour[0]);
  CHECK(layers_colour(t, PointNm{0, 0, 5 * kMm - 1}) == t.colour[0]);
  CHECK(layers_colour(t, PointNm{0, 0, 5 * kMm}) == t.colour[1]);  // on a boundary: the band above
  CHECK(layers_colour(t, PointNm{0, 0, 12 * kMm - 1}) == t.colour[1]);
  CHECK(layers_colour(t, PointNm{9, -9, 12 * kMm}) == t.colour[2]);
  CHECK(layers_colour(t, PointNm{0, 0, INT64_MAX}) == t.colour[2]);
  // The default is the paper's equation 4: yellow below z = 0, black from it up.
  const LayersTexture d;
  CHECK(layers_colour(d, PointNm{0, 0, -1}) == (Rgb8{232, 192, 24}));
  CHECK(layers_colour(d, PointNm{0, 0, 0}) == (Rgb8{24, 24, 24}));
}

TEST(texture_palettes) {
  const MarbleTexture m;
  const WoodTexture w;
  const BronzeTexture b;
  const GraniteTexture g;
  int granite_seen[4] = {0, 0, 0, 0};
  int marble_vein = 0, marble_base = 0, bronze_patina = 0, wood_dark = 0, wood_light = 0;
  bool ok_all = true;
  each_point([&](PointNm p) {
    const Rgb8 cm = marble_colour(m, p), cw = wood_colour(w, p), cb = bronze_colour(b, p), cg = granite_colour(g, p);
    ok_all = ok_all && CHECK(blend_of(cm, m.base, m.vein)) && CHECK(blend_of(cw, w.light, w.dark)) &&
             CHECK(within3(cb.r, b.base.r, b.highlight.r, b.patina.r) && within3(cb.g, b.base.g, b.highlight.g, b.patina.g) &&
                   within3(cb.b, b.base.b, b.highlight.b, b.patina.b));
    const Rgb8 pal[4] = {g.base, g.dark, g.light, g.feldspar};
    int which = -1;
    for (int i = 0; i < 4; ++i)
      if (cg == pal[i]) which = i;
    ok_all = ok_all && CHECK_GE(which, 0);
    if (which >= 0) ++granite_seen[which];
    marble_vein += std::abs(cm.b - m.vein.b) < 20;
    marble_base += std::abs(cm.b - m.base.b) < 20;
    bronze_patina += std::abs(cb.g - b.patina.g) < 10 && std::abs(cb.r - b.patina.r) < 10;
    wood_dark += std::abs(cw.r - w.dark.r) < 20;
    wood_light += std::abs(cw.r - w.light.r) < 20;
  });
  // Not constant: each texture shows its palette's ends somewhere.
  for (int i = 0; i < 4; ++i) CHECK_GT(granite_seen[i], 10);
  CHECK_GT(granite_seen[0], granite_seen[1]);  // grey base dominates the speckles
  CHECK_GT(marble_vein, 20);
  CHECK_GT(marble_base, marble_vein);          // veins are thin
  CHECK_GT(bronze_patina, 20);
  CHECK_GT(wood_dark, 20);
  CHECK_GT(wood_light, wood_dark);             // thin dark late wood
}

TEST(texture_marble_period_and_crests) {
  MarbleTexture t;
  t.turbulence_turns_q16 = 0;  // straight veins: exactly periodic along the axis
  t.origin_nm = 3 * kMm;
  for (int a = 0; a < 3; ++a) {
    t.axis = static_cast<Axis>(a);
    each_point([&](PointNm p) {
      PointNm q = p;
      (a == 0 ? q.x_nm : a == 1 ? q.y_nm : q.z_nm) += 2 * t.period_nm;
      CHECK(marble_colour(t, p) == marble_colour(t, q));
    });
  }
  // Crests a quarter period after the origin (the vein colour, exactly),
  // troughs three quarters after (the base).
  t.axis = Axis::kX;
  for (int64_t k = -3; k <= 3; ++k) {
    CHECK(marble_colour(t, PointNm{t.origin_nm + k * t.period_nm + t.period_nm / 4, 5, 7}) == t.vein);
    CHECK(marble_colour(t, PointNm{t.origin_nm + k * t.period_nm + 3 * t.period_nm / 4, 5, 7}) == t.base);
  }
  // Against double: w = ((1 + sin(2 pi phase)) / 2)^4 for the default sharpness 2.
  std::mt19937_64 rng(3);
  for (int i = 0; i < 5000; ++i) {
    const int64_t x = static_cast<int64_t>(rng() % (1000 * kMm)) - 500 * kMm;
    const double phase = static_cast<double>(x - t.origin_nm) / static_cast<double>(t.period_nm);
    const double w = std::pow((1 + std::sin(6.283185307179586 * phase)) / 2, 4);
    if (!CHECK(near_mix(marble_colour(t, PointNm{x, 0, 0}), t.base, t.vein, w, 1.01))) break;
  }
}

TEST(texture_marble_turbulence_bends_veins) {
  // With turbulence the colour is no longer periodic along the axis, but
  // still a blend of the two colours (texture_palettes).
  const MarbleTexture t;
  int differ = 0;
  for (int i = 0; i < 200; ++i) {
    const PointNm p{i * 1300007, i * 700001, i * 90001};
    const PointNm q{p.x_nm + t.period_nm, p.y_nm, p.z_nm};
    differ += !(marble_colour(t, p) == marble_colour(t, q));
  }
  CHECK_GT(differ, 100);
}

TEST(texture_wood_rings) {
  WoodTexture t;
  t.wobble_nm = 0;  // perfect rings: the colour depends on the radius only
  std::mt19937_64 rng(5);
  for (int i = 0; i < 3000; ++i) {
    const int64_t r = static_cast<int64_t>(rng() % (300 * kMm));
    const int64_t y = static_cast<int64_t>(rng() % (100 * kMm));
    // Axis y through (x, z) = (centre_a, centre_b): radial along x and along z.
    const Rgb8 along_x = wood_colour(t, PointNm{t.centre_a_nm + r, y, t.centre_b_nm});
    CHECK(along_x == wood_colour(t, PointNm{t.centre_a_nm, y + 17, t.centre_b_nm - r}));
    CHECK(along_x == wood_colour(t, PointNm{t.centre_a_nm - r - 2 * t.ring_pitch_nm, 0, t.centre_b_nm}));
    const double w = std::pow((1 + std::sin(6.283185307179586 * static_cast<double>(r) / static_cast<double>(t.ring_pitch_nm))) / 2, 2);
    if (!CHECK(near_mix(along_x, t.light, t.dark, w, 1.01))) break;
  }
  // The default wobble moves the rings: not a function of the radius alone.
  const WoodTexture d;
  int differ = 0;
  for (int i = 0; i < 200; ++i) {
    const int64_t r = 20 * kMm + i * 377777;
    differ += !(wood_colour(d, PointNm{d.centre_a_nm + r, 0, d.centre_b_nm}) ==
                wood_colour(d, PointNm{d.centre_a_nm - r, 40 * kMm, d.centre_b_nm}));
  }
  CHECK_GT(differ, 50);
}

TEST(texture_bronze_patina_follows_fbm) {
  // Full patina where the fBm is over threshold + ramp, none under the threshold.
  const BronzeTexture t;
  int full = 0, none = 0;
  each_point([&](PointNm p) {
    const int32_t f = fbm_q15(p, t.patina_feature_nm, t.octaves, t.seed);
    const Rgb8 c = bronze_colour(t, p);
    if (f >= t.patina_threshold_q15 + t.patina_ramp_q15) {
      ++full;
      CHECK(c == t.patina);
    } else if (f <= t.patina_threshold_q15) {
      ++none;
      CHECK(blend_of(c, t.base, t.highlight));
    }
  });
  CHECK_GT(full, 10);
  CHECK_GT(none, 10);
}

TEST(texture_extremes_are_defined) {
  // Degenerate parameters and the largest coordinates: no overflow (UBSan),
  // colours still from the palette.
  Texture t[kTextureKindCount];
  for (int k = 0; k < kTextureKindCount; ++k) t[k] = of_kind(static_cast<TextureKind>(k));
  t[1].layers.boundary_count = 99;
  t[2].marble.period_nm = 0;
  t[2].marble.turbulence_turns_q16 = INT32_MAX;
  t[2].marble.sharpness = 99;
  t[2].marble.origin_nm = INT64_MIN;
  t[3].wood.ring_pitch_nm = -5;
  t[3].wood.wobble_nm = INT64_MAX;
  t[3].wood.centre_b_nm = INT64_MAX;
  t[4].bronze.patina_ramp_q15 = 0;
  t[4].bronze.patina_threshold_q15 = INT32_MIN;
  t[5].granite.grain_nm = 0;
  const int64_t cs[] = {INT64_MIN, -kCoordLimitNm, -1, 0, 1, kCoordLimitNm, INT64_MAX};
  for (const Texture& tk : t)
    for (int64_t c : cs) (void)texture_colour(tk, PointNm{c, c / -3, c / 2});
  CHECK(blend_of(texture_colour(t[2], PointNm{INT64_MAX, 0, 0}), t[2].marble.base, t[2].marble.vein));
}

TEST(texture_marble_and_wood_against_double) {
  // The whole formulas of texture.h in double, given the integer
  // turbulence and fBm (tested against their own oracle in test_noise.cpp).
  const double kTwoPi = 6.283185307179586;
  const MarbleTexture m;
  WoodTexture w;
  w.axis = Axis::kZ;
  w.centre_a_nm = 40 * kMm;
  w.centre_b_nm = 30 * kMm;
  std::mt19937_64 rng(9);
  for (int i = 0; i < 4000; ++i) {
    const PointNm p{static_cast<int64_t>(rng() % (200 * kMm)) - 100 * kMm, static_cast<int64_t>(rng() % (200 * kMm)) - 100 * kMm,
                    static_cast<int64_t>(rng() % (200 * kMm)) - 100 * kMm};
    const double turb = turbulence_q15(p, m.feature_nm, m.octaves, m.seed) / 32768.0;
    const double phase = static_cast<double>(p.x_nm - m.origin_nm) / static_cast<double>(m.period_nm) +
                         m.turbulence_turns_q16 / 65536.0 * turb;
    const double wm = std::pow((1 + std::sin(kTwoPi * phase)) / 2, 4);
    if (!CHECK(near_mix(marble_colour(m, p), m.base, m.vein, wm, 1.01))) break;
    const double r = std::hypot(static_cast<double>(p.x_nm - w.centre_a_nm), static_cast<double>(p.y_nm - w.centre_b_nm)) +
                     static_cast<double>(w.wobble_nm) * fbm_q15(p, w.feature_nm, w.octaves, w.seed) / 32768.0;
    const double ww = std::pow((1 + std::sin(kTwoPi * r / static_cast<double>(w.ring_pitch_nm))) / 2, 2);
    if (!CHECK(near_mix(wood_colour(w, p), w.light, w.dark, ww, 1.01))) break;
  }
}
