// The colour modes `--color tool|slope|thin|engagement` of `dexmill run` (tools/README.md):
// each mode's memory, its classes (display/colour/tool_colours.h,
// slope_colours.h, thin_colours.h, engage_colours.h) and its legend. `material` and `error`
// are set up beside them in run_job (run_assess.h, display/colour/material_colours.h).
#ifndef DEXMILL_TOOLS_RUN_RUN_COLOURS_H
#define DEXMILL_TOOLS_RUN_RUN_COLOURS_H

#include <cstdint>
#include <vector>

#include "core/config.h"
#include "core/cut/mill.h"
#include "core/sim/provenance.h"
#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "display/colour/engage_colours.h"
#include "display/colour/slope_colours.h"
#include "display/colour/thin_colours.h"
#include "display/colour/tool_colours.h"
#include "display/view/colour_legend.h"
#include "tools/run/run_options.h"
#include "tools/run/run_render.h"

namespace dexmill {
namespace cli {

// The tool in the spindle before any M6 (the --tool default): listed by its
// shape alone.
constexpr int32_t kInitialToolNumber = kLegendInitialTool;

struct RunColours {
  ViewOptions::Color mode = ViewOptions::Color::kPlain;
  std::vector<uint8_t> cls;      // a class a dexel (slope, thin; tool: the simulation's provenance)
  std::vector<uint32_t> luts;    // the renderer's ramps, kMaxColourClasses of them
  const ToolProvenance<height_t>* prov = nullptr;  // tool: which tool cut each column
  int32_t legend_tools = 0;      // tool: prov->ntools when the legend was made
  SurfaceColours tool;
  SurfaceColours engagement;
  SlopeColours<height_t> slope;
  ThinColours<height_t> thin;
  ViewLegend legend;             // display/view/colour_legend.h
  const ToolLibrary* lib = nullptr;  // tool: names the tools in the legend
  Tool initial;                      // tool: the one before any M6

  // The mode's classes for the renderer; null for the modes set up elsewhere.
  const SurfaceColours* colours() const;
};

// Sets up o.view.color's mode over g (as stocked) when it is tool, slope,
// thin or engagement; nothing otherwise (tool: over the simulation's
// provenance, prov; engagement: over its load bands, engage_cls, named by
// the limits or by the angle).
// c must stay where it is while outputs use it.
void run_colours_start(RunColours* c, const RunOptions& o, const DexelGrid<height_t>& g, const ToolLibrary* lib,
                       const ToolProvenance<height_t>* prov, uint8_t* engage_cls, bool by_limits);

// The tool mode after every record: the legend names a tool the record
// listed for the first time.
void run_colours_record(RunColours* c);

}  // namespace cli
}  // namespace dexmill

#endif
