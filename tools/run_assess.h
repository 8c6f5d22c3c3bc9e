// The design part of `dexmill run --design` (paper §2.5): read before the
// cut (a bad file costs no simulation), assessed after it into the report.
#ifndef DEXMILL_TOOLS_RUN_ASSESS_H
#define DEXMILL_TOOLS_RUN_ASSESS_H

#include <cstdint>
#include <vector>

#include "core/config.h"
#include "core/design/design.h"
#include "display/surface_colours.h"
#include "platform/report_json.h"
#include "tools/run_render.h"
#include "tools/run_options.h"
#include "tools/run_stock.h"

namespace dexmill {
namespace cli {

struct RunDesign {
  std::vector<int32_t> tops;  // the design grid's memory
  DesignGrid grid;
  ReportAssessment report;
  AssessOptions opt;          // tolerance, boxes and the stock's columns
  // --color error: the bands of every dexel, their ramps, and the legend.
  const DexelGrid<height_t>* cut = nullptr;
  std::vector<uint8_t> bands;
  std::vector<uint32_t> luts;
  SurfaceColours colours;
  RenderOutput::Legend legend;
};

// Reads o.design onto the grid of `plan`. Returns kExitOk, or the exit code
// after printing the error (input errors: the file's own message).
int load_design(const RunOptions& o, const GridPlan& plan, RunDesign* d);

// The error view (paper §2.5.1, figure 10) of grid g against the design:
// d->colours and d->legend for the outputs to draw with.
void error_view_init(const DexelGrid<height_t>& g, RunDesign* d);

// Compares the cut with the design into d->report.
void assess_design(const DexelGrid<height_t>& g, RunDesign* d);

}  // namespace cli
}  // namespace dexmill

#endif
