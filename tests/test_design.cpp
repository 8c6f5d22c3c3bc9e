// core/design/design.h: the design dexel set from triangles and height
// images, against a double-precision oracle (with exact 128-bit inside tests,
// so coverage must agree column for column and heights within the bound).
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/design/design.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

GridGeometry geometry(int32_t nx, int32_t ny, int64_t pitch_nm, int64_t lsb_nm) {
  GridGeometry g{};
  g.nx = nx;
  g.ny = ny;
  g.x0_nm = -3 * pitch_nm + 123;
  g.y0_nm = 7 * pitch_nm - 77;
  g.pitch_nm = pitch_nm;
  g.z0_nm = -20000000;
  g.lsb_nm = lsb_nm;
  return g;
}

// The oracle: the highest z of the triangles over each column axis, or
// none. Inside: exact edge functions in 128 bits (edges included); z in
// double from the barycentric weights.
struct Oracle {
  std::vector<double> z;  // nm above z0; NAN: no triangle
  explicit Oracle(const GridGeometry& g) : z(static_cast<size_t>(g.nx) * g.ny, NAN) {}
  void add(const GridGeometry& g, const TriangleNm& t) {
    __int128 x[3], y[3];
    double zz[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = t.v[k].x_nm - g.x0_nm;
      y[k] = t.v[k].y_nm - g.y0_nm;
      zz[k] = static_cast<double>(t.v[k].z_nm - g.z0_nm);
    }
    auto e = [](__int128 ax, __int128 ay, __int128 bx, __int128 by, __int128 px, __int128 py) {
      return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    };
    const __int128 area = e(x[0], y[0], x[1], y[1], x[2], y[2]);
    if (area == 0) return;
    for (int32_t j = 0; j < g.ny; ++j)
      for (int32_t i = 0; i < g.nx; ++i) {
        const __int128 px = static_cast<__int128>(i) * g.pitch_nm, py = static_cast<__int128>(j) * g.pitch_nm;
        __int128 w0 = e(x[1], y[1], x[2], y[2], px, py), w1 = e(x[2], y[2], x[0], y[0], px, py),
                 w2 = e(x[0], y[0], x[1], y[1], px, py);
        if (area < 0) { w0 = -w0; w1 = -w1; w2 = -w2; }
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double a = static_cast<double>(area < 0 ? -area : area);
        const double zv = (static_cast<double>(w0) * zz[0] + static_cast<double>(w1) * zz[1] + static_cast<double>(w2) * zz[2]) / a;
        double& o = z[static_cast<size_t>(j) * g.nx + i];
        if (std::isnan(o) || zv > o) o = zv;
      }
  }
};

// Every column: design and oracle agree on coverage, and the height is within
// 0.5 LSB + 2 nm (+ 1e-6 relative for the oracle's own rounding).
int compare(const DesignGrid& d, const Oracle& o, double* worst_lsb) {
  int bad = 0;
  *worst_lsb = 0;
  const GridGeometry& g = d.geo;
  for (size_t k = 0; k < o.z.size(); ++k) {
    const int32_t top = d.top_lsb[k];
    if (std::isnan(o.z[k]) != (top == kNoDesign)) {
      ++bad;
      continue;
    }
    if (top == kNoDesign) continue;
    const double err = std::fabs(static_cast<double>(top) * g.lsb_nm - o.z[k]);
    *worst_lsb = std::fmax(*worst_lsb, err / g.lsb_nm);
    if (err > 0.5 * g.lsb_nm + 2.0 + 1e-9 * std::fabs(o.z[k])) ++bad;
  }
  return bad;
}

PointNm around(const GridGeometry& g, t::Rng& r, int64_t margin) {
  const int64_t w = (g.nx - 1) * g.pitch_nm, h = (g.ny - 1) * g.pitch_nm;
  return PointNm{g.x0_nm + r.range(-margin, w + margin), g.y0_nm + r.range(-margin, h + margin),
                 g.z0_nm + r.range(0, 30000000)};
}

}  // namespace

TEST(design_random_triangles_match_the_oracle) {
  t::Rng r(18);
  for (int run = 0; run < 40; ++run) {
    const GridGeometry g = geometry(static_cast<int32_t>(r.range(2, 60)), static_cast<int32_t>(r.range(2, 60)),
                                    r.range(1000, 500000), run % 3 == 0 ? 1 : r.range(1, 5000));
    std::vector<int32_t> mem(static_cast<size_t>(g.nx) * g.ny);
    DesignGrid d;
    CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOk);
    Oracle o(g);
    const int n = static_cast<int>(r.range(1, 12));
    for (int k = 0; k < n; ++k) {
      TriangleNm t{{around(g, r, g.pitch_nm * 3), around(g, r, g.pitch_nm * 3), around(g, r, g.pitch_nm * 3)}};
      // Some vertices on dexel axes and some edges along rows: the ties.
      if (k % 3 == 1) {
        t.v[0].x_nm = g.x0_nm + g.pitch_nm * r.range(0, g.nx - 1);
        t.v[1].y_nm = t.v[0].y_nm = g.y0_nm + g.pitch_nm * r.range(0, g.ny - 1);
      }
      // Others with every vertex on a dexel axis: edges through many axes.
      if (k % 3 == 2)
        for (PointNm& v : t.v) {
          v.x_nm = g.x0_nm + g.pitch_nm * r.range(-2, g.nx + 1);
          v.y_nm = g.y0_nm + g.pitch_nm * r.range(-2, g.ny + 1);
        }
      CHECK_EQ(design_add_triangle(&d, t), Status::kOk);
      o.add(g, t);
    }
    double worst;
    CHECK_EQ(compare(d, o, &worst), 0);
    CHECK(worst <= 0.5 + 2.0 / static_cast<double>(g.lsb_nm) + 1e-6);
  }
}

