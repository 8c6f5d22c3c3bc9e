// `--material PRESET|FILE` of `dexmill run` (tools/README.md, "Materials"): the stock's
// composition, for the process rules the simulation runs on the cut
// (core/safety/material_limits.h), their warnings and the report's `materials`.
#ifndef DEXMILL_TOOLS_RUN_RUN_MATERIAL_H
#define DEXMILL_TOOLS_RUN_RUN_MATERIAL_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/safety/material_limits.h"
#include "core/config.h"
#include "core/grid/grid.h"
#include "core/material/material.h"
#include "platform/report/run_report.h"

namespace dexmill {
namespace cli {

struct RunMaterial {
  std::unique_ptr<StockComposition> comp;  // a few KB
  std::string source;                      // "preset NAME" or the file
};

// Builds the composition of `what` (a preset's name, else a file) over the
// stock box. Returns an exit status (kExitOk; kExitUsage for neither a
// preset nor a file; the file's read or input error), with the message
// printed.
int material_start(RunMaterial* m, const std::string& what, const BoxNm& stock);

// Prints every kept violation of the watch as FILE:LINE:1: warning: ...,
// the same message on several lines once with its count and last line
// (platform/input/warning_fold.h), and how many were not kept.
void material_print(const RunMaterial& m, const ProcessWatch& w, const std::string& file);

// Into the report.
void material_to_report(const RunMaterial& m, const ProcessWatch& w, const DexelGrid<height_t>& g, RunReport* rep);

// The warning's message for a violation.
std::string process_violation_text(const ProcessViolation& v, const StockComposition& c);

}  // namespace cli
}  // namespace dexmill

#endif
