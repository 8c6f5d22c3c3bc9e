// The checks of the tool's body (core/safety/body.h) as the CLI gives them: a tool
// whose spec has a flute length is checked without --check, its finding a
// FILE:LINE:1 warning, counted in the summary of a run with no output;
// --fixture's usage, --stop-at collision's exit 4 at a fixture; `check
// --simulate` gives the verdict without images; a warning for the findings
// past the list. The findings of the shank, the holder, fixtures and a
// plunge by a tool that is not centre cutting, their lines and depths, and
// the programs without them, are the engine's (test_sim_safety.cpp).
#include <cstdio>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/sim_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

std::string program(const char* name, const char* text) { return write_tmp(name, text); }

int warnings_in(const std::string& s) {
  int n = 0;
  for (size_t at = s.find("warning:"); at != std::string::npos; at = s.find("warning:", at + 1)) ++n;
  return n;
}

// A slot along X at Y20 and depth Z (a string), into a 40 x 40 x 30 block.
std::string slot(const char* name, const char* z) {
  return program(name, (std::string("G21 G90\nM3 S10000\nG0 Z5\nG0 X-20 Y20\nG1 Z") + z +
                        " F300\nG1 X60\nG0 Z5\nM2\n").c_str());
}

const char* kBlock = " --stock 0,0,-30,40,40,0 --pitch 0.2 -q --report /dev/null";

}  // namespace

TEST(safety_shank_above_the_flutes) {
  if (skip()) return;
  // Flutes 5 mm long, the slot 8 deep: the shank rubs 3 mm of the wall.
  // With no output the summary counts it.
  const Result r = run(slot("shank_bad.ngc", "-8") + " --stock 0,0,-30,40,40,0 --pitch 0.2 -q --tool flat:6,len=5");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "shank_bad.ngc:6:1: warning: the shank touches material: 3.000 mm above the flutes"));
  CHECK_EQ(warnings_in(r.err), 1);
  CHECK(has(r.out, "safety   1 finding(s) (on standard error)"));
}

TEST(safety_fixture_options) {
  if (skip()) return;
  const std::string p = program("fixture.ngc", "G21 G90\nM3 S10000\nG0 Z5\nG0 X-5 Y20\nG1 Z-2 F300\nG1 X38\n"
                                               "G1 X48\nG0 Z5\nM2\n");
  CHECK_EQ(run(p + kBlock + " --tool ball:6 --fixture 1,2,3").code, 2);
  // --stop-at collision stops at the clamp (line 7), exit 4.
  CHECK_EQ(run(p + kBlock + " --tool ball:6 --fixture 42,10,-30,50,30,3 --stop-at collision").code, 4);
}

TEST(safety_check_simulate_gives_the_verdict) {
  if (skip()) return;
  const std::string bad = slot("sim_bad.ngc", "-8"), good = slot("sim_good.ngc", "-4");
  Result r = run_command("check --simulate " + bad + " --stock 0,0,-30,40,40,0 --pitch 0.2 --tool flat:6,len=5");
  CHECK_EQ(r.code, 4);
  CHECK(has(r.err, "sim_bad.ngc:6:1: warning: the shank touches material"));
  CHECK(has(r.err, "sim_bad.ngc: 1 safety finding(s)"));
  CHECK(r.out.empty());
  r = run_command("check --simulate " + good + " --stock 0,0,-30,40,40,0 --pitch 0.2 --tool flat:6,len=5");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(run_command("check --simulate " + bad + " --image x.png").code, 2);
}

TEST(safety_findings_past_the_list_are_counted_once_each) {
  if (skip()) return;
  // 70 rapids, each through fresh stock on its own line: 64 kept, 70 in all.
  const std::string text = sim_test::seventy_rapids();
  const std::string p = program("many.ngc", text.c_str());
  const Result r = run(p + " --stock 0,0,-30,40,40,0 --pitch 0.2 -q --check rapid --report " + tmp_dir() + "/many.json");
  CHECK(has(slurp(tmp_dir() + "/many.json"), "\"collisions\": {\"total\": 70,"));
  CHECK(has(r.err, "many.ngc: warning: 6 more safety findings not listed"));
}
