// `dexmill run`: the whole job. Two passes over the program:
//   scan  the interpreter alone (core/motion/summary.h): motion counts and
//         boxes, the time estimate, the tools it uses; every G-code error
//         and warning is reported here, and a program with an error is not
//         cut (exit 1; the report is still written);
//   cut   the interpreter again into the Mill (core/cut/mill.h) on a grid sized
//         by tools/run_stock.h, with frames, the live view and the progress
//         bar fed as it goes;
// then the outputs: --image, --heightmap, --stl, --report, each written
// completely or not at all (exit 3 when one cannot be written).
#ifndef DEXMILL_TOOLS_RUN_JOB_H
#define DEXMILL_TOOLS_RUN_JOB_H

#include "tools/run_options.h"

namespace dexmill {
namespace cli {

// Runs the job; returns the exit status (CLI.md).
int run_job(RunOptions o);

}  // namespace cli
}  // namespace dexmill

#endif
