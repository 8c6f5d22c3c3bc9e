// Decorations over a picture: an axis triad and a scale bar, side by side
// in the bottom-left corner of an area of the frame (above a legend, when
// there is one). Both follow the view's camera: the triad's X (red), Y
// (green) and Z (blue) arrows point where the machine's axes point on the
// screen, foreshortened as the camera sees them (an axis towards the eye is
// a dot with its letter beside it); the scale bar is a round length in mm
// (1, 2 or 5 times a power of ten) drawn as long as the camera shows that
// length at the stock's centre. In perspective that holds in the plane
// through the stock's centre facing the camera: nearer parts look longer
// than the bar says, farther ones shorter.
//
// Opaque pixels only (outlined in a dark colour so they read over light
// and dark alike): drawing them again over themselves changes nothing, so a
// view can draw them after every incremental update. Integer only, no heap,
// clipped to the frame.
#ifndef DEXMILL_DISPLAY_OVERLAY_DECORATIONS_H
#define DEXMILL_DISPLAY_OVERLAY_DECORATIONS_H

#include <stdint.h>

#include "core/point.h"
#include "display/raster/camera.h"
#include "display/raster/framebuffer.h"

namespace dexmill {

// A scale bar's round length and how long the view draws it.
struct ScaleBar {
  int64_t length_nm = 0;  // 1, 2 or 5 times a power of ten, 1 um .. 1000 m
  int32_t length_px = 0;  // on screen, rounded down
};

// The longest round length the view shows at the stock's centre in at most
// max_px pixels (1 um when even that is longer).
ScaleBar scale_bar_choose(const View& v, const BoxNm& stock, int32_t max_px);

// The bar's label, "10 mm", "0.5 mm", into out (at least 16 bytes); its length.
int32_t scale_bar_label(int64_t length_nm, char* out);

// Draws the triad and the scale bar into the bottom-left corner of `area`
// (clipped to the frame) and returns the rectangle they cover; what
// decorations_rect gives for the same arguments.
ScreenRect decorations_draw(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area);
// Where the triad goes: its origin's pixel and each axis's tip (X, Y, Z)
// relative to it, in pixels (screen y down).
struct Triad {
  int32_t ox = 0, oy = 0;
  int32_t tip[3][2] = {};
};
Triad decorations_triad(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area);
// The rectangle decorations_draw covers, without drawing.
ScreenRect decorations_rect(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area);

}  // namespace dexmill

#endif
