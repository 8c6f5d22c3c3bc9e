// The load plot of a whole NC program: its cutting load, material removal
// rate (MRR) and feed against time, as a CAM programmer puts them in a
// report. A title, three panels over one time axis (load on top, MRR in the
// middle, feed at the bottom), ticks at 1, 2, 5 x 10^k with units, a light
// grid, a dashed line at each tool change ("T3"), the worst moves dotted and
// labelled with their G-code line ("L1234"), and the load limit as a red
// dashed line when there is one.
//
// Each series is a step function over time (a move holds its value for its
// duration), drawn per pixel column: the least and greatest value of the
// moves that overlap the column as a light band, their time-weighted mean as
// a line. So a program of millions of moves gives an SVG of a few hundred KB
// at most and a PNG as fast as its pixels. Both outputs draw one layout
// (load_plot_detail::Scene below) and depend only on their input: numbers
// are formatted from integers (no locale), nothing else (no time) goes in.
// The PNG's text is the repository's 5 x 7 font (display/overlay/font.h),
// which has capitals only: its labels come out upper case.
#ifndef DEXMILL_PLATFORM_REPORT_LOAD_PLOT_H
#define DEXMILL_PLATFORM_REPORT_LOAD_PLOT_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dexmill {

struct LoadPlotMove {      // one feed move (a row of the engagement CSV)
  double time_s;           // the program's estimated time at the move's end
  double duration_s;       // the move's own time
  double load;             // in load_unit (e.g. W, or mm of chip)
  double mrr_mm3_per_min;
  double feed_mm_per_min;
  uint32_t line;           // G-code line, 1-based
};

// A moment marked on the plot; label e.g. "T3" or "L120 max power" (empty:
// "L" and the line).
struct LoadPlotMark {
  double time_s;
  uint32_t line;
  std::string label;
};

struct LoadPlotData {
  std::string title;        // e.g. "bracket.ngc — load, removal rate and feed"
  std::string load_name;    // e.g. "spindle power" or "chip load"
  std::string load_unit;    // e.g. "W" or "mm"; W and N get k and M prefixes
  double load_limit = 0;    // 0: none
  double total_time_s = 0;  // the time axis' end (0: the last move's end)
  std::vector<LoadPlotMove> moves;         // in time order
  std::vector<LoadPlotMark> tool_changes;
  std::vector<LoadPlotMark> worst;         // at most a handful
};

// The figure as an SVG document (UTF-8) of width_px x height_px.
std::string load_plot_svg(const LoadPlotData& d, int width_px, int height_px);
// The same figure as a PNG file (RGB, 8 bits) in *png; empty when a side is
// below 1.
void load_plot_png(const LoadPlotData& d, int width_px, int height_px, std::vector<uint8_t>* png);