namespace {

// A closed mesh from a parametric surface: u around, v from one pole or
// seam to the other, as quads split into two triangles.
template <class F>
void add_mesh(DesignGrid* d, Oracle* o, int nu, int nv, F point, uint64_t* tris) {
  for (int a = 0; a < nu; ++a)
    for (int b = 0; b < nv; ++b) {
      const PointNm p00 = point(a, b), p10 = point(a + 1, b), p01 = point(a, b + 1), p11 = point(a + 1, b + 1);
      const TriangleNm t1{{p00, p10, p11}}, t2{{p00, p11, p01}};
      for (const TriangleNm& t : {t1, t2}) {
        CHECK_EQ(design_add_triangle(d, t), Status::kOk);
        o->add(d->geo, t);
        ++*tris;
      }
    }
}

}  // namespace

TEST(design_closed_sphere_and_torus_match_the_oracle) {
  const GridGeometry g = geometry(120, 100, 250000, 500);  // 0.25 mm pitch, 0.5 um LSB
  std::vector<int32_t> mem(static_cast<size_t>(g.nx) * g.ny);
  DesignGrid d;
  CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOk);
  Oracle o(g);
  uint64_t tris = 0;
  const double pi = 3.14159265358979323846;
  const double cx = static_cast<double>(g.x0_nm) + 8e6, cy = static_cast<double>(g.y0_nm) + 12e6;
  auto nm = [](double v) { return static_cast<int64_t>(std::llround(v)); };
  // Sphere of radius 7 mm, centre 10 mm above z0.
  add_mesh(&d, &o, 48, 24, [&](int a, int b) {
    const double th = 2 * pi * a / 48, ph = pi * b / 24;
    return PointNm{nm(cx + 7e6 * std::sin(ph) * std::cos(th)), nm(cy + 7e6 * std::sin(ph) * std::sin(th)),
                   nm(static_cast<double>(g.z0_nm) + 10e6 + 7e6 * std::cos(ph))};
  }, &tris);
  // Torus (R 6 mm, r 2 mm) beside it, tilted 20 degrees about x: overhangs.
  const double tx = static_cast<double>(g.x0_nm) + 21e6, ty = static_cast<double>(g.y0_nm) + 12e6, tilt = 20 * pi / 180;
  add_mesh(&d, &o, 40, 20, [&](int a, int b) {
    const double u = 2 * pi * a / 40, v = 2 * pi * b / 20;
    const double x = (6e6 + 2e6 * std::cos(v)) * std::cos(u), y = (6e6 + 2e6 * std::cos(v)) * std::sin(u), z = 2e6 * std::sin(v);
    return PointNm{nm(tx + x), nm(ty + y * std::cos(tilt) - z * std::sin(tilt)),
                   nm(static_cast<double>(g.z0_nm) + 9e6 + y * std::sin(tilt) + z * std::cos(tilt))};
  }, &tris);
  double worst;
  CHECK_EQ(compare(d, o, &worst), 0);
  CHECK(worst <= 0.5 + 2.0 / 500 + 1e-6);
  CHECK_EQ(d.triangles, tris);
  // The sphere's top over its centre is within the mesh's chord error of 17 mm.
  const int32_t i = static_cast<int32_t>(8e6 / g.pitch_nm), j = static_cast<int32_t>(12e6 / g.pitch_nm);
  CHECK(std::fabs(d.top_lsb[d.index(i, j)] * 500.0 - 17e6) < 0.05e6);
  CHECK(design_columns(d) > 0);
}

