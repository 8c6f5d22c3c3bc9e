// The design part of `dexmill run --design` (paper §2.5): read before the
// cut (a bad file costs no simulation), assessed after it into the report.
#ifndef DEXMILL_TOOLS_RUN_ASSESS_H
#define DEXMILL_TOOLS_RUN_ASSESS_H

#include <cstdint>
#include <vector>

#include "core/config.h"
#include "core/design/design.h"
#include "platform/report_json.h"
#include "tools/run_options.h"
#include "tools/run_stock.h"

namespace dexmill {
namespace cli {

struct RunDesign {
  std::vector<int32_t> tops;  // the design grid's memory
  DesignGrid grid;
  ReportAssessment report;
};

// Reads o.design onto the grid of `plan`. Returns kExitOk, or the exit code
// after printing the error (input errors: the file's own message).
int load_design(const RunOptions& o, const GridPlan& plan, RunDesign* d);

// Compares the cut with the design into d->report.
// Only the stock's columns count (not the grid's ring of holes).
void assess_design(const RunOptions& o, const GridPlan& plan, const DexelGrid<height_t>& g, RunDesign* d);

}  // namespace cli
}  // namespace dexmill

#endif
