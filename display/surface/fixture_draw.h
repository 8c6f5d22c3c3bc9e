// Fixtures (clamps, vices, the boxes the tool must never enter)
// drawn as shaded solids: each an axis-aligned box in machine coordinates,
// six faces, each face flat in the shade of its normal under the frame's
// light, depth-tested against everything else like the stock and the
// cutter. The renderer places the boxes once per view (fixture_place, in
// its prepare_view) and draws them inside every rectangle it repaints
// (display/surface/render.cpp draw_rect), so a frame redrawn a rectangle at a time
// equals one drawn whole.
//
// Faces are two triangles each, counterclockwise seen from outside (the
// rasterizer's front faces), so back faces are culled and a box never
// overdraws itself: at most three faces of one box show.
#ifndef DEXMILL_DISPLAY_SURFACE_FIXTURE_DRAW_H
#define DEXMILL_DISPLAY_SURFACE_FIXTURE_DRAW_H

#include <stdint.h>

#include "core/point.h"
#include "display/raster/camera.h"
#include "display/raster/clip.h"
#include "display/raster/framebuffer.h"
#include "display/raster/raster.h"
#include "display/surface/shade.h"

namespace dexmill {

// Fixtures a renderer draws at most (display/surface/render.h renderer_set_fixtures).
constexpr int kFixturesMax = 8;

// `around` widened to hold boxes[0, n) (lo and hi in either order on each
// axis): the scene a renderer frames with its fixtures.
BoxNm fixtures_box(BoxNm around, const BoxNm* boxes, int n);

// Faces of a box, in this order: -x, +x, -y, +y, -z (bottom), +z (top).
constexpr int kFixtureFaces = 6;

// The shade index (0..255, display/surface/shade.h) of each face's outward normal
// under a light: the same for every axis-aligned box.
struct FixtureShades {
  int32_t face[kFixtureFaces];
};
void fixture_light(const Lighting& l, FixtureShades* s);

// One box placed in a view. Corner k is at x = (k & 1 ? hi : lo),
// y = (k & 2 ? hi : lo), z = (k & 4 ? hi : lo).
struct FixtureMesh {
  ClipVertex clip[8];      // corners in clip space (shade unused)
  RasterVertex screen[8];  // corners on the screen, valid where oc == 0 (shade unused)
  uint8_t oc[8];           // clip_outcode of each corner
  ScreenRect rect;         // pixels the box can touch (the whole frame when a corner leaves the guard band)
};

// Places box b (lo and hi in either order on each axis) for view v on a
// width x height frame.
void fixture_place(const BoxNm& b, const View& v, int32_t width, int32_t height, FixtureMesh* m);

// Draws the placed box into t (with t's clip and LUT), face f in shade
// s.face[f].
void fixture_draw(RasterTarget* t, const View& v, const FixtureMesh& m, const FixtureShades& s);

}  // namespace dexmill

#endif
