// The cutter as a lit solid of revolution (see cutter_draw.h).
#include "display/surface/cutter_draw.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {
namespace {

constexpr int64_t kOneQ30 = static_cast<int64_t>(1) << 30;

inline int idx(int ring, int seg) { return ring * kCutterSegments + seg; }

}  // namespace

void cutter_shape_build(const ToolProfile& p, CutterShape* s) {
  s->valid = p.radius_nm > 0;
  s->radius_nm = p.radius_nm;
  s->length_nm = max_of(p.length_nm, profile_full_height_nm(p));
  for (int k = 0; k < kCutterSegments; ++k) {
    const SinCosQ30 sc = sincos_bam(static_cast<uint32_t>((static_cast<uint64_t>(k) << 32) / kCutterSegments));
    s->cos_q30[k] = sc.cos_q30;
    s->sin_q30[k] = sc.sin_q30;
  }
  // Lower surface.
  for (int k = 0; k <= kCutterRings; ++k) {
    const uint32_t a = static_cast<uint32_t>((static_cast<uint64_t>(kBamQuarterTurn) * k) / kCutterRings);
    const int64_t r = k == kCutterRings ? p.radius_nm : muldiv_round(p.radius_nm, sincos_bam(a).sin_q30, kOneQ30);
    s->ring_r_nm[k] = r;
    s->ring_h_nm[k] = profile_height_nm(p, r);
  }
  // Outward normal of z = h(r): (h'(r), -1), from the neighbouring rings.
  s->ring_nr[0] = 0;
  s->ring_nz[0] = -1;
  for (int k = 1; k <= kCutterRings; ++k) {
    const int lo = k - 1, hi = k < kCutterRings ? k + 1 : k;
    s->ring_nr[k] = s->ring_h_nm[hi] - s->ring_h_nm[lo];
    s->ring_nz[k] = -(s->ring_r_nm[hi] - s->ring_r_nm[lo]);
  }
  const int sb = kCutterRings + 1, st = sb + 1, cap = st + 1, centre = cap + 1;
  s->ring_r_nm[sb] = p.radius_nm;  // shaft
  s->ring_h_nm[sb] = s->ring_h_nm[kCutterRings];
  s->ring_r_nm[st] = p.radius_nm;
  s->ring_h_nm[st] = s->length_nm;
  s->ring_nr[sb] = s->ring_nr[st] = 1;
  s->ring_nz[sb] = s->ring_nz[st] = 0;
  s->ring_r_nm[cap] = p.radius_nm;  // cap
  s->ring_h_nm[cap] = s->length_nm;
  s->ring_r_nm[centre] = 0;
  s->ring_h_nm[centre] = s->length_nm;
  s->ring_nr[cap] = s->ring_nr[centre] = 0;
  s->ring_nz[cap] = s->ring_nz[centre] = 1;
}

ScreenRect cutter_rect(const CutterShape& s, const View& v, PointNm tip, int32_t width, int32_t height) {
  const ScreenRect all{0, 0, width, height};
  if (!s.valid) return ScreenRect{0, 0, 0, 0};
  int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  auto add = [&](const PointNm& q, int64_t mx, int64_t my) {
    const ClipVertex cv = view_point(v, q);
    if (clip_outcode(v.proj, cv.x, cv.y, cv.w)) return false;
    const RasterVertex r = clip_project(v.proj, cv);
    x0 = min_of<int64_t>(x0, r.x_q4 - mx);
    y0 = min_of<int64_t>(y0, r.y_q4 - my);
    x1 = max_of<int64_t>(x1, r.x_q4 + mx);
    y1 = max_of<int64_t>(y1, r.y_q4 + my);
    return true;
  };
  if (v.proj.kind == Projection::kOrthographic) {
    // Every point is within R of the vertical axis horizontally, and a
    // horizontal offset moves the projection by at most R along screen x
    // (r is horizontal) and R |sin e| along screen y: the axis segment's
    // projection widened by those. The offsets are measured on the screen
    // by projecting the tip moved by R along r and along (cos a, sin a).
    const ClipVertex a = view_point(v, tip);
    const ClipVertex bx = view_point(v, PointNm{tip.x_nm + muldiv_round(s.radius_nm, v.right_q30[0], kOneQ30),
                                                 tip.y_nm + muldiv_round(s.radius_nm, v.right_q30[1], kOneQ30), tip.z_nm});
    const ClipVertex by = view_point(v, PointNm{tip.x_nm + muldiv_round(s.radius_nm, v.right_q30[1], kOneQ30),
                                                 tip.y_nm - muldiv_round(s.radius_nm, v.right_q30[0], kOneQ30), tip.z_nm});
    const int64_t mx = static_cast<int64_t>(abs_u64(bx.x - a.x)) + 1, my = static_cast<int64_t>(abs_u64(by.y - a.y)) + 1;
    if (!add(tip, mx, my) || !add(PointNm{tip.x_nm, tip.y_nm, tip.z_nm + s.length_nm}, mx, my)) return all;
  } else {
    // The corners of the tool's bounding box.
    for (int c = 0; c < 8; ++c) {
      const PointNm q{tip.x_nm + ((c & 1) ? s.radius_nm : -s.radius_nm), tip.y_nm + ((c & 2) ? s.radius_nm : -s.radius_nm),
                      tip.z_nm + ((c & 4) ? s.length_nm : 0)};
      if (!add(q, 0, 0)) return all;
    }
  }
  // One pixel of margin for the rounding of each vertex's projection.
  const ScreenRect r{static_cast<int32_t>((x0 >> kSubpixelBits) - 1), static_cast<int32_t>((y0 >> kSubpixelBits) - 1),
                     static_cast<int32_t>((x1 >> kSubpixelBits) + 2), static_cast<int32_t>((y1 >> kSubpixelBits) + 2)};
  return rect_intersect(r, all);
}

