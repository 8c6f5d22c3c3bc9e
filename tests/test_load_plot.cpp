// platform/report/load_plot.h: the load plot as SVG and PNG. A synthetic
// program of a few moves, two tool changes and a limit gives a figure with
// its title, axis labels, marks and limit, the same bytes every time; a
// million moves stay a small SVG; the PNG is decoded (tests/inflate_oracle.h)
// to see the load drawn where the layout put it; no data draws bare axes.
// The synthetic figure is left in the tests' temporary folder
// (load_plot_test.svg and .png) to be looked at.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "platform/report/load_plot.h"
#include "tests/inflate_oracle.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int kW = 1200, kH = 800;

// 36 moves of 8 s over 300 s, a tool change every 100 s, one move well
// over the 1.2 kW limit (line 120).
LoadPlotData synthetic() {
  LoadPlotData d;
  d.title = "bracket.ngc — load, removal rate & feed";
  d.load_name = "spindle power";
  d.load_unit = "W";
  d.load_limit = 1200;
  d.total_time_s = 300;
  double t = 0;
  for (uint32_t i = 0; i < 36; ++i) {
    t += i % 12 == 0 ? 4 : 0.5;  // rapids between moves, longer after a tool change
    const double dur = 7.5;
    t += dur;
    const double load = i == 15 ? 1650 : 300 + 40 * (i % 7) + 200 * (i / 12);
    d.moves.push_back(LoadPlotMove{t, dur, load, load * 9, 600.0 + 100.0 * (i % 4), 100 + i});
    if (i % 12 == 0 && i > 0) d.tool_changes.push_back(LoadPlotMark{t - dur, 100 + i, "T" + std::to_string(1 + i / 12)});
  }
  d.worst.push_back(LoadPlotMark{d.moves[15].time_s, 115, "L115 max power"});
  d.worst.push_back(LoadPlotMark{d.moves[33].time_s, 133, ""});
  return d;
}

bool contains(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

// Balanced <svg ...></svg>, and every '<' opens a tag, a comment or the
// XML declaration (text never holds a raw '<').
bool svg_well_formed(const std::string& svg) {
  size_t open = 0, close = 0;
  for (size_t i = 0; i < svg.size(); ++i) {
    if (svg[i] != '<') continue;
    const char c = i + 1 < svg.size() ? svg[i + 1] : 0;
    const bool tag = (c >= 'a' && c <= 'z') || c == '/' || c == '?' || c == '!';
    if (!tag) return false;
    if (svg.compare(i, 5, "<svg ") == 0) ++open;
    if (svg.compare(i, 6, "</svg>") == 0) ++close;
  }
  return open == 1 && close == 1 && svg.rfind("</svg>") > svg.find("<svg ");
}

uint32_t be32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) << 24 | static_cast<uint32_t>(p[1]) << 16 | static_cast<uint32_t>(p[2]) << 8 | p[3];
}

// The PNG's pixels (RGB, 8 bits, unfiltered rows as png.h writes them).
bool decode_png(const std::vector<uint8_t>& png, uint32_t* w, uint32_t* h, std::vector<uint8_t>* rgb) {
  std::vector<uint8_t> z, raw;
  for (size_t p = 8; p + 12 <= png.size();) {
    const uint32_t n = be32(&png[p]);
    const std::string type(png.begin() + static_cast<std::ptrdiff_t>(p + 4), png.begin() + static_cast<std::ptrdiff_t>(p + 8));
    if (type == "IHDR") *w = be32(&png[p + 8]), *h = be32(&png[p + 12]);
    if (type == "IDAT") z.insert(z.end(), png.begin() + static_cast<std::ptrdiff_t>(p + 8), png.begin() + static_cast<std::ptrdiff_t>(p + 8 + n));
    p += 12 + n;
  }
  oracle::InflateStats st;
  if (!oracle::zlib_decompress(z.data(), z.size(), &raw, &st)) return false;
  const size_t row = 1 + 3 * static_cast<size_t>(*w);
  if (raw.size() != row * *h) return false;
  rgb->clear();
  for (size_t y = 0; y < *h; ++y) {
    if (raw[y * row] != 0) return false;
    rgb->insert(rgb->end(), raw.begin() + static_cast<std::ptrdiff_t>(y * row + 1), raw.begin() + static_cast<std::ptrdiff_t>((y + 1) * row));
  }
  return true;
}

void save(const std::string& path, const void* p, size_t n) {
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(p, 1, n, f);
    std::fclose(f);
  }
}

}  // namespace

