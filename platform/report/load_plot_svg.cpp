// The load plot as SVG (platform/report/load_plot.h): each item of the
// scene one element. Coordinates are whole pixels; a stroke of odd width
// runs through pixel centres (x.5), so that it covers the pixels the PNG
// sets. Text is monospace at 10 px per font scale, whose 0.6 em advance is
// the bitmap font's 6 px cell: labels take the room the layout gave them.
#include <string>

#include "platform/report/load_plot.h"

namespace dexmill {

namespace {

using namespace load_plot_detail;

std::string colour(PlotColour c) {
  static const char kHex[] = "0123456789abcdef";
  std::string s = "#";
  for (uint8_t v : {c.r, c.g, c.b}) s += kHex[v >> 4], s += kHex[v & 15];
  return s;
}

std::string num(int32_t v) { return std::to_string(v); }

// v + 0.5 when the stroke is odd, so that it fills whole pixels.
std::string at(int32_t v, int32_t width) {
  return width % 2 ? format_fixed(v + 0.5, 1) : num(v);
}

std::string opacity(uint8_t alpha) { return format_fixed(alpha / 255.0, 2); }

void rect_svg(const Item& it, std::string* o) {
  *o += "<rect x=\"" + num(it.x0) + "\" y=\"" + num(it.y0) + "\" width=\"" + num(it.x1 - it.x0) + "\" height=\"" +
        num(it.y1 - it.y0) + "\" fill=\"" + colour(it.colour) + "\"";
  if (it.alpha != 255) *o += " fill-opacity=\"" + opacity(it.alpha) + "\"";
  *o += "/>\n";
}

void line_svg(const Item& it, std::string* o) {
  const int32_t w = it.width;
  *o += "<line x1=\"" + at(it.x0, w) + "\" y1=\"" + at(it.y0, w) + "\" x2=\"" + at(it.x1, w) + "\" y2=\"" +
        at(it.y1, w) + "\" stroke=\"" + colour(it.colour) + "\"";
  if (w != 1) *o += " stroke-width=\"" + num(w) + "\"";
  if (it.dashed) *o += " stroke-dasharray=\"" + num(4 * w) + " " + num(3 * w) + "\"";
  *o += "/>\n";
}

// The mean: along each column's row, down or up to the next one's at the
// column boundary; a run of equal rows is one horizontal.
void steps_svg(const Item& it, std::string* o) {
  const int32_t w = it.width;
  *o += "<path fill=\"none\" stroke=\"" + colour(it.colour) + "\"";
  if (w != 1) *o += " stroke-width=\"" + num(w) + "\"";
  *o += " d=\"M" + num(it.x0) + " " + at(it.ys[0], w);
  for (size_t i = 0; i < it.ys.size();) {
    size_t j = i + 1;
    while (j < it.ys.size() && it.ys[j] == it.ys[i]) ++j;
    *o += "h" + num(static_cast<int32_t>(j - i));
    if (j < it.ys.size()) *o += "V" + at(it.ys[j], w);
    i = j;
  }
  *o += "\"/>\n";
}

// The band's outline: along the tops left to right, back along the
// bottoms (a bottom row's lower edge is the row below it); a run of equal
// rows is one horizontal.
void band_svg(const Item& it, std::string* o) {
  const size_t n = it.ys.size() / 2;
  const auto top = [&](size_t i) { return it.ys[2 * i]; };
  const auto bottom = [&](size_t i) { return it.ys[2 * i + 1] + 1; };
  *o += "<path fill=\"" + colour(it.colour) + "\" fill-opacity=\"" + opacity(it.alpha) + "\" d=\"M" + num(it.x0) + " " +
        num(top(0));
  for (size_t i = 0, j; i < n; i = j) {
    for (j = i + 1; j < n && top(j) == top(i);) ++j;
    *o += "h" + num(static_cast<int32_t>(j - i)) + "V" + num(j < n ? top(j) : bottom(n - 1));
  }
  for (size_t i = n, j; i > 0; i = j) {
    for (j = i - 1; j > 0 && bottom(j - 1) == bottom(i - 1);) --j;
    *o += "h-" + num(static_cast<int32_t>(i - j));
    if (j > 0) *o += "V" + num(bottom(j - 1));
  }
  *o += "Z\"/>\n";
}

// The layout's y is the glyphs' top; a capital's height is 0.7 em, so the
// baseline is 7 px per scale below it.
void text_svg(const Item& it, std::string* o) {
  static const char* const kAnchor[] = {"", " text-anchor=\"middle\"", " text-anchor=\"end\""};
  *o += "<text x=\"" + num(it.x0) + "\" y=\"" + num(it.y0 + 7 * it.scale) + "\"";
  if (it.scale != 1) *o += " font-size=\"" + num(10 * it.scale) + "\"";
  *o += std::string(kAnchor[static_cast<int>(it.anchor)]) + " fill=\"" + colour(it.colour) + "\">" + markup_escape(it.text) +
        "</text>\n";
}

void dot_svg(const Item& it, std::string* o) {
  *o += "<circle cx=\"" + at(it.x0, 1) + "\" cy=\"" + at(it.y0, 1) + "\" r=\"" + num(it.x1) + "\" fill=\"" +
        colour(it.colour) + "\"/>\n";
}

}  // namespace

namespace load_plot_detail {

std::string markup_escape(const std::string& s) {
  std::string out;
  uint32_t cp;
  for (size_t i = 0, j; i < s.size(); i = j) {
    j = utf8_next(s, i, &cp);
    if (cp == '&') out += "&amp;";
    else if (cp == '<') out += "&lt;";
    else if (cp == '>') out += "&gt;";
    else if (cp == '"') out += "&quot;";
    else if (cp == '\'') out += "&apos;";
    else if (cp < 0x20 || cp == 0x7f || cp == 0xfffd) out += '?';
    else out.append(s, i, j - i);
  }
  return out;
}

}  // namespace load_plot_detail

std::string load_plot_svg(const LoadPlotData& d, int width_px, int height_px) {
  const Scene sc = load_plot_scene(d, width_px, height_px);
  const std::string w = num(sc.width), h = num(sc.height);
  std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " +
       h + "\" font-family=\"DejaVu Sans Mono, Menlo, Consolas, monospace\" font-size=\"10\">\n";
  o += "<title>" + markup_escape(d.title) + "</title>\n";
  o += "<rect width=\"" + w + "\" height=\"" + h + "\" fill=\"" + colour(sc.background) + "\"/>\n";
  for (const Item& it : sc.items) {
    switch (it.shape) {
      case Shape::kRect: rect_svg(it, &o); break;
      case Shape::kLine: line_svg(it, &o); break;
      case Shape::kSteps: if (!it.ys.empty()) steps_svg(it, &o); break;
      case Shape::kBand: if (it.ys.size() >= 2) band_svg(it, &o); break;
      case Shape::kText: text_svg(it, &o); break;
      case Shape::kDot: dot_svg(it, &o); break;
    }
  }
  o += "</svg>\n";
  return o;
}

}  // namespace dexmill