void cutter_light(const CutterShape& s, const Lighting& l, CutterMesh* m) {
  for (int k = 0; k < kCutterRingCount; ++k)
    for (int a = 0; a < kCutterSegments; ++a)
      m->shade[idx(k, a)] = static_cast<uint8_t>(
          shade_of_vector(l, s.ring_nr[k] * s.cos_q30[a], s.ring_nr[k] * s.sin_q30[a], s.ring_nz[k] * kOneQ30));
}

void cutter_place(const CutterShape& s, const View& v, PointNm tip, int32_t width, int32_t height, CutterMesh* m) {
  m->rect = cutter_rect(s, v, tip, width, height);
  m->step = 1;
  if (!s.valid) return;
  const int32_t across = m->rect.x1 - m->rect.x0;
  if (m->rect.x0 > 0 && m->rect.x1 < width) m->step = across < 24 ? 3 : (across < 48 ? 2 : 1);
  for (int k = 0; k < kCutterRingCount; ++k) {
    // Radii and heights are below 2^31 nm (tool_check's 1 m), cosines q30:
    // 64-bit products.
    const int64_t r = s.ring_r_nm[k];
    for (int a = 0; a < kCutterSegments; a += m->step) {
      const int n = idx(k, a);
      const int64_t ox = (r * s.cos_q30[a] + (kOneQ30 >> 1)) >> 30, oy = (r * s.sin_q30[a] + (kOneQ30 >> 1)) >> 30;
      ClipVertex cv = view_point(v, PointNm{tip.x_nm + ox, tip.y_nm + oy, tip.z_nm + s.ring_h_nm[k]});
      cv.shade = m->shade[n];
      m->clip[n] = cv;
      m->oc[n] = clip_outcode(v.proj, cv.x, cv.y, cv.w);
      if (m->oc[n] == 0) m->screen[n] = clip_project(v.proj, cv);
    }
  }
}

namespace {

void tri(RasterTarget* t, const View& v, const CutterMesh& m, int a, int b, int c) {
  if ((m.oc[a] | m.oc[b] | m.oc[c]) == 0) raster_triangle(t, m.screen[a], m.screen[b], m.screen[c]);
  else if ((m.oc[a] & m.oc[b] & m.oc[c]) == 0) clip_draw_triangle(t, v.proj, m.clip[a], m.clip[b], m.clip[c]);
}

}  // namespace

void cutter_draw(RasterTarget* t, const View& v, const CutterMesh& m) {
  const int sb = kCutterRings + 1, st = sb + 1, cap = st + 1, centre = cap + 1;
  for (int a = 0; a < kCutterSegments; a += m.step) {
    const int b = (a + m.step) % kCutterSegments;
    // Lower surface, counterclockwise seen from below.
    tri(t, v, m, idx(0, a), idx(1, b), idx(1, a));
    for (int k = 1; k < kCutterRings; ++k) {
      tri(t, v, m, idx(k, a), idx(k, b), idx(k + 1, b));
      tri(t, v, m, idx(k, a), idx(k + 1, b), idx(k + 1, a));
    }
    // Shaft, seen from outside.
    tri(t, v, m, idx(st, a), idx(sb, a), idx(sb, b));
    tri(t, v, m, idx(st, a), idx(sb, b), idx(st, b));
    // Cap, seen from above.
    tri(t, v, m, idx(centre, a), idx(cap, a), idx(cap, b));
  }
}

}  // namespace dexmill
