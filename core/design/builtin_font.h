// A 5 x 7 bitmap font for the lettering of the built-in instrument panel
// (core/design/builtin_panel.cpp): one font pixel per dexel at the paper's
// 80 x 40 resolution, the smallest size at which capitals stay legible.
// Only the glyphs the built-in designs spell; any other character is blank.
// The glyphs are display/overlay/font.h's (which core/ may not include; a test
// holds the two equal), so the panel's lettering matches the frames' text.
#ifndef DEXMILL_CORE_DESIGN_BUILTIN_FONT_H
#define DEXMILL_CORE_DESIGN_BUILTIN_FONT_H

#include <stdint.h>

namespace dexmill {

constexpr int32_t kGlyphCols = 5, kGlyphRows = 7;
constexpr int32_t kGlyphAdvance = kGlyphCols + 1;  // one blank column between letters

// Whether the text's pixel at column `col` (0 = left edge of the first
// letter) and row `row` (0 = top) is inked; false outside the text.
bool text_ink(const char* text, int32_t col, int32_t row);

// The text's width in font pixels (no trailing blank column).
int32_t text_cols(const char* text);

}  // namespace dexmill

#endif
