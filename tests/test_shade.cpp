// display/surface/shade.h: lighting against a double oracle, the blurred normals of
// §2.4.2, the colour ramps.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "core/grid/grid.h"
#include "display/surface/shade.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using t::Rng;

Lighting light(Rng* rng) {
  Lighting l;
  l.light = normal_unit_q14(rng->range(-1000, 1000), rng->range(-1000, 1000), rng->range(-1000, 1000));
  l.fill_light = normal_unit_q14(rng->range(-1000, 1000), rng->range(-1000, 1000), rng->range(-1000, 1000));
  const UnitQ14 eye = normal_unit_q14(rng->range(-1000, 1000), rng->range(-1000, 1000), rng->range(1, 1000));
  lighting_finish(&l, eye);
  return l;
}

// The lighting model of shade.h in double, from the integer vector.
double oracle(const Lighting& l, double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  const double L[3] = {l.light.x / 16384.0, l.light.y / 16384.0, l.light.z / 16384.0};
  const double F[3] = {l.fill_light.x / 16384.0, l.fill_light.y / 16384.0, l.fill_light.z / 16384.0};
  const double H[3] = {l.half.x / 16384.0, l.half.y / 16384.0, l.half.z / 16384.0};
  const double dl = std::fmax(0, (x * L[0] + y * L[1] + z * L[2]) / n), dh = std::fmax(0, (x * H[0] + y * H[1] + z * H[2]) / n);
  const double df = std::fmax(0, (x * F[0] + y * F[1] + z * F[2]) / n);
  const double b = l.ambient_q14 / 16384.0 + l.diffuse_q14 / 16384.0 * dl + l.fill_q14 / 16384.0 * df +
                   l.specular_q14 / 16384.0 * std::pow(dh, 32);
  return b * 255 / ((l.ambient_q14 + l.diffuse_q14 + l.fill_q14 + l.specular_q14) / 16384.0);
}

}  // namespace

TEST(shade_against_double_oracle) {
  Rng rng;
  double worst = 0;
  for (int rep = 0; rep < 200; ++rep) {
    const Lighting l = light(&rng);
    for (int k = 0; k < 2000; ++k) {
      const int bits = static_cast<int>(rng.range(1, 40));
      const int64_t lim = (int64_t(1) << bits) - 1;
      const int64_t x = rng.range(-lim, lim), y = rng.range(-lim, lim), z = rng.range(-lim, lim);
      if (x == 0 && y == 0 && z == 0) continue;
      const double want = oracle(l, double(x), double(y), double(z));
      const double e = std::fabs(shade_of_vector(l, x, y, z) - want);
      const double e2 = std::fabs(shade_of_normal(l, normal_unit_q14(x, y, z)) - want);
      worst = std::fmax(worst, std::fmax(e, e2));
      CHECK_LE(e, 1.0);
      CHECK_LE(e2, 1.0);
    }
  }
  std::printf("shade: worst index error %.3f (bound 1)\n", worst);
}

TEST(shade_ramp_runs_black_colour_white) {
  uint32_t lut[256];
  shade_ramp(PixelFormat::kXrgb8888, Rgb{200, 40, 30}, 180, lut);
  CHECK_EQ(lut[0], 0xFF000000u);
  CHECK_EQ(lut[180], pixel_pack(PixelFormat::kXrgb8888, Rgb{200, 40, 30}));
  CHECK_EQ(lut[255], 0xFFFFFFFFu);
  for (int i = 1; i < 256; ++i) {
    const Rgb a = pixel_unpack(PixelFormat::kXrgb8888, lut[i - 1]), b = pixel_unpack(PixelFormat::kXrgb8888, lut[i]);
    CHECK(a.r <= b.r && a.g <= b.g && a.b <= b.b);
  }
  shade_ramp(PixelFormat::kRgb565, Rgb{255, 255, 255}, 100, lut);
  CHECK_EQ(lut[255], 0xFFFFu);
}

template <class H>
static void check_shade_grid() {
  // A random relief with holes: the interior fast path of shade_grid must
  // give what shade_gradient (the blur of grid_gradient, eq. 1, turned on
  // steep slopes) and shade_of_vector give, dexel by dexel; side-face shades wherever a hole
  // is within one dexel.
  Rng rng;
  const int32_t nx = 23, ny = 17;
  std::vector<H> top(nx * ny), bottom(nx * ny, 0);
  DexelGrid<H> g;
  GridGeometry geo{nx, ny, 0, 0, 500000, 0, 1000};
  CHECK_EQ(grid_init(&g, geo, top.data(), bottom.data(), top.size()), Status::kOk);
  const int64_t hmax = height_max<H>() < 60000 ? height_max<H>() : 60000;
  for (int rep = 0; rep < 20; ++rep) {
    for (auto& t : top) t = static_cast<H>(rng.next() % 5 == 0 ? 0 : rng.range(1, hmax));
    std::vector<uint8_t> st(top.size(), 0), sw(top.size(), 0);
    ShadeCache cache{st.data(), sw.data()};
    Lighting l = light(&rng);
    shade_grid(g, l, g.bounds(), &cache);
    const int64_t dz16 = 16 * div_round(2 * g.pitch_nm, g.lsb_nm);
    for (int32_t j = 0; j < ny; ++j) {
      for (int32_t i = 0; i < nx; ++i) {
        if (g.is_hole(i, j)) continue;
        int64_t gx, gy;
        shade_gradient(g, i, j, &gx, &gy);
        const size_t k = g.index(i, j);
        CHECK_EQ(int(st[k]), shade_of_vector(l, -gx, -gy, dz16));
        bool near_hole = false;
        for (int32_t b = -1; b <= 1; ++b)
          for (int32_t a = -1; a <= 1; ++a)
            if (g.contains(i + a, j + b) && g.is_hole(i + a, j + b)) near_hole = true;
        if (near_hole && (gx || gy)) CHECK_EQ(int(sw[k]), shade_of_vector(l, -gx, -gy, 0));
      }
    }
  }
}

TEST(shade_grid_fast_path_matches_reference) {
  check_shade_grid<uint8_t>();
  check_shade_grid<uint16_t>();
  check_shade_grid<uint32_t>();
}

TEST(blurred_gradient_is_the_papers_kernel) {
  // One bump in a flat field: the blur spreads the central differences of
  // its neighbours with weights 1 2 1 / 2 4 2 / 1 2 1.
  const int32_t n = 9;
  std::vector<uint16_t> top(n * n, 100), bottom(n * n, 0);
  DexelGrid<uint16_t> g;
  GridGeometry geo{n, n, 0, 0, 1000, 0, 1000};
  CHECK_EQ(grid_init(&g, geo, top.data(), bottom.data(), top.size()), Status::kOk);
  top[g.index(4, 4)] = 108;
  int64_t gx, gy;
  // At (3, 4): its own difference (108 - 100) * 4 plus (4, 4)'s own 0.
  blurred_gradient(g, 3, 4, &gx, &gy);
  CHECK_EQ(gx, 4 * 8);
  CHECK_EQ(gy, 0);
  // At (3, 3): neighbours (3, 4) [weight 2] and (4, 3) [weight 2] see the bump.
  blurred_gradient(g, 3, 3, &gx, &gy);
  CHECK_EQ(gx, 2 * 8);
  CHECK_EQ(gy, 2 * 8);
  blurred_gradient(g, 4, 4, &gx, &gy);
  CHECK_EQ(gx, 0);
  CHECK_EQ(gy, 0);
}
