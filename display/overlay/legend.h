// A colour legend drawn into a frame with the built-in font: a strip along
// the bottom edge of n swatches, left to right, with the n - 1 limits
// between them written above their boundaries and a title (the unit) at
// the right. What the error view (paper §2.5.1, figure 10) shows its bands
// with. Integer only, clipped to the frame, drawn over whatever is there.
#ifndef DEXMILL_DISPLAY_OVERLAY_LEGEND_H
#define DEXMILL_DISPLAY_OVERLAY_LEGEND_H

#include <stdint.h>

#include "display/raster/framebuffer.h"

namespace dexmill {

constexpr int32_t kLegendMaxSwatches = 8;

// The font scale of text over a frame (the legend's, the decorations'): 2
// on frames at least 400 pixels tall, else 1.
int32_t legend_font_scale(const FrameView& fb);

// The rectangle the legend covers (its part of the frame to present); a
// row taller with captions.
ScreenRect legend_rect(const FrameView& fb, bool captions = false);

// Draws the legend; n in 1..kLegendMaxSwatches, labels[n - 1] short texts.
// With captions (either may be null: none), a row above the limits says
// what the ends mean: low_caption from the left end, high_caption up to the
// right end (the error view: "gouge (cut below the design)" over the reds,
// "material left" over the greens); on a frame too narrow for both on one
// row at the legend's scale they are drawn at scale 1, then without their
// bracketed explanations ("gouge"), then not at all.
void legend_draw(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* labels, const char* title,
                 const char* low_caption = nullptr, const char* high_caption = nullptr);

// The same strip with a name for each swatch instead of limits between them
// (the tool colour mode: "UNCUT", "T1 FLAT 6", ...): swatch and name after
// swatch and name, left to right; those that do not fit the frame's width
// are left out and counted at the end ("+2"). n in 1..kLegendMaxSwatches.
void legend_draw_named(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* names);

}  // namespace dexmill

#endif
