// display/raster/raster.h and display/raster/clip.h: the fill rule, clip independence,
// interpolation against a double oracle, clipping.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "display/raster/clip.h"
#include "display/raster/raster.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using t::Rng;

// A frame with colour and depth, XRGB8888 and 32-bit depth.
struct Canvas {
  int32_t w, h;
  std::vector<uint32_t> color;
  std::vector<uint32_t> z;
  uint32_t lut[256];
  RasterTarget t;
  Canvas(int32_t width, int32_t height) : w(width), h(height), color(size_t(width) * height, 0), z(size_t(width) * height) {
    for (int i = 0; i < 256; ++i) lut[i] = 0xFF000000u | uint32_t(i) * 0x010101u;
    t.color = reinterpret_cast<uint8_t*>(color.data());
    t.color_stride = w * 4;
    t.format = PixelFormat::kXrgb8888;
    t.z = reinterpret_cast<uint8_t*>(z.data());
    t.z_stride = w * 4;
    t.zformat = ZFormat::kZ32;
    t.clip = ScreenRect{0, 0, w, h};
    t.lut = lut;
    raster_clear(&t, t.clip, 0);
  }
};

RasterVertex V(int32_t x, int32_t y, int32_t depth = 1 << 20, int32_t shade = 128) { return RasterVertex{x, y, depth, shade}; }

int64_t area2(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c) {
  return (int64_t(c.x_q4) - a.x_q4) * (int64_t(b.y_q4) - a.y_q4) - (int64_t(b.x_q4) - a.x_q4) * (int64_t(c.y_q4) - a.y_q4);
}

// A mesh of triangles exactly covering the q4 rectangle [x0, x1] x [y0, y1]:
// an (na x nb)-cell lattice, interior vertices jittered (by under a quarter
// of a cell, so every quad stays convex), boundary vertices slid along their
// edge, each quad split along a random diagonal; all counterclockwise on the
// screen.
std::vector<RasterVertex> rect_mesh(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int na, int nb, int32_t jitter,
                                    Rng* rng) {
  std::vector<RasterVertex> v(size_t(na + 1) * (nb + 1));
  for (int b = 0; b <= nb; ++b) {
    for (int a = 0; a <= na; ++a) {
      int32_t x = x0 + int32_t(int64_t(x1 - x0) * a / na), y = y0 + int32_t(int64_t(y1 - y0) * b / nb);
      if (jitter) {
        if (a > 0 && a < na) x += int32_t(rng->range(-jitter, jitter));
        if (b > 0 && b < nb) y += int32_t(rng->range(-jitter, jitter));
      }
      v[size_t(b) * (na + 1) + a] = V(x, y);
    }
  }
  std::vector<RasterVertex> tris;
  // Lattice order is clockwise on the screen (y down); a triangle of the
  // other orientation would mean the jitter folded the mesh.
  auto add = [&](RasterVertex p, RasterVertex q, RasterVertex r) {
    CHECK_LT(area2(p, q, r), 0);
    std::swap(q, r);
    tris.push_back(p);
    tris.push_back(q);
    tris.push_back(r);
  };
  for (int b = 0; b < nb; ++b) {
    for (int a = 0; a < na; ++a) {
      const RasterVertex& p00 = v[size_t(b) * (na + 1) + a];
      const RasterVertex& p10 = v[size_t(b) * (na + 1) + a + 1];
      const RasterVertex& p01 = v[size_t(b + 1) * (na + 1) + a];
      const RasterVertex& p11 = v[size_t(b + 1) * (na + 1) + a + 1];
      if (rng->next() & 1) {
        add(p00, p10, p11);
        add(p00, p11, p01);
      } else {
        add(p00, p10, p01);
        add(p10, p11, p01);
      }
    }
  }
  return tris;
}

// Pixels whose centre lies in [x0, x1) x [y0, y1) (q4): the top-left rule's
// share of the rectangle.
bool in_rect(int32_t px, int32_t py, int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
  const int32_t cx = px * 16 + 8, cy = py * 16 + 8;
  return cx >= x0 && cx < x1 && cy >= y0 && cy < y1;
}

