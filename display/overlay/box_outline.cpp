// A box's screen outline; see box_outline.h.
#include "display/overlay/box_outline.h"

#include "core/math/fixed.h"
#include "display/raster/clip.h"

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

// The bounding box of points p[0, n), q4.
struct Q4Box {
  int64_t x0, y0, x1, y1;
};
Q4Box bounds_of(const Q4* p, int n) {
  Q4Box b{p[0].x, p[0].y, p[0].x, p[0].y};
  for (int k = 1; k < n; ++k) {
    b.x0 = min_of(b.x0, p[k].x);
    b.y0 = min_of(b.y0, p[k].y);
    b.x1 = max_of(b.x1, p[k].x);
    b.y1 = max_of(b.y1, p[k].y);
  }
  return b;
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
  const Q4Box b = bounds_of(c, 8);
  return ScreenRect{static_cast<int32_t>(b.x0 >> kSubpixelBits), static_cast<int32_t>(b.y0 >> kSubpixelBits),
                    static_cast<int32_t>((b.x1 >> kSubpixelBits) + 1), static_cast<int32_t>((b.y1 >> kSubpixelBits) + 1)};
}

bool box_outline_meets(const View& v, const BoxNm& box, const ScreenRect& r) {
  if (r.empty()) return false;
  Q4 c[8], h[16];
  corners(v, box, c);
  const Q4Box bb = bounds_of(c, 8);  // the hull's too: it holds the extreme corners
  const int n = hull(c, h);
  // r in q4: its pixels' whole squares.
  const int64_t rx0 = static_cast<int64_t>(r.x0) << kSubpixelBits, ry0 = static_cast<int64_t>(r.y0) << kSubpixelBits;
  const int64_t rx1 = static_cast<int64_t>(r.x1) << kSubpixelBits, ry1 = static_cast<int64_t>(r.y1) << kSubpixelBits;
  if (bb.x1 < rx0 || bb.x0 > rx1 || bb.y1 < ry0 || bb.y0 > ry1) return false;
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
