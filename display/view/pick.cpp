// The pixel's ray marched over the grid's columns (see pick.h).
#include "display/view/pick.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int64_t kOneQ30 = static_cast<int64_t>(1) << 30;
constexpr int64_t kFar = static_cast<int64_t>(1) << 61;  // t beyond any box side (|t| < 2^50)

// P(t) = p0 + t * d / 2^30, machine nm; d's largest component in [2^29,
// 2^30), so t is within a factor of two of nm along the ray.
struct Ray {
  int64_t p0[3];
  int64_t d[3];
  int64_t t_min;  // perspective: the eye (t = 0); orthographic: unbounded
};

int64_t ray_at(const Ray& r, int k, int64_t t) { return r.p0[k] + muldiv_floor(t, r.d[k], kOneQ30); }
// t where component k reaches c (d[k] != 0).
int64_t ray_t(const Ray& r, int k, int64_t c) { return muldiv_round(c - r.p0[k], kOneQ30, r.d[k]); }

// Scales d so its largest component lies in [2^29, 2^30); false for d = 0.
bool normalise(int64_t d[3]) {
  uint64_t m = 0;
  for (int k = 0; k < 3; ++k) m = max_of(m, abs_u64(d[k]));
  if (m == 0) return false;
  while (m >= static_cast<uint64_t>(kOneQ30)) {
    for (int k = 0; k < 3; ++k) d[k] = div_floor(d[k], 2);
    m >>= 1;
  }
  while (m < static_cast<uint64_t>(kOneQ30 / 2)) {
    for (int k = 0; k < 3; ++k) d[k] *= 2;
    m <<= 1;
  }
  return true;
}

// The ray through pixel centre (sx, sy) (q4), from the view's basis: in
// perspective from the eye along r a + u b - d f (a, b the offsets from the
// screen centre, f the focal length, all q4: camera.cpp's projection
// x = cx + f X / W, y = cy - f Y / W read backwards); orthographic along -d
// from the point of the target's plane the frame maps there.
bool ray_of(const View& v, int64_t sx, int64_t sy, Ray* r) {
  const int64_t w16 = static_cast<int64_t>(v.width) * kSubpixelOne, h16 = static_cast<int64_t>(v.height) * kSubpixelOne;
  if (v.proj.kind == Projection::kPerspective) {
    const int64_t a = sx - v.proj.cx_q4, b = v.proj.cy_q4 - sy, f = v.proj.focal_q4;
    for (int k = 0; k < 3; ++k)
      r->d[k] = static_cast<int64_t>(v.right_q30[k]) * a + static_cast<int64_t>(v.up_q30[k]) * b -
                static_cast<int64_t>(v.eye_q30[k]) * f;
    r->p0[0] = v.eye.x_nm;
    r->p0[1] = v.eye.y_nm;
    r->p0[2] = v.eye.z_nm;
    r->t_min = 0;
    return normalise(r->d);
  }
  if (h16 <= 0 || v.view_height_nm <= 0) return false;
  const int64_t along_r = muldiv_round(sx - w16 / 2, v.view_height_nm, h16);
  const int64_t along_u = muldiv_round(h16 / 2 - sy, v.view_height_nm, h16);
  const int64_t t[3] = {v.eye.x_nm, v.eye.y_nm, v.eye.z_nm};
  for (int k = 0; k < 3; ++k) {
    r->p0[k] = t[k] + muldiv_round(along_r, v.right_q30[k], kOneQ30) + muldiv_round(along_u, v.up_q30[k], kOneQ30);
    r->d[k] = -static_cast<int64_t>(v.eye_q30[k]);
  }
  r->t_min = -kFar;
  return normalise(r->d);
}

// The ray's t range inside the box [lo, hi] (slabs); false when it misses.
bool clip_to_box(const Ray& r, const int64_t lo[3], const int64_t hi[3], int64_t* t0, int64_t* t1) {
  int64_t a = r.t_min, b = kFar;
  for (int k = 0; k < 3; ++k) {
    if (r.d[k] == 0) {
      if (r.p0[k] < lo[k] || r.p0[k] > hi[k]) return false;
      continue;
    }
    const int64_t u = ray_t(r, k, lo[k]), w = ray_t(r, k, hi[k]);
    a = max_of(a, min_of(u, w));
    b = min_of(b, max_of(u, w));
  }
  *t0 = a;
  *t1 = b;
  return a <= b;
}

