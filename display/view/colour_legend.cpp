// The colour modes' legends; see colour_legend.h.
#include "display/view/colour_legend.h"

#include <string.h>

#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "display/colour/engage_colours.h"
#include "display/colour/error_colours.h"
#include "display/colour/slope_colours.h"
#include "display/colour/thin_colours.h"
#include "display/colour/tool_colours.h"

namespace dexmill {
namespace {

// A label being written: text appended, cut at the label's size.
class Label {
 public:
  explicit Label(char (&to)[kViewLabelBytes]) : s_(to) { s_[0] = 0; }
  Label& add(const char* t) {
    while (*t && n_ + 1 < kViewLabelBytes) s_[n_++] = *t++;
    s_[n_] = 0;
    return *this;
  }
  Label& add_uint(uint64_t v) {
    char digits[24];
    int k = 0;
    do { digits[k++] = static_cast<char>('0' + v % 10); v /= 10; } while (v);
    char one[2] = {0, 0};
    while (k > 0) {
      one[0] = digits[--k];
      add(one);
    }
    return *this;
  }
  Label& add_int(int64_t v) {
    if (v < 0) add("-");
    return add_uint(abs_u64(v));
  }
  // nm as mm with `decimals` places, rounded to nearest ("-0.20", "1.000").
  Label& add_mm(int64_t nm, int decimals) {
    int64_t scale = 1;
    for (int k = decimals; k < 6; ++k) scale *= 10;
    const int64_t v = div_round(nm, scale);
    uint64_t p = 1;
    for (int k = 0; k < decimals; ++k) p *= 10;
    const uint64_t u = abs_u64(v);
    if (v < 0) add("-");
    add_uint(u / p);
    if (!decimals) return *this;
    add(".");
    for (uint64_t q = p / 10; q > 0; q /= 10) add_uint(u % p / q % 10);
    return *this;
  }
  // nm as mm with at most three decimals and no trailing zeros ("0.5", "1").
  Label& add_short_mm(int64_t nm) {
    const size_t at = n_;
    add_mm(nm, 3);
    while (n_ > at && s_[n_ - 1] == '0') s_[--n_] = 0;
    if (n_ > at && s_[n_ - 1] == '.') s_[--n_] = 0;
    return *this;
  }
  bool empty() const { return n_ == 0; }

 private:
  char* s_;
  size_t n_ = 0;
};

}  // namespace

void colour_legend_clear(ViewLegend* l) { memset(static_cast<void*>(l), 0, sizeof *l); }

void colour_legend_slope(ViewLegend* l) {
  colour_legend_clear(l);
  l->n = kSlopeBands;
  for (int32_t k = 0; k < kSlopeBands; ++k) l->colour[k] = kSlopeBandColour[k];
  for (int32_t k = 0; k + 1 < kSlopeBands; ++k) Label(l->labels[k]).add_int(kSlopeLimitDeg[k]);
  Label(l->title).add("DEG");
}

void colour_legend_thin(ViewLegend* l, int64_t thin_nm) {
  colour_legend_clear(l);
  l->n = kThinBands;
  l->colour[0] = kThinBandColour[kThinUnderHalf];
  l->colour[1] = kThinBandColour[kThinUnder];
  l->colour[2] = kThinBandColour[kThinNot];
  Label(l->labels[0]).add_short_mm(thin_nm / 2);
  Label(l->labels[1]).add_short_mm(thin_nm);
  Label(l->title).add("MM THICK");
}

void colour_legend_engagement(ViewLegend* l, bool by_limits) {
  colour_legend_clear(l);
  l->n = kEngageBands;
  for (int32_t k = 0; k < kEngageBands; ++k) l->colour[k] = kEngageBandColour[k];
  for (int32_t k = 0; k + 1 < kEngageBands; ++k)
    Label(l->labels[k]).add_int(by_limits ? kEngageBandLimitPct[k] : kEngageBandAngleDeg[k]);
  Label(l->title).add(by_limits ? "% OF LOAD LIMIT" : "DEG ENGAGED");
}

void colour_legend_error(ViewLegend* l, int64_t tol_nm) {
  colour_legend_clear(l);
  const uint8_t order[7] = {kBandGouge3, kBandGouge2, kBandGouge1, kBandWithin, kBandLeft1, kBandLeft2, kBandLeft3};
  l->n = 7;
  for (int k = 0; k < 7; ++k) l->colour[k] = kErrorBandColour[order[k]];
  const int64_t t = tol_nm;
  const int64_t limits[6] = {-kBandStep3 * t, -kBandStep2 * t, -t, t, kBandStep2 * t, kBandStep3 * t};
  for (int k = 0; k < 6; ++k) Label(l->labels[k]).add(limits[k] > 0 ? "+" : "").add_mm(limits[k], 2);
  Label(l->title).add("MM");
  Label(l->low_caption).add("gouge (cut below the design)");
  Label(l->high_caption).add("material left");
}

void colour_legend_tool(ViewLegend* l, const int32_t* tools, int32_t ntools, const ToolLegendNames& names) {
  colour_legend_clear(l);
  l->named = true;
  l->n = 1 + min_of(ntools, kToolColourSlots);
  l->colour[0] = kToolUncutColour;
  Label(l->labels[0]).add("uncut");
  char shape[kToolSpecTextMax];
  for (int32_t slot = 0; slot + 1 < l->n; ++slot) {
    Label name(l->labels[slot + 1]);
    l->colour[slot + 1] = kToolPalette[slot];
    for (int32_t k = slot; k < ntools; k += kToolColourSlots) {
      if (!name.empty()) name.add("/");
      if (tools[k] == kLegendInitialTool) name.add("default");
      else name.add("T").add_int(tools[k]);
    }
    if (slot + kToolColourSlots < ntools) continue;  // shared: the numbers alone
    Tool tool = names.initial;
    if (tools[slot] == kLegendInitialTool) {  // no T number: its shape alone
      tool_short_name(tool, shape, sizeof shape);
      Label(l->labels[slot + 1]).add(shape);
    } else if (names.tool && names.tool(names.ctx, tools[slot], &tool)) {
      tool_short_name(tool, shape, sizeof shape);
      name.add(" ").add(shape);
    }
  }
}

size_t tool_short_name(const Tool& t, char* buf, size_t n) {
  if (n == 0) return 0;
  char spec[kToolSpecTextMax];
  tool_spec_format(t, spec, sizeof spec);
  // Up to the first option, and the kind and diameter alone (a bull's
  // corner, a V-bit's angle dropped): "kind diameter".
  size_t k = 0;
  int colons = 0;
  for (const char* c = spec; *c && *c != ',' && k + 1 < n; ++c) {
    if (*c == ':' && ++colons == 2) break;
    buf[k++] = *c == ':' ? ' ' : *c;
  }
  buf[k] = 0;
  return k;
}

}  // namespace dexmill
