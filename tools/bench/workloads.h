// Benchmark workloads: the paper's three Table 2 jobs and the scale-up jobs,
// as polyline programs over a block of stock (hosted code).
#ifndef DEXMILL_TOOLS_BENCH_WORKLOADS_H
#define DEXMILL_TOOLS_BENCH_WORKLOADS_H

#include <cstdint>
#include <vector>

#include "core/grid/grid.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace dexmill {

struct Workload {
  const char* name;
  GridGeometry geo;              // grid over the stock (border dexels are holes)
  int64_t stock_top_nm;          // z of the stock's top
  Tool tool;
  std::vector<PointNm> path;     // the tool tip's polyline; path[0] is the start
  int64_t paper_instances;       // Table 2's count, 0 when not a paper job
  // scale-*: path[pocket_start] begins the spiral pocket (after the relief
  // finish and a rapid); the bench also times the two phases apart. 0: one phase.
  size_t pocket_start = 0;
};

// "paper-w1", "paper-w2", "paper-w3", "scale-1k", "scale-4k"; false if unknown.
bool make_workload(const char* name, Workload* w);

}  // namespace dexmill

#endif
