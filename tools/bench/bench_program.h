// A G-code program made ready for the benchmarks that run whole programs
// (bench_api.cpp, bench_worst.cpp): its text, the engine's job with the
// stock and grid `dexmill run` would choose for it (the scan's extents, a
// 32nd of the tool), the same as an API job, and the time of its scan.
#ifndef DEXMILL_TOOLS_BENCH_BENCH_PROGRAM_H
#define DEXMILL_TOOLS_BENCH_BENCH_PROGRAM_H

#include <stddef.h>
#include <stdint.h>

#include <string>

#include "core/sim/job.h"
#include "display/api/dexmill.h"

namespace dexmill {

// The pieces the benchmarks feed a program's text in, through the engine
// and the API alike.
constexpr size_t kBenchPieceBytes = 4096;

struct BenchProgram {
  std::string name, text, tool_spec;
  SimJob job;           // the engine's job, as `dexmill run` would plan it
  dm_job api;           // the same for the API
  uint32_t lines = 0;
  double scan_s = 0;    // the interpretation alone (fastest of a few)
  bool ok = false;
};

// Plans p (its name, text and tool_spec set) for the engine and the API;
// false with a line on standard error naming `bench`.
bool bench_program_plan(const char* bench, BenchProgram* p);

// The program through the engine alone (core/sim), fed in kBenchPieceBytes pieces
// and stepped a line at a time; its wall time in seconds (-1: no engine).
double bench_engine_run(const BenchProgram& p);

}  // namespace dexmill

#endif
