// display/raster/camera.h: presets, projections against a double oracle, fitting.
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "core/math/trig.h"
#include "display/raster/camera.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;
constexpr double kPi = 3.14159265358979323846;

using t::Rng;

// A 100 x 60 x 30 mm scene around a 200 x 120 grid of 0.5 mm.
SceneFrame scene() {
  SceneFrame s;
  s.box = BoxNm{PointNm{-10 * mm, -5 * mm, -1 * mm}, PointNm{110 * mm, 65 * mm, 40 * mm}};
  s.x0_nm = 0;
  s.y0_nm = 0;
  s.z0_nm = 0;
  s.pitch_nm = mm / 2;
  s.lsb_nm = 1000;
  s.stock_top_nm = 25 * mm;
  return s;
}

struct Oracle {
  double r[3], u[3], d[3];
  explicit Oracle(const Camera& c) {
    const double a = c.azimuth_bam * (2 * kPi / 4294967296.0), e = c.elevation_bam * (2 * kPi / 4294967296.0);
    const double rr[3] = {-std::sin(a), std::cos(a), 0};
    const double uu[3] = {-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)};
    const double dd[3] = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
    for (int k = 0; k < 3; ++k) {
      r[k] = rr[k];
      u[k] = uu[k];
      d[k] = dd[k];
    }
  }
};

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

