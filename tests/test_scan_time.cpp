// The time estimate by tool (core/sim/scan.h ScanToolTime) and the largest
// G64 P, from the first pass with the look-ahead's memory: a tool change
// stops the machine, so the first tool's share is exactly the time of its
// moves alone (the program cut at its M6), and the shares add up to the
// whole; the blended figure lies between its bounds; without the memory
// every share is the model's (stop at every move).
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/sim/chunk_input.h"
#include "core/sim/scan.h"
#include "core/tool/spec.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

class Quiet final : public GcodeMessages {
 public:
  void error(const GcodeDiag&) override { ++errors_; }
  void warning(const GcodeDiag&) override { ++warnings_; }
};

const char* kTwoTools =
    "G21 G90 G64 P0.05\nT1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F600\nG1 X40 F1500\nG1 Y30\nG1 X0 Y29\n"
    "T2 M6\nG0 Z5\nG1 X10 Y10 F800\nG64 P0.02\nG2 X20 Y10 I5 J0\nG61\nG1 X30\nG1 Y20\nM2\n";
// The first tool's part alone, ending where the M6 stops the machine.
const char* kFirstOnly = "G21 G90 G64 P0.05\nT1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F600\nG1 X40 F1500\nG1 Y30\nG1 X0 Y29\nM2\n";

struct Scanned {
  std::unique_ptr<ProgramScan> scan;
  MotionPlanner plan;
};

void scan(const char* text, bool with_planner, Scanned* s) {
  SimJob job;
  (void)tool_spec_parse("flat:6", 6, &job.tool);
  job.time.accel_nm_per_s2 = 400 * 1000000LL;
  job.time.blend = true;
  s->scan.reset(new ProgramScan(job));
  if (with_planner) s->scan->set_planner(&s->plan);
  std::vector<char> buf(LineReader::kStartBytes);
  ChunkInput in(buf.data(), buf.size());
  in.feed(text, std::strlen(text));
  in.close();
  Quiet q;
  const std::unique_ptr<ProgramMemory> mem(new ProgramMemory());
  s->scan->run(&in, &q, mem.get());
  CHECK_EQ(q.errors(), 0u);
}

int index_of(const ProgramScan& s, int32_t number) {
  for (int k = 0; k < s.ntools; ++k)
    if (s.numbers[k] == number) return k;
  return -1;
}

}  // namespace

TEST(scan_time_by_tool_adds_up_and_splits_at_the_tool_change) {
  Scanned all, first, flat;
  scan(kTwoTools, true, &all);
  scan(kFirstOnly, true, &first);
  scan(kTwoTools, false, &flat);
  const ProgramScan& s = *all.scan;
  CHECK(s.summary.blending());
  const int t1 = index_of(s, 1), t2 = index_of(s, 2);
  CHECK(t1 > 0 && t2 > 0);
  if (t1 <= 0 || t2 <= 0) return;
  // Nothing ran before the first M6; each tool's moves are its own.
  CHECK_EQ(s.tool_time[0].moves, uint64_t{0});
  CHECK_EQ(s.tool_time[t1].moves, uint64_t{5});
  CHECK_EQ(s.tool_time[t2].moves, uint64_t{5});
  CHECK_EQ(s.tool_time[t1].estimated_us + s.tool_time[t2].estimated_us, s.summary.blended_time_us());
  CHECK_EQ(s.tool_time[t1].feed_us + s.tool_time[t2].feed_us, s.summary.blended_feed_us());
  CHECK_EQ(s.tool_time[t1].rapid_us + s.tool_time[t2].rapid_us, s.summary.blended_rapid_us());
  // The first tool's share is its moves' time alone, to the microsecond.
  CHECK_EQ(s.tool_time[t1].estimated_us, first.scan->summary.blended_time_us());
  CHECK(s.summary.no_accel_time_us() < s.summary.blended_time_us());
  CHECK(s.summary.blended_time_us() < s.summary.stop_time_us());
  CHECK_EQ(s.path_tolerance_max_nm, 50000);
  // Without the look-ahead's memory: the model's figure, by tool too.
  const ProgramScan& f = *flat.scan;
  CHECK(!f.summary.blending());
  CHECK_EQ(f.summary.blended_time_us(), f.summary.stop_time_us());
  CHECK_EQ(f.tool_time[t1].estimated_us + f.tool_time[t2].estimated_us, f.summary.stop_time_us());
}

TEST(scan_time_without_g64_p_has_no_tolerance) {
  Scanned s;
  scan("G21 G90 G64\nG1 X10 F600\nG61 G1 Y10\nM2\n", true, &s);
  CHECK_EQ(s.scan->path_tolerance_max_nm, -1);
  CHECK_EQ(s.scan->tool_time[0].moves, uint64_t{2});  // the tool before any M6
}
