// The load plot's layout (platform/report/load_plot.h): where the title,
// panels, axes and series go, as the items both writers draw; the marks
// over them are load_plot_marks.cpp's.
#include "platform/report/load_plot.h"

#include <algorithm>
#include <cmath>

namespace dexmill {
namespace load_plot_detail {
namespace {

constexpr PlotColour kInk{20, 20, 20}, kLabel{70, 70, 70}, kFrame{150, 150, 150}, kGrid{228, 228, 228};
constexpr PlotColour kSeries[3] = {{31, 96, 180}, {34, 139, 60}, {214, 110, 10}};

}  // namespace

Item text_item(int32_t x, int32_t y, const std::string& text, PlotColour c, int32_t scale, Anchor a) {
  Item it;
  it.shape = Shape::kText;
  it.x0 = x, it.y0 = y, it.text = text, it.colour = c, it.scale = scale, it.anchor = a;
  return it;
}

Item line_item(int32_t x0, int32_t y0, int32_t x1, int32_t y1, PlotColour c, int32_t width, bool dashed) {
  Item it;
  it.shape = Shape::kLine;
  it.x0 = x0, it.y0 = y0, it.x1 = x1, it.y1 = y1, it.colour = c, it.width = width, it.dashed = dashed;
  return it;
}

Item rect_item(const Box& b, PlotColour c, uint8_t alpha) {
  Item it;
  it.shape = Shape::kRect;
  it.x0 = b.x0, it.y0 = b.y0, it.x1 = b.x1, it.y1 = b.y1, it.colour = c, it.alpha = alpha;
  return it;
}

Item dot_item(int32_t x, int32_t y, int32_t r, PlotColour c) {
  Item it;
  it.shape = Shape::kDot;
  it.x0 = x, it.y0 = y, it.x1 = r, it.colour = c;
  return it;
}

int32_t y_of(const Layout& L, int k, double v) {
  const Frame& f = L.plot[k];
  const ValueAxis& a = L.axis[k];
  const double u = std::clamp((v - a.lo) / (a.hi - a.lo), 0.0, 1.0);
  return f.bottom - 1 - static_cast<int32_t>(std::lround(u * (f.bottom - f.top - 1)));
}

// The column of time t, as fill_columns counts them.
int32_t x_of(const Layout& L, double t) {
  const Frame& f = L.plot[0];
  const double u = std::floor(t / L.time.end * (f.right - f.left));
  return f.left + static_cast<int32_t>(std::clamp(u, 0.0, f.right - f.left - 1.0));
}

namespace {

// text cut to max_w pixels at scale, "..." marking the cut.
std::string fit_text(const std::string& text, int32_t max_w, int32_t scale) {
  if (text_width(text, scale) <= max_w) return text;
  std::string out;
  uint32_t cp;
  for (size_t i = 0, j; i < text.size(); i = j) {
    j = utf8_next(text, i, &cp);
    if (text_width(out + text.substr(i, j - i) + "...", scale) > max_w) break;
    out += text.substr(i, j - i);
  }
  return out + "...";
}

// Rows top to bottom: title, then per panel a heading line and the plot,
// then the time axis' labels and title. The plots share what is left.
void lay_out_rows(int32_t h, Layout* L) {
  const int32_t s = L->s, ch = 8 * s;
  const int32_t heading = ch + 4 * s, gap = 10 * s;
  int32_t y = L->pad + 8 * (s + 1) + 6 * s;
  const int32_t below = 6 * s + ch + 6 * s + ch + L->pad;
  const int32_t ph = std::max<int32_t>(8, (h - y - below - 3 * heading - 2 * gap) / 3);
  for (int k = 0; k < 3; ++k) {
    L->heading_top[k] = y;
    L->plot[k].top = y + heading;
    L->plot[k].bottom = L->plot[k].top + ph;
    y = L->plot[k].bottom + gap;
  }
  L->ticks_top = L->plot[2].bottom + 6 * s;
  L->time_title_top = L->ticks_top + ch + 6 * s;
}

// Columns: the value axes' labels on the left, half a time label on the
// right.
void lay_out_columns(const LoadPlotData& d, double t_end, Layout* L) {
  double lo[3], hi[3];
  series_range(d.moves, t_end, lo, hi);
  if (d.load_limit > 0 && std::isfinite(d.load_limit)) hi[0] = std::max(hi[0], d.load_limit);
  const int32_t s = L->s, ph = L->plot[0].bottom - L->plot[0].top;
  const int32_t ticks = std::clamp<int32_t>(ph / (20 * s), 2, 6);
  const std::string units[3] = {d.load_unit, "mm³/min", "mm/min"};
  int32_t label_w = 0;
  for (int k = 0; k < 3; ++k) {
    L->axis[k] = value_axis(lo[k], hi[k], ticks, units[k]);
    const ValueAxis& a = L->axis[k];
    for (double v : {a.lo, a.hi, a.lo + a.step}) label_w = std::max(label_w, text_width(value_label(a, v), s));
  }
  const TimeAxis guess = time_axis(t_end, 8);
  const int32_t right = L->pad + std::max(12 * s, text_width(time_label(guess, t_end), s) / 2 + 2 * s);
  const int32_t left = L->pad + label_w + 8 * s;
  const int32_t pw = std::max(8, L->width - left - right);
  for (Frame& f : L->plot) f.left = left, f.right = left + pw;
  const int32_t tick_w = text_width(time_label(guess, t_end), s) + 6 * 6 * s;
  L->time = time_axis(t_end, std::clamp(pw / std::max(tick_w, 1), 2, 12));
}

void add_title(const LoadPlotData& d, Layout* L, Scene* sc) {
  const int32_t ts = L->s + 1;
  const std::string title = fit_text(d.title, L->width - 2 * L->pad, ts);
  sc->items.push_back(text_item(L->width / 2, L->pad, title, kInk, ts, Anchor::kMiddle));
}

// A panel's heading ("spindle power [kW]") and its greatest value at the
// right; the load panel's labels may use the rest of its line.
void add_heading(int k, const std::string& name, double peak, bool any, Layout* L, Scene* sc) {
  const Frame& f = L->plot[k];
  const ValueAxis& a = L->axis[k];
  const int32_t s = L->s, y = L->heading_top[k];
  const std::string title = name + (a.unit.empty() ? "" : " [" + a.unit + "]");
  sc->items.push_back(text_item(f.left, y, title, kInk, s, Anchor::kStart));
  if (k == 0) L->taken.push_back(Box{f.left - s, y - s, f.left + text_width(title, s) + 2 * s, y + 8 * s});
  if (!any) return;
  const std::string max_text = "max " + format_compact(peak / a.factor) + (a.unit.empty() ? "" : " " + a.unit);
  sc->items.push_back(text_item(f.right, y, max_text, kLabel, s, Anchor::kEnd));
  if (k == 0) L->taken.push_back(Box{f.right - text_width(max_text, s) - 2 * s, y - s, f.right, y + 8 * s});
}

// The value grid, ticks and labels of panel k.
void add_value_axis(const Layout& L, int k, Scene* sc) {
  const Frame& f = L.plot[k];
  const ValueAxis& a = L.axis[k];
  const int32_t s = L.s;
  const int32_t n = static_cast<int32_t>(std::lround((a.hi - a.lo) / a.step));
  for (int32_t i = 0; i <= n; ++i) {
    const double v = a.lo + i * a.step;
    const int32_t y = y_of(L, k, v);
    if (y > f.top && y < f.bottom - 1) sc->items.push_back(line_item(f.left, y, f.right - 1, y, kGrid, 1, false));
    sc->items.push_back(line_item(f.left - 1 - 4 * s, y, f.left - 2, y, kFrame, 1, false));
    const int32_t top = std::clamp(y - 7 * s / 2, f.top - 4 * s, f.bottom - 3 * s);
    sc->items.push_back(text_item(f.left - 7 * s, top, value_label(a, v), kLabel, s, Anchor::kEnd));
  }
}

// The time grid through all panels, ticks and labels under the last.
void add_time_axis(const Layout& L, Scene* sc) {
  const TimeAxis& a = L.time;
  const int32_t s = L.s;
  const Frame& last = L.plot[2];
  const int32_t n = static_cast<int32_t>(std::floor(a.end / a.step + 1e-9));
  for (int32_t i = 0; i <= n; ++i) {
    const double t = i * a.step;
    const int32_t x = x_of(L, t);
    for (const Frame& f : L.plot) {
      if (x > f.left && x < f.right - 1) sc->items.push_back(line_item(x, f.top, x, f.bottom - 1, kGrid, 1, false));
    }
    sc->items.push_back(line_item(x, last.bottom + 1, x, last.bottom + 4 * s, kFrame, 1, false));
    sc->items.push_back(text_item(x, L.ticks_top, time_label(a, t), kLabel, s, Anchor::kMiddle));
  }
  const int32_t mid = (last.left + last.right) / 2;
  sc->items.push_back(text_item(mid, L.time_title_top, a.title, kInk, s, Anchor::kMiddle));
}

void add_frames(const Layout& L, Scene* sc) {
  for (const Frame& f : L.plot) {
    const int32_t l = f.left - 1, t = f.top - 1, r = f.right, b = f.bottom;
    sc->items.push_back(line_item(l, t, r, t, kFrame, 1, false));
    sc->items.push_back(line_item(l, b, r, b, kFrame, 1, false));
    sc->items.push_back(line_item(l, t, l, b, kFrame, 1, false));
    sc->items.push_back(line_item(r, t, r, b, kFrame, 1, false));
  }
}

// Each run of columns that have moves: the band from least to greatest,
// then the mean as a line over it.
void add_series(const Layout& L, int k, const std::vector<Column>& cols, Scene* sc) {
  const int32_t n = static_cast<int32_t>(cols.size());
  for (int32_t c = 0; c < n;) {
    if (cols[static_cast<size_t>(c)].weight == 0) { ++c; continue; }
    Item band, line;
    band.shape = Shape::kBand, band.colour = kSeries[k], band.alpha = 72, band.x0 = L.plot[k].left + c;
    line.shape = Shape::kSteps, line.colour = kSeries[k], line.width = L.s + 1, line.x0 = band.x0;
    for (; c < n && cols[static_cast<size_t>(c)].weight > 0; ++c) {
      const Column& col = cols[static_cast<size_t>(c)];
      band.ys.push_back(y_of(L, k, col.hi));
      band.ys.push_back(y_of(L, k, col.lo));
      line.ys.push_back(y_of(L, k, col.sum / col.weight));
    }
    // Where each column holds one value the band is the line's own row.
    bool wide = false;
    for (size_t i = 0; i < band.ys.size() && !wide; i += 2) wide = band.ys[i] != band.ys[i + 1];
    if (wide) sc->items.push_back(std::move(band));
    sc->items.push_back(std::move(line));
  }
}

double axis_end(const LoadPlotData& d) {
  double t = d.total_time_s;
  if (!(t > 0) || !std::isfinite(t)) {
    t = 0;
    for (const LoadPlotMove& m : d.moves) {
      if (std::isfinite(m.time_s)) t = std::max(t, m.time_s);
    }
  }
  return t > 0 ? t : 1;
}

}  // namespace

// Back to front: grids, series, frames, then the marks.
Scene load_plot_scene(const LoadPlotData& d, int width_px, int height_px) {
  Scene sc;
  sc.width = std::max(width_px, 1), sc.height = std::max(height_px, 1);
  Layout L;
  // The font grows a step per 600 x 400 pixels: the labels keep about the
  // same share of the figure, 14 px capitals at 1200 x 800.
  L.s = std::clamp(std::min(sc.width / 600, sc.height / 400), 1, 4);
  L.width = sc.width, L.pad = 8 * L.s;
  const double t_end = axis_end(d);
  lay_out_rows(sc.height, &L);
  lay_out_columns(d, t_end, &L);
  add_title(d, &L, &sc);
  double lo[3], hi[3];
  const bool any = series_range(d.moves, t_end, lo, hi);
  const std::string names[3] = {d.load_name.empty() ? "load" : d.load_name, "removal rate", "feed"};
  for (int k = 0; k < 3; ++k) {
    add_heading(k, names[k], hi[k], any, &L, &sc);
    add_value_axis(L, k, &sc);
  }
  add_time_axis(L, &sc);
  std::vector<Column> cols[3];
  fill_columns(d.moves, t_end, L.plot[0].right - L.plot[0].left, cols);
  for (int k = 0; k < 3; ++k) add_series(L, k, cols[k], &sc);
  add_frames(L, &sc);
  add_marks(d, &L, &sc);
  return sc;
}

}  // namespace load_plot_detail
}  // namespace dexmill
