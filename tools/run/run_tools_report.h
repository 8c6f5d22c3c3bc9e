// The tools of a run as the user and the report see them (the scan's list,
// core/sim/scan.h, by the run's tool choice, core/sim/tool_choice.h): each
// with its source in the report's tool.used; a note for each tool a comment
// of the program gave; one warning naming the tools that cut with the
// default, a guess; a warning for comments that disagreed.
#ifndef DEXMILL_TOOLS_RUN_RUN_TOOLS_REPORT_H
#define DEXMILL_TOOLS_RUN_RUN_TOOLS_REPORT_H

#include <string>

#include "core/sim/scan.h"
#include "core/sim/tool_choice.h"
#include "platform/report/run_report.h"
#include "tools/run/run_scan.h"

namespace dexmill {
namespace cli {

void report_tools(const ProgramScan& s, const ToolChoice& c, const std::string& file, RunMessages* msgs,
                  RunReport* rep);

}  // namespace cli
}  // namespace dexmill

#endif
