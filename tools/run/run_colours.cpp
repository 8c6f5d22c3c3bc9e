// The colour modes tool, slope, thin and engagement of `dexmill run`; see run_colours.h.
#include "tools/run/run_colours.h"

#include <algorithm>

#include "core/tool/spec.h"
#include "platform/report/report_json.h"

namespace dexmill {
namespace cli {
namespace {

// mm with at most three decimals and no trailing zeros ("0.5", "1").
std::string short_mm(int64_t nm) {
  std::string s = nm_to_mm_text(nm, 3);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

// The tool legend: uncut, then a swatch for each colour in use, named by
// its tools ("T1 FLAT 6"; with more tools than colours, "T1/T8").
void tool_legend(RunColours* c) {
  RenderOutput::Legend& l = c->legend;
  const ToolProvenance<height_t>& t = *c->prov;
  c->legend_tools = t.ntools;
  l.named = true;
  l.n = 1 + min_of(t.ntools, kToolColourSlots);
  l.colour[0] = kToolUncutColour;
  l.labels[0] = "uncut";
  for (int32_t slot = 0; slot + 1 < l.n; ++slot) {
    std::string& name = l.labels[slot + 1];
    name.clear();
    l.colour[slot + 1] = kToolPalette[slot];
    for (int32_t k = slot; k < t.ntools; k += kToolColourSlots)
      name += (name.empty() ? "" : "/") + (t.tool[k] == kInitialToolNumber ? std::string("default") : "T" + std::to_string(t.tool[k]));
    if (slot + kToolColourSlots < t.ntools) continue;  // shared: the numbers alone
    Tool tool = c->initial;
    if (t.tool[slot] == kInitialToolNumber) name = tool_short_name(tool);  // no T number: its shape alone
    else if (c->lib->tool(t.tool[slot], &tool)) name += " " + tool_short_name(tool);
  }
}

}  // namespace

std::string tool_short_name(const Tool& t) {
  char spec[kToolSpecTextMax];
  tool_spec_format(t, spec, sizeof spec);
  std::string s(spec);
  s.erase(std::min(s.find(','), s.size()));
  const size_t second = s.find(':', s.find(':') + 1);
  if (second != std::string::npos) s.erase(second);  // bull's corner, a V-bit's angle
  for (char& ch : s)
    if (ch == ':') ch = ' ';
  return s;
}

const SurfaceColours* RunColours::colours() const {
  switch (mode) {
    case ViewOptions::Color::kTool: return &tool;
    case ViewOptions::Color::kSlope: return &slope.colours;
    case ViewOptions::Color::kThin: return &thin.colours;
    case ViewOptions::Color::kEngagement: return &engagement;
    default: return nullptr;
  }
}

void run_colours_start(RunColours* c, const RunOptions& o, const DexelGrid<height_t>& g, const ToolLibrary* lib,
                       const ToolProvenance<height_t>* prov, uint8_t* engage_cls, bool by_limits) {
  c->mode = o.view.color;
  if (!c->colours()) return;
  const size_t cells = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  c->cls.assign(cells, 0);
  c->luts.assign(static_cast<size_t>(kMaxColourClasses) * kShadeLevels, 0);
  RenderOutput::Legend& l = c->legend;
  switch (c->mode) {
    case ViewOptions::Color::kTool:
      c->lib = lib;
      c->initial = o.job.tool;
      c->prov = prov;
      tool_colours_init(&c->tool, *prov, c->luts.data());
      tool_legend(c);
      break;
    case ViewOptions::Color::kSlope:
      slope_colours_init(&c->slope, g, c->cls.data(), c->luts.data());
      l.n = kSlopeBands;
      for (int32_t k = 0; k < kSlopeBands; ++k) l.colour[k] = kSlopeBandColour[k];
      for (int32_t k = 0; k + 1 < kSlopeBands; ++k) l.labels[k] = std::to_string(kSlopeLimitDeg[k]);
      l.title = "DEG";
      break;
    case ViewOptions::Color::kEngagement:
      engage_colours_init(&c->engagement, engage_cls, c->luts.data());
      l.n = kEngageBands;
      for (int32_t k = 0; k < kEngageBands; ++k) l.colour[k] = kEngageBandColour[k];
      for (int32_t k = 0; k + 1 < kEngageBands; ++k)
        l.labels[k] = std::to_string(by_limits ? kEngageBandLimitPct[k] : kEngageBandAngleDeg[k]);
      l.title = by_limits ? "% OF LOAD LIMIT" : "DEG ENGAGED";
      break;
    default:  // thin: thinnest on the left
      thin_colours_init(&c->thin, g, o.view.thin_nm, c->cls.data(), c->luts.data());
      l.n = kThinBands;
      l.colour[0] = kThinBandColour[kThinUnderHalf];
      l.colour[1] = kThinBandColour[kThinUnder];
      l.colour[2] = kThinBandColour[kThinNot];
      l.labels[0] = short_mm(o.view.thin_nm / 2);
      l.labels[1] = short_mm(o.view.thin_nm);
      l.title = "MM THICK";
      break;
  }
}

void run_colours_record(RunColours* c) {
  if (c->prov && c->prov->ntools != c->legend_tools) tool_legend(c);
}

}  // namespace cli
}  // namespace dexmill
