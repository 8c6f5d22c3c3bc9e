// The cutter drawn as a shaded solid of its real shape (core/tool/tool.h): the
// lower surface of revolution sampled from the ToolProfile on rings, the
// shaft of the same diameter up to the tool's length, and a cap.
//
// Rings sit at r = R sin(k * 90 deg / kCutterRings) so that a ball's steep
// rim gets as many rings as its flat centre; normals come from the profile's
// slope between neighbouring rings (radial on the shaft, up on the cap).
// Every vertex lies inside the tool's bounding box, which is what the
// incremental redraw projects to find the screen area the cutter can touch.
// A tool drawn small uses every 2nd or 3rd segment (12 or 8 around), chosen
// from its box on the screen: under 24 pixels across 8, under 48 12.
#ifndef DEXMILL_DISPLAY_SURFACE_CUTTER_DRAW_H
#define DEXMILL_DISPLAY_SURFACE_CUTTER_DRAW_H

#include <stdint.h>

#include "core/point.h"
#include "core/tool/tool.h"
#include "display/raster/camera.h"
#include "display/raster/raster.h"
#include "display/surface/shade.h"

namespace dexmill {

constexpr int kCutterSegments = 24;  // around the axis
constexpr int kCutterRings = 6;      // on the lower surface, besides the centre

// Rings of the solid, bottom to top: the lower surface's kCutterRings + 1
// (ring 0 is the tip point), the shaft's bottom and top, the cap's rim, and
// the cap's centre (kCutterRingCount - 1, one point).
constexpr int kCutterRingCount = kCutterRings + 1 + 3 + 1;
constexpr int kCutterVertices = kCutterRingCount * kCutterSegments;

// The tessellation of one tool, relative to its tip, nm.
struct CutterShape {
  bool valid = false;
  int64_t radius_nm = 0, length_nm = 0;
  int64_t ring_r_nm[kCutterRingCount];
  int64_t ring_h_nm[kCutterRingCount];
  int64_t ring_nr[kCutterRingCount], ring_nz[kCutterRingCount];  // normal: radial and vertical parts
  int32_t cos_q30[kCutterSegments], sin_q30[kCutterSegments];
};

void cutter_shape_build(const ToolProfile& p, CutterShape* s);

// The solid lit for a view and placed at a tip.
struct CutterMesh {
  uint8_t shade[kCutterVertices];  // from cutter_light
  ClipVertex clip[kCutterVertices];
  RasterVertex screen[kCutterVertices];  // valid where oc == 0
  uint8_t oc[kCutterVertices];
  ScreenRect rect;  // pixels it can touch (the whole frame when any bound leaves the guard band)
  int step;         // segments used: every step-th of kCutterSegments
};

// Shades of the solid's vertices under a light (a directional light and a
// distant viewer: the shades do not depend on where the tool is).
void cutter_light(const CutterShape& s, const Lighting& l, CutterMesh* m);
// Places the lit solid with its tip at `tip`.
void cutter_place(const CutterShape& s, const View& v, PointNm tip, int32_t width, int32_t height, CutterMesh* m);

// Pixels the tool can cover (what cutter_place puts in rect): orthographic,
// its axis's projection widened by the radius; perspective, its bounding
// box's.
ScreenRect cutter_rect(const CutterShape& s, const View& v, PointNm tip, int32_t width, int32_t height);

// Draws the placed solid into t (with t's clip and LUT).
void cutter_draw(RasterTarget* t, const View& v, const CutterMesh& m);

}  // namespace dexmill

#endif
