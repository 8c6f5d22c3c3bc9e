// `dexmill run --machine FILE` (tools/run/run_machine.h, core/safety/travel_watch.h)
// on machines and programs the test writes: a LinuxCNC INI whose travel a
// move leaves at its line (the axis, the side, how far), a program inside
// it with no finding, the tool length offset from the INI's tool table
// taking Z past its limit, the INI's defaults (tool table, units, rapid)
// said and an option winning; a grbl dump, its travel in negative space
// and its G54 from `$#`; --fail-on-travel's exit 4 and 0; usage errors.
#include <cmath>
#include <cstdlib>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

const char* kIni =
    "# a router, LinuxCNC 2.9\n"
    "[EMC]\nVERSION = 1.1\n\n"
    "[TRAJ]\nCOORDINATES = XYZ\nLINEAR_UNITS = mm\nMAX_LINEAR_VELOCITY = 100\n\n"
    "[EMCIO]\nTOOL_TABLE = router.tbl\n\n"
    "[AXIS_X]\nMIN_LIMIT = -5\nMAX_LIMIT = 100\nMAX_VELOCITY = 80\nMAX_ACCELERATION = 500\n\n"
    "[AXIS_Y]\nMIN_LIMIT = -5\nMAX_LIMIT = 60\nMAX_VELOCITY = 80\nMAX_ACCELERATION = 500\n\n"
    "[AXIS_Z]\nMIN_LIMIT = -40\nMAX_LIMIT = 10\nMAX_VELOCITY = 40\nMAX_ACCELERATION = 300\n";

}  // namespace

TEST(run_machine_linuxcnc_travel) {
  if (skip()) return;
  write_tmp("router.ini", kIni);
  write_tmp("router.tbl", "T1 P1 D6 Z+20 ;flat:6\n");
  // Line 6 goes 12 mm past X's MAX_LIMIT; line 8 comes back (no finding).
  write_tmp("past.ngc", "G21 G90\nT1 M6\nS10000 M3\nG0 X10 Y10 Z5\nG1 Z-2 F600\nG1 X112\nG0 Z5\nG0 X10\nM30\n");
  Result r = run("%/past.ngc -q --machine %/router.ini --stock 0,0,-10,90,50,0 --report %/past.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "past.ngc:6:1: warning: travel: X 12.000 mm past the machine's MAX_LIMIT (machine X 112.000, limit 100.000)"));
  CHECK(lacks(r.err, "past.ngc:8:"));
  const std::string rep = slurp(tmp_dir() + "/past.json");
  CHECK(has(rep, "\"travel\": {\"total\": 1, \"findings\": ["));
  CHECK(has(rep, "\"axis\": \"X\", \"side\": \"max\", \"by_mm\": 12.000"));
  CHECK(has(rep, "\"kind\": \"linuxcnc\", \"travel_mm\": {\"x\": [-5.000, 100.000]"));
  CHECK(has(rep, "tool table"));
  CHECK_EQ(run("%/past.ngc -q --machine %/router.ini --stock 0,0,-10,90,50,0 --fail-on-travel").code, 4);
  // Inside: no finding, exit 0 with --fail-on-travel.
  write_tmp("inside.ngc", "G21 G90\nT1 M6\nS10000 M3\nG0 X10 Y10 Z5\nG1 Z-2 F600\nG1 X95\nG2 X95 Y30 I0 J10\nG0 Z5\nM30\n");
  r = run("%/inside.ngc -q --machine %/router.ini --stock 0,0,-10,90,50,0 --fail-on-travel --report %/inside.json");
  CHECK_EQ(r.code, 0);
  CHECK(lacks(r.err, "travel:"));
  CHECK(has(slurp(tmp_dir() + "/inside.json"), "\"travel\": {\"total\": 0, \"findings\": []}"));
  // The arc's bulge: G2 from X95 Y10 to X95 Y30 about X95 Y20 reaches X105.
  write_tmp("bulge.ngc", "G21 G90\nT1 M6\nS10000 M3\nG0 X95 Y10 Z5\nG1 Z-2 F600\nG3 X95 Y30 I0 J10\nG0 Z5\nM30\n");
  r = run("%/bulge.ngc -q --machine %/router.ini --stock 0,0,-10,90,50,0");
  CHECK(has(r.err, "bulge.ngc:6:1: warning: travel: X 5.000 mm past the machine's MAX_LIMIT"));
  // G43 with the table's 20 mm: Z5 at the tip is machine Z 25, 15 past Z's 10.
  write_tmp("tlo.ngc", "G21 G90\nT1 M6 G43 H1\nG0 X10 Y10 Z5\nM30\n");
  r = run("%/tlo.ngc -q --machine %/router.ini --stock 0,0,-10,90,50,0");
  CHECK(has(r.err, "tlo.ngc:3:1: warning: travel: Z 15.000 mm past the machine's MAX_LIMIT (machine Z 25.000, limit 10.000)"));
}

TEST(run_machine_defaults_and_options) {
  if (skip()) return;
  write_tmp("router2.ini", kIni);
  write_tmp("router.tbl", "T1 P1 D6 Z+20 ;flat:6\n");
  write_tmp("inside2.ngc", "G21 G90\nT1 M6\nG0 X10 Y10 Z5\nG1 Z-2 F600\nG1 X80\nM30\n");
  Result r = run("%/inside2.ngc --machine %/router2.ini --stock 0,0,-10,90,50,0");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "machine  "));
  CHECK(has(r.out, "tool table "));
  CHECK(has(r.out, "(the machine's)"));
  CHECK(has(r.out, "rapid 2400 mm/min (the slowest axis) (the machine's)"));  // Z's 40 mm/s
  CHECK(has(r.out, "travel   0 move(s) past a soft limit"));
  CHECK(lacks(r.err, "a guess"));  // T1 from the machine's tool table
  r = run("%/inside2.ngc --machine %/router2.ini --stock 0,0,-10,90,50,0 --rapid 9000");
  CHECK(has(r.out, "rapid 2400 mm/min (the slowest axis) (the option's, over the machine's)"));
  CHECK(has(r.out, "rapids at 9000 mm/min"));
  // Usage: --check travel needs a machine; a missing file is an I/O error.
  CHECK_EQ(run("%/inside2.ngc -q --check travel").code, 2);
  CHECK_EQ(run("%/inside2.ngc -q --fail-on-travel").code, 2);
  CHECK_EQ(run("%/inside2.ngc -q --machine %/no-such.ini").code, 3);
  write_tmp("bad.ini", "[AXIS_X]\nMIN_LIMIT = 10\nMAX_LIMIT = -10\n");
  r = run("%/inside2.ngc -q --machine %/bad.ini");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "bad.ini:"));
}

