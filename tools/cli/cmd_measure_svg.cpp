// The chart of a section (`dexmill measure --distance ... --svg FILE`): a
// small hand-written SVG, distance along the segment across and machine Z
// up, the part's material filled between its bottom and top, the top and
// bottom drawn, the design's line dashed, and axes with mm labels. Glue:
// doubles for drawing only (the values are the CSV's).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "platform/report/load_plot.h"
#include "tools/cli/cmd_measure.h"

namespace dexmill {
namespace cli {

namespace {

constexpr double kWidth = 800, kHeight = 360, kLeft = 70, kRight = 20, kTop = 40, kBottom = 50;

// A tick spacing of 1, 2 or 5 times a power of ten giving about n ticks
// (the load plot's, platform/report/load_plot.h).
double tick_step(double span, int n) { return load_plot_detail::nice_step(span / n, true); }

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

std::string label(double v, double step) {
  return load_plot_detail::format_fixed(v, load_plot_detail::step_decimals(step));
}

struct Frame {
  double a0, a1, z0, z1;
  double x(double a) const { return kLeft + (a - a0) / (a1 - a0) * (kWidth - kLeft - kRight); }
  double y(double z) const { return kTop + (z1 - z) / (z1 - z0) * (kHeight - kTop - kBottom); }
};

// One polyline a run of samples where `have` holds.
template <class Have, class Value>
std::string lines(const std::vector<SectionChartPoint>& p, const Frame& f, Have have, Value value, const char* style) {
  std::string o, run;
  auto flush = [&] {
    if (!run.empty()) o += "<polyline fill=\"none\" " + std::string(style) + " points=\"" + run + "\"/>\n";
    run.clear();
  };
  for (const auto& s : p) {
    if (!have(s)) {
      flush();
      continue;
    }
    run += (run.empty() ? "" : " ") + num(f.x(s.along_mm)) + "," + num(f.y(value(s)));
  }
  flush();
  return o;
}

std::string material_fill(const std::vector<SectionChartPoint>& p, const Frame& f) {
  std::string o;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!p[k].material) continue;
    // Each sample's column as a bar half-way to its neighbours.
    const double a0 = k > 0 ? (p[k - 1].along_mm + p[k].along_mm) / 2 : p[k].along_mm;
    const double a1 = k + 1 < p.size() ? (p[k].along_mm + p[k + 1].along_mm) / 2 : p[k].along_mm;
    o += "<rect x=\"" + num(f.x(a0)) + "\" y=\"" + num(f.y(p[k].top_mm)) + "\" width=\"" +
         num(std::max(0.5, f.x(a1) - f.x(a0))) + "\" height=\"" + num(f.y(p[k].bottom_mm) - f.y(p[k].top_mm)) +
         "\" fill=\"#c9d6e3\" shape-rendering=\"crispEdges\"/>\n";
  }
  return o;
}

std::string axes(const Frame& f) {
  std::string o = "<g stroke=\"#444\" stroke-width=\"1\">\n<line x1=\"" + num(kLeft) + "\" y1=\"" +
                  num(kHeight - kBottom) + "\" x2=\"" + num(kWidth - kRight) + "\" y2=\"" + num(kHeight - kBottom) +
                  "\"/>\n<line x1=\"" + num(kLeft) + "\" y1=\"" + num(kTop) + "\" x2=\"" + num(kLeft) + "\" y2=\"" +
                  num(kHeight - kBottom) + "\"/>\n</g>\n<g font-family=\"sans-serif\" font-size=\"12\" fill=\"#222\">\n";
  const double sa = tick_step(f.a1 - f.a0, 8), sz = tick_step(f.z1 - f.z0, 6);
  for (double a = std::ceil(f.a0 / sa - 1e-9) * sa; a <= f.a1 + 1e-9 * sa; a += sa)
    o += "<line x1=\"" + num(f.x(a)) + "\" y1=\"" + num(kHeight - kBottom) + "\" x2=\"" + num(f.x(a)) + "\" y2=\"" +
         num(kHeight - kBottom + 5) + "\" stroke=\"#444\"/><text x=\"" + num(f.x(a)) + "\" y=\"" +
         num(kHeight - kBottom + 18) + "\" text-anchor=\"middle\">" + label(a, sa) + "</text>\n";
  for (double z = std::ceil(f.z0 / sz - 1e-9) * sz; z <= f.z1 + 1e-9 * sz; z += sz)
    o += "<line x1=\"" + num(kLeft - 5) + "\" y1=\"" + num(f.y(z)) + "\" x2=\"" + num(kLeft) + "\" y2=\"" +
         num(f.y(z)) + "\" stroke=\"#444\"/><text x=\"" + num(kLeft - 8) + "\" y=\"" + num(f.y(z) + 4) +
         "\" text-anchor=\"end\">" + label(z, sz) + "</text>\n";
  o += "<text x=\"" + num((kLeft + kWidth - kRight) / 2) + "\" y=\"" + num(kHeight - 12) +
       "\" text-anchor=\"middle\">distance along the section (mm)</text>\n<text transform=\"translate(16," +
       num((kTop + kHeight - kBottom) / 2) + ") rotate(-90)\" text-anchor=\"middle\">Z (mm)</text>\n</g>\n";
  return o;
}

}  // namespace

std::string section_svg(const std::vector<SectionChartPoint>& p, const std::string& title) {
  Frame f{0, 1, 0, 1};
  bool any = false, design = false;
  for (const auto& s : p) {
    f.a1 = std::max(f.a1, s.along_mm);
    auto take = [&](double z) {
      f.z0 = any ? std::min(f.z0, z) : z;
      f.z1 = any ? std::max(f.z1, z) : z;
      any = true;
    };
    if (s.material) {
      take(s.top_mm);
      take(s.bottom_mm);
    }
    if (s.have_design) take(s.design_mm), design = true;
  }
  if (!any || f.z1 - f.z0 < 1e-3) f.z0 -= 0.5, f.z1 += 0.5;
  const double pad = (f.z1 - f.z0) * 0.08;
  f.z0 -= pad;
  f.z1 += pad;
  std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                  num(kWidth) + "\" height=\"" + num(kHeight) + "\" viewBox=\"0 0 " + num(kWidth) + " " +
                  num(kHeight) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o += "<text x=\"" + num(kLeft) + "\" y=\"22\" font-family=\"sans-serif\" font-size=\"14\" fill=\"#222\">section " +
       title + (design ? " (dashed: the design)" : "") + "</text>\n";
  o += material_fill(p, f);
  o += lines(p, f, [](const SectionChartPoint& s) { return s.material; },
             [](const SectionChartPoint& s) { return s.top_mm; }, "stroke=\"#1f4e79\" stroke-width=\"1.5\"");
  o += lines(p, f, [](const SectionChartPoint& s) { return s.material; },
             [](const SectionChartPoint& s) { return s.bottom_mm; }, "stroke=\"#7f7f7f\" stroke-width=\"1\"");
  o += lines(p, f, [](const SectionChartPoint& s) { return s.have_design; },
             [](const SectionChartPoint& s) { return s.design_mm; },
             "stroke=\"#c0392b\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"");
  o += axes(f) + "</svg>\n";
  return o;
}

}  // namespace cli
}  // namespace dexmill
