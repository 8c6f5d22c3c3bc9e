// display/view/pick.h: the dexel under a pixel, held to a double-precision
// oracle (the camera's projection and a brute-force ray cast over every
// column's box) on a plate with a pocket and a through hole, in orthographic
// and perspective views: hits and misses both.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/math/trig.h"
#include "display/raster/camera.h"
#include "display/view/pick.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;
constexpr double kPi = 3.14159265358979323846;
constexpr int32_t kW = 320, kH = 240;

// A 40 x 30 mm plate, 10 mm thick, of 1 mm dexels; a 20 x 14 mm pocket 4
// mm deep in its middle with a 3 x 3 dexel hole through its floor.
struct Plate {
  t::TestGrid<uint16_t> tg;
  int64_t floor_z = 0;
  Plate() {
    t::make_block(&tg, 42, 32, mm, 10 * mm);
    DexelGrid<uint16_t>& g = tg.g;
    const uint16_t floor = static_cast<uint16_t>(grid_height_of_z(g, 6 * mm));
    floor_z = g.z0_nm + static_cast<int64_t>(floor) * g.lsb_nm;
    for (int32_t j = 9; j < 23; ++j)
      for (int32_t i = 11; i < 31; ++i) g.top[g.index(i, j)] = floor;
    for (int32_t j = 15; j < 18; ++j)
      for (int32_t i = 19; i < 22; ++i) g.top[g.index(i, j)] = 0;
  }
};

// The scene frame the renderer would build for g (display/surface/render.cpp).
SceneFrame scene_of(const DexelGrid<uint16_t>& g, BoxNm* stock) {
  uint32_t hmax = 0;
  for (int32_t k = 0; k < g.nx * g.ny; ++k) hmax = g.top[k] > hmax ? g.top[k] : hmax;
  stock->lo = PointNm{g.x0_nm, g.y0_nm, g.z0_nm};
  stock->hi = PointNm{g.x0_nm + (g.nx - 1) * g.pitch_nm, g.y0_nm + (g.ny - 1) * g.pitch_nm, g.z0_nm + hmax * g.lsb_nm};
  const int64_t span = stock->hi.x_nm - stock->lo.x_nm;
  SceneFrame s;
  s.box.lo = PointNm{stock->lo.x_nm - span / 10, stock->lo.y_nm - span / 10, stock->lo.z_nm - g.pitch_nm};
  s.box.hi = PointNm{stock->hi.x_nm + span / 10, stock->hi.y_nm + span / 10, stock->hi.z_nm + span / 2};
  s.x0_nm = g.x0_nm;
  s.y0_nm = g.y0_nm;
  s.z0_nm = g.z0_nm;
  s.pitch_nm = g.pitch_nm;
  s.lsb_nm = g.lsb_nm;
  s.stock_top_nm = stock->hi.z_nm;
  return s;
}

// The camera in doubles: projection of machine points, and the ray of a
// pixel's centre.
struct Oracle {
  double r[3], u[3], d[3], t[3];
  bool persp;
  double vh = 0, dist = 0, focal = 0;
  explicit Oracle(const Camera& c) {
    const double a = c.azimuth_bam * (2 * kPi / 4294967296.0), e = c.elevation_bam * (2 * kPi / 4294967296.0);
    const double rr[3] = {-std::sin(a), std::cos(a), 0};
    const double uu[3] = {-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)};
    const double dd[3] = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
    const double tt[3] = {double(c.target.x_nm), double(c.target.y_nm), double(c.target.z_nm)};
    for (int k = 0; k < 3; ++k) {
      r[k] = rr[k];
      u[k] = uu[k];
      d[k] = dd[k];
      t[k] = tt[k];
    }
    persp = c.projection == Projection::kPerspective;
    vh = double(c.view_height_nm);
    dist = double(c.distance_nm);
    const double half = c.fov_bam * (kPi / 4294967296.0);
    focal = kH / 2.0 * std::cos(half) / std::sin(half);
  }
  void project(const double p[3], double* x, double* y) const {
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = p[k] - t[k];
    const double a = q[0] * r[0] + q[1] * r[1] + q[2] * r[2], b = q[0] * u[0] + q[1] * u[1] + q[2] * u[2];
    if (!persp) {
      *x = kW / 2.0 + kH * a / vh;
      *y = kH / 2.0 - kH * b / vh;
      return;
    }
    const double w = dist - (q[0] * d[0] + q[1] * d[1] + q[2] * d[2]);
    *x = kW / 2.0 + focal * a / w;
    *y = kH / 2.0 - focal * b / w;
  }
  void ray(int32_t px, int32_t py, double o[3], double dir[3]) const {
    const double a = px + 0.5 - kW / 2.0, b = kH / 2.0 - (py + 0.5);
    for (int k = 0; k < 3; ++k) {
      if (persp) {
        o[k] = t[k] + dist * d[k];
        dir[k] = r[k] * a + u[k] * b - d[k] * focal;
      } else {
        o[k] = t[k] + (r[k] * a + u[k] * b) * vh / kH;
        dir[k] = -d[k];
      }
    }
  }
};