TEST(load_plot_svg_has_labels_marks_and_limit) {
  const LoadPlotData d = synthetic();
  const std::string svg = load_plot_svg(d, kW, kH);
  save(run_cli::tmp_dir() + "/load_plot_test.svg", svg.data(), svg.size());
  CHECK(contains(svg, "bracket.ngc — load, removal rate &amp; feed"));
  CHECK(contains(svg, ">spindle power [kW]<"));
  CHECK(contains(svg, ">removal rate [cm³/min]<"));
  CHECK(contains(svg, ">feed [mm/min]<"));
  CHECK(contains(svg, ">time [min:s]<"));
  CHECK(contains(svg, ">T2<"));
  CHECK(contains(svg, ">T3<"));
  CHECK(contains(svg, ">limit 1.2 kW<"));
  CHECK(contains(svg, ">L115 max power<"));
  CHECK(contains(svg, ">L133<"));
  CHECK(contains(svg, ">5:00<"));
  CHECK(svg_well_formed(svg));
  CHECK(svg == load_plot_svg(d, kW, kH));
}

TEST(load_plot_svg_of_a_million_moves_is_small) {
  LoadPlotData d;
  d.title = "a million moves";
  d.load_name = "chip load";
  d.load_unit = "mm";
  uint32_t x = 12345;
  for (uint32_t i = 0; i < 1000000; ++i) {
    x = x * 1103515245u + 12345u;
    const double v = (x >> 8 & 0xffff) / 65536.0;
    d.moves.push_back(LoadPlotMove{(i + 1) * 0.01, 0.009, 0.02 + 0.1 * v, 5000 * v, 800 + 1200 * v, i + 1});
  }
  d.tool_changes.push_back(LoadPlotMark{2500, 250000, "T2"});
  d.worst.push_back(LoadPlotMark{d.moves[777].time_s, 778, ""});
  const std::string svg = load_plot_svg(d, kW, kH);
  std::printf("load plot: SVG of 10^6 moves: %zu bytes\n", svg.size());
  CHECK_LT(svg.size(), size_t{500000});
  CHECK(svg_well_formed(svg));
  CHECK(contains(svg, ">time [h:min:s]<"));
  CHECK(contains(svg, ">chip load [mm]<"));
  std::vector<uint8_t> png;
  load_plot_png(d, kW, kH, &png);
  CHECK_GT(png.size(), size_t{1000});
}

TEST(load_plot_png_draws_the_load_where_the_layout_puts_it) {
  const LoadPlotData d = synthetic();
  std::vector<uint8_t> png;
  load_plot_png(d, kW, kH, &png);
  save(run_cli::tmp_dir() + "/load_plot_test.png", png.data(), png.size());
  static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  CHECK(png.size() > 33 && std::equal(kSignature, kSignature + 8, png.begin()));
  uint32_t w = 0, h = 0;
  std::vector<uint8_t> rgb;
  CHECK(decode_png(png, &w, &h, &rgb));
  CHECK_EQ(w, uint32_t{kW});
  CHECK_EQ(h, uint32_t{kH});
  // The load line's highest row (the 1650 W move), in the top panel.
  const load_plot_detail::Scene sc = load_plot_detail::load_plot_scene(d, kW, kH);
  const load_plot_detail::Item* load = nullptr;
  for (const auto& it : sc.items) {
    if (it.shape == load_plot_detail::Shape::kSteps) { load = &it; break; }
  }
  CHECK(load != nullptr);
  if (!load || rgb.size() != size_t{w} * h * 3) return;
  size_t top = 0;
  for (size_t i = 0; i < load->ys.size(); ++i) top = load->ys[i] < load->ys[top] ? i : top;
  const size_t x = static_cast<size_t>(load->x0) + top, y = static_cast<size_t>(load->ys[top]);
  CHECK_LT(y, size_t{kH / 3});
  const uint8_t* p = &rgb[(y * w + x) * 3];
  CHECK(!(p[0] == 255 && p[1] == 255 && p[2] == 255));
  std::vector<uint8_t> again;
  load_plot_png(d, kW, kH, &again);
  CHECK(again == png);
}

TEST(load_plot_of_no_data_draws_axes) {
  const LoadPlotData d;
  const std::string svg = load_plot_svg(d, kW, kH);
  CHECK(svg_well_formed(svg));
  CHECK(contains(svg, ">time [s]<"));
  CHECK(contains(svg, ">load<"));
  CHECK(contains(svg, ">1.0<"));  // the range 0..1
  std::vector<uint8_t> png;
  load_plot_png(d, kW, kH, &png);
  uint32_t w = 0, h = 0;
  std::vector<uint8_t> rgb;
  CHECK(decode_png(png, &w, &h, &rgb));
  load_plot_png(d, 0, 10, &png);
  CHECK(png.empty());
  CHECK(svg_well_formed(load_plot_svg(d, 1, 1)));
}
