// What `dexmill run` with no FILE cuts (tools/run/run_options.h
// choose_program): standard input when it is a file or a pipe, the
// built-in demo on a terminal or with --demo pocket, and a usage error
// naming `-` when standard input holds nothing.
#include <sys/stat.h>

#include <cstdlib>

#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

bool exists(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

// Absolute: the runs below change folder first.
std::string pocket() {
  char abs[4096];
  const std::string p = std::string(t::tests_dir()) + "/run/pocket.ngc";
  return realpath(p.c_str(), abs) ? abs : p;
}

}  // namespace

TEST(run_stdin_no_file_cuts_the_file) {
  if (skip()) return;
  // In a folder of its own: a demo would leave out/ there.
  Result r = run_shell("mkdir -p %/piped && cd %/piped && {bin} run -q --size 160x120 --image in.ppm --report in.json < '" +
                       pocket() + "'");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/piped/in.json"), "\"file\": \"<stdin>\""));
  CHECK(!exists(tmp_dir() + "/piped/out"));
  r = run("pocket.ngc -q --size 160x120 --image %/piped/file.ppm");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(file_hash(tmp_dir() + "/piped/in.ppm"), file_hash(tmp_dir() + "/piped/file.ppm"));
  CHECK(!slurp(tmp_dir() + "/piped/in.ppm").empty());
}

TEST(run_empty_stdin_no_file_is_refused) {
  if (skip()) return;
  const Result r = run_shell("mkdir -p %/empty && cd %/empty && {bin} run -q");  // standard input /dev/null
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "no FILE was given and standard input (not a terminal) is empty"));
  CHECK(has(r.err, "- to read standard input, or --demo pocket"));
  CHECK(r.out.empty());  // no summary of a demo
  CHECK(!exists(tmp_dir() + "/empty/out"));
  // `-` said outright reads the same empty input: a warning, no refusal.
  const Result dash = run("- -q", nullptr, true);
  CHECK_EQ(dash.code, 0);
  CHECK(has(dash.err, "the program is empty"));
  CHECK(has(dash.out, "<stdin>:"));
}

TEST(run_demo_pocket_by_name_and_on_a_terminal) {
  if (skip()) return;
  // By name, with standard input not a terminal.
  Result r = run_shell("mkdir -p %/named && cd %/named && {bin} run --demo pocket -q --size 80x60 --frames f --every 100000");
  CHECK_EQ(r.code, 0);
  CHECK(exists(tmp_dir() + "/named/out/demo.ngc"));
  CHECK(exists(tmp_dir() + "/named/out/final.ppm"));
  r = run("--demo pocket pocket.ngc");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--demo pocket runs the built-in demo's own program: give no FILE"));
  // On a terminal (script(1) gives the run one), no FILE is the demo.
  r = run_shell("command -v script >/dev/null || exit 77; mkdir -p %/tty && cd %/tty && "
                "script -qec \"{bin} run -q --size 80x60 --frames f --every 100000\" /dev/null");
  if (r.code == 77) {
    std::printf("  (no script(1): the terminal case is not run)\n");
    return;
  }
  CHECK_EQ(r.code, 0);
  CHECK(exists(tmp_dir() + "/tty/out/demo.ngc"));
  CHECK(exists(tmp_dir() + "/tty/out/final.ppm"));
}

TEST(run_demo_list_names_pocket) {
  if (skip()) return;
  const Result r = run("--demo list");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "pocket    the built-in demo"));
}
