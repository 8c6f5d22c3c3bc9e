// `dexmill run --demo NAME` (paper §3, its loop of design, program, cut and
// assessment; tools/README.md "The paper's loop"): one of the paper's
// workpieces end to end: its design part (core/design/builtin.h), a
// zig-milling program generated from it (tools/run/zig_job.h: the paper's
// stripes one dexel apart, lifted returns, its ball), cut from its material,
// drawn in the material's colours and in the error view, and assessed, all
// in out/NAME/. `--demo list` names them.
#ifndef DEXMILL_TOOLS_RUN_RUN_DEMO_H
#define DEXMILL_TOOLS_RUN_RUN_DEMO_H

#include "core/sim/stock_plan.h"
#include "platform/input/file_guard.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

int run_demo(RunOptions o, FileGuard* guard);

// The built-in demo of `dexmill run` with no FILE (tools/run/demo_program.h):
// its program for kDemoProgramPath (JobOptions::made_program) and what the
// options leave out (out/final.ppm, its part's error view out/error.ppm,
// frames in out/frames, its material drawn in its colours). kExitOk or an
// exit code (printed).
constexpr const char* kDemoProgramPath = "out/demo.ngc";
// Its name for `--demo` (what `make run` asks for: its standard input may
// be no terminal), and its line in `--demo list`.
constexpr const char* kBuiltinDemoName = "pocket";
int demo_defaults(RunOptions* o);
// The block it is written for.
StockBox demo_stock_box();

}  // namespace cli
}  // namespace dexmill

#endif
