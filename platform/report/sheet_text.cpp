// The sheet's text pieces: escaping, base64, times; see sheet_html.h.
#include <algorithm>
#include <string>
#include <vector>

#include "platform/report/load_plot.h"
#include "platform/report/report_json.h"
#include "platform/report/sheet_html.h"

namespace dexmill {
namespace sheet_detail {

std::string html(const std::string& s) { return load_plot_detail::markup_escape(s); }

std::string base64(const std::vector<uint8_t>& b) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string o;
  o.reserve((b.size() + 2) / 3 * 4);
  for (size_t i = 0; i < b.size(); i += 3) {
    const uint32_t n = static_cast<uint32_t>(b[i]) << 16 | (i + 1 < b.size() ? static_cast<uint32_t>(b[i + 1]) << 8 : 0) |
                       (i + 2 < b.size() ? b[i + 2] : 0);
    o += kAlphabet[n >> 18 & 63];
    o += kAlphabet[n >> 12 & 63];
    o += i + 1 < b.size() ? kAlphabet[n >> 6 & 63] : '=';
    o += i + 2 < b.size() ? kAlphabet[n & 63] : '=';
  }
  return o;
}

std::string img_png(const std::vector<uint8_t>& png, const std::string& alt, const char* css_class) {
  return "<img class=\"" + std::string(css_class) + "\" alt=\"" + html(alt) + "\" src=\"data:image/png;base64," +
         base64(png) + "\">";
}

std::string seconds_text(int64_t us, bool clock) {
  std::string o = seconds_of_us(us) + "\xc2\xa0s";  // the report's text
  const int64_t s = ((std::max<int64_t>(us, 0) + 500) / 1000 + 500) / 1000;  // the shown ms, rounded
  if (clock && s >= 60) {
    o += " (" + (s >= 3600 ? std::to_string(s / 3600) + " h " : std::string()) + std::to_string(s / 60 % 60) + " min " +
         std::to_string(s % 60) + " s)";
  }
  return o;
}

}  // namespace sheet_detail

std::vector<size_t> sheet_worst_gouges(const ReportAssessment& a) {
  std::vector<size_t> k(a.gouges.size());
  for (size_t i = 0; i < k.size(); ++i) k[i] = i;
  std::stable_sort(k.begin(), k.end(), [&a](size_t x, size_t y) {
    const ReportGouge &gx = a.gouges[x], &gy = a.gouges[y];
    return gx.depth_nm != gy.depth_nm ? gx.depth_nm > gy.depth_nm : gx.line < gy.line;
  });
  if (k.size() > kSheetWorstGouges) k.resize(kSheetWorstGouges);
  return k;
}

}  // namespace dexmill
