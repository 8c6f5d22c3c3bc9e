// The checks of the tool's body (issue 20): the shank above the flutes, the
// holder, fixtures and a plunge by a tool that is not centre cutting. For
// each, a program with one offence on a known line gives one finding on
// that line with its depth exact (the stock top and the offending Z lie on
// the LSB lattice), and the same program without the offence gives none;
// `check --simulate` gives the verdict without images.
#include <cstdio>
#include <string>

#include "tests/run_cli_util.h"
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
  Result r = run(slot("shank_bad.ngc", "-8") + kBlock + " --tool flat:6,len=5");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "shank_bad.ngc:6:1: warning: the shank touches material: 3.000 mm above the flutes"));
  CHECK_EQ(warnings_in(r.err), 1);
  // With no output the summary counts it.
  r = run(slot("shank_bad.ngc", "-8") + " --stock 0,0,-30,40,40,0 --pitch 0.2 -q --tool flat:6,len=5");
  CHECK(has(r.out, "safety   1 finding(s) (on standard error)"));
  r = run(slot("shank_good.ngc", "-5") + kBlock + " --tool flat:6,len=5");  // exactly the flute length
  CHECK_EQ(warnings_in(r.err), 0);
  // Deeper than the stick-out: the dexels keep the material over the tool,
  // which the shank meets all the same.
  r = run(slot("shank_deep.ngc", "-27") + kBlock + " --tool flat:6,len=20,stick=25");
  CHECK(has(r.err, "shank_deep.ngc:6:1: warning: the shank touches material: 7.000 mm above the flutes"));
  CHECK_EQ(warnings_in(r.err), 1);
}

TEST(safety_holder_touches_material) {
  if (skip()) return;
  // A 30 mm holder 20 mm above the tip: a slot 21 deep puts it 1 mm into the stock.
  Result r = run(slot("holder_bad.ngc", "-21") + kBlock + " --tool flat:6,stick=20,holder=30x10");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "holder_bad.ngc:6:1: warning: the holder touches material: 1.000 mm deep"));
  CHECK_EQ(warnings_in(r.err), 1);
  r = run(slot("holder_good.ngc", "-19.8") + kBlock + " --tool flat:6,stick=20,holder=30x10");
  CHECK_EQ(warnings_in(r.err), 0);
  // A cone flaring from 10 to 40 mm over 15: over the slot's wall (3 mm
  // from the axis) its 5 mm bottom disc is at the stick-out; at 21 deep
  // it is the disc, 1 mm in, and the flank no deeper.
  r = run(slot("cone_bad.ngc", "-21") + kBlock + " --tool flat:6,stick=20,holder=10-40x15");
  CHECK(has(r.err, "cone_bad.ngc:6:1: warning: the holder touches material: 1.000 mm deep"));
  CHECK_EQ(warnings_in(r.err), 1);
}

TEST(safety_fixtures_are_never_entered) {
  if (skip()) return;
  const std::string p = program("fixture.ngc", "G21 G90\nM3 S10000\nG0 Z5\nG0 X-5 Y20\nG1 Z-2 F300\nG1 X38\n"
                                               "G1 X48\nG0 Z5\nM2\n");
  // A clamp from X42 with its top at Z3: line 7 runs 5 mm into it (the
  // rise out of it, line 8, is not a second offence).
  Result r = run(p + kBlock + " --tool ball:6 --fixture 42,10,-30,50,30,3");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "fixture.ngc:7:1: warning: the tool enters a fixture: 5.000 mm deep"));
  CHECK_EQ(warnings_in(r.err), 1);
  // Past the ball's reach (X48 + 3): nothing; the holder reaches it.
  r = run(p + kBlock + " --tool ball:6 --fixture 51.2,10,-30,60,30,3");
  CHECK_EQ(warnings_in(r.err), 0);
  r = run(p + kBlock + " --tool ball:6,stick=4,holder=20x10 --fixture 51.2,10,-30,60,30,3");
  CHECK(has(r.err, "fixture.ngc:7:1: warning: the tool enters a fixture: 1.000 mm deep"));
  CHECK_EQ(run(p + kBlock + " --tool ball:6 --fixture 1,2,3").code, 2);
  // --stop-at collision stops there.
  CHECK_EQ(run(p + kBlock + " --tool ball:6 --fixture 42,10,-30,50,30,3 --stop-at collision").code, 4);
}

TEST(safety_plunge_without_centre_cutting) {
  if (skip()) return;
  const std::string plunge = program("plunge_bad.ngc", "G21 G90\nM3 S10000\nG0 Z5\nG0 X10 Y20\nG1 Z-3 F100\n"
                                                       "G1 X30 F300\nG0 Z5\nM2\n");
  Result r = run(plunge + kBlock + " --tool flat:6,nocentre");
  CHECK(has(r.err, "plunge_bad.ngc:5:1: warning: a tool that is not centre cutting plunges 3.000 mm straight down "
                   "into material at X10.000 Y20.000"));
  CHECK_EQ(warnings_in(r.err), 1);
  r = run(plunge + kBlock + " --tool flat:6");  // centre cutting: fine
  CHECK_EQ(warnings_in(r.err), 0);
  const std::string ramp = program("plunge_ramp.ngc", "G21 G90\nM3 S10000\nG0 Z5\nG0 X10 Y20 Z1\nG1 X20 Z-3 F100\n"
                                                      "G1 X30 F300\nG0 Z5\nM2\n");
  r = run(ramp + kBlock + " --tool flat:6,nocentre");
  CHECK_EQ(warnings_in(r.err), 0);
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
  std::string text = "G21 G90\nM3 S1000\nG0 X-5 Y2 Z5\nG0 Z-1\n";
  for (int k = 0; k < 70; ++k) {
    char line[64];
    std::snprintf(line, sizeof line, "G0 X%d Y%.1f\n", k % 2 ? -5 : 45, 2 + 0.5 * k);
    text += line;
  }
  text += "G0 Z5\nM2\n";
  const std::string p = program("many.ngc", text.c_str());
  const Result r = run(p + " --stock 0,0,-30,40,40,0 --pitch 0.2 -q --check rapid --report " + tmp_dir() + "/many.json");
  CHECK(has(slurp(tmp_dir() + "/many.json"), "\"collisions\": {\"total\": 70,"));
  CHECK(has(r.err, "many.ngc: warning: 6 more safety findings not listed"));
}
