// The load plot as a PNG (platform/report/load_plot.h): the scene drawn
// into RGB bytes, with integer lines and the repository's bitmap font
// (display/overlay/font.h), and encoded by platform/format/png.h.
#include <algorithm>

#include "display/overlay/font.h"
#include "platform/format/png.h"
#include "platform/report/load_plot.h"

namespace dexmill {

namespace {

using namespace load_plot_detail;

struct Canvas {
  int32_t w = 0, h = 0;
  std::vector<uint8_t> rgb;

  // c over the pixel at opacity a / 255; nothing outside the picture.
  void put(int32_t x, int32_t y, PlotColour c, uint8_t a) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    uint8_t* p = &rgb[(static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 3];
    const uint8_t v[3] = {c.r, c.g, c.b};
    for (int i = 0; i < 3; ++i) p[i] = static_cast<uint8_t>((p[i] * (255 - a) + v[i] * a + 127) / 255);
  }

  void fill(int32_t x0, int32_t y0, int32_t x1, int32_t y1, PlotColour c, uint8_t a) {
    for (int32_t y = std::max(y0, 0); y < std::min(y1, h); ++y) {
      for (int32_t x = std::max(x0, 0); x < std::min(x1, w); ++x) put(x, y, c, a);
    }
  }

  // A width x width square around (x, y), placed as an SVG stroke of
  // that width through the pixel's centre covers it.
  void brush(int32_t x, int32_t y, int32_t width, PlotColour c) {
    const int32_t o = -(width / 2);
    fill(x + o, y + o, x + o + width, y + o + width, c, 255);
  }
};

// Bresenham's line; dashed as SVG's "4w 3w", counted in steps from the start.
void draw_line(Canvas* cv, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t width, bool dashed, PlotColour c) {
  const int32_t dx = x1 > x0 ? x1 - x0 : x0 - x1, dy = y1 > y0 ? y0 - y1 : y1 - y0;
  const int32_t sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int32_t err = dx + dy;
  for (int32_t k = 0;; ++k) {
    if (!dashed || k % (7 * width) < 4 * width) cv->brush(x0, y0, width, c);
    if (x0 == x1 && y0 == y1) break;
    const int32_t e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void draw_steps(Canvas* cv, const Item& it) {
  for (size_t i = 0; i < it.ys.size(); ++i) {
    const int32_t x = it.x0 + static_cast<int32_t>(i);
    if (i > 0 && it.ys[i] != it.ys[i - 1]) draw_line(cv, x, it.ys[i - 1], x, it.ys[i], it.width, false, it.colour);
    cv->brush(x, it.ys[i], it.width, it.colour);
  }
}

void draw_band(Canvas* cv, const Item& it) {
  for (size_t i = 0; i + 1 < it.ys.size(); i += 2) {
    const int32_t x = it.x0 + static_cast<int32_t>(i / 2);
    cv->fill(x, it.ys[i], x + 1, it.ys[i + 1] + 1, it.colour, it.alpha);
  }
}

// The font's character for a code point: ASCII as it is (lower case drawn
// as capitals), '&' (no glyph) as '+', the superscripts and dashes units
// and titles use as their plain forms, anything else '?'.
char font_char(uint32_t cp) {
  if (cp == '&') return '+';
  if (cp >= 32 && cp < 127) return static_cast<char>(cp);
  switch (cp) {
    case 0xb2: return '2';
    case 0xb3: return '3';
    case 0xb5: case 0x3bc: return 'U';
    case 0xb7: case 0x22c5: return '.';
    case 0xd7: return 'X';
    case 0x2013: case 0x2014: case 0x2212: return '-';
    default: return '?';
  }
}

void draw_text(Canvas* cv, const Item& it) {
  const int32_t s = it.scale, w = text_width(it.text, s);
  int32_t x = it.anchor == Anchor::kStart ? it.x0 : it.anchor == Anchor::kMiddle ? it.x0 - w / 2 : it.x0 - w;
  uint32_t cp;
  for (size_t i = 0; i < it.text.size(); i = utf8_next(it.text, i, &cp), x += kFontCellW * s) {
    utf8_next(it.text, i, &cp);
    const uint8_t* g = font_glyph(font_char(cp));
    for (int32_t row = 0; row < 7; ++row) {
      for (int32_t col = 0; col < 5; ++col) {
        if (g[row] & (0x10 >> col)) cv->fill(x + col * s, it.y0 + row * s, x + col * s + s, it.y0 + row * s + s, it.colour, 255);
      }
    }
  }
}

void draw_dot(Canvas* cv, const Item& it) {
  const int32_t r = it.x1;
  for (int32_t dy = -r; dy <= r; ++dy) {
    for (int32_t dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy <= r * r) cv->put(it.x0 + dx, it.y0 + dy, it.colour, 255);
    }
  }
}

}  // namespace

void load_plot_png(const LoadPlotData& d, int width_px, int height_px, std::vector<uint8_t>* png) {
  png->clear();
  if (width_px < 1 || height_px < 1) return;
  const Scene sc = load_plot_scene(d, width_px, height_px);
  Canvas cv;
  cv.w = sc.width, cv.h = sc.height;
  cv.rgb.resize(static_cast<size_t>(cv.w) * static_cast<size_t>(cv.h) * 3);
  for (size_t i = 0; i < cv.rgb.size(); i += 3) {
    cv.rgb[i] = sc.background.r, cv.rgb[i + 1] = sc.background.g, cv.rgb[i + 2] = sc.background.b;
  }
  for (const Item& it : sc.items) {
    switch (it.shape) {
      case Shape::kRect: cv.fill(it.x0, it.y0, it.x1, it.y1, it.colour, it.alpha); break;
      case Shape::kLine: draw_line(&cv, it.x0, it.y0, it.x1, it.y1, it.width, it.dashed, it.colour); break;
      case Shape::kSteps: draw_steps(&cv, it); break;
      case Shape::kBand: draw_band(&cv, it); break;
      case Shape::kText: draw_text(&cv, it); break;
      case Shape::kDot: draw_dot(&cv, it); break;
    }
  }
  png_encode_rgb8(cv.rgb.data(), cv.w, cv.h, png);
}

}  // namespace dexmill
