// The embedding API's costs (display/api/dexmill.h), on a program from
// $DEXMILL_BENCH_PROGRAM (a G-code file) or, without it, paper-w3's path
// written as G-code; the stock and grid are the ones `dexmill run` would
// choose for it (the scan's extents, a 32nd of the tool), the tool
// $DEXMILL_BENCH_TOOL or flat:6 (the CLI's default).
//
//   api-lines  ns per program line: the API fed in 4 KiB pieces and
//              stepped a line at a time, the engine (core/sim) driven the
//              same way without the API, and the interpretation alone
//              (the scan, what `dexmill check` does besides reading the
//              file); api_overhead = api - engine.
//   api-slice  the longest dm_step with a budget of one move (what a
//              controller's idle loop must allow for): each slice's least
//              time over three runs, the line of the longest, the raw
//              longest and the mean slice.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/sim/chunk_input.h"
#include "core/sim/scan.h"
#include "core/sim/simulation.h"
#include "core/tool/spec.h"
#include "display/api/dexmill.h"
#include "platform/os/read_file.h"
#include "tools/bench/bench.h"
#include "tools/bench/bench_program.h"
#include "tools/bench/workloads.h"

namespace dexmill {
namespace {

// paper-w3's polyline as a program.
std::string workload_program() {
  Workload w;
  if (!make_workload("paper-w3", &w)) return "";
  std::string s = "G21 G90 G17\n";
  char line[128];
  for (size_t k = 0; k < w.path.size(); ++k) {
    const PointNm& p = w.path[k];
    std::snprintf(line, sizeof line, "%s X%.4f Y%.4f Z%.4f%s\n", k ? "G1" : "G0", p.x_nm * 1e-6, p.y_nm * 1e-6,
                  p.z_nm * 1e-6, k == 1 ? " F1000" : "");
    s += line;
  }
  return s + "M30\n";
}

using Program = BenchProgram;

// The program of $DEXMILL_BENCH_PROGRAM, or paper-w3's path, planned.
bool load(const char* bench, Program* p) {
  const char* path = std::getenv("DEXMILL_BENCH_PROGRAM");
  const char* tool = std::getenv("DEXMILL_BENCH_TOOL");
  p->tool_spec = tool ? tool : "flat:6";
  if (path) {
    std::vector<unsigned char> bytes;
    std::string err;
    if (read_whole_file(path, size_t{1} << 30, &bytes, &err) != ReadFile::kOk) {
      std::fprintf(stderr, "%s: %s\n", bench, err.c_str());
      return false;
    }
    p->text.assign(bytes.begin(), bytes.end());
    p->name = path;
  } else {
    p->text = workload_program();
    p->name = "paper-w3-as-gcode";
  }
  return bench_program_plan(bench, p);
}

// One run through the API with budget b; calls slice(seconds) after each
// step that cut. Its wall time.
template <class F>
double api_run(const Program& p, const dm_budget& b, F slice) {
  size_t n = 0;
  if (dm_required_bytes(&p.api, &n) != DM_OK) return -1;
  std::vector<uint64_t> mem(n / 8 + 1);
  dm_sim* sim = nullptr;
  if (dm_create(&p.api, mem.data(), n, &sim) != DM_OK) return -1;
  size_t at = 0;
  int32_t state = DM_READY;
  const double t0 = bench::now_s();
  while (state == DM_READY || state == DM_NEED_INPUT) {
    const double s0 = bench::now_s();
    dm_step(sim, &b, &state);
    const double s1 = bench::now_s();
    if (state == DM_NEED_INPUT) {
      if (at < p.text.size()) {
        const size_t k = std::min(kBenchPieceBytes, p.text.size() - at);
        dm_feed(sim, p.text.data() + at, k);
        at += k;
      } else {
        dm_end_input(sim);
      }
    } else {
      slice(s1 - s0, sim);
    }
  }
  const double t = bench::now_s() - t0;
  dm_destroy(sim);
  return t;
}

void run_lines(const char* name) {
  Program p;
  if (!load(name, &p)) return;
  dm_budget line{};
  line.lines = 1;
  // Alternated, the fastest of each: the two see the same machine.
  double api = 1e300, engine = 1e300;
  const int runs = bench::single_run() ? 1 : 7;
  for (int r = 0; r < runs; ++r) {
    api = std::min(api, api_run(p, line, [](double, dm_sim*) {}));
    engine = std::min(engine, bench_engine_run(p));
  }
  const double per = 1e9 / std::max<uint32_t>(p.lines, 1);
  bench::result(name, "program=%s lines=%u api_ns_per_line=%.0f engine_ns_per_line=%.0f api_overhead_ns_per_line=%.1f "
                "interpret_ns_per_line=%.0f", p.name.c_str(), p.lines, api * per, engine * per, (api - engine) * per,
                p.scan_s * per);
}

// Each slice's time is its least over the runs (the same slices each run:
// the cut is deterministic), so a slice the machine preempted once does not
// count as long; the raw longest is given too.
void run_slice(const char* name) {
  Program p;
  if (!load(name, &p)) return;
  dm_budget one{};
  one.moves = 1;
  const int runs = bench::single_run() ? 1 : 3;
  std::vector<double> least;
  std::vector<uint32_t> lines;
  double raw = 0, total = 0;
  for (int r = 0; r < runs; ++r) {
    size_t k = 0;
    const double t = api_run(p, one, [&](double s, dm_sim* sim) {
      raw = std::max(raw, s);
      if (r == 0) {
        dm_progress pr;
        dm_get_progress(sim, &pr);
        least.push_back(s);
        lines.push_back(pr.line);
      } else if (k < least.size()) {
        least[k] = std::min(least[k], s);
      }
      ++k;
    });
    total = r ? std::min(total, t) : t;
  }
  const size_t at = static_cast<size_t>(std::max_element(least.begin(), least.end()) - least.begin());
  const double longest = least.empty() ? 0 : least[at];
  bench::result(name, "program=%s slices=%zu runs=%d max_slice_us=%.0f at_line=%u raw_max_slice_us=%.0f "
                "mean_slice_us=%.2f limit_us=2000", p.name.c_str(), least.size(), runs, longest * 1e6,
                least.empty() ? 0u : lines[at], raw * 1e6, total * 1e6 / static_cast<double>(std::max<size_t>(least.size(), 1)));
}

}  // namespace
}  // namespace dexmill

BENCH(api_lines, "api-lines", dexmill::run_lines);
BENCH(api_slice, "api-slice", dexmill::run_slice);
