// Edge anti-aliasing by 2x2 supersampling: the scene is drawn into a frame
// twice the size each way (caller memory: 4x the colour, and the renderer's
// depth at that size too), then each 2x2 block is averaged into one pixel of
// the picture. Coverage per span end was the other way; it misses
// near-horizontal edges and its fringe pixels are overwritten by surfaces
// drawn later, so the picture averages whole samples instead. Integer only.
#ifndef DEXMILL_DISPLAY_VIEW_SUPERSAMPLE_H
#define DEXMILL_DISPLAY_VIEW_SUPERSAMPLE_H

#include "display/raster/framebuffer.h"

namespace dexmill {

// The rectangle of the picture that big's rectangle r (in big's pixels)
// resolves to: halved, widened outwards to whole pixels.
ScreenRect supersample_half_rect(const ScreenRect& r);

// Writes pixel (x, y) of `out` inside r (clipped to out and to half of big)
// as the box filter of big's pixels (2x, 2y) .. (2x + 1, 2y + 1): per
// channel (a + b + c + d + 2) >> 2, the channels as the format stores them
// (RGB565 averages its 5- and 6-bit fields, so a flat colour stays
// bit-identical). Both frames share one format; nothing is done otherwise.
void downsample_2x2(const FrameView& big, const FrameView& out, const ScreenRect& r);

}  // namespace dexmill

#endif
