// Safety checks of `dexmill run` (core/safety/safety.h) as the
// CLI gives them: a program with one offence of each kind gives each
// warning as FILE:LINE:1 with its message, and the report's collisions;
// without --check the report says null and nothing is warned;
// --stop-at collision and --fail-on-collision exit 4, a finding nothing
// asked to fail on exits 0; --check's usage. Which findings, their lines,
// depths and volumes, and the programs without offences, are the engine's
// (test_sim_safety.cpp).
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

const char* kStock = " --stock 0,0,-5,40,40,0 --tool flat:6 --pitch 0.2";

std::string write_program(const char* name, const char* text) { return write_tmp(name, text); }

// Line 6 rapids 20 mm through the stock 1 mm deep; line 8 feeds after M5;
// line 10 plunges 2 mm below the stock's bottom (1 mm into a table at -6).
// Each test writes it itself: the cases may run in different processes.
std::string write_bad_program() {
  return write_program("safety_bad.ngc",
                       "G21 G90\nG0 X-10 Y10 Z5\nG0 Z-1\nM3 S1000\nG1 X10 F300\nG0 X30\nM5\n"
                       "G1 Y20 F300\nM3\nG1 X35 Y35 Z-7 F200\nG0 Z5\nM2\n");
}

// The report's collisions object.
std::string collisions_of(const std::string& report) {
  const size_t a = report.find("  \"collisions\""), b = report.find("  \"timing\"");
  return a == std::string::npos || b == std::string::npos ? std::string() : report.substr(a, b - a);
}

int count_of(const std::string& s, const std::string& part) {
  int n = 0;
  for (size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(safety_each_kind_is_warned_on_its_line_and_reported) {
  if (skip()) return;
  const std::string bad = write_bad_program();
  Result r = run(bad + kStock + " -q --check all --table -6 --report " + tmp_dir() + "/safety_bad.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "safety_bad.ngc:6:1: warning: rapid into material: "));
  CHECK(has(r.err, "safety_bad.ngc:8:1: warning: cutting with the spindle stopped (no M3/M4) from here to line 8: "));
  CHECK(has(r.err, "safety_bad.ngc:10:1: warning: the tool goes 2.000 mm below the stock's bottom at X35.000 Y35.000 Z-7.000"));
  CHECK(has(r.err, "safety_bad.ngc:10:1: warning: the tool goes 1.000 mm into the table at X35.000 Y35.000 Z-7.000"));
  CHECK_EQ(count_of(r.err, "warning:"), 4);  // the rise out of the hole (line 11) is not a second offence
  const std::string c = collisions_of(slurp(tmp_dir() + "/safety_bad.json"));
  CHECK(has(c, "\"total\": 4"));
  CHECK(has(c, "{\"kind\": \"rapid\", \"line\": 6"));
  CHECK(has(c, "\"depth_mm\": 1.0000"));
  // Without --check the report says null and nothing is watched.
  r = run(bad + kStock + " -q --report " + tmp_dir() + "/safety_off.json");
  CHECK_EQ(count_of(r.err, "warning:"), 0);
  CHECK(has(slurp(tmp_dir() + "/safety_off.json"), "\"collisions\": null"));
}

TEST(safety_stop_and_fail_exit_4) {
  if (skip()) return;
  const std::string bad = write_bad_program();
  Result r = run(bad + kStock + " -q --stop-at collision --report " + tmp_dir() + "/safety_stop.json");
  CHECK_EQ(r.code, 4);
  CHECK(has(slurp(tmp_dir() + "/safety_stop.json"), "\"stopped\": {\"reason\": \"collision\", \"line\": 6}"));
  r = run(bad + kStock + " -q --fail-on-collision --report /dev/null");
  CHECK_EQ(r.code, 4);
  r = run(bad + kStock + " -q --check rapid --report /dev/null");  // found, but nothing asked to fail
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_of(r.err, "warning:"), 1);
  CHECK_EQ(run(bad + kStock + " -q --check wobble").code, 2);
}
