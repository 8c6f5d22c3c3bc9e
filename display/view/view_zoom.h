// Zoom about a point of the picture: the live window's wheel and the
// embedding API's dm_view_zoom (display/api/dexmill.h) share it.
//
// A zoom is a level (a step is 9/10 of the height of world shown) and a pan
// of the target in the screen's plane, applied to the camera the view was
// given (fitted, orbited): orbiting keeps the zoom. The level's scale is
// recomputed from the level, and the pan is held in exact units (half
// pixels of the given camera times the level scale's unit), so zooming in
// about a pixel and back out about it gives the same camera, bit for bit:
// the point under the pixel stays put (orthographic; a perspective camera
// zooms its distance about the frame's centre). Integer only, no heap.
#ifndef DEXMILL_DISPLAY_VIEW_VIEW_ZOOM_H
#define DEXMILL_DISPLAY_VIEW_VIEW_ZOOM_H

#include <stdint.h>

#include "display/raster/camera.h"

namespace dexmill {

// Levels from kZoomLevelMin (zoomed out, 10/9 a step) to kZoomLevelMax (in).
constexpr int32_t kZoomLevelMin = -20;
constexpr int32_t kZoomLevelMax = 60;
// The scale of level 0, the unit of zoom_scale_q.
constexpr int64_t kZoomOne = int64_t{1} << 24;

struct ViewZoom {
  int32_t level = 0;
  // The target's offset right and down on the screen, in half pixels of the
  // given camera times kZoomOne.
  int64_t pan_right = 0, pan_down = 0;
};

// kZoomOne * (9/10)^level, rounded down a step at a time (the same number
// for a level every time).
int64_t zoom_scale_q(int32_t level);

// `steps` (> 0 towards the scene) about the pixel (x_px, y_px) of a
// width x height frame: the world point drawn at its centre stays there.
// The level stops at its limits; false when nothing changed.
bool view_zoom_about(ViewZoom* z, int32_t steps, int32_t x_px, int32_t y_px, int32_t width, int32_t height);

// The camera `c` zoomed for a frame `height` pixels high.
Camera view_zoom_apply(const Camera& c, const ViewZoom& z, int32_t height);

}  // namespace dexmill

#endif
