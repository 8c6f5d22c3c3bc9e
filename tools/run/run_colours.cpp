// The colour modes tool, slope, thin and engagement of `dexmill run`; see run_colours.h.
#include "tools/run/run_colours.h"

#include "display/view/colour_legend.h"

namespace dexmill {
namespace cli {
namespace {

// A tool number's tool for the legend (the run's library).
bool library_tool(const void* ctx, int32_t number, Tool* out) {
  return static_cast<const ToolLibrary*>(ctx)->tool(number, out);
}

// The tool legend over the provenance's tools as they are now.
void tool_legend(RunColours* c) {
  ToolLegendNames names;
  names.tool = library_tool;
  names.ctx = c->lib;
  names.initial = c->initial;
  c->legend_tools = c->prov->ntools;
  colour_legend_tool(&c->legend, c->prov->tool, c->prov->ntools, names);
}

}  // namespace

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
      colour_legend_slope(&c->legend);
      break;
    case ViewOptions::Color::kEngagement:
      engage_colours_init(&c->engagement, engage_cls, c->luts.data());
      colour_legend_engagement(&c->legend, by_limits);
      break;
    default:  // thin: thinnest on the left
      thin_colours_init(&c->thin, g, o.view.thin_nm, c->cls.data(), c->luts.data());
      colour_legend_thin(&c->legend, o.view.thin_nm);
      break;
  }
}

void run_colours_record(RunColours* c) {
  if (c->prov && c->prov->ntools != c->legend_tools) tool_legend(c);
}

}  // namespace cli
}  // namespace dexmill