struct MeshCase {
  int32_t x0, y0, x1, y1;
  int na, nb;
  int32_t jitter;
};
const MeshCase kMeshCases[] = {
    {40, 40, 16 * 60 + 8, 16 * 50 + 8, 80, 70, 2},      // cells under a pixel: the small-triangle path
    {37, 21, 16 * 150 + 3, 16 * 100 + 13, 40, 30, 12},  // a few pixels each
    {8, 8, 16 * 180 + 8, 16 * 120 + 8, 3, 2, 200},      // wide triangles: the analytic span path
    {8, 8, 16 * 100 + 8, 16 * 80 + 8, 25, 20, 0},       // vertices on pixel centres: edges through centres
    {0, 0, 16 * 64, 16 * 64, 64, 64, 0},                // vertices on pixel corners
    {1000, 500, 1001 + 16 * 90, 503 + 16 * 70, 90, 7, 3},  // long thin slivers
};

}  // namespace

TEST(fill_rule_covers_a_rectangle_exactly_once) {
  Rng rng(1);
  for (const MeshCase& m : kMeshCases) {
    for (int rep = 0; rep < 4; ++rep) {
      Canvas c(200, 140);
      c.t.count_coverage = true;
      const std::vector<RasterVertex> tris = rect_mesh(m.x0, m.y0, m.x1, m.y1, m.na, m.nb, m.jitter, &rng);
      for (size_t k = 0; k < tris.size(); k += 3) raster_triangle(&c.t, tris[k], tris[k + 1], tris[k + 2]);
      int bad = 0;
      for (int32_t y = 0; y < c.h; ++y) {
        for (int32_t x = 0; x < c.w; ++x) {
          const int count = reinterpret_cast<const uint8_t*>(c.color.data())[size_t(y) * c.w * 4 + x];
          const int want = in_rect(x, y, m.x0, m.y0, m.x1, m.y1) ? 1 : 0;
          if (count != want && bad++ < 3) CHECK_EQ(count, want);
        }
      }
      CHECK_EQ(bad, 0);
    }
  }
}

TEST(fill_rule_through_the_depth_tested_path) {
  // Each triangle nearer than the last: every fragment passes the depth test,
  // so pixels_written counts fragments and any overlap shows.
  Rng rng(2);
  for (const MeshCase& m : kMeshCases) {
    Canvas c(200, 140);
    std::vector<RasterVertex> tris = rect_mesh(m.x0, m.y0, m.x1, m.y1, m.na, m.nb, m.jitter, &rng);
    int64_t want = 0;
    for (int32_t y = 0; y < c.h; ++y)
      for (int32_t x = 0; x < c.w; ++x) want += in_rect(x, y, m.x0, m.y0, m.x1, m.y1);
    int32_t depth = kDepthMax - kDepthMargin;
    for (size_t k = 0; k < tris.size(); k += 3, depth -= 7) {
      for (int q = 0; q < 3; ++q) {
        tris[k + q].depth = depth;
        tris[k + q].shade = 255;
      }
      raster_triangle(&c.t, tris[k], tris[k + 1], tris[k + 2]);
    }
    CHECK_EQ(int64_t(c.t.stats.pixels_written), want);
    int holes = 0;
    for (int32_t y = 0; y < c.h; ++y)
      for (int32_t x = 0; x < c.w; ++x)
        if (in_rect(x, y, m.x0, m.y0, m.x1, m.y1) && c.color[size_t(y) * c.w + x] == 0) ++holes;
    CHECK_EQ(holes, 0);
  }
}

TEST(fill_rule_top_left_by_hand) {
  // A square split along its diagonal, edges through pixel centres: the left
  // and top edges belong to it, the right and bottom ones do not.
  Canvas c(8, 8);
  c.t.count_coverage = true;
  const RasterVertex a = V(24, 24), b = V(24, 72), d = V(72, 72), e = V(72, 24);  // centres of (1,1) (1,4) (4,4) (4,1)
  raster_triangle(&c.t, a, b, d);
  raster_triangle(&c.t, a, d, e);
  const uint8_t* cnt = reinterpret_cast<const uint8_t*>(c.color.data());
  for (int32_t y = 0; y < 8; ++y)
    for (int32_t x = 0; x < 8; ++x) CHECK_EQ(int(cnt[size_t(y) * 32 + x]), (x >= 1 && x < 4 && y >= 1 && y < 4) ? 1 : 0);
  // Clockwise triangles are culled by default.
  Canvas d2(8, 8);
  raster_triangle(&d2.t, a, d, b);
  CHECK_EQ(d2.t.stats.pixels_written, 0u);
}

