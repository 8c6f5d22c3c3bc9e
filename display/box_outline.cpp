// A box's screen outline; see box_outline.h.
#include "display/box_outline.h"

#include "core/math/fixed.h"
#include "display/clip.h"

namespace dexmill {

namespace {

struct Q4 {
  int64_t x, y;  // screen q4
};

// The corners on the screen.
void corners(const View& v, const BoxNm& b, Q4 out[8]) {
  for (int k = 0; k < 8; ++k) {
    const PointNm p{(k & 1) ? b.hi.x_nm : b.lo.x_nm, (k & 2) ? b.hi.y_nm : b.lo.y_nm, (k & 4) ? b.hi.z_nm : b.lo.z_nm};
    const RasterVertex r = clip_project(v.proj, view_point(v, p));
    out[k] = Q4{r.x_q4, r.y_q4};
  }
}

int64_t cross(const Q4& o, const Q4& a, const Q4& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain over the eight corners: the hull counterclockwise
// (in screen axes), collinear points dropped. Returns its size.
int hull(Q4 p[8], Q4 h[16]) {
  for (int a = 1; a < 8; ++a)  // sort by x, then y
    for (int b = a; b > 0 && (p[b].x < p[b - 1].x || (p[b].x == p[b - 1].x && p[b].y < p[b - 1].y)); --b) {
      const Q4 t = p[b];
      p[b] = p[b - 1];
      p[b - 1] = t;
    }
  int n = 0;
  for (int k = 0; k < 8; ++k) {
    while (n >= 2 && cross(h[n - 2], h[n - 1], p[k]) <= 0) --n;
    h[n++] = p[k];
  }
  for (int k = 6, lo = n + 1; k >= 0; --k) {
    while (n >= lo && cross(h[n - 2], h[n - 1], p[k]) <= 0) --n;
    h[n++] = p[k];
  }
  return n > 1 ? n - 1 : n;
}

}  // namespace

ScreenRect box_outline_bounds(const View& v, const BoxNm& box) {
  Q4 c[8];
  corners(v, box, c);
  int64_t x0 = c[0].x, y0 = c[0].y, x1 = c[0].x, y1 = c[0].y;
  for (const Q4& q : c) {
    x0 = min_of(x0, q.x);
    y0 = min_of(y0, q.y);
    x1 = max_of(x1, q.x);
    y1 = max_of(y1, q.y);
  }
  return ScreenRect{static_cast<int32_t>(x0 >> kSubpixelBits), static_cast<int32_t>(y0 >> kSubpixelBits),
                    static_cast<int32_t>((x1 >> kSubpixelBits) + 1), static_cast<int32_t>((y1 >> kSubpixelBits) + 1)};
}

bool box_outline_meets(const View& v, const BoxNm& box, const ScreenRect& r) {
  if (r.empty()) return false;
  Q4 c[8], h[16];
  corners(v, box, c);
  const int n = hull(c, h);
  // r in q4: its pixels' whole squares.
  const int64_t rx0 = static_cast<int64_t>(r.x0) << kSubpixelBits, ry0 = static_cast<int64_t>(r.y0) << kSubpixelBits;
  const int64_t rx1 = static_cast<int64_t>(r.x1) << kSubpixelBits, ry1 = static_cast<int64_t>(r.y1) << kSubpixelBits;
  int64_t x0 = h[0].x, y0 = h[0].y, x1 = h[0].x, y1 = h[0].y;
  for (int k = 0; k < n; ++k) {
    x0 = min_of(x0, h[k].x);
    y0 = min_of(y0, h[k].y);
    x1 = max_of(x1, h[k].x);
    y1 = max_of(y1, h[k].y);
  }
  if (x1 < rx0 || x0 > rx1 || y1 < ry0 || y0 > ry1) return false;
  if (n < 3) return true;  // a point or a segment whose box meets r: near enough
  const Q4 rc[4] = {{rx0, ry0}, {rx1, ry0}, {rx1, ry1}, {rx0, ry1}};
  for (int k = 0; k < n; ++k) {
    // r wholly outside this edge (the hull lies on its left) separates them.
    const Q4& a = h[k];
    const Q4& b = h[(k + 1) % n];
    bool all_out = true;
    for (const Q4& q : rc) all_out = all_out && cross(a, b, q) < 0;
    if (all_out) return false;
  }
  return true;
}

}  // namespace dexmill
