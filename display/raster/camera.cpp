// Orbit camera, presets, fit-to-stock and the per-frame maps.
#include "display/raster/camera.h"

#include <string.h>

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {
namespace {

constexpr int64_t kOneQ30 = static_cast<int64_t>(1) << 30;
constexpr uint32_t kBamDeg40 = 0x1C71C71Cu;  // 40 degrees

int32_t mul_q30(int64_t a, int64_t b) { return static_cast<int32_t>((a * b + (kOneQ30 >> 1)) >> 30); }

struct Basis {
  int32_t r[3], u[3], d[3];
};

Basis basis_of(uint32_t az, int32_t el) {
  const SinCosQ30 a = sincos_bam(az);
  const SinCosQ30 e = sincos_bam(static_cast<uint32_t>(el));
  Basis b;
  b.r[0] = -a.sin_q30;
  b.r[1] = a.cos_q30;
  b.r[2] = 0;
  b.u[0] = -mul_q30(e.sin_q30, a.cos_q30);
  b.u[1] = -mul_q30(e.sin_q30, a.sin_q30);
  b.u[2] = e.cos_q30;
  b.d[0] = mul_q30(e.cos_q30, a.cos_q30);
  b.d[1] = mul_q30(e.cos_q30, a.sin_q30);
  b.d[2] = e.sin_q30;
  return b;
}

int32_t clamp_elevation(int32_t e) { return clamp<int32_t>(e, -static_cast<int32_t>(kBamQuarterTurn), kBamQuarterTurn); }

// sqrt(x^2 + y^2 + z^2) for |x|, |y|, |z| < 2^62, exact floor.
int64_t length3(int64_t x, int64_t y, int64_t z) {
  U128 s{0, 0};
  const int64_t c[3] = {x, y, z};
  for (int64_t v : c) {
    const U128 p = mul_wide_u64(abs_u64(v), abs_u64(v));
    const uint64_t lo = s.lo + p.lo;
    s.hi = s.hi + p.hi + (lo < s.lo ? 1u : 0u);
    s.lo = lo;
  }
  return static_cast<int64_t>(isqrt_u128(s));
}

PointNm box_centre(const BoxNm& b) {
  return PointNm{b.lo.x_nm + (b.hi.x_nm - b.lo.x_nm) / 2, b.lo.y_nm + (b.hi.y_nm - b.lo.y_nm) / 2,
                 b.lo.z_nm + (b.hi.z_nm - b.lo.z_nm) / 2};
}

// round(b * len * k / den) in q32 from a q30 basis component: precise, for
// the per-dexel and per-LSB steps (len * k * 4 must stay below 2^62).
int64_t coef_fine(int32_t b_q30, int64_t len, int64_t k, int64_t den) { return muldiv_round(b_q30, len * k * 4, den); }
// The same for long offsets: the ratio first (saturating), then the scale.
int64_t coef_long(int32_t b_q30, int64_t len, int64_t k, int64_t den) {
  return sat_mul_i64(muldiv_round(b_q30, len, den), k * 4);
}

}  // namespace

Camera camera_preset(ViewPreset v) {
  Camera c;
  switch (v) {
    case ViewPreset::kIso:
      c.azimuth_bam = 0u - (kBamQuarterTurn / 2);  // -45 degrees
      c.elevation_bam = static_cast<int32_t>(atan2_bam(1000000000, 1414213562));  // atan(1/sqrt 2)
      break;
    case ViewPreset::kTop:
      c.azimuth_bam = 0u - kBamQuarterTurn;
      c.elevation_bam = static_cast<int32_t>(kBamQuarterTurn);
      break;
    case ViewPreset::kFront:
      c.azimuth_bam = 0u - kBamQuarterTurn;
      c.elevation_bam = 0;
      break;
    case ViewPreset::kRight:
      c.azimuth_bam = 0;
      c.elevation_bam = 0;
      break;
  }
  return c;
}

bool view_preset_from_name(const char* name, ViewPreset* out) {
  static const struct { const char* name; ViewPreset v; } kNames[] = {
      {"iso", ViewPreset::kIso}, {"top", ViewPreset::kTop}, {"front", ViewPreset::kFront}, {"right", ViewPreset::kRight}};
  for (const auto& n : kNames) {
    if (strcmp(n.name, name) == 0) {
      *out = n.v;
      return true;
    }
  }
  return false;
}

void camera_fit(Camera* c, const BoxNm& box, int32_t width, int32_t height) {
  camera_fit_inside(c, box, width, height, ScreenRect{0, 0, width, height});
}

void camera_fit_inside(Camera* c, const BoxNm& box, int32_t width, int32_t height, const ScreenRect& inside) {
  c->elevation_bam = clamp_elevation(c->elevation_bam);
  c->target = box_centre(box);
  const Basis b = basis_of(c->azimuth_bam, c->elevation_bam);
  const int64_t half[3] = {(box.hi.x_nm - box.lo.x_nm) / 2, (box.hi.y_nm - box.lo.y_nm) / 2,
                           (box.hi.z_nm - box.lo.z_nm) / 2};
  const int64_t w = max_of<int64_t>(width, 1), h = max_of<int64_t>(height, 1);
  const ScreenRect in = rect_intersect(inside, ScreenRect{0, 0, static_cast<int32_t>(w), static_cast<int32_t>(h)});
  const bool whole = in.x0 == 0 && in.y0 == 0 && in.x1 == w && in.y1 == h;
  const int64_t iw = max_of<int64_t>(in.x1 - in.x0, 1), ih = max_of<int64_t>(in.y1 - in.y0, 1);
  // Inside's centre from the frame's, in half pixels (x right, y down).
  const int64_t off2[2] = {in.empty() ? 0 : in.x0 + in.x1 - w, in.empty() ? 0 : in.y0 + in.y1 - h};
  int64_t nm_per_px_num = 0, nm_per_px_den = 1;  // the scale at the target, for the shift
  if (c->projection == Projection::kOrthographic) {
    // Half-extents of the box's projection along screen right and up.
    int64_t hr = 0, hu = 0;
    for (int k = 0; k < 3; ++k) {
      hr += muldiv_round(half[k], abs_u64(b.r[k]), kOneQ30);
      hu += muldiv_round(half[k], abs_u64(b.u[k]), kOneQ30);
    }
    const int64_t need = max_of(muldiv_round(2 * hu, h, ih), muldiv_round(2 * hr, h, iw));
    c->view_height_nm = max_of<int64_t>(1, muldiv_round(need, 105, 100));
    nm_per_px_num = c->view_height_nm;
    nm_per_px_den = h;
  } else {
    if (c->fov_bam == 0 || c->fov_bam >= kBamHalfTurn) c->fov_bam = kBamDeg40;
    const SinCosQ30 v = sincos_bam(c->fov_bam / 2);
    // The narrower of the vertical and horizontal half-angles (of inside:
    // its half-sides seen from the eye, the focal length (h / 2) cos / sin).
    uint32_t half_angle = c->fov_bam / 2;
    if (whole) {
      if (w < h) half_angle = atan2_bam(static_cast<int64_t>(v.sin_q30) * w, static_cast<int64_t>(v.cos_q30) * h);
    } else {
      half_angle = atan2_bam(static_cast<int64_t>(v.sin_q30) * min_of(iw, ih), static_cast<int64_t>(v.cos_q30) * h);
    }
    const SinCosQ30 s = sincos_bam(half_angle);
    const int64_t radius = length3(half[0], half[1], half[2]);
    c->distance_nm = max_of<int64_t>(1, muldiv_round(radius, static_cast<int64_t>(105) * kOneQ30, 100 * static_cast<int64_t>(max_of<int32_t>(s.sin_q30, 1))));
    // nm per pixel at the target: distance / focal = distance sin / ((h / 2) cos).
    nm_per_px_num = muldiv_round(c->distance_nm, 2 * static_cast<int64_t>(v.sin_q30), max_of<int32_t>(v.cos_q30, 1));
    nm_per_px_den = h;
  }
  if (off2[0] == 0 && off2[1] == 0) return;
  // T = C - a r - b u puts C at inside's centre: a = offset x, b = -offset y
  // (screen y points down), in nm at the target.
  const int64_t a = muldiv_round(off2[0], nm_per_px_num, 2 * nm_per_px_den);
  const int64_t bu = -muldiv_round(off2[1], nm_per_px_num, 2 * nm_per_px_den);
  c->target.x_nm -= muldiv_round(a, b.r[0], kOneQ30) + muldiv_round(bu, b.u[0], kOneQ30);
  c->target.y_nm -= muldiv_round(a, b.r[1], kOneQ30) + muldiv_round(bu, b.u[1], kOneQ30);
  c->target.z_nm -= muldiv_round(a, b.r[2], kOneQ30) + muldiv_round(bu, b.u[2], kOneQ30);
}

void view_build(const Camera& cam, const SceneFrame& scene, int32_t width, int32_t height, View* v) {
  const Basis b = basis_of(cam.azimuth_bam, clamp_elevation(cam.elevation_bam));
  for (int k = 0; k < 3; ++k) {
    v->right_q30[k] = b.r[k];
    v->up_q30[k] = b.u[k];
    v->eye_q30[k] = b.d[k];
  }
  const PointNm cen = box_centre(scene.box);
  const int64_t radius = max_of<int64_t>(
      kNmPerUm, length3(scene.box.hi.x_nm - cen.x_nm, scene.box.hi.y_nm - cen.y_nm, scene.box.hi.z_nm - cen.z_nm));
  v->origin = cen;
  const int64_t lim = 16 * radius;
  const PointNm t{clamp(cam.target.x_nm, cen.x_nm - lim, cen.x_nm + lim), clamp(cam.target.y_nm, cen.y_nm - lim, cen.y_nm + lim),
                  clamp(cam.target.z_nm, cen.z_nm - lim, cen.z_nm + lim)};
  // Offsets of the grid's origin and of the scene centre from the target.
  const int64_t o_t[3] = {scene.x0_nm - t.x_nm, scene.y0_nm - t.y_nm, scene.z0_nm - t.z_nm};
  const int64_t c_t[3] = {cen.x_nm - t.x_nm, cen.y_nm - t.y_nm, cen.z_nm - t.z_nm};
  const int64_t o_c[3] = {scene.x0_nm - cen.x_nm, scene.y0_nm - cen.y_nm, scene.z0_nm - cen.z_nm};
  const int64_t steps[3] = {scene.pitch_nm, scene.pitch_nm, scene.lsb_nm};
  const int32_t* axes[3] = {b.r, b.u, b.d};
  Projector& p = v->proj;
  p = Projector{};
  v->width = width;
  v->height = height;
  v->view_height_nm = 0;
  p.kind = cam.projection;
  const int64_t w16 = static_cast<int64_t>(width) * kSubpixelOne, h16 = static_cast<int64_t>(height) * kSubpixelOne;
  const int64_t one32 = static_cast<int64_t>(1) << 32;

  if (cam.projection == Projection::kOrthographic) {
    // Screen q4 = centre + s * (r, -u) . (P - T), s = 16 * height / view
    // height; depth = mid - (d . (P - C)) * range / (2 R), so the scene's
    // bounding sphere fills the depth range.
    const int64_t vh = max_of(cam.view_height_nm, max_of<int64_t>(1, muldiv_round(radius, height, static_cast<int64_t>(1) << 20)));
    const int64_t range = kDepthMax - 2 * kDepthMargin, mid = kDepthMax / 2;
    const int64_t sgn[3] = {1, -1, -1};                       // x, y (down), depth (away)
    const int64_t scale[3] = {h16, h16, range};                // numerators
    const int64_t den[3] = {vh, vh, 2 * radius};
    const int64_t base[3] = {w16 / 2 * one32, h16 / 2 * one32, mid * one32};
    const int32_t* dirs[3] = {b.r, b.u, b.d};
    for (int row = 0; row < 3; ++row) {
      const int64_t* off = row == 2 ? o_c : o_t;
      const int64_t* woff = row == 2 ? nullptr : c_t;
      v->grid.c[row] = base[row];
      v->world.c[row] = base[row];
      for (int k = 0; k < 3; ++k) {
        v->grid.m[row][k] = sgn[row] * coef_fine(dirs[row][k], steps[k], scale[row], den[row]);
        v->grid.c[row] = sat_add_i64(v->grid.c[row], sgn[row] * coef_long(dirs[row][k], off[k], scale[row], den[row]));
        v->world.m[row][k] = sgn[row] * coef_fine(dirs[row][k], 1, scale[row], den[row]);
        if (woff) v->world.c[row] = sat_add_i64(v->world.c[row], sgn[row] * coef_long(dirs[row][k], woff[k], scale[row], den[row]));
      }
    }
    v->sees_below = b.d[2] < 0;
    v->eye = t;
    v->view_height_nm = vh;
  } else {
    // Camera space in units U = R / 2^16: x = r.(P - T), y = u.(P - T),
    // w = D - d.(P - T), the distance in front of the eye.
    const int64_t dist = clamp<int64_t>(cam.distance_nm, radius / 256 + 1, 64 * radius);
    const int64_t ku = static_cast<int64_t>(1) << 16;
    const int64_t dist_u = muldiv_round(dist, ku, radius);
    for (int row = 0; row < 3; ++row) {
      const int64_t sg = row == 2 ? -1 : 1;
      v->grid.c[row] = row == 2 ? dist_u * one32 : 0;
      v->world.c[row] = v->grid.c[row];
      for (int k = 0; k < 3; ++k) {
        v->grid.m[row][k] = sg * coef_fine(axes[row][k], steps[k], ku, radius);
        v->grid.c[row] = sat_add_i64(v->grid.c[row], sg * coef_long(axes[row][k], o_t[k], ku, radius));
        v->world.m[row][k] = sg * coef_fine(axes[row][k], 1, ku, radius);
        v->world.c[row] = sat_add_i64(v->world.c[row], sg * coef_long(axes[row][k], c_t[k], ku, radius));
      }
    }
    // Depth range: the scene's sphere as seen along d, the near plane no
    // closer than R / 256.
    const int64_t wc_u = (v->world.c[2] + (static_cast<int64_t>(1) << 31)) >> 32;  // w of the scene centre
    const int64_t near_u = max_of<int64_t>(ku / 256, wc_u - ku - ku / 64);
    const int64_t far_u = max_of<int64_t>(wc_u + ku + ku / 64, near_u + near_u / 256 + 1);
    uint32_t fov = cam.fov_bam;
    if (fov == 0 || fov >= kBamHalfTurn) fov = kBamDeg40;
    const SinCosQ30 f = sincos_bam(fov / 2);
    p.cx_q4 = static_cast<int32_t>(w16 / 2);
    p.cy_q4 = static_cast<int32_t>(h16 / 2);
    p.focal_q4 = max_of<int64_t>(1, muldiv_round(h16 / 2, f.cos_q30, max_of<int32_t>(f.sin_q30, 1)));
    p.near_u = static_cast<int32_t>(near_u);
    const int64_t range = kDepthMax - 2 * kDepthMargin;
    p.depth_bn = muldiv_round(range, far_u, far_u - near_u);
    p.depth_far = kDepthMargin + p.depth_bn;
    v->eye = PointNm{t.x_nm + muldiv_round(dist, b.d[0], kOneQ30), t.y_nm + muldiv_round(dist, b.d[1], kOneQ30),
                     t.z_nm + muldiv_round(dist, b.d[2], kOneQ30)};
    v->sees_below = v->eye.z_nm < scene.stock_top_nm;
  }
  // The maps end with >> 32: half a unit here makes that round to nearest.
  for (int row = 0; row < 3; ++row) {
    v->grid.c[row] = sat_add_i64(v->grid.c[row], static_cast<int64_t>(1) << 31);
    v->world.c[row] = sat_add_i64(v->world.c[row], static_cast<int64_t>(1) << 31);
  }
  clip_set_planes(&p, width, height);
}

ClipVertex view_point(const View& v, PointNm p) {
  constexpr int64_t kLim = static_cast<int64_t>(1) << 40;
  const int64_t o[3] = {clamp(p.x_nm - v.origin.x_nm, -kLim, kLim), clamp(p.y_nm - v.origin.y_nm, -kLim, kLim),
                        clamp(p.z_nm - v.origin.z_nm, -kLim, kLim)};
  int64_t out[3];
  for (int row = 0; row < 3; ++row) {
    int64_t acc = v.world.c[row];
    for (int k = 0; k < 3; ++k) acc = sat_add_i64(acc, sat_mul_i64(v.world.m[row][k], o[k]));
    out[row] = clamp(acc >> 32, -kLim, kLim);
  }
  ClipVertex c;
  c.x = out[0];
  c.y = out[1];
  c.shade = 0;
  if (v.proj.kind == Projection::kOrthographic) {
    c.w = 1;
    c.depth = static_cast<int32_t>(clamp<int64_t>(out[2], kDepthMargin, kDepthMax - kDepthMargin));
  } else {
    c.w = out[2];
    c.depth = 0;
  }
  return c;
}

}  // namespace dexmill