// Brute force: the nearest column box the pixel's ray meets.
bool cast(const Oracle& o, const DexelGrid<uint16_t>& g, int32_t px, int32_t py, int32_t* bi, int32_t* bj) {
  double p[3], d[3];
  o.ray(px, py, p, d);
  double best = 1e300;
  const double h = double(g.pitch_nm) / 2;
  for (int32_t j = 0; j < g.ny; ++j) {
    for (int32_t i = 0; i < g.nx; ++i) {
      const size_t k = g.index(i, j);
      if (g.top[k] == 0 && g.bottom[k] == 0) continue;
      const double lo[3] = {double(g.x0_nm + i * g.pitch_nm) - h, double(g.y0_nm + j * g.pitch_nm) - h,
                            double(g.z0_nm + g.bottom[k] * g.lsb_nm)};
      const double hi[3] = {lo[0] + 2 * h, lo[1] + 2 * h, double(g.z0_nm + g.top[k] * g.lsb_nm)};
      double a = o.persp ? 0 : -1e300, b = 1e300;
      for (int c = 0; c < 3; ++c) {
        if (d[c] == 0) {
          if (p[c] < lo[c] || p[c] > hi[c]) a = 1e300;
          continue;
        }
        const double u = (lo[c] - p[c]) / d[c], w = (hi[c] - p[c]) / d[c];
        a = std::fmax(a, std::fmin(u, w));
        b = std::fmin(b, std::fmax(u, w));
      }
      if (a <= b && a < best) {
        best = a;
        *bi = i;
        *bj = j;
      }
    }
  }
  return best < 1e299;
}

struct Views {
  Camera cam[4];
  const char* name[4] = {"iso", "top", "perspective", "low"};
};

Views views(const BoxNm& stock) {
  Views v;
  v.cam[0] = camera_preset(ViewPreset::kIso);
  v.cam[1] = camera_preset(ViewPreset::kTop);
  v.cam[2] = camera_preset(ViewPreset::kIso);
  v.cam[2].projection = Projection::kPerspective;
  v.cam[3] = camera_preset(ViewPreset::kIso);
  v.cam[3].azimuth_bam = 0u - bam_from_mdeg(60000);
  v.cam[3].elevation_bam = static_cast<int32_t>(bam_from_mdeg(20000));
  for (Camera& c : v.cam) camera_fit(&c, stock, kW, kH);
  return v;
}

// Calls f(name, view, oracle) for each of views()'s cameras fitted to g,
// the view built at kW x kH as the renderer builds it.
template <class F>
void for_each_view(const DexelGrid<uint16_t>& g, F f) {
  BoxNm stock;
  const SceneFrame scene = scene_of(g, &stock);
  const Views vs = views(stock);
  for (int c = 0; c < 4; ++c) {
    View v;
    view_build(vs.cam[c], scene, kW, kH, &v);
    f(vs.name[c], v, Oracle(vs.cam[c]));
  }
}

int32_t cheb(int32_t ai, int32_t aj, int32_t bi, int32_t bj) {
  return std::max(std::abs(ai - bi), std::abs(aj - bj));
}

}  // namespace

