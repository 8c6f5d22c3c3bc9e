// The GNU forms of the command line on every subcommand (tools/cli/option_parse.h):
// `--opt=value` does what `--opt value` does, `--` ends the options (a file
// whose name begins with '-' is then an operand, and without it an unknown
// option), and a misspelled option gets "did you mean" when a name is close
// and no guess when none is.
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// pocket.ngc as "-p.ngc" in the temporary folder (the commands run there).
void dash_program() { write_file(tmp_dir() + "/-p.ngc", slurp(std::string(t::tests_dir()) + "/run/pocket.ngc")); }

Result in_tmp(const std::string& args) { return run_command(args, nullptr, true); }

// The usage error of a misspelling: with the guess when `close`, else none.
void misspelled(const std::string& args, const char* typed, const char* close) {
  const Result r = in_tmp(args);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, (std::string("unknown option '") + typed + "'").c_str()));
  if (close) CHECK(has(r.err, (std::string("; did you mean ") + close + "?").c_str()));
  else CHECK_EQ(r.err.find("did you mean"), std::string::npos);
}

// "-p.ngc" without `--` is an option, which no subcommand has.
void dash_file_needs_double_dash(const std::string& command) {
  const Result r = in_tmp(command + " -p.ngc");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "unknown option '-p.ngc'"));
}

}  // namespace

TEST(cli_forms_run) {
  if (skip()) return;
  dash_program();
  const Result spaced = in_tmp("run -q --pitch 0.5 -- -p.ngc");
  CHECK_EQ(spaced.code, 0);
  CHECK(has(spaced.out, "-p.ngc: 23 blocks run"));
  CHECK(has(spaced.out, "pitch 0.5000 mm"));
  CHECK_EQ(in_tmp("run -q --pitch=0.5 -- -p.ngc").out, spaced.out);
  const Result bad = in_tmp("run -q --pitch=-1 -- -p.ngc");
  CHECK_EQ(bad.code, 2);
  CHECK(has(bad.err, "--pitch needs a dexel spacing"));
  CHECK_EQ(in_tmp("run -q --image=%/forms.png -- -p.ngc").code, 0);
  CHECK_EQ(slurp(tmp_dir() + "/forms.png").compare(1, 3, "PNG"), 0);
  dash_file_needs_double_dash("run -q");
  misspelled("run x.ngc --pitc 0.5", "--pitc", "--pitch");
  misspelled("run --frobnicate", "--frobnicate", nullptr);
}

TEST(cli_forms_check) {
  if (skip()) return;
  dash_program();
  const Result r = in_tmp("check --max-errors=1 -- -p.ngc");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.err, std::string("-p.ngc: ok, 23 blocks, 0 warnings\n"));
  CHECK_EQ(in_tmp("check --max-errors=x -- -p.ngc").code, 2);
  dash_file_needs_double_dash("check");
  misspelled("check --max-erors 1 x.ngc", "--max-erors", "--max-errors");
  misspelled("check --frobnicate x.ngc", "--frobnicate", nullptr);
}

TEST(cli_forms_path) {
  if (skip()) return;
  dash_program();
  const Result spaced = in_tmp("path --chord 0.5 -- -p.ngc");
  CHECK_EQ(spaced.code, 0);
  CHECK(has(spaced.out, "tol=0.5\n"));
  CHECK_EQ(in_tmp("path --chord=0.5 -- -p.ngc").out, spaced.out);
  dash_file_needs_double_dash("path");
  misspelled("path --chrd 0.5 x.ngc", "--chrd", "--chord");
  misspelled("path --frobnicate x.ngc", "--frobnicate", nullptr);
}

TEST(cli_forms_optimize) {
  if (skip()) return;
  dash_program();
  const Result spaced = in_tmp("optimize --material aluminium -- -p.ngc");
  CHECK_EQ(spaced.code, 0);
  CHECK(has(spaced.out, "G21 G90 G17 G94"));
  CHECK_EQ(in_tmp("optimize --material=aluminium -- -p.ngc").out, spaced.out);
  dash_file_needs_double_dash("optimize --material aluminium");
  misspelled("optimize --materal aluminium x.ngc", "--materal", "--material");
  misspelled("optimize --frobnicate x.ngc", "--frobnicate", nullptr);
}

TEST(cli_forms_zig) {
  if (skip()) return;
  const Result spaced = in_tmp("zig smiley --stepover 2");
  CHECK_EQ(spaced.code, 0);
  CHECK(has(spaced.out, "stripes along x every 2.0000 mm"));
  CHECK_EQ(in_tmp("zig smiley --stepover=2").out, spaced.out);
  // A design file named "-flat.stl", after `--`.
  write_file(tmp_dir() + "/-flat.stl", "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 -5\nvertex 10 0 -5\n"
                                       "vertex 10 10 -5\nendloop\nendfacet\nendsolid f\n");
  const Result dashed = in_tmp("zig --stock 0,0,-10,10,10,0 --stepover 2 -- -flat.stl");
  CHECK_EQ(dashed.code, 0);
  CHECK(has(dashed.out, "(dexmill zig: -flat.stl, "));
  const Result undashed = in_tmp("zig --stock 0,0,-10,10,10,0 -flat.stl");
  CHECK_EQ(undashed.code, 2);
  CHECK(has(undashed.err, "unknown option '-flat.stl'"));
  misspelled("zig smiley --stepovr 2", "--stepovr", "--stepover");
  misspelled("zig smiley --frobnicate", "--frobnicate", nullptr);
}

TEST(cli_forms_bench) {
  if (skip()) return;
  const Result list = in_tmp("bench --list");
  CHECK_EQ(list.code, 0);
  CHECK(has(list.out, "api-lines\n"));
  // A switch takes no value, in the = form either.
  const Result valued = in_tmp("bench --list=1");
  CHECK_EQ(valued.code, 2);
  CHECK(has(valued.err, "--list takes no value"));
  // After `--`, "--list" is a benchmark's name (there is none).
  const Result named = in_tmp("bench -- --list");
  CHECK_EQ(named.code, 2);
  CHECK(has(named.err, "no benchmark matches"));
  misspelled("bench --lis", "--lis", "--list");
  misspelled("bench --frobnicate", "--frobnicate", nullptr);
}