TEST(run_machine_grbl_travel_and_offsets) {
  if (skip()) return;
  // grbl 1.1's $$ (part of it) and $#: 300 x 200 x 80 mm of travel in
  // negative space, soft limits on, G54 at X-290 Y-190 Z-60.
  write_tmp("grbl.txt",
            "$0=10\n$1=25\n$2=0\n$3=0\n$4=0\n$5=0\n$6=0\n$10=1\n$11=0.010\n$12=0.002\n$13=0\n$20=1\n$21=0\n$22=1\n"
            "$23=0\n$24=25.000\n$25=500.000\n$26=250\n$27=1.000\n$30=1000\n$31=0\n$32=0\n$100=250.000\n$101=250.000\n"
            "$102=250.000\n$110=5000.000\n$111=5000.000\n$112=500.000\n$120=10.000\n$121=10.000\n$122=10.000\n"
            "$130=300.000\n$131=200.000\n$132=80.000\nok\n"
            "[G54:-290.000,-190.000,-60.000]\n[G55:0.000,0.000,0.000]\n[G56:0.000,0.000,0.000]\n[G57:0.000,0.000,0.000]\n"
            "[G58:0.000,0.000,0.000]\n[G59:0.000,0.000,0.000]\n[G28:0.000,0.000,0.000]\n[G30:0.000,0.000,0.000]\n"
            "[G92:0.000,0.000,0.000]\n[TLO:0.000]\n[PRB:0.000,0.000,0.000:0]\nok\n");
  // Work X 5 is machine X -285 (inside); work X 20 is machine -270... and
  // work Z 70 is machine +10, past grbl's 0.
  write_tmp("grbl.ngc", "G21 G90 G54\nG0 X5 Y5 Z5\nG1 Z-1 F300\nG1 X20\nG0 Z70\nM30\n");
  Result r = run("%/grbl.ngc -q --machine %/grbl.txt --tool flat:3 --stock 0,0,-10,30,30,0 --report %/grbl.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "grbl.ngc:5:1: warning: travel: Z 10.000 mm past the machine's 0 (grbl's home)"));
  CHECK(lacks(r.err, "grbl.ngc:4:"));
  const std::string rep = slurp(tmp_dir() + "/grbl.json");
  CHECK(has(rep, "\"kind\": \"grbl\", \"travel_mm\": {\"x\": [-300.000, 0.000], \"y\": [-200.000, 0.000], \"z\": [-80.000, 0.000]}"));
  CHECK(has(rep, "work offsets"));
  // grbl reads F on a G20 line in inches (LinuxCNC in the units before the
  // line, warned of: core/interp/interp_modes.cpp): no warning with the dump.
  write_tmp("inch.ngc", "G20 F6\nG0 X0.2 Y0.2 Z0.2\nG1 Z-0.02\nG1 X1\nM30\n");
  const char* warned = "inch.ngc:1:5: warning: F on the line that changes the units is read in the units before it";
  r = run("%/inch.ngc -q --machine %/grbl.txt --tool flat:3 --stock 0,0,-10,30,30,0");
  CHECK_EQ(r.code, 0);
  CHECK(lacks(r.err, "F on the line"));
  r = run("%/inch.ngc -q --tool flat:3 --stock 0,0,-10,30,30,0");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, warned));
}