// Each dexel's top centre projected to its pixel: where the oracle's ray
// there meets that column or a neighbour (the point is seen), the pick
// returns it, within one cell.
TEST(pick_dexel_centres_come_back) {
  Plate plate;
  const DexelGrid<uint16_t>& g = plate.tg.g;
  for_each_view(g, [&](const char* name, const View& v, const Oracle& o) {
    int seen = 0, exact = 0;
    for (int32_t j = 0; j < g.ny; ++j) {
      for (int32_t i = 0; i < g.nx; ++i) {
        const size_t k = g.index(i, j);
        if (g.top[k] == 0) continue;
        const double p[3] = {double(g.x0_nm + i * g.pitch_nm), double(g.y0_nm + j * g.pitch_nm),
                             double(g.z0_nm + g.top[k] * g.lsb_nm)};
        double x = 0, y = 0;
        o.project(p, &x, &y);
        const int32_t px = static_cast<int32_t>(std::floor(x)), py = static_cast<int32_t>(std::floor(y));
        int32_t oi = -1, oj = -1;
        if (!cast(o, g, px, py, &oi, &oj) || cheb(oi, oj, i, j) > 1) continue;  // hidden
        ++seen;
        const PickHit h = pick_dexel(v, g, px, py);
        if (!CHECK(h.hit)) {
          std::printf("  %s: dexel (%d, %d) at pixel (%d, %d): no hit\n", name, i, j, px, py);
          continue;
        }
        if (!CHECK(cheb(h.i, h.j, i, j) <= 1))
          std::printf("  %s: dexel (%d, %d) at pixel (%d, %d): picked (%d, %d)\n", name, i, j, px, py, h.i, h.j);
        exact += h.i == i && h.j == j;
      }
    }
    // Most of the plate faces the camera, and most centres come back exact.
    CHECK(seen > g.nx * g.ny / 3);
    CHECK(exact * 10 > seen * 7);
  });
}

// Every fourth pixel of each view: the pick and the oracle's ray cast agree
// on hit or miss, and on the column within one cell; both kinds occur.
TEST(pick_agrees_with_ray_cast_hits_and_misses) {
  Plate plate;
  const DexelGrid<uint16_t>& g = plate.tg.g;
  for_each_view(g, [&](const char* name, const View& v, const Oracle& o) {
    int hits = 0, misses = 0, differ = 0;
    for (int32_t py = 0; py < kH; py += 4) {
      for (int32_t px = 0; px < kW; px += 4) {
        int32_t oi = -1, oj = -1;
        const bool want = cast(o, g, px, py, &oi, &oj);
        const PickHit h = pick_dexel(v, g, px, py);
        if (h.hit != want || (want && cheb(h.i, h.j, oi, oj) > 1)) {
          ++differ;
          std::printf("  %s: pixel (%d, %d): oracle %d (%d, %d), pick %d (%d, %d)\n", name, px, py, want, oi, oj,
                      h.hit, h.i, h.j);
        }
        (want ? hits : misses) += 1;
      }
    }
    CHECK_EQ(differ, 0);
    CHECK(hits > 500);
    CHECK(misses > 500);
    // The frame's corners are background; pixels outside it miss.
    CHECK(!pick_dexel(v, g, 0, 0).hit);
    CHECK(!pick_dexel(v, g, kW - 1, kH - 1).hit);
    CHECK(!pick_dexel(v, g, -1, kH / 2).hit);
    CHECK(!pick_dexel(v, g, kW / 2, kH).hit);
  });
}

// From the top: the pocket's floor at its height, and the hole through it
// a miss; the plate's top at the stock's height.
TEST(pick_top_view_floor_hole_and_top) {
  Plate plate;
  const DexelGrid<uint16_t>& g = plate.tg.g;
  BoxNm stock;
  const SceneFrame scene = scene_of(g, &stock);
  Camera cam = camera_preset(ViewPreset::kTop);
  camera_fit(&cam, stock, kW, kH);
  View v;
  view_build(cam, scene, kW, kH, &v);
  const Oracle o(cam);
  auto pixel_of = [&](int32_t i, int32_t j, int32_t* px, int32_t* py) {
    const double p[3] = {double(g.x0_nm + i * g.pitch_nm), double(g.y0_nm + j * g.pitch_nm), 0.0};
    double x = 0, y = 0;
    o.project(p, &x, &y);
    *px = static_cast<int32_t>(std::floor(x));
    *py = static_cast<int32_t>(std::floor(y));
  };
  int32_t px = 0, py = 0;
  pixel_of(14, 12, &px, &py);  // the pocket
  PickHit h = pick_dexel(v, g, px, py);
  CHECK(h.hit);
  CHECK(cheb(h.i, h.j, 14, 12) <= 1);
  CHECK_EQ(h.point.z_nm, plate.floor_z);
  pixel_of(20, 16, &px, &py);  // the hole
  CHECK(!pick_dexel(v, g, px, py).hit);
  pixel_of(5, 5, &px, &py);  // the top
  h = pick_dexel(v, g, px, py);
  CHECK(h.hit);
  CHECK(cheb(h.i, h.j, 5, 5) <= 1);
  CHECK_EQ(h.point.z_nm, g.z0_nm + static_cast<int64_t>(g.top[g.index(5, 5)]) * g.lsb_nm);
}
