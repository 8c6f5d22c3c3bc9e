// `dexmill run --machine FILE` (tools/CLI.md): the machine's file read
// (platform/format/machine_file.h) before anything else of the run, what it
// gives applied to the options that do not say (the tool table, the
// subroutine path, a LinuxCNC machine's units, the rapid rate and the
// acceleration, the work offsets; an option given wins), each default said
// in the summary and the report; then the travel check's findings printed
// at their lines and written to the report.
#ifndef DEXMILL_TOOLS_RUN_RUN_MACHINE_H
#define DEXMILL_TOOLS_RUN_RUN_MACHINE_H

#include <string>
#include <vector>

#include "core/safety/travel_watch.h"
#include "platform/format/machine_file.h"
#include "platform/report/run_report.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

struct RunMachine {
  MachineFile file;
  std::vector<std::string> said;  // "tool table /x/tools.tbl (the machine's)", "rapid 5000 mm/min (--rapid)"
};

// Reads o->job.machine_file into *m and applies its defaults to *o; an exit
// code (the file's errors printed).
int run_machine_load(RunOptions* o, RunMachine* m);

// The travel findings: one warning a line ("FILE:LINE:1: warning: X 12.300
// mm past the machine's maximum ..."), folded, and the report's keys.
void travel_print(const TravelWatch& w, const std::string& file);
void machine_to_report(const RunMachine& m, const std::string& path, const TravelWatch* w, RunReport* rep);

}  // namespace cli
}  // namespace dexmill

#endif
