// A box's outline on the screen: the convex hull of its eight corners as a
// view projects them. What the stock view's framing checks the picture's
// decorations against (display/view/stock_view.cpp), so they never cover the
// stock. Integer only; every corner must lie in front of the eye (a fitted
// camera's box does).
#ifndef DEXMILL_DISPLAY_OVERLAY_BOX_OUTLINE_H
#define DEXMILL_DISPLAY_OVERLAY_BOX_OUTLINE_H

#include <stdint.h>

#include "core/point.h"
#include "display/raster/camera.h"
#include "display/raster/framebuffer.h"

namespace dexmill {

// The smallest pixel rectangle holding every corner's pixel.
ScreenRect box_outline_bounds(const View& v, const BoxNm& box);

// True when the outline and the pixel rectangle r (half-open) share a
// point: tested with r's sides and every hull edge as separating axes.
bool box_outline_meets(const View& v, const BoxNm& box, const ScreenRect& r);

}  // namespace dexmill

#endif