// What the writers share, not for callers: load_plot.cpp lays the figure
// out as a Scene (the marks over it: load_plot_marks.cpp, the numbers:
// load_plot_axis.cpp), load_plot_svg.cpp and load_plot_png.cpp draw it.
namespace load_plot_detail {

// ---- the scene --------------------------------------------------------------

struct PlotColour {
  uint8_t r, g, b;
};

enum class Shape : uint8_t {
  kRect,   // filled [x0, x1) x [y0, y1)
  kLine,   // (x0, y0) to (x1, y1), through pixel centres
  kSteps,  // a line through pixel row ys[i] of column x0 + i, joined by verticals
  kBand,   // column x0 + i filled from row ys[2i] down to row ys[2i + 1]
  kText,   // text whose glyph tops are row y0, placed at x0 by anchor
  kDot,    // a disc of radius x1 around (x0, y0)
};

enum class Anchor : uint8_t { kStart, kMiddle, kEnd };

// One drawing operation, in pixels; the scene draws them in order.
struct Item {
  Shape shape = Shape::kLine;
  PlotColour colour{0, 0, 0};
  uint8_t alpha = 255;  // opacity of kRect and kBand
  int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int32_t width = 1;    // stroke of kLine and kSteps
  bool dashed = false;  // kLine
  int32_t scale = 1;    // kText: font scale, glyphs 5 x 7 pixels times it
  Anchor anchor = Anchor::kStart;
  std::vector<int32_t> ys;
  std::string text;     // kText, UTF-8
};

struct Scene {
  int32_t width = 1, height = 1;
  PlotColour background{255, 255, 255};
  std::vector<Item> items;
};

Scene load_plot_scene(const LoadPlotData& d, int width_px, int height_px);

// ---- the numbers (load_plot_axis.cpp) ---------------------------------------

// One pixel column of one series: the least and greatest value of the moves
// that overlap it, and their values' sum weighted by the overlap (seconds).
struct Column {
  double lo = 0, hi = 0, sum = 0, weight = 0;  // weight 0: no move
};
// Whether a move is drawn: finite, and ending in [0, t_end] or overlapping it.
bool move_usable(const LoadPlotMove& m, double t_end);
// The least and greatest load, MRR and feed (k = 0, 1, 2) of the usable
// moves; false (and all 0) when there is none.
bool series_range(const std::vector<LoadPlotMove>& moves, double t_end, double lo[3], double hi[3]);
// cols[0..2] (load, MRR, feed) get n columns over [0, t_end].
void fill_columns(const std::vector<LoadPlotMove>& moves, double t_end, int32_t n, std::vector<Column> cols[3]);

// A value axis from lo to hi with a tick every step, its labels value /
// factor with `decimals` decimals in `unit` (the unit asked for, or it with
// a prefix: kW, cm³/min).
struct ValueAxis {
  double lo = 0, hi = 1, step = 1, factor = 1;
  int decimals = 0;
  std::string unit;
};
// The axis over [min(lo, 0), max(hi, 0)] with some headroom and about
// `ticks` steps; 0..1 when that is empty.
ValueAxis value_axis(double lo, double hi, int32_t ticks, const std::string& unit);
std::string value_label(const ValueAxis& a, double v);

// The time axis over [0, end]: seconds, or a clock (min:ss, h:mm:ss).
struct TimeAxis {
  double end = 1, step = 1;
  int decimals = 0;
  bool clock = false, hours = false;
  std::string title;  // "time [s]", "time [min:s]", "time [h:min:s]"
};
TimeAxis time_axis(double end, int32_t ticks);
std::string time_label(const TimeAxis& a, double t);

// 1, 2 or 5 times a power of ten: the least not below raw, or (nearest)
// the one nearest to it, so that an axis gets about as many ticks as asked.
double nice_step(double raw, bool nearest);
// Decimals that print every multiple of step exactly.
int step_decimals(double step);
// v with exactly `decimals` (0..9) decimals, rounded half away from zero.
std::string format_fixed(double v, int decimals);
// v with three significant digits at most, no trailing zeros: "1.2", "850".
std::string format_compact(double v);

// XML (and HTML) text: markup characters escaped; control characters,
// which XML does not allow, and bytes that are not UTF-8 become '?'. The
// load plot's SVG and the sheet's page (platform/report/sheet_html.h).
std::string markup_escape(const std::string& s);

// The code point at s[i] and the index after it; a byte that does not start
// a valid UTF-8 sequence is U+FFFD and one byte long.
size_t utf8_next(const std::string& s, size_t i, uint32_t* code_point);
// Width of text in font cells: one per code point.
int32_t text_cells(const std::string& s);
// Pixel width of text at a font scale, the last cell's spacing left out.
int32_t text_width(const std::string& s, int32_t scale);

// ---- the layout (load_plot.cpp), the marks placed on it ---------------------

// A plot area: pixels [left, right) x [top, bottom).
struct Frame {
  int32_t left = 0, top = 0, right = 1, bottom = 1;
};

// A rectangle a label or dot covers, so that no label hides another.
struct Box {
  int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Layout {
  int32_t s = 1;  // font scale of labels (cells 6 s x 8 s); the title's is s + 1
  int32_t width = 1, pad = 8;
  Frame plot[3];  // load, MRR, feed
  int32_t heading_top[3] = {0, 0, 0};
  int32_t ticks_top = 0, time_title_top = 0;
  ValueAxis axis[3];
  TimeAxis time;
  std::vector<Box> taken;  // in the load panel
};

// The row of value v in panel k, clamped to the panel.
int32_t y_of(const Layout& L, int k, double v);
// The column of time t, as fill_columns counts them.
int32_t x_of(const Layout& L, double t);
Item text_item(int32_t x, int32_t y, const std::string& text, PlotColour c, int32_t scale, Anchor a);
Item line_item(int32_t x0, int32_t y0, int32_t x1, int32_t y1, PlotColour c, int32_t width, bool dashed);
Item rect_item(const Box& b, PlotColour c, uint8_t alpha);
Item dot_item(int32_t x, int32_t y, int32_t r, PlotColour c);
// Tool changes, the limit, the worst moves (load_plot_marks.cpp), over
// everything else.
void add_marks(const LoadPlotData& d, Layout* L, Scene* sc);

}  // namespace load_plot_detail
}  // namespace dexmill

#endif
