// The axis triad and the scale bar; see decorations.h.
#include "display/overlay/decorations.h"

#include "core/math/fixed.h"
#include "display/overlay/font.h"
#include "display/overlay/legend.h"

namespace dexmill {

namespace {

constexpr int64_t kOneQ30 = static_cast<int64_t>(1) << 30;
const Rgb kOutline{16, 18, 24};
const Rgb kInk{236, 238, 242};
const Rgb kAxisColour[3] = {{236, 64, 52}, {64, 200, 80}, {80, 150, 255}};  // X, Y, Z

// Where everything goes, worked out once for drawing and for the rectangle.
struct Layout {
  int32_t s;               // the font scale (legend.h)
  int32_t ox, oy;          // the triad's origin, pixels
  int32_t tip[3][2];       // each axis's tip, relative to the origin
  bool dot[3];             // the axis points (nearly) at or away from the eye
  int32_t label[3][2];     // each letter's top-left, relative to the origin
  int32_t order[3];        // drawing order: farthest from the eye first
  ScaleBar bar;
  int32_t bar_x, bar_y;    // the bar's left end and its centre line
  char text[16];
  int32_t text_n;
  ScreenRect rect;
};

ScreenRect grow(const ScreenRect& r, int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
  const ScreenRect add{x0, y0, x1, y1};
  return r.empty() ? add : rect_union(r, add);
}

// A line of w x w squares (w = 2 half + 1) centred on the pixels from a to b.
void thick_line(const FrameView& fb, int32_t ax, int32_t ay, int32_t bx, int32_t by, int32_t half, uint32_t value) {
  const int32_t dx = bx - ax, dy = by - ay;
  const int32_t n = max_of(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
  for (int32_t k = 0; k <= n; ++k) {
    const int32_t x = ax + (n ? static_cast<int32_t>(div_round(static_cast<int64_t>(dx) * k, n)) : 0);
    const int32_t y = ay + (n ? static_cast<int32_t>(div_round(static_cast<int64_t>(dy) * k, n)) : 0);
    frame_fill(fb, ScreenRect{x - half, y - half, x + half + 1, y + half + 1}, value);
  }
}

// Text with a dark rim (the text drawn one font pixel off each way first).
void outlined_text(const FrameView& fb, int32_t x, int32_t y, const char* t, int32_t n, uint32_t ink, uint32_t rim,
                   int32_t s) {
  const int32_t off[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  for (const auto& o : off) font_draw(fb, x + o[0] * s, y + o[1] * s, t, static_cast<size_t>(n), rim, s);
  font_draw(fb, x, y, t, static_cast<size_t>(n), ink, s);
}

void triad_layout(const View& v, Layout* l) {
  const int32_t s = l->s, len = 20 * s, gap = 5 * s;
  const int32_t cw = (kFontCellW - 1) * s, ch = (kFontCellH - 1) * s;
  for (int k = 0; k < 3; ++k) {
    // Screen right is r, screen down is -u (camera.h): the axis's unit
    // vector there, foreshortened.
    const int64_t sx = v.right_q30[k], sy = -static_cast<int64_t>(v.up_q30[k]);
    l->tip[k][0] = static_cast<int32_t>(div_round(sx * len, kOneQ30));
    l->tip[k][1] = static_cast<int32_t>(div_round(sy * len, kOneQ30));
    const int32_t n = static_cast<int32_t>(hypot_round(l->tip[k][0], l->tip[k][1]));
    l->dot[k] = n < 3 * s;
    if (l->dot[k]) {
      // Down and to the left of the origin, where no other axis of a
      // preset view points.
      l->label[k][0] = -gap - cw;
      l->label[k][1] = gap / 2;
    } else {
      // The letter's centre a gap beyond the tip, along the axis.
      l->label[k][0] = l->tip[k][0] + l->tip[k][0] * gap / n - cw / 2;
      l->label[k][1] = l->tip[k][1] + l->tip[k][1] * gap / n - ch / 2;
    }
  }
  for (int k = 0; k < 3; ++k) l->order[k] = k;
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b)
      if (v.eye_q30[l->order[b]] < v.eye_q30[l->order[a]]) {
        const int32_t t = l->order[a];
        l->order[a] = l->order[b];
        l->order[b] = t;
      }
}

// The triad's and bar's places in the bottom-left corner of `area`.
bool layout(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area, Layout* l) {
  l->s = legend_font_scale(fb);
  const int32_t s = l->s, margin = 6 * s, pad = 2 * s;
  const ScreenRect a = rect_intersect(area, ScreenRect{0, 0, fb.width, fb.height});
  if (a.empty()) return false;
  triad_layout(v, l);
  // The triad's extent around its origin: tips, letters, the outline.
  ScreenRect t{-pad, -pad, pad + 1, pad + 1};
  for (int k = 0; k < 3; ++k) {
    t = grow(t, l->tip[k][0] - pad, l->tip[k][1] - pad, l->tip[k][0] + pad + 1, l->tip[k][1] + pad + 1);
    t = grow(t, l->label[k][0] - s, l->label[k][1] - s, l->label[k][0] + kFontCellW * s, l->label[k][1] + kFontCellH * s);
  }
  l->ox = a.x0 + margin - t.x0;
  l->oy = a.y1 - margin - t.y1;
  l->rect = ScreenRect{t.x0 + l->ox, t.y0 + l->oy, t.x1 + l->ox, t.y1 + l->oy};
  // The bar right of the triad, on its bottom line, at most a quarter of
  // the area's width long.
  l->bar_x = l->rect.x1 + 3 * margin;
  l->bar_y = l->rect.y1 - 2 * s;
  l->bar = scale_bar_choose(v, stock, min_of<int32_t>(60 * s, max_of<int32_t>(a.x1 - a.x0, 4) / 4));
  l->text_n = scale_bar_label(l->bar.length_nm, l->text);
  const int32_t text_w = font_text_width(static_cast<size_t>(l->text_n), s);
  const int32_t mid = l->bar_x + l->bar.length_px / 2;
  const int32_t top = l->bar_y - 5 * s - kFontCellH * s;
  l->rect = grow(l->rect, min_of(l->bar_x, mid - text_w / 2) - s, top - s,
                 max_of(l->bar_x + l->bar.length_px, mid + text_w / 2) + pad + 1, l->bar_y + pad + 1);
  l->rect = rect_intersect(l->rect, a);
  return true;
}

void draw_triad(const FrameView& fb, const Layout& l) {
  const int32_t s = l.s, head = 5 * s;
  const uint32_t rim = pixel_pack(fb.format, kOutline);
  for (int n = 0; n < 3; ++n) {
    const int32_t k = l.order[n];
    const uint32_t ink = pixel_pack(fb.format, kAxisColour[k]);
    const int32_t tx = l.ox + l.tip[k][0], ty = l.oy + l.tip[k][1];
    if (l.dot[k]) {
      frame_fill(fb, ScreenRect{l.ox - 2 * s, l.oy - 2 * s, l.ox + 2 * s + 1, l.oy + 2 * s + 1}, rim);
      frame_fill(fb, ScreenRect{l.ox - s, l.oy - s, l.ox + s + 1, l.oy + s + 1}, ink);
    } else {
      // The shaft and an arrow head of two strokes back from the tip.
      const int32_t dx = l.tip[k][0], dy = l.tip[k][1];
      const int32_t len = max_of<int32_t>(1, static_cast<int32_t>(hypot_round(dx, dy)));
      const int32_t bx = tx - dx * head / len, by = ty - dy * head / len;
      const int32_t px = -dy * head / (2 * len), py = dx * head / (2 * len);
      for (int pass = 0; pass < 2; ++pass) {
        const uint32_t value = pass == 0 ? rim : ink;
        const int32_t half = pass == 0 ? s : s / 2;
        thick_line(fb, l.ox, l.oy, tx, ty, half, value);
        thick_line(fb, tx, ty, bx + px, by + py, half, value);
        thick_line(fb, tx, ty, bx - px, by - py, half, value);
      }
    }
    const char letter = static_cast<char>('X' + k);
    outlined_text(fb, l.ox + l.label[k][0], l.oy + l.label[k][1], &letter, 1, ink, rim, s);
  }
}

void draw_bar(const FrameView& fb, const Layout& l) {
  const int32_t s = l.s, x0 = l.bar_x, x1 = l.bar_x + l.bar.length_px, y = l.bar_y, tick = 4 * s;
  const uint32_t rim = pixel_pack(fb.format, kOutline), ink = pixel_pack(fb.format, kInk);
  for (int pass = 0; pass < 2; ++pass) {
    const uint32_t value = pass == 0 ? rim : ink;
    const int32_t half = pass == 0 ? s : s / 2;
    thick_line(fb, x0, y, x1, y, half, value);
    thick_line(fb, x0, y, x0, y - tick, half, value);
    thick_line(fb, x1, y, x1, y - tick, half, value);
  }
  const int32_t text_w = font_text_width(static_cast<size_t>(l.text_n), s);
  outlined_text(fb, x0 + l.bar.length_px / 2 - text_w / 2, y - tick - s - kFontCellH * s + s, l.text, l.text_n, ink, rim, s);
}

}  // namespace

ScaleBar scale_bar_choose(const View& v, const BoxNm& stock, int32_t max_px) {
  // The screen length of a step along screen right at the stock's centre
  // (a step along r keeps the distance from the eye, so in perspective the
  // whole step lies at the centre's depth).
  const PointNm c{stock.lo.x_nm + (stock.hi.x_nm - stock.lo.x_nm) / 2, stock.lo.y_nm + (stock.hi.y_nm - stock.lo.y_nm) / 2,
                  stock.lo.z_nm + (stock.hi.z_nm - stock.lo.z_nm) / 2};
  const int64_t step = clamp<int64_t>(max_of(stock.hi.x_nm - stock.lo.x_nm, stock.hi.y_nm - stock.lo.y_nm) / 2, kNmPerUm,
                                      static_cast<int64_t>(1) << 38);
  const PointNm e{c.x_nm + muldiv_round(step, v.right_q30[0], kOneQ30), c.y_nm + muldiv_round(step, v.right_q30[1], kOneQ30),
                  c.z_nm};
  const ClipVertex a = view_point(v, c), b = view_point(v, e);
  int64_t step_q4 = abs_u64(b.x - a.x) > abs_u64(b.y - a.y) ? static_cast<int64_t>(abs_u64(b.x - a.x))
                                                             : static_cast<int64_t>(abs_u64(b.y - a.y));
  if (v.proj.kind == Projection::kPerspective) step_q4 = muldiv_floor(step_q4, v.proj.focal_q4, max_of<int64_t>(a.w, 1));
  ScaleBar bar;
  bar.length_nm = kNmPerUm;
  bar.length_px = static_cast<int32_t>(min_of<int64_t>(muldiv_floor(kNmPerUm, step_q4, step * 16), INT32_MAX));
  const int64_t mant[3] = {1, 2, 5};
  for (int64_t p = kNmPerUm; p <= 1000 * 1000 * kNmPerMm / 5; p *= 10)
    for (int64_t m : mant) {
      const int64_t px = muldiv_floor(m * p, step_q4, step * 16);
      if (px > max_px) return bar;
      bar.length_nm = m * p;
      bar.length_px = static_cast<int32_t>(px);
    }
  return bar;
}

int32_t scale_bar_label(int64_t length_nm, char* out) {
  // Whole mm, or "0." and the digits of a fraction (1-2-5 lengths have one
  // significant digit).
  char digits[24];
  int32_t n = 0;
  if (length_nm >= kNmPerMm) {
    int64_t mm = length_nm / kNmPerMm;
    char rev[20];
    int32_t r = 0;
    do {
      rev[r++] = static_cast<char>('0' + mm % 10);
      mm /= 10;
    } while (mm > 0 && r < 12);
    while (r > 0) digits[n++] = rev[--r];
  } else {
    digits[n++] = '0';
    digits[n++] = '.';
    for (int64_t p = kNmPerMm / 10; p > 0 && n < 9; p /= 10) {
      digits[n++] = static_cast<char>('0' + length_nm / p % 10);
      if (length_nm % p == 0) break;
    }
  }
  const char unit[] = " mm";
  for (int32_t k = 0; k < 3; ++k) digits[n++] = unit[k];
  for (int32_t k = 0; k < n && k < 15; ++k) out[k] = digits[k];
  n = min_of<int32_t>(n, 15);
  out[n] = 0;
  return n;
}

ScreenRect decorations_rect(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area) {
  Layout l;
  if (!layout(fb, v, stock, area, &l)) return ScreenRect{0, 0, 0, 0};
  return l.rect;
}

Triad decorations_triad(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area) {
  Layout l;
  Triad t;
  if (!layout(fb, v, stock, area, &l)) return t;
  t.ox = l.ox;
  t.oy = l.oy;
  for (int k = 0; k < 3; ++k) {
    t.tip[k][0] = l.tip[k][0];
    t.tip[k][1] = l.tip[k][1];
  }
  return t;
}

ScreenRect decorations_draw(const FrameView& fb, const View& v, const BoxNm& stock, const ScreenRect& area) {
  Layout l;
  if (!layout(fb, v, stock, area, &l)) return ScreenRect{0, 0, 0, 0};
  draw_triad(fb, l);
  draw_bar(fb, l);
  return l.rect;
}

}  // namespace dexmill
