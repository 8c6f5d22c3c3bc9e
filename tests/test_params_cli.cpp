// Parameters and expressions through the commands: `check` and
// `path` read them, message comments print as FILE:LINE: debug|print|message
// and reach `run`'s report, expression errors are FILE:LINE:COL errors with
// exit 1, and LinuxCNC's semantics hold end to end (assignments after the
// line, the position parameters after a move; the probe's results are the
// engine's, test_sim_reading.cpp).
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {
using namespace run_cli;
}  // namespace

TEST(params_through_the_commands) {
  if (skip()) return;
  const std::string p = write_tmp("params.ngc",
                                  "G21 G90\n#<d> = 2.5\n(DEBUG, depth #<d>)\nG0 X10 Y5 Z5\n"
                                  "#1 = #5420 #2 = [#<_y> * 2]\n(PRINT, x=#1 y2=#2)\n(MSG, change to T2)\n"
                                  "G1 Z-#<d> F300\nG1 X[#1 + #2] Y[ATAN[1]/[1]]\nM2\n");
  Result r = run_command("path " + p);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "params.ngc:3: debug:  depth 2.500000"));
  CHECK(has(r.err, "params.ngc:6: print:  x=10.000000 y2=10.000000"));
  CHECK(has(r.err, "params.ngc:7: message:  change to T2"));
  CHECK(has(r.out, "feed 10.00000 5.00000 -2.50000"));
  CHECK(has(r.out, "feed 20.00000 45.00000 -2.50000"));
  r = run_command("check " + p);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "params.ngc:3: debug:  depth 2.500000"));
  // run: printed once, and in the report.
  r = run(p + " --stock 0,0,-10,30,50,0 -q --report " + tmp_dir() + "/params.json");
  CHECK_EQ(r.code, 0);
  size_t at = 0, n = 0;
  while ((at = r.err.find("debug:", at)) != std::string::npos) ++n, ++at;
  CHECK_EQ(n, size_t(1));
  const std::string rep = slurp(tmp_dir() + "/params.json");
  CHECK(has(rep, "\"messages\": [\n    {\"line\": 3, \"kind\": \"debug\", \"text\": \" depth 2.500000\"},"));
  CHECK(has(rep, "{\"line\": 7, \"kind\": \"message\", \"text\": \" change to T2\"}"));  // as rs274: the blank kept
}

TEST(params_errors_are_file_line_col) {
  if (skip()) return;
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      {"G21\nG1 X[1/0] F100\nM2\n", ":2:7: error: /: division by zero"},  // at the operator
      {"G21\nG1 X#<nope> F100\nM2\n", ":2:5: error: named parameter #<NOPE> used before it was set"},
      {"G21\n#5420 = 1\nM2\n", ":2:1: error: parameter #5420 is read-only"},
      {"G21\nG1 X[1 + ] F100\nM2\n", ":2:"},
      {"G21\nG1 X SQRT[-4] F100\nM2\n", ":2:6: error: SQRT[-4]: argument outside the function's domain"},
      {"G21\n#9000 = 1\nM2\n", ":2:1: error: parameter #9000 out of range"},
  };
  for (const Case& c : cases) {
    const std::string p = write_tmp("bad_param.ngc", c.text);
    const Result r = run_command("check " + p);
    CHECK_EQ(r.code, 1);
    CHECK(has(r.err, c.message));
  }
}