TEST(clipping_changes_no_pixel) {
  // The same triangles drawn whole and through random clip rectangles give
  // the same bits inside each rectangle and nothing outside it.
  Rng rng(3);
  for (int rep = 0; rep < 60; ++rep) {
    std::vector<RasterVertex> tris;
    for (int k = 0; k < 40; ++k) {
      const int32_t size = int32_t(rng.range(4, k < 20 ? 40 : 3000));
      const int32_t cx = int32_t(rng.range(-200, 16 * 120)), cy = int32_t(rng.range(-200, 16 * 90));
      RasterVertex p[3];
      for (RasterVertex& q : p)
        q = V(cx + int32_t(rng.range(-size, size)), cy + int32_t(rng.range(-size, size)),
              int32_t(rng.range(kDepthMargin, kDepthMax - kDepthMargin)), int32_t(rng.range(0, 255)));
      if (area2(p[0], p[1], p[2]) < 0) std::swap(p[1], p[2]);
      tris.insert(tris.end(), p, p + 3);
    }
    Canvas whole(120, 90);
    for (size_t k = 0; k < tris.size(); k += 3) raster_triangle(&whole.t, tris[k], tris[k + 1], tris[k + 2]);
    Canvas part(120, 90);
    const int32_t x0 = int32_t(rng.range(0, 119)), y0 = int32_t(rng.range(0, 89));
    part.t.clip = ScreenRect{x0, y0, int32_t(rng.range(x0 + 1, 120)), int32_t(rng.range(y0 + 1, 90))};
    for (size_t k = 0; k < tris.size(); k += 3) raster_triangle(&part.t, tris[k], tris[k + 1], tris[k + 2]);
    int diff = 0;
    for (int32_t y = 0; y < 90; ++y) {
      for (int32_t x = 0; x < 120; ++x) {
        const size_t i = size_t(y) * 120 + x;
        const bool inside = x >= part.t.clip.x0 && x < part.t.clip.x1 && y >= part.t.clip.y0 && y < part.t.clip.y1;
        if (inside ? (part.color[i] != whole.color[i] || part.z[i] != whole.z[i]) : (part.color[i] != 0 || part.z[i] != 0xFFFFFFFFu))
          ++diff;
      }
    }
    CHECK_EQ(diff, 0);
  }
}

// Calls f(i, w, px, py) for every pixel of c (64 x 64) the triangle p
// (twice its area A) covered: its index, the exact barycentric weights of
// its centre (px, py, q4).
template <class F>
void each_covered(const Canvas& c, const RasterVertex p[3], double A, F f) {
  for (int32_t y = 0; y < 64; ++y)
    for (int32_t x = 0; x < 64; ++x) {
      const size_t i = size_t(y) * 64 + x;
      if (c.z[i] == 0xFFFFFFFFu) continue;
      const double px = x * 16 + 8, py = y * 16 + 8;
      auto E = [&](const RasterVertex& a, const RasterVertex& b) {
        return (px - a.x_q4) * (b.y_q4 - a.y_q4) - (py - a.y_q4) * (b.x_q4 - a.x_q4);
      };
      const double w[3] = {E(p[1], p[2]) / A, E(p[2], p[0]) / A, E(p[0], p[1]) / A};
      f(i, w, px, py);
    }
}

// The oracle tests' triangles: vertices 1 and 2 moved by up to `size` q4
// from vertex 0 (every other rep within 3 pixels of it: the small-triangle
// path), turned counterclockwise; returns twice the area (0: degenerate).
static double oracle_shape(Rng* rng, int rep, int32_t size, RasterVertex p[3]) {
  p[1].x_q4 = p[0].x_q4 + int32_t(rng->range(-size, size));
  p[2].y_q4 = p[0].y_q4 + int32_t(rng->range(-size, size));
  if (rep % 2)
    for (int k = 1; k < 3; ++k) {
      p[k].x_q4 = p[0].x_q4 + int32_t(rng->range(-24, 24));
      p[k].y_q4 = p[0].y_q4 + int32_t(rng->range(-24, 24));
    }
  if (area2(p[0], p[1], p[2]) < 0) std::swap(p[1], p[2]);
  return double(area2(p[0], p[1], p[2]));
}