TEST(run_machine_start_state_from_the_controller) {
  if (skip()) return;
  // LinuxCNC's parameter file: G55 in force (#5220 = 2), its X origin at
  // 50, and a G92 of X5 kept (#5210 = 1): the program's X60 is machine
  // X115, 15 past the 100 of MAX_LIMIT.
  write_tmp("state.ini", (std::string(kIni) + "\n[RS274NGC]\nPARAMETER_FILE = state.var\n").c_str());
  write_tmp("router.tbl", "T1 P1 D6 Z+20 ;flat:6\n");
  write_tmp("state.var", "5210 1.0\n5211 5.0\n5212 0.0\n5213 0.0\n5220 2.0\n5241 50.0\n5242 0.0\n5243 0.0\n");
  write_tmp("state.ngc", "G21 G90\nG0 X40 Y10 Z5\nG0 X60\nM30\n");
  Result r = run("%/state.ngc --machine %/state.ini --tool flat:6 --stock 0,0,-10,90,50,0");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "state.ngc:3:1: warning: travel: X 15.000 mm past the machine's MAX_LIMIT (machine X 115.000"));
  CHECK(lacks(r.err, "state.ngc:2:"));  // X40 is machine X95
  CHECK(has(r.out, "G55 in force (the machine's)"));
  CHECK(has(r.out, "a G92 offset (the machine's)"));
  // grbl's [TLO:30]: the tip at work Z-20 is machine Z10, 10 past grbl's 0.
  write_tmp("tlo.txt", "$20=1\n$130=300.000\n$131=200.000\n$132=80.000\n[G54:-200.000,-100.000,0.000]\n[TLO:30.000]\n");
  write_tmp("tlo2.ngc", "G21 G90\nG0 X5 Y5\nG0 Z-20\nM30\n");
  r = run("%/tlo2.ngc -q --machine %/tlo.txt --tool flat:3 --stock -200,-100,-60,-150,-50,-40");
  CHECK(has(r.err, "tlo2.ngc:3:1: warning: travel: Z 10.000 mm past the machine's 0 (grbl's home)"));
}

namespace {

// The number after "KEY": in a report's text (NaN when absent or null).
double number_of(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\"" + key + "\": ");
  if (at == std::string::npos) return 0.0 / 0.0;
  const char* p = text.c_str() + at + key.size() + 4;
  char* end = nullptr;
  const double v = std::strtod(p, &end);
  return end == p ? 0.0 / 0.0 : v;
}

std::string axis_ini(int ax_x, int ax_y) {
  return "[TRAJ]\nLINEAR_UNITS = mm\n"
         "[AXIS_X]\nMIN_LIMIT = -500\nMAX_LIMIT = 500\nMAX_VELOCITY = 100\nMAX_ACCELERATION = " + std::to_string(ax_x) +
         "\n[AXIS_Y]\nMIN_LIMIT = -500\nMAX_LIMIT = 500\nMAX_VELOCITY = 100\nMAX_ACCELERATION = " + std::to_string(ax_y) +
         "\n[AXIS_Z]\nMIN_LIMIT = -100\nMAX_LIMIT = 100\nMAX_VELOCITY = 50\nMAX_ACCELERATION = 1000\n";
}

}  // namespace

