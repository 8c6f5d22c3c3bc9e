// The colour legend; see legend.h.
#include "display/legend.h"

#include "core/math/fixed.h"
#include "display/font.h"

namespace dexmill {

namespace {

size_t text_length(const char* s) {
  size_t n = 0;
  while (s[n]) ++n;
  return n;
}

// Font scale: 2 on frames at least 400 pixels tall, else 1.
int32_t legend_scale(const FrameView& fb) { return fb.height >= 400 ? 2 : 1; }

}  // namespace

ScreenRect legend_rect(const FrameView& fb) {
  const int32_t s = legend_scale(fb);
  const int32_t h = min_of(fb.height, (2 * kFontCellH + 8) * s);
  return ScreenRect{0, fb.height - h, fb.width, fb.height};
}

void legend_draw(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* labels, const char* title) {
  if (n < 1 || n > kLegendMaxSwatches) return;
  const int32_t s = legend_scale(fb);
  const ScreenRect band = legend_rect(fb);
  frame_fill(fb, band, pixel_pack(fb.format, Rgb{24, 28, 36}));
  const uint32_t ink = pixel_pack(fb.format, Rgb{230, 232, 236});
  // Swatches as wide as a six-character label, the title after them.
  const int32_t title_w = font_text_width(text_length(title) + 1, s);
  const int32_t sw = max_of<int32_t>(2, min_of(font_text_width(6, s), (fb.width - 8 * s - title_w) / n));
  const int32_t x0 = 4 * s, label_y = band.y0 + 2 * s, sy0 = label_y + kFontCellH * s + s, sy1 = fb.height - 2 * s;
  for (int32_t k = 0; k < n; ++k)
    frame_fill(fb, ScreenRect{x0 + k * sw, sy0, x0 + (k + 1) * sw - (k + 1 < n ? s : 0), sy1},
               pixel_pack(fb.format, colour[k]));
  // Labels centred over their boundaries; on a narrow frame a label that
  // would run into the one before is left out.
  int32_t free_x = 0;
  for (int32_t k = 0; k + 1 < n; ++k) {
    const size_t len = text_length(labels[k]);
    const int32_t x = x0 + (k + 1) * sw - font_text_width(len, s) / 2;
    if (x < free_x) continue;
    free_x = font_draw(fb, x, label_y, labels[k], len, ink, s) + kFontCellW * s;
  }
  font_draw(fb, x0 + n * sw + 2 * s, sy0, title, text_length(title), ink, s);
}

void legend_draw_named(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* names) {
  if (n < 1 || n > kLegendMaxSwatches) return;
  const int32_t s = legend_scale(fb);
  const ScreenRect band = legend_rect(fb);
  frame_fill(fb, band, pixel_pack(fb.format, Rgb{24, 28, 36}));
  const uint32_t ink = pixel_pack(fb.format, Rgb{230, 232, 236});
  // One row of text in the middle of the strip; a swatch as tall as a
  // glyph, half a cell before its name; two cells between entries, one
  // when that makes them all fit.
  const int32_t y = band.y0 + (band.y1 - band.y0 - kFontCellH * s) / 2, swatch_w = 2 * kFontCellW * s;
  const int32_t x0 = 4 * s, lead = swatch_w + kFontCellW * s / 2;
  int32_t all = x0 - 2 * kFontCellW * s;
  for (int32_t k = 0; k < n; ++k) all += lead + font_text_width(text_length(names[k]) + 2, s);
  const int32_t gap = all <= fb.width ? 2 * kFontCellW * s : kFontCellW * s;
  const int32_t room = fb.width - font_text_width(3, s);  // "+N" after the last that fits
  int32_t x = x0, k = 0;
  for (; k < n; ++k) {
    const size_t len = text_length(names[k]);
    const int32_t end = x + lead + font_text_width(len, s);
    if (end > (k + 1 < n ? room : fb.width)) break;
    frame_fill(fb, ScreenRect{x, y, x + swatch_w, y + (kFontCellH - 1) * s}, pixel_pack(fb.format, colour[k]));
    x = font_draw(fb, x + lead, y, names[k], len, ink, s) + gap;
  }
  if (k < n) {
    const char more[3] = {'+', static_cast<char>('0' + (n - k)), 0};
    font_draw(fb, x, y, more, 2, ink, s);
  }
}

}  // namespace dexmill
