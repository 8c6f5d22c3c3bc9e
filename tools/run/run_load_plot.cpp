// --load-plot FILE.svg|FILE.png (tools/run/run_engage.h): the recorder's
// series into platform/report/load_plot.h's figure: spindle power where
// the material gave cutting coefficients, else the thickest chip; the
// tool changes; the moves of the largest load and removal rate marked.
#include <string>
#include <vector>

#include "platform/os/output_file.h"
#include "tools/run/run_engage.h"

namespace dexmill {
namespace cli {

namespace {

bool ends_with(const std::string& s, const char* tail) {
  const std::string t(tail);
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

std::string base_name(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

LoadPlotData plot_data(const EngageRecorder& r, const EngageSummary& s, const std::string& file, int64_t limit_mw) {
  LoadPlotData d;
  const bool power = r.any_load();
  d.title = base_name(file) + " - load, removal rate and feed";
  d.load_name = power ? "spindle power" : "chip";
  d.load_unit = power ? "W" : "mm";
  d.load_limit = power && limit_mw > 0 ? static_cast<double>(limit_mw) * 1e-3 : 0;
  int32_t tool = INT32_MIN;
  for (const EngageRecorder::PlotMove& m : r.plot_moves()) {
    d.moves.push_back(LoadPlotMove{m.end_s, m.duration_s, power ? m.power_w : m.chip_mm, m.mrr_mm3_per_min,
                                   m.feed_mm_per_min, m.line});
    if (m.tool != tool) {  // the first move of each tool: where it starts cutting
      d.tool_changes.push_back(LoadPlotMark{m.end_s - m.duration_s, m.line, "T" + std::to_string(m.tool)});
      tool = m.tool;
    }
  }
  auto mark = [&d](const EngageMove& m, const char* what) {
    if (m.line) d.worst.push_back(LoadPlotMark{static_cast<double>(m.end_us) * 1e-6, m.line,
                                               "L" + std::to_string(m.line) + " " + what});
  };
  if (power) mark(s.power, "max power");
  else mark(s.chip, "max chip");
  if (s.rate.line != (power ? s.power.line : s.chip.line)) mark(s.rate, "max MRR");
  return d;
}

}  // namespace

std::string load_plot_svg_text(const EngageRecorder& r, const EngageSummary& s, const std::string& file, int64_t limit_mw,
                               int width_px, int height_px) {
  return load_plot_svg(plot_data(r, s, file, limit_mw), width_px, height_px);
}

bool write_load_plot(const std::string& path, const EngageRecorder& r, const EngageSummary& s, const std::string& file,
                     int64_t limit_mw, std::string* err) {
  const LoadPlotData d = plot_data(r, s, file, limit_mw);
  OutputFile out;
  if (!out.open(path.c_str())) return *err = out.error(), false;
  if (ends_with(path, ".png")) {
    std::vector<uint8_t> png;
    load_plot_png(d, 1200, 800, &png);
    out.write(png.data(), png.size());
  } else {
    const std::string svg = load_plot_svg(d, 1200, 800);
    out.write(svg.data(), svg.size());
  }
  if (!out.commit()) return *err = out.error(), false;
  return true;
}

}  // namespace cli
}  // namespace dexmill
