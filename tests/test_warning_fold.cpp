// Repeated warnings fold into one (platform/input/warning_fold.h): the list and
// its text, then `dexmill check` and `run` on a program with 64 identical
// warnings (stderr, the report, the summary's count), the process rules'
// warnings of one missing spindle speed, and what must stay apart:
// different messages, a single warning (no count), warnings on either side
// of an error. And check's one line for a program with no error.
#include <string>

#include "platform/input/warning_fold.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// Lines 1-2 set up, then 64 pairs: a cut (lines 3, 5, ...) and an M123
// (lines 4, 6, ... 130), which is ignored with a warning, one distinct
// warning more (M124, line 131), the end: 132 lines.
std::string flood(const char* name, bool error_between = false) {
  std::string s = "G21 G90 G0 X0 Y0 Z5\nM3\n";
  for (int k = 0; k < 64; ++k) {
    s += "G1 Z-1 X" + std::to_string(k % 2 * 20) + " Y" + std::to_string(3 * k) + " F100\n";  // fresh stock each
    s += error_between && k == 32 ? "G1 Q\n" : "M123\n";
  }
  s += "M124\nM30\n";
  return write_tmp(name, s.c_str());
}

size_t count_of(const std::string& s, const std::string& part) {
  size_t n = 0;
  for (size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(warning_list_folds_by_file_and_message) {
  dexmill::WarningList l(2);
  CHECK(l.add("a.ngc", 4, 1, "M123 ignored"));
  CHECK(l.add("a.ngc", 9, 3, "M123 ignored"));
  CHECK(l.add("a.ngc", 7, 1, "M123 ignored"));
  CHECK(l.add("b.ngc", 5, 1, "M123 ignored"));  // another file: apart
  CHECK(!l.add("a.ngc", 8, 1, "M124 ignored"));  // full: a new one is not kept...
  CHECK(l.add("a.ngc", 10, 1, "M123 ignored"));  // ...a repeat still counts
  CHECK_EQ(l.entries().size(), 2u);
  const dexmill::FoldedWarning& w = l.entries()[0];
  CHECK_EQ(w.count, 4u);
  CHECK_EQ(w.line, 4u);
  CHECK_EQ(w.column, 1u);
  CHECK_EQ(w.last_line, 10u);
  CHECK_EQ(dexmill::folded_warning_text(w), std::string("a.ngc:4:1: warning: M123 ignored (4 times, lines 4 to 10)"));
  CHECK_EQ(dexmill::folded_warning_text(l.entries()[1]), std::string("b.ngc:5:1: warning: M123 ignored"));
  dexmill::FoldedWarning loop{"c.ngc", "x", 3, 1, 3, 5};
  CHECK_EQ(dexmill::folded_warning_text(loop), std::string("c.ngc:3:1: warning: x (5 times, all on line 3)"));
}

TEST(check_folds_64_identical_warnings_into_one) {
  if (skip()) return;
  const std::string p = flood("fold-check.ngc");
  const Result r = run_command("check " + p);
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_of(r.err, "M123 ignored"), 1u);
  CHECK(has(r.err, ":4:1: warning: M123 ignored (it does not move the tool) (64 times, lines 4 to 130)\n"));
  // A different message is a line of its own, with no count.
  CHECK(has(r.err, ":131:1: warning: M124 ignored (it does not move the tool)\n"));
  // The count is of every warning, as they came.
  CHECK(has(r.err, "fold-check.ngc: ok, 132 blocks, 65 warnings\n"));
}

TEST(check_keeps_warnings_apart_across_an_error) {
  if (skip()) return;
  const std::string p = flood("fold-error.ngc", true);
  const Result r = run_command("check " + p);
  CHECK_EQ(r.code, 1);
  // Before the error (lines 4..64), the error (line 68), after it (70..130).
  const size_t before = r.err.find(":4:1: warning: M123 ignored (it does not move the tool) (32 times, lines 4 to 66)");
  const size_t error = r.err.find(":68:4: error: ");
  const size_t after = r.err.find(":70:1: warning: M123 ignored (it does not move the tool) (31 times, lines 70 to 130)");
  CHECK(before != std::string::npos);
  CHECK(error != std::string::npos);
  CHECK(after != std::string::npos);
  CHECK(before < error && error < after);
  CHECK_EQ(r.err.find(": ok, "), std::string::npos);  // an error: no "ok" line
}

TEST(run_folds_warnings_on_stderr_and_in_the_report) {
  if (skip()) return;
  const std::string p = flood("fold-run.ngc");
  Result r = run(p + " --tool flat:2 --report %/fold-run.json");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_of(r.err, "M123 ignored"), 1u);
  CHECK(has(r.err, ":4:1: warning: M123 ignored (it does not move the tool) (64 times, lines 4 to 130)\n"));
  const std::string rep = slurp(tmp_dir() + "/fold-run.json");
  CHECK(has(rep, "{\"line\": 4, \"column\": 1, \"message\": \"M123 ignored (it does not move the tool)\", \"count\": 64, "
                 "\"last_line\": 130}"));
  // A warning that came once has no count.
  CHECK(has(rep, "{\"line\": 131, \"column\": 1, \"message\": \"M124 ignored (it does not move the tool)\"}"));
  CHECK(has(rep, "\"warnings_total\": 65"));
  r = run(p + " --tool flat:2");
  CHECK(has(r.out, "warnings 65 (2 distinct, on standard error)\n"));
  // One warning: no "distinct".
  CHECK(has(run("pocket.ngc").out, "warnings 1 (on standard error)\n"));
}

TEST(run_folds_one_missing_spindle_speed) {
  if (skip()) return;
  // M3 with no S: every line that cuts aluminium breaks its spindle range.
  const std::string p = flood("fold-spindle.ngc");
  const Result r = run(p + " --tool flat:2 --material aluminium");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_of(r.err, "spindle 0 rpm outside aluminium's range"), 1u);
  CHECK(has(r.err, "warning: spindle 0 rpm outside aluminium's range 6000..24000 rpm (64 times, lines "));
  CHECK(has(r.out, "process  "));
}

TEST(check_says_ok_in_one_line) {
  if (skip()) return;
  Result r = run_command("check pocket.ngc");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.err, std::string("pocket.ngc: ok, 23 blocks, 0 warnings\n"));
  CHECK(r.out.empty());
  r = run_command("check arcs_inch.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "arcs_inch.ngc: ok, "));
  // An error: the errors, no "ok".
  r = run_command("check bad_word.ngc");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "error: "));
  CHECK_EQ(r.err.find(": ok, "), std::string::npos);
}