// Where the ray meets column (i, j) of heights [zb, zt] while it crosses
// its square over [t0, t1], if it does.
bool meet_column(const Ray& r, int64_t t0, int64_t t1, int64_t zb, int64_t zt, PointNm* at) {
  const int64_t z0 = ray_at(r, 2, t0), z1 = ray_at(r, 2, t1);
  if (max_of(z0, z1) < zb || min_of(z0, z1) > zt) return false;
  int64_t t = t0;  // through the side
  if (z0 > zt) t = t0 + muldiv_round(zt - z0, t1 - t0, z1 - z0);        // down onto the top
  else if (z0 < zb) t = t0 + muldiv_round(zb - z0, t1 - t0, z1 - z0);   // up onto the bottom
  *at = PointNm{ray_at(r, 0, t), ray_at(r, 1, t), clamp(ray_at(r, 2, t), zb, zt)};
  return true;
}

}  // namespace

template <class H>
PickHit pick_dexel(const View& v, const DexelGrid<H>& g, int32_t px, int32_t py) {
  PickHit out;
  if (px < 0 || py < 0 || px >= v.width || py >= v.height || g.nx < 1 || g.ny < 1 || g.pitch_nm < 1) return out;
  Ray r;
  if (!ray_of(v, static_cast<int64_t>(px) * kSubpixelOne + kSubpixelOne / 2,
              static_cast<int64_t>(py) * kSubpixelOne + kSubpixelOne / 2, &r))
    return out;
  // Dexel (i, j)'s square: [lo + i p, lo + (i + 1) p) each way, its axis
  // at the centre; heights up to the grid's bound.
  const int64_t p = g.pitch_nm;
  const int64_t top_bound = g.top_bound_lsb > 0 ? min_of(g.top_bound_lsb, height_max<H>()) : height_max<H>();
  const int64_t lo[3] = {g.x0_nm - p / 2, g.y0_nm - p / 2, g.z0_nm};
  const int64_t hi[3] = {lo[0] + g.nx * p, lo[1] + g.ny * p, g.z0_nm + top_bound * g.lsb_nm};
  int64_t t_in = 0, t_end = 0;
  if (!clip_to_box(r, lo, hi, &t_in, &t_end)) return out;
  int32_t i = static_cast<int32_t>(clamp<int64_t>(div_floor(ray_at(r, 0, t_in) - lo[0], p), 0, g.nx - 1));
  int32_t j = static_cast<int32_t>(clamp<int64_t>(div_floor(ray_at(r, 1, t_in) - lo[1], p), 0, g.ny - 1));
  const int32_t si = r.d[0] > 0 ? 1 : -1, sj = r.d[1] > 0 ? 1 : -1;
  for (;;) {
    // Where the ray leaves this square: the nearer of its next x and y sides.
    const int64_t tx = r.d[0] == 0 ? kFar : ray_t(r, 0, lo[0] + (static_cast<int64_t>(i) + (si > 0 ? 1 : 0)) * p);
    const int64_t ty = r.d[1] == 0 ? kFar : ray_t(r, 1, lo[1] + (static_cast<int64_t>(j) + (sj > 0 ? 1 : 0)) * p);
    const int64_t t_out = max_of(t_in, min_of(min_of(tx, ty), t_end));
    const size_t k = g.index(i, j);
    if (g.top[k] != 0 || g.bottom[k] != 0) {
      const int64_t zb = g.z0_nm + static_cast<int64_t>(g.bottom[k]) * g.lsb_nm;
      const int64_t zt = g.z0_nm + static_cast<int64_t>(g.top[k]) * g.lsb_nm;
      if (meet_column(r, t_in, t_out, zb, zt, &out.point)) {
        out.hit = true;
        out.i = i;
        out.j = j;
        return out;
      }
    }
    if (t_out >= t_end) return out;
    if (tx <= ty) i += si;
    if (ty <= tx) j += sj;
    if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) return out;
    t_in = t_out;
  }
}

template PickHit pick_dexel<uint8_t>(const View&, const DexelGrid<uint8_t>&, int32_t, int32_t);
template PickHit pick_dexel<uint16_t>(const View&, const DexelGrid<uint16_t>&, int32_t, int32_t);
template PickHit pick_dexel<uint32_t>(const View&, const DexelGrid<uint32_t>&, int32_t, int32_t);

}  // namespace dexmill
