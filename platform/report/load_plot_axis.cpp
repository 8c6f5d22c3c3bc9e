// The load plot's numbers (platform/report/load_plot.h): pixel columns of
// each series, nice tick steps, units and the text of tick labels. Numbers
// are printed from integers so that no locale can change a byte.
#include <algorithm>
#include <cmath>

#include "platform/report/load_plot.h"

namespace dexmill {
namespace load_plot_detail {

size_t utf8_next(const std::string& s, size_t i, uint32_t* cp) {
  const auto b = [&](size_t k) { return static_cast<uint8_t>(s[k]); };
  const uint8_t c = b(i);
  const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
  if (extra < 0 || i + static_cast<size_t>(extra) >= s.size()) {
    *cp = 0xfffd;
    return i + 1;
  }
  uint32_t v = extra == 0 ? c : extra == 1 ? c & 0x1fu : extra == 2 ? c & 0x0fu : c & 0x07u;
  for (int k = 1; k <= extra; ++k) {
    if ((b(i + k) & 0xc0) != 0x80) { *cp = 0xfffd; return i + 1; }
    v = v << 6 | (b(i + k) & 0x3fu);
  }
  // Overlong forms and surrogates are not text either.
  static const uint32_t kLeast[4] = {0, 0x80, 0x800, 0x10000};
  if (v < kLeast[extra] || (v >= 0xd800 && v <= 0xdfff) || v > 0x10ffff) { *cp = 0xfffd; return i + 1; }
  *cp = v;
  return i + 1 + static_cast<size_t>(extra);
}

int32_t text_cells(const std::string& s) {
  int32_t n = 0;
  uint32_t cp;
  for (size_t i = 0; i < s.size(); i = utf8_next(s, i, &cp)) ++n;
  return n;
}

int32_t text_width(const std::string& s, int32_t scale) {
  const int32_t n = text_cells(s);
  return n ? n * 6 * scale - scale : 0;
}

namespace {

double pow10i(int k) {
  double p = 1;
  for (int i = 0; i < k; ++i) p *= 10;
  return p;
}

// Large values of power and force read better in kW and kN, removal rates
// in cm³/min.
void scale_unit(const std::string& unit, double magnitude, double* factor, std::string* name) {
  *factor = 1;
  *name = unit;
  if (unit == "mm³/min" || unit == "mm3/min") {
    if (magnitude >= 1e4) *factor = 1e3, *name = "cm³/min";
    return;
  }
  if (unit != "W" && unit != "N" && unit != "Nm" && unit != "N·m") return;
  if (magnitude >= 1e6) *factor = 1e6, *name = "M" + unit;
  else if (magnitude >= 1e3) *factor = 1e3, *name = "k" + unit;
}

std::string clock_label(double t, bool hours) {
  const long long total = std::llround(std::clamp(t, 0.0, 1e12));
  const long long h = total / 3600, m = hours ? total / 60 % 60 : total / 60, s = total % 60;
  auto two = [](long long v) { return (v < 10 ? "0" : "") + std::to_string(v); };
  return hours ? std::to_string(h) + ":" + two(m) + ":" + two(s) : std::to_string(m) + ":" + two(s);
}

}  // namespace

double nice_step(double raw, bool nearest) {
  if (!(raw > 0) || !std::isfinite(raw)) return 1;
  double p = 1;
  for (int i = 0; i < 400 && p * 10 <= raw; ++i) p *= 10;
  for (int i = 0; i < 400 && p > raw; ++i) p /= 10;
  const double m = raw / p;
  if (nearest) return (m < 1.5 ? 1 : m < 3 ? 2 : m < 7 ? 5 : 10) * p;
  return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
}

int step_decimals(double step) {
  int d = 0;
  while (d < 9) {
    const double r = step * pow10i(d);
    if (std::fabs(r - std::round(r)) < 1e-6 * std::max(1.0, r)) break;
    ++d;
  }
  return d;
}

std::string format_fixed(double v, int decimals) {
  if (!std::isfinite(v) || std::fabs(v) > 1e15) return "?";
  decimals = std::clamp(decimals, 0, 9);
  const double scale = pow10i(decimals);
  const long long k = std::llround(v * scale);
  const unsigned long long a = k < 0 ? 0ull - static_cast<unsigned long long>(k) : static_cast<unsigned long long>(k);
  const unsigned long long unit = static_cast<unsigned long long>(scale);
  std::string out = k < 0 ? "-" : "";
  out += std::to_string(a / unit);
  if (decimals > 0) {
    std::string frac = std::to_string(a % unit);
    out += "." + std::string(static_cast<size_t>(decimals) - frac.size(), '0') + frac;
  }
  return out;
}

std::string format_compact(double v) {
  const double a = std::fabs(v);
  std::string s = format_fixed(v, a >= 100 ? 0 : a >= 10 ? 1 : a >= 1 ? 2 : 3);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

ValueAxis value_axis(double lo_v, double hi_v, int32_t ticks, const std::string& unit) {
  ValueAxis a;
  double hi = std::max(hi_v, 0.0) * 1.05, lo = std::min(lo_v, 0.0) * 1.05;
  if (!(hi - lo > 0) || !std::isfinite(hi - lo)) lo = 0, hi = 1;
  a.step = nice_step((hi - lo) / std::max(ticks, 1), true);
  a.hi = std::ceil(hi / a.step - 1e-9) * a.step;
  a.lo = std::floor(lo / a.step + 1e-9) * a.step;
  scale_unit(unit, std::max(std::fabs(a.hi), std::fabs(a.lo)), &a.factor, &a.unit);
  a.decimals = step_decimals(a.step / a.factor);
  return a;
}

std::string value_label(const ValueAxis& a, double v) {
  std::string s = format_fixed(v / a.factor, a.decimals);
  return s == "-0" ? "0" : s;
}

// Seconds up to two minutes, min:ss beyond, h:mm:ss from an hour; steps of
// a clock (15 s, 5 min, ...) once it shows one.
TimeAxis time_axis(double t_end, int32_t ticks) {
  TimeAxis a;
  a.end = t_end;
  a.clock = t_end > 120;
  a.hours = t_end >= 3600;
  a.title = a.hours ? "time [h:min:s]" : a.clock ? "time [min:s]" : "time [s]";
  if (!a.clock) {
    a.step = nice_step(t_end / std::max(ticks, 1), false);
    a.decimals = step_decimals(a.step);
    return a;
  }
  static const double kClockSteps[] = {10, 15, 30, 60, 120, 300, 600, 900, 1200, 1800, 3600, 7200, 10800, 21600, 43200};
  a.step = nice_step(t_end / std::max(ticks, 1) / 86400, false) * 86400;
  for (double s : kClockSteps) {
    if (t_end / s <= ticks) { a.step = s; break; }
  }
  return a;
}

std::string time_label(const TimeAxis& a, double t) {
  return a.clock ? clock_label(t, a.hours) : format_fixed(t, a.decimals);
}

namespace {

double series_value(const LoadPlotMove& m, int k) {
  return k == 0 ? m.load : k == 1 ? m.mrr_mm3_per_min : m.feed_mm_per_min;
}

void column_add(Column* c, double v, double w) {
  if (c->weight == 0) c->lo = c->hi = v;
  c->lo = std::min(c->lo, v);
  c->hi = std::max(c->hi, v);
  c->sum += v * w;
  c->weight += w;
}

}  // namespace

bool move_usable(const LoadPlotMove& m, double t_end) {
  const double t0 = m.time_s - (m.duration_s > 0 ? m.duration_s : 0);
  return std::isfinite(m.time_s) && std::isfinite(t0) && m.time_s >= 0 && t0 <= t_end && std::isfinite(m.load) &&
         std::isfinite(m.mrr_mm3_per_min) && std::isfinite(m.feed_mm_per_min);
}

bool series_range(const std::vector<LoadPlotMove>& moves, double t_end, double lo[3], double hi[3]) {
  bool any = false;
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = 0;
  for (const LoadPlotMove& m : moves) {
    if (!move_usable(m, t_end)) continue;
    for (int k = 0; k < 3; ++k) {
      const double v = series_value(m, k);
      lo[k] = any ? std::min(lo[k], v) : v;
      hi[k] = any ? std::max(hi[k], v) : v;
    }
    any = true;
  }
  return any;
}

// Each move adds its value to every column its time interval overlaps,
// weighted by the overlap, so a column's mean is the step function's mean
// over the part of the column that has moves.
void fill_columns(const std::vector<LoadPlotMove>& moves, double t_end, int32_t n, std::vector<Column> cols[3]) {
  for (int k = 0; k < 3; ++k) cols[k].assign(static_cast<size_t>(std::max(n, 0)), Column{});
  if (n <= 0 || !(t_end > 0)) return;
  const double per = n / t_end;  // columns per second
  for (const LoadPlotMove& m : moves) {
    if (!move_usable(m, t_end)) continue;
    const double t1 = m.time_s, dur = m.duration_s > 0 ? m.duration_s : 0, t0 = t1 - dur;
    const double c0d = std::floor(t0 * per), c1d = dur > 0 ? std::ceil(t1 * per) - 1 : c0d;
    const int32_t c0 = static_cast<int32_t>(std::clamp(c0d, 0.0, n - 1.0));
    const int32_t c1 = static_cast<int32_t>(std::clamp(std::max(c1d, c0d), 0.0, n - 1.0));
    for (int32_t c = c0; c <= c1; ++c) {
      const double w = std::max(std::min(t1, (c + 1) / per) - std::max(t0, c / per), 1e-6 / per);
      for (int k = 0; k < 3; ++k) column_add(&cols[k][static_cast<size_t>(c)], series_value(m, k), w);
    }
  }
}

}  // namespace load_plot_detail
}  // namespace dexmill