TEST(interpolation_against_double_oracle) {
  // Depth and shade at every covered pixel against barycentric interpolation
  // in double: depth within 2^-7 * (1 + pixels from vertex 0) + 1/2 units
  // (gradients truncated per pixel, the small-triangle path rounds once),
  // shade index within 1 of the exact value.
  Rng rng(4);
  double worst_z = 0, worst_s = 0;
  for (int rep = 0; rep < 2000; ++rep) {
    Canvas c(64, 64);
    const int32_t size = int32_t(rng.range(10, 16 * 64));
    RasterVertex p[3];
    for (RasterVertex& q : p)
      q = V(int32_t(rng.range(0, 16 * 64)), int32_t(rng.range(0, 16 * 64)),
            int32_t(rng.range(kDepthMargin, kDepthMax - kDepthMargin)), int32_t(rng.range(0, 255)));
    const double A = oracle_shape(&rng, rep, size, p);
    if (A == 0) continue;
    raster_triangle(&c.t, p[0], p[1], p[2]);
    each_covered(c, p, A, [&](size_t i, const double w[3], double px, double py) {
      const double w0 = w[0], w1 = w[1], w2 = w[2];
      const double z = w0 * p[0].depth + w1 * p[1].depth + w2 * p[2].depth;
      const double s = w0 * p[0].shade + w1 * p[1].shade + w2 * p[2].shade;
      const double dist = (std::fabs(px - p[0].x_q4) + std::fabs(py - p[0].y_q4)) / 16;
      const double ez = std::fabs(c.z[i] / 128.0 - z), es = std::fabs(double(c.color[i] & 0xFF) - s);
      worst_z = ez > worst_z ? ez : worst_z;
      worst_s = es > worst_s ? es : worst_s;
      CHECK_LE(ez, (1 + dist) / 128.0 + 0.5);
      CHECK_LE(es, 1.0);
    });
  }
  std::printf("interpolation: worst depth error %.3f units, worst shade error %.3f levels\n", worst_z, worst_s);
}

TEST(vertex_colours_against_double_oracle) {
  // Colour per vertex (a texture's colours): every channel at every covered
  // pixel within 1 of barycentric interpolation in double, on both the
  // small-triangle and the plane path and in both pixel formats (RGB565
  // compared after the same truncation to 5/6/5 bits).
  Rng rng(14);
  double worst = 0;
  for (int rep = 0; rep < 1500; ++rep) {
    Canvas c(64, 64);
    const bool c565 = rep % 3 == 2;
    std::vector<uint16_t> px16(64 * 64, 0);
    if (c565) {
      c.t.color = reinterpret_cast<uint8_t*>(px16.data());
      c.t.color_stride = 128;
      c.t.format = PixelFormat::kRgb565;
    }
    c.t.vertex_rgb = true;
    const int32_t size = int32_t(rng.range(10, 16 * 64));
    RasterVertex p[3];
    for (RasterVertex& q : p) {
      q = V(int32_t(rng.range(0, 16 * 64)), int32_t(rng.range(0, 16 * 64)), 1 << 20, 0);
      q.rgb = uint32_t(rng.range(0, 0xFFFFFF));
    }
    const double A = oracle_shape(&rng, rep, size, p);
    if (A == 0) continue;
    raster_triangle(&c.t, p[0], p[1], p[2]);
    each_covered(c, p, A, [&](size_t i, const double w[3], double, double) {
      for (int k = 0; k < 3; ++k) {
        const int shift = 16 - 8 * k;
        double want = 0;
        for (int v = 0; v < 3; ++v) want += w[v] * double((p[v].rgb >> shift) & 0xFF);
        double got;
        if (c565) {
          // The channel's top bits: compare in the stored precision.
          const uint32_t v16 = px16[i];
          const int bits = k == 1 ? 6 : 5;
          const uint32_t stored = k == 0 ? v16 >> 11 : (k == 1 ? (v16 >> 5) & 63 : v16 & 31);
          got = double(stored);
          want = std::floor(std::floor(want + 0.5) / double(1 << (8 - bits)));
        } else {
          got = double((c.color[i] >> shift) & 0xFF);
        }
        const double e = std::fabs(got - want);
        worst = e > worst ? e : worst;
        CHECK_LE(e, 1.0);
      }
    });
  }
  std::printf("vertex colours: worst channel error %.3f levels\n", worst);
}

