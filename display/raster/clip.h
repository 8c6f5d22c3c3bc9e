// From camera space to the screen: projection and geometric clipping.
//
// Vertices come in "clip space": for an orthographic view that is the screen
// itself (x, y in q4 pixels, depth already mapped), for a perspective view
// camera coordinates (x right, y up, w the distance in front of the eye, in
// the frame's unit U, display/raster/camera.h). A triangle with every vertex inside
// the guard band (kGuardPx around the frame) and, in perspective, in front of
// the near plane goes straight to the rasterizer; one entirely outside a
// plane is dropped; the rest are clipped (Sutherland-Hodgman) and drawn as a
// fan.
//
// Crack-free clipping: an edge is always cut from its inside end towards its
// outside end, so the two triangles sharing an edge make the same new vertex.
// Depth, shade and colour are interpolated linearly along the clipped edge in clip
// space.
#ifndef DEXMILL_DISPLAY_RASTER_CLIP_H
#define DEXMILL_DISPLAY_RASTER_CLIP_H

#include <stdint.h>

#include "display/raster/approx.h"
#include "display/raster/raster.h"

namespace dexmill {

enum class Projection : uint8_t { kOrthographic = 0, kPerspective = 1 };

struct ClipVertex {
  int64_t x, y, w;  // orthographic: screen q4 (w unused); perspective: camera space, U
  int32_t depth;    // orthographic only: depth units (perspective derives it from w)
  int32_t shade;
  uint32_t rgb = 0;  // RasterVertex::rgb, interpolated channel by channel
};

// A clip plane: inside when a*x + b*y + c*w + e >= 0.
struct ClipPlane {
  int64_t a, b, c, e;
};

// One frame's screen mapping (built by display/raster/camera.cpp).
struct Projector {
  Projection kind = Projection::kOrthographic;
  int32_t cx_q4 = 0, cy_q4 = 0;  // perspective: the screen centre, q4
  int64_t focal_q4 = 0;          // perspective: screen offset (q4) per unit of x/w
  // Perspective depth = depth_far - bn * near / w, so near maps to the
  // nearest depth and `far` to the farthest (1/w is affine in screen space,
  // so the rasterizer interpolates it exactly).
  int32_t near_u = 1;
  int64_t depth_far = 0;
  int64_t depth_bn = 0;
  ClipPlane plane[5] = {};
  int nplanes = 0;
};

// Bit k set when the vertex is outside plane k.
inline uint8_t clip_outcode(const Projector& p, int64_t x, int64_t y, int64_t w) {
  uint8_t oc = 0;
  for (int k = 0; k < p.nplanes; ++k) {
    const ClipPlane& q = p.plane[k];
    if (q.a * x + q.b * y + q.c * w + q.e < 0) oc = static_cast<uint8_t>(oc | (1u << k));
  }
  return oc;
}

// The screen vertex of a clip vertex inside every plane.
RasterVertex clip_project(const Projector& p, const ClipVertex& v);

// Clips the triangle and draws what is left (outcodes as from clip_outcode).
void clip_draw_triangle(RasterTarget* t, const Projector& p, const ClipVertex& a, const ClipVertex& b,
                        const ClipVertex& c);

// The guard-band and near planes of a frame (fills p.plane and p.nplanes).
void clip_set_planes(Projector* p, int32_t width, int32_t height);

}  // namespace dexmill

#endif
