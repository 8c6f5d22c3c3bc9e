// The input guard (platform/input/file_guard.h) for the subcommands: the files
// their options name registered as inputs (one place: a new input file is
// one line here), and a verdict as an exit status with its message
// printed.
#ifndef DEXMILL_TOOLS_RUN_GUARD_INPUTS_H
#define DEXMILL_TOOLS_RUN_GUARD_INPUTS_H

#include <string>

#include "platform/input/file_guard.h"
#include "tools/run/read_options.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// kExitOk; kExitUsage for a clash, kExitIo for an output that cannot be
// written, each with the guard's message printed.
int guard_status(const FileGuard& guard, FileGuard::Verdict v);

// The program (`path` and `check` read it, and --tools) as inputs.
int guard_read_inputs(const std::string& program, const ReadOptions& read, FileGuard* guard);

// A job's files (tools/run/run_options.h JobOptions): `program` (the path the
// passes read), --tools, a --material that is a file, a --design that is
// a file, --stock FILE.stl.
int guard_job_inputs(const JobOptions& job, const std::string& program, FileGuard* guard);

}  // namespace cli
}  // namespace dexmill

#endif
