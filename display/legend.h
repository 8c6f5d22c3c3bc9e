// A colour legend drawn into a frame with the built-in font: a strip along
// the bottom edge of n swatches, left to right, with the n - 1 limits
// between them written above their boundaries and a title (the unit) at
// the right. What the error view (paper §2.5.1, figure 10) shows its bands
// with. Integer only, clipped to the frame, drawn over whatever is there.
#ifndef DEXMILL_DISPLAY_LEGEND_H
#define DEXMILL_DISPLAY_LEGEND_H

#include <stdint.h>

#include "display/framebuffer.h"

namespace dexmill {

constexpr int32_t kLegendMaxSwatches = 8;

// The rectangle the legend covers (its part of the frame to present).
ScreenRect legend_rect(const FrameView& fb);

// Draws the legend; n in 1..kLegendMaxSwatches, labels[n - 1] short texts.
void legend_draw(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* labels, const char* title);

// The same strip with a name for each swatch instead of limits between them
// (the tool colour mode: "UNCUT", "T1 FLAT 6", ...): swatch and name after
// swatch and name, left to right; those that do not fit the frame's width
// are left out and counted at the end ("+2"). n in 1..kLegendMaxSwatches.
void legend_draw_named(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* names);

}  // namespace dexmill

#endif
