// Projection and near / guard-band clipping.
#include "display/raster/clip.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

inline int64_t plane_dist(const ClipPlane& q, const ClipVertex& v) { return q.a * v.x + q.b * v.y + q.c * v.w + q.e; }

// The point where the edge from `in` (d_in >= 0) to `out` (d_out < 0) meets
// the plane.
ClipVertex cut(const ClipVertex& in, const ClipVertex& out, int64_t d_in, int64_t d_out) {
  const int64_t den = d_in - d_out;
  ClipVertex r;
  r.x = in.x + muldiv_round(out.x - in.x, d_in, den);
  r.y = in.y + muldiv_round(out.y - in.y, d_in, den);
  r.w = in.w + muldiv_round(out.w - in.w, d_in, den);
  r.depth = static_cast<int32_t>(in.depth + muldiv_round(static_cast<int64_t>(out.depth) - in.depth, d_in, den));
  r.shade = static_cast<int32_t>(in.shade + muldiv_round(static_cast<int64_t>(out.shade) - in.shade, d_in, den));
  r.rgb = 0;
  for (int k = 0; k < 24; k += 8) {
    const int64_t a = (in.rgb >> k) & 0xFF, b = (out.rgb >> k) & 0xFF;
    r.rgb |= static_cast<uint32_t>(a + muldiv_round(b - a, d_in, den)) << k;
  }
  return r;
}

// 3 vertices plus one per plane.
constexpr int kMaxPoly = 3 + 5;

}  // namespace

RasterVertex clip_project(const Projector& p, const ClipVertex& v) {
  RasterVertex r;
  r.shade = v.shade;
  r.rgb = v.rgb;
  if (p.kind == Projection::kOrthographic) {
    r.x_q4 = static_cast<int32_t>(v.x);
    r.y_q4 = static_cast<int32_t>(v.y);
    r.depth = v.depth;
    return r;
  }
  // x / w in q20 through one reciprocal, then times the focal length: inside
  // the guard band |x / w| * focal < 2^17, so nothing overflows.
  const int64_t w = v.w < 1 ? 1 : v.w;
  ScaledRecip inv = recip_u32(static_cast<uint32_t>(w));
  ScaledRecip inv20 = inv;
  inv20.shift -= 20;
  const int64_t xr = scale_recip(v.x, inv20), yr = scale_recip(v.y, inv20);
  r.x_q4 = p.cx_q4 + static_cast<int32_t>((xr * p.focal_q4 + (1 << 19)) >> 20);
  r.y_q4 = p.cy_q4 - static_cast<int32_t>((yr * p.focal_q4 + (1 << 19)) >> 20);
  // near / w in q30, in (0, 1] for w >= near.
  ScaledRecip inv30 = inv;
  inv30.shift -= 30;
  const int64_t ratio_q30 = scale_recip(p.near_u, inv30);
  const int64_t d = p.depth_far - ((ratio_q30 * p.depth_bn + (1 << 29)) >> 30);
  r.depth = static_cast<int32_t>(clamp<int64_t>(d, kDepthMargin / 2, kDepthMax - kDepthMargin / 2));
  return r;
}

void clip_draw_triangle(RasterTarget* t, const Projector& p, const ClipVertex& a, const ClipVertex& b,
                        const ClipVertex& c) {
  ClipVertex buf[2][kMaxPoly];
  int n = 3;
  buf[0][0] = a;
  buf[0][1] = b;
  buf[0][2] = c;
  int cur = 0;
  for (int k = 0; k < p.nplanes && n >= 3; ++k) {
    const ClipPlane& q = p.plane[k];
    const ClipVertex* in = buf[cur];
    ClipVertex* out = buf[cur ^ 1];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const ClipVertex& s = in[i];
      const ClipVertex& e = in[(i + 1) % n];
      const int64_t ds = plane_dist(q, s), de = plane_dist(q, e);
      if (ds >= 0) out[m++] = s;
      if ((ds >= 0) != (de >= 0)) out[m++] = ds >= 0 ? cut(s, e, ds, de) : cut(e, s, de, ds);
    }
    n = m;
    cur ^= 1;
  }
  if (n < 3) return;
  RasterVertex rv[kMaxPoly];
  for (int i = 0; i < n; ++i) rv[i] = clip_project(p, buf[cur][i]);
  for (int i = 1; i + 1 < n; ++i) raster_triangle(t, rv[0], rv[i], rv[i + 1]);
}

void clip_set_planes(Projector* p, int32_t width, int32_t height) {
  const int64_t g = static_cast<int64_t>(kGuardPx) * kSubpixelOne;
  const int64_t w16 = static_cast<int64_t>(width) * kSubpixelOne, h16 = static_cast<int64_t>(height) * kSubpixelOne;
  if (p->kind == Projection::kOrthographic) {
    p->nplanes = 4;
    p->plane[0] = ClipPlane{1, 0, 0, g};         // x >= -g
    p->plane[1] = ClipPlane{-1, 0, 0, w16 + g};  // x <= w + g
    p->plane[2] = ClipPlane{0, 1, 0, g};         // y >= -g
    p->plane[3] = ClipPlane{0, -1, 0, h16 + g};  // y <= h + g
    return;
  }
  // Screen x = cx + f x / w, screen y = cy - f y / w, for w > 0; each bound
  // multiplied through by w. Planes a little inside the guard band, so that
  // rounding in the projection cannot push a vertex past it.
  const int64_t f = p->focal_q4, gi = g - 2 * kSubpixelOne;
  p->nplanes = 5;
  p->plane[0] = ClipPlane{0, 0, 1, -static_cast<int64_t>(p->near_u)};  // w >= near
  p->plane[1] = ClipPlane{f, 0, p->cx_q4 + gi, 0};                      // sx >= -g
  p->plane[2] = ClipPlane{-f, 0, w16 + gi - p->cx_q4, 0};               // sx <= w + g
  p->plane[3] = ClipPlane{0, -f, p->cy_q4 + gi, 0};                     // sy >= -g
  p->plane[4] = ClipPlane{0, f, h16 + gi - p->cy_q4, 0};                // sy <= h + g
}

}  // namespace dexmill
