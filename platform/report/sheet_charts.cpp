// The sheet's charts as inline SVG (see sheet_html.h), in the load plot's
// style (platform/report/load_plot_svg.cpp): whole pixels, monospace text,
// a light grid, no script.
#include <cmath>
#include <cstdint>
#include <string>

#include "core/assess/assess.h"
#include "platform/report/report_json.h"
#include "platform/report/sheet_html.h"

namespace dexmill {
namespace sheet_detail {
namespace {

std::string num(int64_t v) { return std::to_string(v); }

std::string svg_open(int w, int h, const std::string& title) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart\" width=\"" + num(w) + "\" height=\"" + num(h) +
         "\" viewBox=\"0 0 " + num(w) + " " + num(h) +
         "\" font-family=\"DejaVu Sans Mono, Menlo, Consolas, monospace\" font-size=\"9\" role=\"img\"><title>" +
         html(title) + "</title>\n";
}

std::string text(int x, int y, const std::string& s, const char* anchor, const char* fill = "#333") {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor + "\" fill=\"" + fill + "\">" +
         html(s) + "</text>\n";
}

// A bin's colour by the sign of d: gouge red, around 0 grey, material left green.
const char* bin_colour(int k) {
  if (k < kAssessBins / 2) return "#d9412b";
  if (k > kAssessBins / 2) return "#3f9e4d";
  return "#9a9a9a";
}

}  // namespace

std::string histogram_svg(const AssessResult& a) {
  // Bar heights on a log scale (log10(1 + columns)): the bin around 0
  // holds most columns, and a bin of one gouged column must still show.
  const int w = 360, h = 150, left = 34, right = w - 6, top = 14, bottom = h - 34;
  const int bw = (right - left) / kAssessBins;
  uint64_t most = 1;
  for (uint64_t n : a.histogram) most = n > most ? n : most;
  const double scale = (bottom - top) / std::log10(1.0 + static_cast<double>(most));
  std::string o = svg_open(w, h, "histogram of cut - design, columns per band (log scale)");
  for (uint64_t p = 1; p <= most; p *= 10) {  // the grid at 1, 10, 100, ...
    const int y = bottom - static_cast<int>(std::lround(std::log10(1.0 + static_cast<double>(p)) * scale));
    o += "<line x1=\"" + num(left) + "\" y1=\"" + num(y) + ".5\" x2=\"" + num(right) + "\" y2=\"" + num(y) +
         ".5\" stroke=\"#e4e4e4\"/>\n";
    o += text(left - 3, y + 3, p >= 1000000 ? num(static_cast<int64_t>(p / 1000000)) + "M"
                               : p >= 1000 ? num(static_cast<int64_t>(p / 1000)) + "k"
                                           : num(static_cast<int64_t>(p)),
              "end", "#777");
    if (p > UINT64_MAX / 10) break;
  }
  for (int k = 0; k < kAssessBins; ++k) {
    const uint64_t n = a.histogram[k];
    const int bh = static_cast<int>(std::lround(std::log10(1.0 + static_cast<double>(n)) * scale));
    const int x = left + k * bw;
    o += "<rect x=\"" + num(x + 1) + "\" y=\"" + num(bottom - bh) + "\" width=\"" + num(bw - 2) + "\" height=\"" +
         num(bh) + "\" fill=\"" + bin_colour(k) + "\"><title>" + num(static_cast<int64_t>(n)) + " columns</title></rect>\n";
    if (n) o += "<text x=\"" + num(x + bw / 2) + "\" y=\"" + num(bottom - bh - 2) +
                "\" text-anchor=\"middle\" font-size=\"7\" fill=\"#333\">" + num(static_cast<int64_t>(n)) + "</text>\n";
  }
  o += "<line x1=\"" + num(left) + "\" y1=\"" + num(bottom) + ".5\" x2=\"" + num(right) + "\" y2=\"" + num(bottom) +
       ".5\" stroke=\"#555\"/>\n";
  for (int k = 0; k < kAssessEdges; ++k) {  // the edges between the bins, in mm
    const int x = left + (k + 1) * bw, y = bottom + 6;
    std::string label = nm_to_mm_text(kAssessBinEdgesNm[k], 2);
    o += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"7\" text-anchor=\"end\" fill=\"#555\" transform=\"rotate(-50 " +
         num(x) + " " + num(y) + ")\">" + html(label) + "</text>\n";
  }
  o += text((left + right) / 2, h - 2, "cut - design [mm]   (< 0 gouge, > 0 material left)", "middle", "#333");
  return o + "</svg>\n";
}

std::string time_bars_svg(const RunReport& r) {
  const int w = 360, row = 14, left = 56, right = w - 92;
  const int h = 6 + row * static_cast<int>(r.time_by_tool.size());
  int64_t most = 1;
  for (const ReportToolTime& t : r.time_by_tool) most = t.estimated_us > most ? t.estimated_us : most;
  std::string o = svg_open(w, h, "the time estimate by tool");
  int y = 3;
  for (const ReportToolTime& t : r.time_by_tool) {
    const int64_t span = right - left;
    const int feed = static_cast<int>(span * t.feed_us / most), rapid = static_cast<int>(span * t.rapid_us / most);
    o += text(left - 4, y + 9, t.tool < 0 ? std::string("first") : "T" + num(t.tool), "end");
    o += "<rect x=\"" + num(left) + "\" y=\"" + num(y + 1) + "\" width=\"" + num(feed) + "\" height=\"" + num(row - 4) +
         "\" fill=\"#3b6fb6\"/>\n";
    o += "<rect x=\"" + num(left + feed) + "\" y=\"" + num(y + 1) + "\" width=\"" + num(rapid) + "\" height=\"" +
         num(row - 4) + "\" fill=\"#a9c1e3\"/>\n";
    o += text(right + 4, y + 9, seconds_text(t.estimated_us, false), "start");
    y += row;
  }
  return o + "</svg>\n";
}

}  // namespace sheet_detail
}  // namespace dexmill