// The time estimate with a machine: blended between its two bounds, the
// largest G64 P, the share of each tool adding up to the total; and each
// axis's own acceleration reaches the planner (a zigzag along X takes
// longer on a machine slow in X than on one slow in Y, and so does its
// upper bound, every move from rest to rest; the lower one, without
// acceleration, is the same on both).
TEST(run_machine_time_estimate_per_axis_and_by_tool) {
  if (skip()) return;
  write_tmp("slowx.ini", axis_ini(100, 1000).c_str());
  write_tmp("slowy.ini", axis_ini(1000, 100).c_str());
  std::string prog = "G21 G90 G64 P0.05\nT1 M6\nG0 X0 Y0 Z2\nG1 Z-1 F600\n";
  for (int k = 0; k < 20; ++k) prog += "G1 X" + std::string(k % 2 ? "0" : "60") + " Y" + std::to_string(k) + " F3000\n";
  prog += "T2 M6\nG0 Z2\nG1 X5 Y5 F1000\nG1 Z-1\nG1 X20\nM30\n";
  write_tmp("zigx.ngc", prog.c_str());
  CHECK_EQ(run("%/zigx.ngc -q --tool flat:6 --stock -5,-5,-5,70,30,0 --machine %/slowx.ini --report %/slowx.json").code, 0);
  CHECK_EQ(run("%/zigx.ngc -q --tool flat:6 --stock -5,-5,-5,70,30,0 --machine %/slowy.ini --report %/slowy.json").code, 0);
  const std::string x = slurp(tmp_dir() + "/slowx.json"), y = slurp(tmp_dir() + "/slowy.json");
  const double bx = number_of(x, "blended_s"), by = number_of(y, "blended_s");
  CHECK(number_of(x, "no_accel_s") < bx && bx < number_of(x, "stop_s"));
  CHECK(by < bx);
  CHECK(number_of(y, "stop_s") < number_of(x, "stop_s"));
  CHECK(number_of(y, "no_accel_s") < by && by < number_of(y, "stop_s"));
  CHECK_EQ(number_of(x, "no_accel_s"), number_of(y, "no_accel_s"));
  CHECK_EQ(number_of(x, "estimated_time_s"), bx);
  CHECK_EQ(number_of(x, "path_tolerance_mm"), 0.05);
  CHECK(has(x, "\"time_by_tool\": [{\"tool\": 1, "));
  CHECK(has(x, "}, {\"tool\": 2, "));
  const std::size_t t2 = x.find("{\"tool\": 2, ");
  const double share1 = number_of(x, "time_by_tool\": [{\"tool\": 1, \"estimated_s");
  const double share2 = t2 == std::string::npos ? 0 : number_of(x.substr(t2), "estimated_s");
  CHECK(share1 > 0 && share2 > 0);
  CHECK(std::fabs(share1 + share2 - bx) < 0.0015);  // each rounded to the ms
  // The summary says what the estimate is.
  const Result r = run("%/zigx.ngc --tool flat:6 --stock -5,-5,-5,70,30,0 --machine %/slowx.ini");
  CHECK(has(r.out, " blended at corners (G64 P up to 0.0500 mm), each axis within its velocity and acceleration (the machine's)\n"));
  CHECK(has(r.out, "         bounds: "));
}

// The time a saved stock keeps for the program is the report's estimate
// (blended with a machine), so the chain of programs adds up what the
// reports said, not the engine's unblended clock.
TEST(run_machine_chain_keeps_the_blended_time) {
  if (skip()) return;
  write_tmp("slowx2.ini", axis_ini(100, 1000).c_str());
  std::string prog = "G21 G90 G64\nG0 X0 Y0 Z2\nG1 Z-1 F600\n";
  for (int k = 0; k < 10; ++k) prog += "G1 X" + std::string(k % 2 ? "0" : "40") + " Y" + std::to_string(k) + " F3000\n";
  prog += "M30\n";
  write_tmp("zigc.ngc", prog.c_str());
  CHECK_EQ(run("%/zigc.ngc -q --tool flat:6 --stock -5,-5,-5,50,15,0 --machine %/slowx2.ini --save-stock %/zigc.dxstock "
               "--report %/zigc.json").code, 0);
  const std::string x = slurp(tmp_dir() + "/zigc.json");
  const std::size_t chain = x.find("\"chain\": ");
  CHECK(chain != std::string::npos);
  const double blended = number_of(x, "blended_s");
  CHECK(blended < number_of(x, "stop_s"));
  if (chain == std::string::npos) return;
  CHECK_EQ(number_of(x.substr(chain), "estimated_time_s"), blended);
  CHECK_EQ(number_of(x.substr(x.find("\"programs\": [", chain)), "estimated_time_s"), blended);
}