TEST(depth_test_keeps_the_nearer_surface) {
  const RasterVertex a = V(16, 16, 5000, 10), b = V(16, 600, 5000, 10), d = V(600, 16, 5000, 10);
  const RasterVertex a2 = V(16, 16, 4000, 200), b2 = V(16, 600, 4000, 200), d2 = V(600, 16, 4000, 200);
  Canvas one(40, 40), two(40, 40);
  raster_triangle(&one.t, a, b, d);
  raster_triangle(&one.t, a2, b2, d2);
  raster_triangle(&two.t, a2, b2, d2);
  raster_triangle(&two.t, a, b, d);
  CHECK(one.color == two.color);
  CHECK_EQ(one.color[size_t(5) * 40 + 5] & 0xFF, 200u);
  // A 16-bit depth buffer gives the same picture here.
  std::vector<uint16_t> z16(40 * 40);
  Canvas three(40, 40);
  three.t.z = reinterpret_cast<uint8_t*>(z16.data());
  three.t.z_stride = 80;
  three.t.zformat = ZFormat::kZ16;
  raster_clear(&three.t, three.t.clip, 0);
  raster_triangle(&three.t, a, b, d);
  raster_triangle(&three.t, a2, b2, d2);
  CHECK(one.color == three.color);
}

TEST(guard_band_clipping_matches_exact_coverage) {
  // Orthographic: huge triangles with vertices far outside the guard band
  // are cut to it; the pixels match an exact point-in-triangle test except
  // within a pixel of an edge (the cut vertices are rounded to q4).
  Rng rng(5);
  Projector p;
  p.kind = Projection::kOrthographic;
  clip_set_planes(&p, 100, 80);
  int checked = 0;
  for (int rep = 0; rep < 50; ++rep) {
    ClipVertex v[3];
    for (ClipVertex& q : v) q = ClipVertex{rng.range(-40000000, 40000000), rng.range(-40000000, 40000000), 1, 1 << 20, 100};
    Canvas c(100, 80);
    c.t.cull_back = false;
    clip_draw_triangle(&c.t, p, v[0], v[1], v[2]);
    for (int32_t y = 0; y < 80; ++y) {
      for (int32_t x = 0; x < 100; ++x) {
        const double px = x * 16 + 8, py = y * 16 + 8;
        double e[3], len[3];
        for (int k = 0; k < 3; ++k) {
          const ClipVertex& a = v[(k + 1) % 3];
          const ClipVertex& b = v[(k + 2) % 3];
          e[k] = (px - a.x) * double(b.y - a.y) - (py - a.y) * double(b.x - a.x);
          len[k] = std::hypot(double(b.x - a.x), double(b.y - a.y));
        }
        const bool pos = e[0] >= 0 && e[1] >= 0 && e[2] >= 0, neg = e[0] <= 0 && e[1] <= 0 && e[2] <= 0;
        double margin = 1e300;
        for (int k = 0; k < 3; ++k) margin = std::fmin(margin, std::fabs(e[k]) / len[k]);
        if (margin < 16) continue;  // within a pixel of an edge
        ++checked;
        CHECK_EQ(c.color[size_t(y) * 100 + x] != 0, pos || neg);
      }
    }
  }
  CHECK_GT(checked, 100000);
}

TEST(near_plane_clipping) {
  // Perspective: a floor under the eye reaching behind it. Without the near
  // plane the projection would flip; clipped, the floor fills the lower
  // part of the frame and nothing above the horizon.
  Projector p;
  p.kind = Projection::kPerspective;
  p.cx_q4 = 50 * 16;
  p.cy_q4 = 40 * 16;
  p.focal_q4 = 40 * 16;
  p.near_u = 64;
  p.depth_bn = kDepthMax / 2;
  p.depth_far = kDepthMargin + p.depth_bn;
  clip_set_planes(&p, 100, 80);
  // y = -1000 (below the eye), w from -50000 (behind) to 50000 (ahead).
  const ClipVertex a{-100000, -1000, -50000, 0, 50}, b{100000, -1000, -50000, 0, 50}, c{100000, -1000, 50000, 0, 50},
                   d{-100000, -1000, 50000, 0, 50};
  Canvas cv(100, 80);
  cv.t.cull_back = false;
  clip_draw_triangle(&cv.t, p, a, b, c);
  clip_draw_triangle(&cv.t, p, a, c, d);
  int above = 0;
  for (int32_t y = 0; y < 40; ++y)
    for (int32_t x = 0; x < 100; ++x) above += cv.color[size_t(y) * 100 + x] != 0;
  CHECK_EQ(above, 0);
  // Below the horizon (y > 40 + f * 1000 / 50000 = 40.8) everything is floor.
  for (int32_t y = 42; y < 80; ++y)
    for (int32_t x = 0; x < 100; ++x) CHECK_NE(cv.color[size_t(y) * 100 + x], 0u);
}
