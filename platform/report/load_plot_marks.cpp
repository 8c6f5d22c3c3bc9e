// The load plot's marks (platform/report/load_plot.h): dashed lines at tool
// changes, the load limit, dots on the worst moves, and their labels in the
// load panel, each on white and placed clear of those before it.
#include <algorithm>
#include <cmath>

#include "platform/report/load_plot.h"

namespace dexmill {
namespace load_plot_detail {
namespace {

constexpr PlotColour kLimit{210, 30, 30}, kTool{105, 105, 105}, kWorst{0, 0, 0}, kWhite{255, 255, 255};

// Whether b lies in the load panel (or, heading, also in its heading's
// line) and meets no box taken before.
bool box_free(const Layout& L, const Box& b, bool heading) {
  const Frame& f = L.plot[0];
  const int32_t top = heading ? L.heading_top[0] - L.s : f.top;
  if (b.x0 < f.left || b.x1 > f.right || b.y0 < top || b.y1 > f.bottom) return false;
  for (const Box& o : L.taken) {
    if (b.x0 < o.x1 && o.x0 < b.x1 && b.y0 < o.y1 && o.y0 < b.y1) return false;
  }
  return true;
}

// A label in the load panel on a white box: the box of text whose top-left
// is (x, y), grown by s.
Box label_box(const Layout& L, int32_t x, int32_t y, const std::string& text) {
  return Box{x - L.s, y - L.s, x + text_width(text, L.s) + L.s, y + 7 * L.s + L.s};
}

void add_label(const Box& b, const std::string& text, PlotColour c, Layout* L, Scene* sc) {
  sc->items.push_back(rect_item(b, kWhite, 210));
  sc->items.push_back(text_item(b.x0 + L->s, b.y0 + L->s, text, c, L->s, Anchor::kStart));
  L->taken.push_back(b);
}

std::string mark_text(const LoadPlotMark& m) { return m.label.empty() ? "L" + std::to_string(m.line) : m.label; }

// The label's box at the first free of the candidate top-left corners for
// its text; false, and the first moved inside the panel, when none is.
// Only tool changes may use the heading's line: a label there crosses no
// line but their own.
bool place_label(const Layout& L, const std::vector<std::pair<int32_t, int32_t>>& at, const std::string& text, bool heading,
                 Box* out) {
  const Frame& f = L.plot[0];
  const int32_t w = text_width(text, L.s);
  for (const auto& [x, y] : at) {
    *out = label_box(L, x, y, text);
    if (box_free(L, *out, heading)) return true;
  }
  const int32_t x = std::clamp(at[0].first, f.left + L.s, std::max(f.left + L.s, f.right - w - L.s));
  const int32_t y = std::clamp(at[0].second, f.top + L.s, std::max(f.top + L.s, f.bottom - 8 * L.s));
  *out = label_box(L, x, y, text);
  return false;
}

// The move a worst mark means: of those ending near its time the one on
// its line, else the one its time falls in; none when no move does.
const LoadPlotMove* mark_move(const std::vector<LoadPlotMove>& moves, const LoadPlotMark& m) {
  if (moves.empty() || !std::isfinite(m.time_s)) return nullptr;
  const auto it = std::lower_bound(moves.begin(), moves.end(), m.time_s - 1e-9,
                                   [](const LoadPlotMove& a, double t) { return a.time_s < t; });
  const size_t i = static_cast<size_t>(it - moves.begin());
  for (size_t j = i > 2 ? i - 2 : 0; j < std::min(moves.size(), i + 3); ++j) {
    if (moves[j].line == m.line) return &moves[j];
  }
  if (i == moves.size()) return nullptr;
  const LoadPlotMove& mv = moves[i];
  return mv.time_s - std::max(mv.duration_s, 0.0) <= m.time_s + 1e-9 ? &mv : nullptr;
}

bool tool_shown(const Layout& L, const LoadPlotMark& m) {
  return std::isfinite(m.time_s) && m.time_s >= 0 && m.time_s <= L.time.end;
}

// Dashed lines at tool changes through every panel.
void add_tool_lines(const LoadPlotData& d, const Layout& L, Scene* sc) {
  for (const LoadPlotMark& m : d.tool_changes) {
    if (!tool_shown(L, m)) continue;
    const int32_t x = x_of(L, m.time_s);
    for (const Frame& f : L.plot) sc->items.push_back(line_item(x, f.top, x, f.bottom - 1, kTool, 1, true));
  }
}

// Their labels at the top of the load panel, right of the line or left of
// it, in one of three rows, or above the line in the heading's line; left
// out where there is no room (the line stays).
void add_tool_labels(const LoadPlotData& d, Layout* L, Scene* sc) {
  const int32_t s = L->s;
  for (const LoadPlotMark& m : d.tool_changes) {
    if (!tool_shown(*L, m)) continue;
    const int32_t x = x_of(*L, m.time_s);
    const std::string text = mark_text(m);
    std::vector<std::pair<int32_t, int32_t>> at;
    for (int32_t row = 0; row < 3; ++row) {
      const int32_t y = L->plot[0].top + 3 * s + row * 10 * s;
      at.emplace_back(x + 3 * s, y);
      at.emplace_back(x - 3 * s - text_width(text, s), y);
    }
    at.emplace_back(x - text_width(text, s) / 2, L->heading_top[0]);  // above the line's top
    Box b;
    if (place_label(*L, at, text, true, &b)) add_label(b, text, kTool, L, sc);
  }
}

// The red dashed limit; labels placed later keep off it.
void add_limit_line(const LoadPlotData& d, Layout* L, Scene* sc) {
  if (!(d.load_limit > 0) || !std::isfinite(d.load_limit)) return;
  const int32_t s = L->s, y = y_of(*L, 0, d.load_limit);
  const Frame& f = L->plot[0];
  sc->items.push_back(line_item(f.left, y, f.right - 1, y, kLimit, s, true));
  L->taken.push_back(Box{f.left, y - s, f.right, y + s + 1});
}

// The limit's label at the right, above the line or, near the top, below.
void add_limit_label(const LoadPlotData& d, Layout* L, Scene* sc) {
  if (!(d.load_limit > 0) || !std::isfinite(d.load_limit)) return;
  const int32_t s = L->s, y = y_of(*L, 0, d.load_limit);
  const ValueAxis& a = L->axis[0];
  const std::string text = "limit " + format_compact(d.load_limit / a.factor) + (a.unit.empty() ? "" : " " + a.unit);
  const int32_t x = L->plot[0].right - 4 * s - text_width(text, s);
  Box b;
  place_label(*L, {{x, y - 4 * s - 7 * s}, {x, y + 4 * s}}, text, false, &b);
  add_label(b, text, kLimit, L, sc);
}

using Dots = std::vector<std::pair<Box, std::string>>;

// A dot on each worst move's load, at the middle of its time.
void add_worst_dots(const LoadPlotData& d, Layout* L, Scene* sc, Dots* dots) {
  const int32_t s = L->s, r = 3 * s;
  for (const LoadPlotMark& m : d.worst) {
    const LoadPlotMove* mv = mark_move(d.moves, m);
    if (!mv || !move_usable(*mv, L->time.end)) continue;
    const int32_t x = x_of(*L, mv->time_s - std::max(mv->duration_s, 0.0) / 2), y = y_of(*L, 0, mv->load);
    sc->items.push_back(dot_item(x, y, r + s, kWhite));
    sc->items.push_back(dot_item(x, y, r, kWorst));
    const Box b{x - r - s, y - r - s, x + r + s + 1, y + r + s + 1};
    L->taken.push_back(b);
    dots->emplace_back(b, mark_text(m));
  }
}

// Each dot's label above it, or higher, or below, or beside it, wherever
// it hides no other.
void add_worst_labels(const Dots& dots, Layout* L, Scene* sc) {
  const int32_t s = L->s;
  for (const auto& [b, text] : dots) {
    const int32_t w = text_width(text, s), cx = (b.x0 + b.x1) / 2 - w / 2, cy = (b.y0 + b.y1) / 2 - 7 * s / 2;
    std::vector<std::pair<int32_t, int32_t>> at;
    for (int32_t up = 0; up < 3; ++up) at.emplace_back(cx, b.y0 - 2 * s - 7 * s - up * 10 * s);
    at.emplace_back(cx, b.y1 + 2 * s);
    at.emplace_back(b.x1 + 2 * s, cy);
    at.emplace_back(b.x0 - 2 * s - w, cy);
    Box box;
    place_label(*L, at, text, false, &box);
    add_label(box, text, kWorst, L, sc);
  }
}

}  // namespace

// Lines and dots first, then the labels by how much they matter: the
// limit's, the worst moves' (placed even where all spots are taken), the
// tool changes' (left out then).
void add_marks(const LoadPlotData& d, Layout* L, Scene* sc) {
  add_tool_lines(d, *L, sc);
  add_limit_line(d, L, sc);
  Dots dots;
  add_worst_dots(d, L, sc, &dots);
  add_limit_label(d, L, sc);
  add_worst_labels(dots, L, sc);
  add_tool_labels(d, L, sc);
}

}  // namespace load_plot_detail
}  // namespace dexmill
