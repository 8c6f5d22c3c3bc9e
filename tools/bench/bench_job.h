// A benchmark's job: a workload (tools/bench/workloads.h) over its grid, with the
// stock kept to reset to, the cutter's dexel set and its sweep tool. Shared
// by the cutting benchmarks and the Table 2 comparison.
#ifndef DEXMILL_TOOLS_BENCH_BENCH_JOB_H
#define DEXMILL_TOOLS_BENCH_BENCH_JOB_H

#include <vector>

#include "core/config.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "tools/bench/workloads.h"

namespace dexmill {

struct Job {
  Workload w;
  std::vector<height_t> stock, top, bottom;
  DexelGrid<height_t> g;
  std::vector<int32_t> cutter_words;
  CutterDexels cutter;
  SweepTool sweep_tool;
};

// The job of workload `name` for benchmark `bench`; says so when it cannot
// be set up.
bool setup(const char* bench, const char* name, Job* j);

// Moves from .. to - 1 of the path (move k ends at path[k]) swept as one
// chain, as core/cut/mill.h cuts a polyline.
void sweep_moves(Job* j, size_t from, size_t to, CutStats* st);

// Back to the uncut stock, nothing dirty.
void reset(Job* j);

}  // namespace dexmill

#endif
