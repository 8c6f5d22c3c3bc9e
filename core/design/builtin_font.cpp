// The panel's 5 x 7 capitals; see builtin_font.h.
#include "core/design/builtin_font.h"

namespace dexmill {

namespace {

struct Glyph {
  char c;
  uint8_t rows[kGlyphRows];  // top row first; bit 4 is the leftmost column
};

constexpr Glyph kGlyphs[] = {
    {'D', {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C}},
    {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}},
    {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
    {'M', {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}},
    {'X', {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11}},
};

const Glyph* glyph(char c) {
  for (const Glyph& g : kGlyphs)
    if (g.c == c) return &g;
  return nullptr;
}

}  // namespace

int32_t text_cols(const char* text) {
  int32_t n = 0;
  while (text[n]) ++n;
  return n ? n * kGlyphAdvance - 1 : 0;
}

bool text_ink(const char* text, int32_t col, int32_t row) {
  if (col < 0 || row < 0 || row >= kGlyphRows || col >= text_cols(text)) return false;
  const Glyph* g = glyph(text[col / kGlyphAdvance]);
  const int32_t x = col % kGlyphAdvance;
  return g && x < kGlyphCols && ((g->rows[row] >> (kGlyphCols - 1 - x)) & 1u);
}

}  // namespace dexmill
