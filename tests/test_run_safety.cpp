// Safety checks of `dexmill run` (issue 20, core/check/safety.h): for each
// kind a program with one offence on a known line gives one finding on that
// line, with its depth exact; the same program without the offence gives
// none (misses and false alarms alike); --stop-at collision and
// --fail-on-collision exit 4.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

const char* kStock = " --stock 0,0,-5,40,40,0 --tool flat:6 --pitch 0.2";

std::string write_program(const char* name, const char* text) { return write_tmp(name, text); }

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

double number_after(const std::string& s, const std::string& key) {
  const size_t at = s.find("\"" + key + "\": ");
  return at == std::string::npos ? -1 : std::atof(s.c_str() + at + key.size() + 4);
}

}  // namespace

TEST(safety_each_kind_on_its_line_and_none_without_it) {
  if (skip()) return;
  // Line 6 rapids 20 mm through the stock 1 mm deep; line 8 feeds after M5;
  // line 10 plunges 2 mm below the stock's bottom (1 mm into a table at -6).
  const std::string bad = write_program("safety_bad.ngc",
                                        "G21 G90\nG0 X-10 Y10 Z5\nG0 Z-1\nM3 S1000\nG1 X10 F300\nG0 X30\nM5\n"
                                        "G1 Y20 F300\nM3\nG1 X35 Y35 Z-7 F200\nG0 Z5\nM2\n");
  Result r = run(bad + kStock + " -q --check all --table -6 --report " + tmp_dir() + "/safety_bad.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "safety_bad.ngc:6:1: warning: rapid into material: "));
  CHECK(has(r.err, "safety_bad.ngc:8:1: warning: cutting with the spindle stopped (no M3/M4) from here to line 8: "));
  CHECK(has(r.err, "safety_bad.ngc:10:1: warning: the tool goes 2.000 mm below the stock's bottom at X35.000 Y35.000 Z-7.000"));
  CHECK(has(r.err, "safety_bad.ngc:10:1: warning: the tool goes 1.000 mm into the table at X35.000 Y35.000 Z-7.000"));
  CHECK_EQ(count_of(r.err, "warning:"), 4);  // the rise out of the hole (line 11) is not a second offence
  const std::string c = collisions_of(slurp(tmp_dir() + "/safety_bad.json"));
  CHECK(has(c, "\"total\": 4"));
  // The rapid: 1 mm deep exactly; its volume a 20 x 6 x 1 mm slot (the
  // disc at its start was the feed's, the one at its end is its own), as
  // the dexels hold it: the slot's edges Y7 and Y13 lie on dexel axes, so
  // 31 rows of 0.2 mm, 6.2 mm: 124 mm^3.
  CHECK(has(c, "{\"kind\": \"rapid\", \"line\": 6"));
  CHECK(has(c, "\"depth_mm\": 1.0000"));
  const double rapid = number_after(c, "rapid_removed_mm3");
  if (std::fabs(rapid - 124.0) > 0.2) std::printf("  rapid removed %.3f mm3\n", rapid);
  CHECK(std::fabs(rapid - 124.0) <= 0.2);
  // Fixed: lifted before the rapid, the spindle on, the plunge to the floor.
  const std::string good = write_program("safety_good.ngc",
                                         "G21 G90\nG0 X-10 Y10 Z5\nG0 Z-1\nM3 S1000\nG1 X10 F300\nG0 Z5\nG0 X30\n"
                                         "G1 Z-1 F300\nG1 Y20 F300\nG1 X35 Y35 Z-5 F200\nG0 Z5\nM2\n");
  r = run(good + kStock + " -q --check all --table -6 --report " + tmp_dir() + "/safety_good.json");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_of(r.err, "warning:"), 0);
  CHECK(has(slurp(tmp_dir() + "/safety_good.json"), "\"collisions\": {\"total\": 0, \"rapid_removed_mm3\": 0.000, \"list\": []}"));
  // Frames flush the Mill's deferred end caps: the findings must not depend
  // on how often a frame is drawn (issue 25 item 2, core/cut/mill.h).
  r = run(bad + kStock + " -q --check all --table -6 --size 64x48 --frames " + tmp_dir() + "/safety_frames --every 1 "
          "--report " + tmp_dir() + "/safety_framed.json");
  CHECK(collisions_of(slurp(tmp_dir() + "/safety_framed.json")) == c);
  // M3 with no S word: the spindle turns (at the controller's default
  // speed); a record's rpm is 0 there, as after M5 (cameo.nc's false alarm).
  const std::string no_s = write_program("safety_no_s.ngc", "G21 G90\nG0 X-10 Y10 Z5\nM3\nG1 Z-1 F300\nG1 X10\nG0 Z5\nM2\n");
  r = run(no_s + kStock + " -q --check all --report /dev/null");
  CHECK_EQ(count_of(r.err, "warning:"), 0);
  // Without --check the report says null and nothing is watched.
  r = run(bad + kStock + " -q --report " + tmp_dir() + "/safety_off.json");
  CHECK_EQ(count_of(r.err, "warning:"), 0);
  CHECK(has(slurp(tmp_dir() + "/safety_off.json"), "\"collisions\": null"));
}

TEST(safety_end_cap_is_charged_to_the_move_that_made_it) {
  if (skip()) return;
  // A plunge (feed, spindle on), then a rapid straight up: the Mill cuts the
  // plunge's end cap with the rapid, but the rapid removes nothing.
  const std::string p = write_program("safety_cap.ngc", "G21 G90\nM3 S1000\nG0 X20 Y20 Z5\nG1 Z-2 F100\nG0 Z5\nM2\n");
  const Result r = run(p + kStock + " -q --check all --report /dev/null");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_of(r.err, "warning:"), 0);
}

TEST(safety_stop_and_fail_exit_4) {
  if (skip()) return;
  const std::string bad = tmp_dir() + "/safety_bad.ngc";
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
