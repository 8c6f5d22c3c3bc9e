// How a run reads its program, on the engine (tests/sim_util.h): a program
// with an input error is cut up to its first bad block, the same cut as the
// program without it; a T the tool table lacks stops the cut at its line;
// the probe parameters after G38.2 are its end point. The messages, the
// exit status and the report's keys stay with the CLI's tests
// (test_run_cli.cpp, test_params_cli.cpp).
#include <string>
#include <vector>

#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::Run;
using sim_test::run_file;

TEST(sim_partial_cut_is_the_program_up_to_its_bad_block) {
  const char* stock = "-5,-5,-2,25,15,0";
  Run part;
  CHECK(part.stock(stock).program(run_file("bad_word.ngc")));
  CHECK_EQ(part.scan_errors(), 1u);
  CHECK_EQ(part.job().stop_line, 4u);
  CHECK_GT(part.sim().removed_lsb(), uint64_t{0});  // line 3 cut
  // The same cut as the program without its bad block and what follows.
  Run good;
  CHECK(good.stock(stock).text("good3.ngc", "G21 G90\nG0 Z5\nG1 X10 Y10 Z-1 F300\n"));
  CHECK_EQ(good.job().stop_line, 0u);
  CHECK_EQ(part.grid_hash(), good.grid_hash());
}

TEST(sim_tool_the_table_lacks_stops_the_cut_at_its_line) {
  Run r;
  CHECK(r.tools(run_file("tools.tbl")).program(run_file("unknown_tool.ngc")));
  CHECK_EQ(r.scan().bad_tool_line, 4u);
  CHECK_EQ(r.scan().bad_tool, 7);
  CHECK_EQ(r.job().stop_line, 4u);
  CHECK(r.sim().stop_reason() == SimStop::kInputError);
  CHECK_EQ(r.sim().stop_line(), 4u);
}

namespace {

struct Moves final : SimObserver {
  std::vector<CanonRecord> list;
  void record(const CanonRecord& r) override {
    if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc) list.push_back(r);
  }
};

}  // namespace

// #5061-#5070 after a probe move: where it touched the stock (the engine
// has it: core/cut/probe.h), in the coordinates in force then, and 1. The
// probe down to Z-2 stops on the untouched top, Z0.
TEST(sim_probe_results_are_where_it_touched) {
  Moves moves;
  Run r;
  r.observer = &moves;
  CHECK(r.stock("0,0,-5,20,10,0").text("probe_params.ngc", "G21 G90\nG10 L2 P1 X10\nG54\nG0 X5 Y5 Z5\nG38.2 Z-2 F50\n"
                                                           "G0 X[#5061 + 1] Y#5062 Z[#5063 + #5070]\nM2\n"));
  CHECK_EQ(r.scan_errors(), 0u);
  const std::vector<CanonRecord>& m = moves.list;
  CHECK_GE(m.size(), size_t{2});
  if (m.size() < 2) return;
  const CanonRecord& probe = m[m.size() - 2];
  const CanonRecord& after = m.back();
  CHECK(probe.kind == CanonKind::kFeed);
  CHECK_EQ(probe.line, 5u);
  CHECK_EQ(probe.end.x_nm, 15 * kNmPerMm);
  CHECK_EQ(probe.end.y_nm, 5 * kNmPerMm);
  CHECK_EQ(probe.end.z_nm, 0);
  CHECK(after.kind == CanonKind::kTraverse);
  CHECK_EQ(after.end.x_nm, 16 * kNmPerMm);
  CHECK_EQ(after.end.y_nm, 5 * kNmPerMm);
  CHECK_EQ(after.end.z_nm, 1 * kNmPerMm);
}
