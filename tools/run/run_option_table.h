// The option table of `dexmill run` (tools/cli/option_table.h): its sections,
// each over one part of RunOptions (run_options.h), and the table itself,
// which `check --simulate`, `optimize` and `zig` include whole.
#ifndef DEXMILL_TOOLS_RUN_RUN_OPTION_TABLE_H
#define DEXMILL_TOOLS_RUN_RUN_OPTION_TABLE_H

#include "tools/cli/option_table.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// The sections (tools/run/run_job_options.cpp, run_view_options.cpp).
OptionList<JobOptions> run_job_options();      // what is cut
OptionList<JobOptions> run_design_options();   // the design part
OptionList<JobOptions> run_check_options();    // safety checks and the verdict
OptionList<OutputOptions> run_output_options();
OptionList<ViewOptions> run_view_options();
OptionList<ViewOptions> run_live_options();

const OptionTable<RunOptions>& run_option_table();

// run's operand: the program FILE (- for standard input); index as
// OptionTable::operand's.
int run_operand(RunOptions* o, const char* arg, int index);

// Parses argv[1..argc) by the table and finishes the options
// (finish_run_options). kExitOk (*help set for --help, nothing else
// done), or the usage error printed and kExitUsage.
int parse_run_options(int argc, char** argv, RunOptions* o, bool* help);

}  // namespace cli
}  // namespace dexmill

#endif
