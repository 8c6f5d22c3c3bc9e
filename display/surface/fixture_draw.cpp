// Fixtures as shaded boxes (see fixture_draw.h).
#include "display/surface/fixture_draw.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int32_t kOneQ14 = 16384;

// Each face's corners, counterclockwise seen from outside (the cross product
// of its first two edges points out of the box); faces in the order of
// fixture_draw.h.
constexpr uint8_t kFaceCorners[kFixtureFaces][4] = {
    {0, 4, 6, 2},  // -x
    {1, 3, 7, 5},  // +x
    {0, 1, 5, 4},  // -y
    {2, 6, 7, 3},  // +y
    {0, 2, 3, 1},  // -z
    {4, 5, 7, 6},  // +z
};
constexpr UnitQ14 kFaceNormals[kFixtureFaces] = {
    {-kOneQ14, 0, 0}, {kOneQ14, 0, 0}, {0, -kOneQ14, 0}, {0, kOneQ14, 0}, {0, 0, -kOneQ14}, {0, 0, kOneQ14},
};

RasterVertex shaded(const RasterVertex& v, int32_t shade) {
  RasterVertex r = v;
  r.shade = shade;
  return r;
}

ClipVertex shaded(const ClipVertex& v, int32_t shade) {
  ClipVertex r = v;
  r.shade = shade;
  return r;
}

// Triangle (a, b, c) of m's corners in one shade: straight to the
// rasterizer when every corner is inside the guard band, clipped when some
// are, dropped when all lie outside one plane (as cutter_draw does).
void tri(RasterTarget* t, const View& v, const FixtureMesh& m, int a, int b, int c, int32_t shade) {
  if ((m.oc[a] | m.oc[b] | m.oc[c]) == 0)
    raster_triangle(t, shaded(m.screen[a], shade), shaded(m.screen[b], shade), shaded(m.screen[c], shade));
  else if ((m.oc[a] & m.oc[b] & m.oc[c]) == 0)
    clip_draw_triangle(t, v.proj, shaded(m.clip[a], shade), shaded(m.clip[b], shade), shaded(m.clip[c], shade));
}

}  // namespace

BoxNm fixtures_box(BoxNm around, const BoxNm* boxes, int n) {
  BoxNm b = around;
  for (int k = 0; k < n; ++k) {
    const BoxNm& f = boxes[k];
    b.lo = PointNm{min_of(b.lo.x_nm, min_of(f.lo.x_nm, f.hi.x_nm)), min_of(b.lo.y_nm, min_of(f.lo.y_nm, f.hi.y_nm)),
                   min_of(b.lo.z_nm, min_of(f.lo.z_nm, f.hi.z_nm))};
    b.hi = PointNm{max_of(b.hi.x_nm, max_of(f.lo.x_nm, f.hi.x_nm)), max_of(b.hi.y_nm, max_of(f.lo.y_nm, f.hi.y_nm)),
                   max_of(b.hi.z_nm, max_of(f.lo.z_nm, f.hi.z_nm))};
  }
  return b;
}

void fixture_light(const Lighting& l, FixtureShades* s) {
  for (int f = 0; f < kFixtureFaces; ++f) s->face[f] = shade_of_normal(l, kFaceNormals[f]);
}

void fixture_place(const BoxNm& b, const View& v, int32_t width, int32_t height, FixtureMesh* m) {
  const int64_t x[2] = {min_of(b.lo.x_nm, b.hi.x_nm), max_of(b.lo.x_nm, b.hi.x_nm)};
  const int64_t y[2] = {min_of(b.lo.y_nm, b.hi.y_nm), max_of(b.lo.y_nm, b.hi.y_nm)};
  const int64_t z[2] = {min_of(b.lo.z_nm, b.hi.z_nm), max_of(b.lo.z_nm, b.hi.z_nm)};
  const ScreenRect all{0, 0, width, height};
  int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  bool outside = false;
  for (int k = 0; k < 8; ++k) {
    m->clip[k] = view_point(v, PointNm{x[k & 1], y[(k >> 1) & 1], z[(k >> 2) & 1]});
    m->oc[k] = clip_outcode(v.proj, m->clip[k].x, m->clip[k].y, m->clip[k].w);
    if (m->oc[k]) {
      outside = true;
      continue;
    }
    m->screen[k] = clip_project(v.proj, m->clip[k]);
    x0 = min_of<int64_t>(x0, m->screen[k].x_q4);
    y0 = min_of<int64_t>(y0, m->screen[k].y_q4);
    x1 = max_of<int64_t>(x1, m->screen[k].x_q4);
    y1 = max_of<int64_t>(y1, m->screen[k].y_q4);
  }
  // A box is convex: its pixels lie inside its corners' bounding rectangle
  // (one pixel of margin, as cutter_rect keeps). When a corner is clipped
  // the clipped polygon can reach anywhere on the frame.
  if (outside) {
    m->rect = all;
    return;
  }
  const ScreenRect r{static_cast<int32_t>((x0 >> kSubpixelBits) - 1), static_cast<int32_t>((y0 >> kSubpixelBits) - 1),
                     static_cast<int32_t>((x1 >> kSubpixelBits) + 2), static_cast<int32_t>((y1 >> kSubpixelBits) + 2)};
  m->rect = rect_intersect(r, all);
}

void fixture_draw(RasterTarget* t, const View& v, const FixtureMesh& m, const FixtureShades& s) {
  for (int f = 0; f < kFixtureFaces; ++f) {
    const uint8_t* c = kFaceCorners[f];
    tri(t, v, m, c[0], c[1], c[2], s.face[f]);
    tri(t, v, m, c[0], c[2], c[3], s.face[f]);
  }
}

}  // namespace dexmill
