// See bench_program.h.
#include "tools/bench/bench_program.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/sim/chunk_input.h"
#include "core/sim/scan.h"
#include "core/sim/simulation.h"
#include "core/tool/spec.h"
#include "tools/bench/bench.h"

namespace dexmill {
namespace {

// Errors and warnings dropped, not printed: a bench measures.
class Quiet final : public GcodeMessages {
 public:
  void error(const GcodeDiag&) override {}
  void warning(const GcodeDiag&) override {}
};

}  // namespace

bool bench_program_plan(const char* bench, BenchProgram* p) {
  if (tool_spec_parse(p->tool_spec.c_str(), p->tool_spec.size(), &p->job.tool) != ToolSpecError::kOk) {
    std::fprintf(stderr, "%s: bad tool '%s'\n", bench, p->tool_spec.c_str());
    return false;
  }
  // The scan, timed: the stock and pitch come from it as on the command line.
  std::unique_ptr<ProgramScan> scan;
  std::unique_ptr<ProgramMemory> mem(new ProgramMemory());
  std::vector<char> buf(LineReader::kStartBytes);
  p->scan_s = bench::best_time_s([&] {
    scan.reset(new ProgramScan(p->job));
    ChunkInput in(buf.data(), buf.size());
    in.feed(p->text.data(), p->text.size());
    in.close();
    Quiet q;
    const double t0 = bench::now_s();
    scan->run(&in, &q, mem.get());
    return bench::now_s() - t0;
  }, 0.5, 5);
  p->lines = scan->lines;
  const StockBox stock = default_stock(scan->summary, scan->max_radius_nm);
  const int64_t pitch = default_pitch_nm(stock, scan->smallest_diameter_nm());
  if (plan_grid(stock, 0, 0, pitch, &p->job.plan) != PlanError::kOk) {
    std::fprintf(stderr, "%s: no grid for this program's stock\n", bench);
    return false;
  }
  p->job.input_buffer_bytes = LineReader::kStartBytes;
  dm_job_init(&p->api, DEXMILL_API_VERSION);
  const PointNm* c[2] = {&stock.lo, &stock.hi};
  for (int k = 0; k < 2; ++k) {
    int64_t* to = k ? p->api.stock.hi_nm : p->api.stock.lo_nm;
    to[0] = c[k]->x_nm;
    to[1] = c[k]->y_nm;
    to[2] = c[k]->z_nm;
  }
  p->api.pitch_nm = pitch;
  p->api.tool.spec = p->tool_spec.c_str();
  p->ok = true;
  return true;
}

double bench_engine_run(const BenchProgram& p) {
  std::vector<uint64_t> mem(sim_required_bytes(p.job) / 8 + 1);
  Simulation* s = sim_create(p.job, mem.data(), mem.size() * 8);
  if (!s) return -1;
  SimBudget b;
  b.lines = 1;
  size_t at = 0;
  const double t0 = bench::now_s();
  for (;;) {
    const SimState st = s->step(b);
    if (st == SimState::kNeedInput) {
      if (at < p.text.size()) {
        const size_t k = std::min(kBenchPieceBytes, p.text.size() - at);
        s->feed(p.text.data() + at, k);
        at += k;
      } else {
        s->close_input();
      }
    } else if (st != SimState::kReady) {
      break;
    }
  }
  const double t = bench::now_s() - t0;
  sim_destroy(s);
  return t;
}

}  // namespace dexmill
