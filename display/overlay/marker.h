// A marker at a machine point, drawn over a frame: a ring with a dot, in
// one colour, on top of everything (not depth-tested: a gouge inside a
// pocket must show even where a wall hides it). What the live views and
// frames mark a gouge with the moment it is found.
#ifndef DEXMILL_DISPLAY_OVERLAY_MARKER_H
#define DEXMILL_DISPLAY_OVERLAY_MARKER_H

#include <stdint.h>

#include "core/point.h"
#include "display/raster/camera.h"
#include "display/raster/framebuffer.h"

namespace dexmill {

// Draws the marker (radius `radius_px`) centred on p's screen position,
// clipped to the frame. Returns the rectangle it may have changed (empty
// when p is outside the view).
ScreenRect marker_draw(const FrameView& fb, const View& v, PointNm p, int32_t radius_px, uint32_t value);

}  // namespace dexmill

#endif
