// The safety checks of `dexmill run` (core/safety/safety.h; the simulation
// runs them, core/sim/simulation.h): which are on, the warnings and the
// report (their marks in the frames: display/api/run_marks.h).
#ifndef DEXMILL_TOOLS_RUN_RUN_SAFETY_H
#define DEXMILL_TOOLS_RUN_RUN_SAFETY_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/safety/safety.h"
#include "core/config.h"
#include "core/grid/grid.h"
#include "core/sim/job.h"
#include "platform/report/run_report.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// The checks the options ask for (fixtures pointing into c's vector).
SimChecks safety_checks(const SafetyChoice& c);

// Prints every kept event as FILE:LINE:1: warning: ... (at the end: a
// line's event grows while its end cap is cut), and how many were not kept.
void safety_print(const SafetyWatch& w, const std::string& file, const DexelGrid<height_t>& g);

// Into the report.
void safety_to_report(const SafetyWatch& w, RunReport* rep);

}  // namespace cli
}  // namespace dexmill

#endif
