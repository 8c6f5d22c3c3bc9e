// A small bitmap font of our own (5 x 7 pixel glyphs in 6 x 8 cells) for
// status lines drawn straight into a framebuffer: digits, upper-case
// letters (lower case is drawn as upper case) and the punctuation G-code
// and numbers need. Integer only, no heap: a controller's panel draws its
// status with it too.
#ifndef DEXMILL_DISPLAY_OVERLAY_FONT_H
#define DEXMILL_DISPLAY_OVERLAY_FONT_H

#include <stddef.h>
#include <stdint.h>

#include "display/raster/framebuffer.h"

namespace dexmill {

constexpr int32_t kFontCellW = 6;  // glyph 5 wide + 1 column of spacing
constexpr int32_t kFontCellH = 8;  // glyph 7 high + 1 row of spacing

// Width in pixels of n characters at an integer scale.
constexpr int32_t font_text_width(size_t n, int32_t scale) { return static_cast<int32_t>(n) * kFontCellW * scale; }

// The glyph's rows, top first, bit 4 the leftmost pixel; blank for
// characters without a glyph.
const uint8_t* font_glyph(char c);

// Draws text[0, n) with its top-left cell corner at (x, y), each font pixel
// a scale x scale square of `fg` (a stored pixel value, pixel_pack).
// Background pixels are left alone. Clipped to the frame. Returns the x
// after the last cell.
int32_t font_draw(const FrameView& fb, int32_t x, int32_t y, const char* text, size_t n, uint32_t fg, int32_t scale);

}  // namespace dexmill

#endif
