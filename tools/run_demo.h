// `dexmill run --demo NAME` (issue 23, paper §3): one of the paper's
// workpieces end to end: its design part (core/design/builtin.h), a
// zig-milling program generated from it (tools/zig_job.h: the paper's
// stripes one dexel apart, lifted returns, its ball), cut from its material,
// drawn in the material's colours and in the error view, and assessed, all
// in out/NAME/. `--demo list` names them.
#ifndef DEXMILL_TOOLS_RUN_DEMO_H
#define DEXMILL_TOOLS_RUN_DEMO_H

#include "tools/run_options.h"

namespace dexmill {
namespace cli {

int run_demo(RunOptions o);

}  // namespace cli
}  // namespace dexmill

#endif