TEST(camera_presets_and_names) {
  struct Want {
    ViewPreset v;
    const char* name;
    double r[3], u[3], d[3];
  };
  const double s3 = 1 / std::sqrt(3.0), s2 = 1 / std::sqrt(2.0), s6 = 1 / std::sqrt(6.0);
  const Want want[] = {
      {ViewPreset::kIso, "iso", {s2, s2, 0}, {-s6, s6, 2 * s6}, {s3, -s3, s3}},
      {ViewPreset::kTop, "top", {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      {ViewPreset::kFront, "front", {1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
      {ViewPreset::kRight, "right", {0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
  };
  for (const Want& w : want) {
    ViewPreset got;
    CHECK(view_preset_from_name(w.name, &got));
    CHECK_EQ(static_cast<int>(got), static_cast<int>(w.v));
    Camera c = camera_preset(w.v);
    camera_fit(&c, scene().box, 640, 480);
    View v;
    view_build(c, scene(), 640, 480, &v);
    for (int k = 0; k < 3; ++k) {
      CHECK_NEAR(v.right_q30[k] / 1073741824.0, w.r[k], 1e-8);
      CHECK_NEAR(v.up_q30[k] / 1073741824.0, w.u[k], 1e-8);
      CHECK_NEAR(v.eye_q30[k] / 1073741824.0, w.d[k], 1e-8);
    }
  }
  ViewPreset dummy;
  CHECK(!view_preset_from_name("left", &dummy));
}

TEST(orthographic_projection_against_double_oracle) {
  Rng rng;
  double worst = 0;
  for (int rep = 0; rep < 200; ++rep) {
    Camera c;
    c.azimuth_bam = static_cast<uint32_t>(rng.next());
    c.elevation_bam = static_cast<int32_t>(rng.range(-(1 << 30), 1 << 30));
    c.target = PointNm{rng.range(0, 100 * mm), rng.range(0, 60 * mm), rng.range(0, 30 * mm)};
    c.view_height_nm = rng.range(20 * mm, 300 * mm);
    View v;
    view_build(c, scene(), 640, 480, &v);
    const Oracle o(c);
    const double s = 480.0 / c.view_height_nm;  // pixels per nm
    for (int k = 0; k < 50; ++k) {
      // A dexel of the grid and its machine position.
      const int64_t i = rng.range(0, 199), j = rng.range(0, 119), h = rng.range(0, 30000);
      const double P[3] = {i * 0.5e6 - c.target.x_nm, j * 0.5e6 - c.target.y_nm, h * 1000.0 - c.target.z_nm};
      const double sx = 320 + s * dot(o.r, P), sy = 240 - s * dot(o.u, P);
      int64_t out[3];
      for (int row = 0; row < 3; ++row) out[row] = (v.grid.m[row][0] * i + v.grid.m[row][1] * j + v.grid.m[row][2] * h + v.grid.c[row]) >> 32;
      const double ex = std::fabs(out[0] / 16.0 - sx), ey = std::fabs(out[1] / 16.0 - sy);
      worst = std::fmax(worst, std::fmax(ex, ey));
      CHECK_LE(ex, 1.0 / 32 + 1e-3);
      CHECK_LE(ey, 1.0 / 32 + 1e-3);
      // The same point through the machine-coordinate map (the cutter's).
      const ClipVertex cv = view_point(v, PointNm{i * mm / 2, j * mm / 2, h * 1000});
      CHECK_LE(std::fabs(cv.x / 16.0 - sx), 1.0 / 32 + 1e-3);
      CHECK_LE(std::fabs(cv.y / 16.0 - sy), 1.0 / 32 + 1e-3);
    }
  }
  std::printf("orthographic: worst screen error %.4f px (bound 1/32 + 1e-3)\n", worst);
}

TEST(perspective_projection_against_double_oracle) {
  Rng rng;
  double worst = 0;
  int in_front = 0;
  for (int rep = 0; rep < 200; ++rep) {
    Camera c;
    c.projection = Projection::kPerspective;
    c.azimuth_bam = static_cast<uint32_t>(rng.next());
    c.elevation_bam = static_cast<int32_t>(rng.range(-(1 << 30), 1 << 30));
    c.target = PointNm{rng.range(0, 100 * mm), rng.range(0, 60 * mm), rng.range(0, 30 * mm)};
    c.distance_nm = rng.range(90 * mm, 600 * mm);
    c.fov_bam = bam_from_mdeg(rng.range(20000, 90000));
    View v;
    view_build(c, scene(), 640, 480, &v);
    const Oracle o(c);
    const double f = 240.0 / std::tan(c.fov_bam * (kPi / 4294967296.0));
    for (int k = 0; k < 50; ++k) {
      const PointNm q{rng.range(0, 100 * mm), rng.range(0, 60 * mm), rng.range(0, 30 * mm)};
      const double P[3] = {double(q.x_nm - c.target.x_nm), double(q.y_nm - c.target.y_nm), double(q.z_nm - c.target.z_nm)};
      const double w = c.distance_nm - dot(o.d, P);
      const ClipVertex cv = view_point(v, q);
      if (clip_outcode(v.proj, cv.x, cv.y, cv.w)) continue;  // behind the near plane or far off screen
      ++in_front;
      const RasterVertex r = clip_project(v.proj, cv);
      const double sx = 320 + f * dot(o.r, P) / w, sy = 240 - f * dot(o.u, P) / w;
      const double e = std::fmax(std::fabs(r.x_q4 / 16.0 - sx), std::fabs(r.y_q4 / 16.0 - sy));
      // Rounding to q4 and of x / w, plus camera space quantised to
      // U = R / 2^16 (R the scene's radius): x and w each off by U / 2,
      // seen at distance w, the latter scaled by the offset from the centre.
      const double R = std::sqrt(60.0 * 60 + 35.0 * 35 + 20.5 * 20.5) * 1e6, U = R / 65536;
      const double off = std::fmax(std::fabs(sx - 320), std::fabs(sy - 240));
      const double bound = 1.0 / 16 + (f + off) * U / w;
      worst = std::fmax(worst, e / bound);
      CHECK_LE(e, bound);
    }
  }
  CHECK_GT(in_front, 5000);
  std::printf("perspective: worst screen error %.3f of the bound (1/16 px + (f + d) R 2^-16 / w)\n", worst);
}

TEST(depth_grows_away_from_the_eye) {
  Rng rng;
  for (int proj = 0; proj < 2; ++proj) {
    for (int rep = 0; rep < 100; ++rep) {
      Camera c = camera_preset(static_cast<ViewPreset>(rep % 4));
      c.projection = proj ? Projection::kPerspective : Projection::kOrthographic;
      c.azimuth_bam += static_cast<uint32_t>(rng.range(0, 1 << 28));
      camera_fit(&c, scene().box, 320, 240);
      View v;
      view_build(c, scene(), 320, 240, &v);
      const Oracle o(c);
      const PointNm a{rng.range(0, 100 * mm), rng.range(0, 60 * mm), rng.range(0, 30 * mm)};
      const PointNm b{rng.range(0, 100 * mm), rng.range(0, 60 * mm), rng.range(0, 30 * mm)};
      const double da[3] = {double(a.x_nm), double(a.y_nm), double(a.z_nm)}, db[3] = {double(b.x_nm), double(b.y_nm), double(b.z_nm)};
      // Distance along the view direction, in mm (nearer = larger d . P).
      const double nearer = (dot(o.d, da) - dot(o.d, db)) / 1e6;
      if (std::fabs(nearer) < 0.05) continue;
      const ClipVertex ca = view_point(v, a), cb = view_point(v, b);
      const int32_t za = clip_project(v.proj, ca).depth, zb = clip_project(v.proj, cb).depth;
      CHECK_EQ(za < zb, nearer > 0);
      CHECK(za >= kDepthMargin / 2 && za <= kDepthMax - kDepthMargin / 2);
    }
  }
}

TEST(fit_frames_the_box) {
  for (int proj = 0; proj < 2; ++proj) {
    for (int p = 0; p < 4; ++p) {
      static const int32_t kSizes[3][2] = {{640, 480}, {480, 272}, {200, 400}};
      for (const auto& size : kSizes) {
        Camera c = camera_preset(static_cast<ViewPreset>(p));
        c.projection = proj ? Projection::kPerspective : Projection::kOrthographic;
        const BoxNm box{PointNm{0, 0, 0}, PointNm{100 * mm, 60 * mm, 25 * mm}};
        camera_fit(&c, box, size[0], size[1]);
        View v;
        view_build(c, scene(), size[0], size[1], &v);
        double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
        for (int k = 0; k < 8; ++k) {
          const PointNm q{(k & 1) ? box.hi.x_nm : 0, (k & 2) ? box.hi.y_nm : 0, (k & 4) ? box.hi.z_nm : 0};
          const RasterVertex r = clip_project(v.proj, view_point(v, q));
          x0 = std::fmin(x0, r.x_q4 / 16.0);
          x1 = std::fmax(x1, r.x_q4 / 16.0);
          y0 = std::fmin(y0, r.y_q4 / 16.0);
          y1 = std::fmax(y1, r.y_q4 / 16.0);
        }
        // Inside the frame, and filling it along one axis (5 % margin; a
        // perspective fit keeps the bounding sphere in view, so it is looser).
        CHECK_GE(x0, 0.0);
        CHECK_GE(y0, 0.0);
        CHECK_LE(x1, double(size[0]));
        CHECK_LE(y1, double(size[1]));
        const double fill = std::fmax((x1 - x0) / size[0], (y1 - y0) / size[1]);
        CHECK_GE(fill, proj ? 0.3 : 0.9);
        CHECK_LE(fill, 0.96);
      }
    }
  }
}