TEST(design_vertical_walls_add_nothing_and_overhangs_keep_the_highest) {
  const GridGeometry g = geometry(20, 20, 1000000, 1000);
  std::vector<int32_t> mem(400);
  DesignGrid d;
  CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOk);
  const int64_t x0 = g.x0_nm, y0 = g.y0_nm, z0 = g.z0_nm;
  // A vertical wall along y = 5 mm: no top of its own.
  CHECK_EQ(design_add_triangle(&d, TriangleNm{{{x0, y0 + 5000000, z0}, {x0 + 10000000, y0 + 5000000, z0},
                                               {x0 + 10000000, y0 + 5000000, z0 + 9000000}}}),
           Status::kOk);
  CHECK_EQ(d.triangles_vertical, uint64_t{1});
  CHECK_EQ(design_columns(d), uint64_t{0});
  // A floor at 2 mm and a roof at 6 mm over part of it (an overhang): the roof wins where both are.
  const TriangleNm floor1{{{x0, y0, z0 + 2000000}, {x0 + 19000000, y0, z0 + 2000000}, {x0 + 19000000, y0 + 19000000, z0 + 2000000}}};
  const TriangleNm roof{{{x0 + 10000000, y0, z0 + 6000000}, {x0 + 19000000, y0, z0 + 6000000}, {x0 + 19000000, y0 + 9000000, z0 + 6000000}}};
  CHECK_EQ(design_add_triangle(&d, roof), Status::kOk);
  CHECK_EQ(design_add_triangle(&d, floor1), Status::kOk);
  CHECK_EQ(d.top_lsb[d.index(15, 2)], 6000);
  CHECK_EQ(d.top_lsb[d.index(5, 2)], 2000);
  CHECK_EQ(d.top_lsb[d.index(2, 5)], kNoDesign);  // above the diagonal: outside the floor
  CHECK_EQ(d.top_lsb[d.index(5, 5)], 2000);       // on the diagonal edge: inside
}

TEST(design_rejects_what_it_cannot_hold) {
  std::vector<int32_t> mem(400);
  DesignGrid d;
  CHECK_EQ(design_init(&d, geometry(20, 21, 1000000, 1000), mem.data(), mem.size()), Status::kBufferTooSmall);
  CHECK_EQ(design_init(&d, geometry(20, 20, 0, 1000), mem.data(), mem.size()), Status::kBadArgument);
  CHECK_EQ(design_init(&d, geometry(20, 20, 100000000, 1000), mem.data(), mem.size()), Status::kOutOfRange);
  const GridGeometry g = geometry(20, 20, 1000000, 1000);
  CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOk);
  const int64_t far = g.x0_nm + kDesignRangeNm + 1;
  CHECK_EQ(design_add_triangle(&d, TriangleNm{{{g.x0_nm, g.y0_nm, g.z0_nm}, {far, g.y0_nm, g.z0_nm}, {far, g.y0_nm + 5, g.z0_nm}}}),
           Status::kOutOfRange);
  CHECK_EQ(d.triangles, uint64_t{0});
}

TEST(design_from_image_maps_pixels_and_grey_levels) {
  const GridGeometry g = geometry(12, 10, 1000000, 1000);
  std::vector<int32_t> mem(120);
  DesignGrid d;
  CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOk);
  // 4 x 2 pixels over x in [1, 9] mm, y in [2, 8] mm from the grid origin: each pixel 2 x 3 mm.
  const uint16_t px[8] = {0, 85, 170, 255, 255, 170, 85, 0};
  const HeightImage img{px, 4, 2, 255};
  const int64_t X0 = g.x0_nm + 1000000, Y0 = g.y0_nm + 2000000;
  CHECK_EQ(design_from_image(&d, img, X0, Y0, X0 + 8000000, Y0 + 6000000, g.z0_nm + 1000000, g.z0_nm + 4000000), Status::kOk);
  CHECK_EQ(d.top_lsb[d.index(0, 5)], kNoDesign);  // left of the image
  CHECK_EQ(d.top_lsb[d.index(1, 7)], 1000);        // top row (largest y), first pixel: black
  CHECK_EQ(d.top_lsb[d.index(3, 7)], 2000);        // second pixel: 85/255 of 3 mm above 1 mm
  CHECK_EQ(d.top_lsb[d.index(9, 7)], 4000);        // the far edge belongs to the last pixel: white
  CHECK_EQ(d.top_lsb[d.index(1, 2)], 4000);        // bottom row, first pixel
  CHECK_EQ(d.top_lsb[d.index(10, 2)], kNoDesign);  // right of the image
  CHECK_EQ(design_from_image(&d, HeightImage{px, 0, 2, 255}, X0, Y0, X0 + 1, Y0 + 1, 0, 1), Status::kBadArgument);
}

TEST(design_edge_functions_hold_at_the_range_limit) {
  // A triangle spanning the whole range from a grid whose last column sits
  // at the limit: the worst-case edge products (checked under UBSan in
  // make test SAN=1), the right columns covered.
  const int64_t lim = kDesignRangeNm;
  GridGeometry g{2, 2, 0, 0, lim, 0, 1000};
  std::vector<int32_t> mem(4);
  DesignGrid d;
  CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOk);
  CHECK_EQ(design_add_triangle(&d, TriangleNm{{{-lim, -lim, lim}, {lim, -lim, lim}, {-lim, lim, -lim}}}), Status::kOk);
  CHECK_EQ(design_add_triangle(&d, TriangleNm{{{lim, lim, -lim}, {-lim, lim, lim}, {lim, -lim, lim}}}), Status::kOk);
  for (int32_t v : mem) CHECK(v != kNoDesign);
  g.pitch_nm = lim + 1;
  CHECK_EQ(design_init(&d, g, mem.data(), mem.size()), Status::kOutOfRange);
}
