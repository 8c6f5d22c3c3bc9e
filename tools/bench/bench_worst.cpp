// Worst cases of a whole program through the engine (core/sim), each a
// program the bench writes, run as `dexmill run` would plan it:
//
//   worst-zero-moves  10^6 feeds of no length at one point after a plunge
//                     (a post that repeats its points): target under 1 s
//   worst-g83         one G83 line of 999,999 pecks (Q 0.000011 mm over
//                     10.999989 mm; the interpreter's limit is 10^6):
//                     target under 5 s
//
// seconds is the fastest of the runs (interpretation, cut and all);
// scan_s the interpretation alone. The tool is flat:6, or
// $DEXMILL_BENCH_TOOL.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tools/bench/bench.h"
#include "tools/bench/bench_program.h"

namespace dexmill {
namespace {

std::string zero_moves_program() {
  std::string s = "G21 G90 G17\nG0 X0 Y0 Z5\nM3 S10000\nG1 Z-1 F500\n";
  s.reserve(s.size() + 1000000 * 13 + 8);
  for (int k = 0; k < 1000000; ++k) s += "G1 X0 Y0 Z-1\n";
  return s + "M30\n";
}

std::string g83_program() {
  return "G21 G90 G17\nG0 X0 Y0 Z5\nM3 S10000\nG98 G83 X0 Y0 Z-10.999989 R0 Q0.000011 F300\nG80\nG0 Z5\nM30\n";
}

void run_worst(const char* name) {
  const bool zero = !std::strcmp(name, "worst-zero-moves");
  BenchProgram p;
  const char* tool = std::getenv("DEXMILL_BENCH_TOOL");
  p.tool_spec = tool ? tool : "flat:6";
  p.name = zero ? "zero-moves" : "g83-999999-pecks";
  p.text = zero ? zero_moves_program() : g83_program();
  if (!bench_program_plan(name, &p)) return;
  const int runs = bench::single_run() ? 1 : 3;
  double best = 1e300;
  for (int r = 0; r < runs; ++r) best = std::min(best, bench_engine_run(p));
  bench::result(name, "program=%s tool=%s lines=%u seconds=%.3f scan_s=%.3f target_s=%d", p.name.c_str(),
                p.tool_spec.c_str(), p.lines, best, p.scan_s, zero ? 1 : 5);
}

}  // namespace
}  // namespace dexmill

BENCH(worst_zero_moves, "worst-zero-moves", dexmill::run_worst);
BENCH(worst_g83, "worst-g83", dexmill::run_worst);
