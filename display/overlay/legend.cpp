// The colour legend; see legend.h.
#include "display/overlay/legend.h"

#include "core/math/fixed.h"
#include "display/overlay/font.h"

namespace dexmill {

namespace {

size_t text_length(const char* s) {
  size_t n = 0;
  while (s[n]) ++n;
  return n;
}

}  // namespace

int32_t legend_font_scale(const FrameView& fb) { return fb.height >= 400 ? 2 : 1; }

ScreenRect legend_rect(const FrameView& fb, bool captions) {
  const int32_t s = legend_font_scale(fb);
  const int32_t h = min_of(fb.height, (2 * kFontCellH + 8 + (captions ? kFontCellH + 1 : 0)) * s);
  return ScreenRect{0, fb.height - h, fb.width, fb.height};
}

namespace {

// The length of s up to its first " (", if it has one: the words before a
// bracketed explanation.
size_t before_bracket(const char* s, size_t n) {
  for (size_t k = 0; k + 1 < n; ++k)
    if (s[k] == ' ' && s[k + 1] == '(') return k;
  return n;
}

// The captions' row: low from the left end, high ending at the right end
// (or at the frame's edge, whichever is nearer). Too wide for the row, at
// scale 1 then with their bracketed explanations left out; still too wide,
// none.
void draw_captions(const FrameView& fb, int32_t x0, int32_t x1, int32_t y, const char* low, const char* high,
                   uint32_t ink, int32_t s) {
  size_t nl = low ? text_length(low) : 0, nh = high ? text_length(high) : 0;
  const int32_t room = fb.width - 2 * x0;
  int32_t cs = s;
  if (cs > 1 && font_text_width(nl + nh + 1, cs) > room) cs = 1;
  if (font_text_width(nl + nh + 1, cs) > room) {
    nl = nl ? before_bracket(low, nl) : 0;
    nh = nh ? before_bracket(high, nh) : 0;
  }
  if (font_text_width(nl + nh + 1, cs) > room) return;
  const int32_t right = min_of(max_of(x1, x0 + font_text_width(nl + nh + 1, cs)), fb.width - x0);
  const int32_t dy = (kFontCellH * s - kFontCellH * cs) / 2;
  if (nl) font_draw(fb, x0, y + dy, low, nl, ink, cs);
  if (nh) font_draw(fb, right - font_text_width(nh, cs) + cs, y + dy, high, nh, ink, cs);
}

}  // namespace

void legend_draw(const FrameView& fb, const Rgb* colour, int32_t n, const char* const* labels, const char* title,
                 const char* low_caption, const char* high_caption) {
  if (n < 1 || n > kLegendMaxSwatches) return;
  const int32_t s = legend_font_scale(fb);
  const bool captions = low_caption || high_caption;
  const ScreenRect band = legend_rect(fb, captions);
  frame_fill(fb, band, pixel_pack(fb.format, Rgb{24, 28, 36}));
  const uint32_t ink = pixel_pack(fb.format, Rgb{230, 232, 236});
  // Swatches as wide as a six-character label, the title after them.
  const int32_t title_w = font_text_width(text_length(title) + 1, s);
  const int32_t sw = max_of<int32_t>(2, min_of(font_text_width(6, s), (fb.width - 8 * s - title_w) / n));
  const int32_t x0 = 4 * s, caption_y = band.y0 + 2 * s;
  const int32_t label_y = caption_y + (captions ? (kFontCellH + 1) * s : 0);
  const int32_t sy0 = label_y + kFontCellH * s + s, sy1 = fb.height - 2 * s;
  if (captions) draw_captions(fb, x0, x0 + n * sw, caption_y, low_caption, high_caption, ink, s);
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
  const int32_t s = legend_font_scale(fb);
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
