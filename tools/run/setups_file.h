// --setups FILE: a job of several programs and setups written down, one
// line a program, for jobs longer than a command line:
//
//   # side one, then the part turned over about X against the same stops
//   side-1.ngc  tools=mill.tbl  design=part.stl
//   side-2.ngc  setup=flip-x  g54=0,0,-2.5  fixture=-5,0,0,0,40,10
//
// The first word is the program; then key=value words: setup= (as
// --setup: flip-x, flip-y, rotate-90|180|270, offset=X,Y,Z, joined by
// '+'), tools= (a tool table), design=, design-offset=, design-z= (as the
// options), fixture= (repeatable: this setup's clamps, in place of
// --fixture's), table=, and g54= ... g59.3= (X,Y,Z mm: where that
// coordinate system's origin is for this setup, as a controller's
// parameter file holds it). A value may be "quoted" to hold spaces; '#'
// starts a comment. Relative paths are the file's folder's. The command
// line's options hold for every program; a line's replace them for its
// program only. Errors are FILE:LINE:COL.
#ifndef DEXMILL_TOOLS_RUN_SETUPS_FILE_H
#define DEXMILL_TOOLS_RUN_SETUPS_FILE_H

#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// Reads o->job.setups_file into the job's programs (file, chain), setups
// (setups, setup_texts, setup_program) and steps, each value checked as
// its option would be. An exit status (the error printed).
int read_setups_file(RunOptions* o);

// Program k's step over its options (before its run).
int apply_step(const JobOptions::Step& step, RunOptions* one);

}  // namespace cli
}  // namespace dexmill

#endif
