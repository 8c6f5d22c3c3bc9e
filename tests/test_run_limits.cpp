// The host's limits (README.md "Limits"): memory that runs out at a
// documented grid (64 M dexels, --grid 8192x8192) is exit 3 with the size
// asked for, where it was an uncaught std::bad_alloc (exit 134); the stack
// the README states (64 KiB) is enough for the heaviest runs (`ulimit -s 128`
// used to make a 3-line run segfault: each GcodeFile held its 64 KiB read
// buffer on the stack, and `check --simulate` needed 192 KiB).
#include <dirent.h>

#include <cstdlib>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

#if defined(__SANITIZE_ADDRESS__)
#define DEXMILL_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DEXMILL_TEST_ASAN 1
#endif
#endif

namespace {

using namespace run_cli;

// AddressSanitizer reserves terabytes of address space (`ulimit -v` stops
// it before main) and makes stack frames larger.
bool skip_under_asan() {
#ifdef DEXMILL_TEST_ASAN
  std::printf("  (skipped: not a measure of the AddressSanitizer build)\n");
  return true;
#else
  return false;
#endif
}

const char* const kBigGrid = " -q --stock 0,0,-10,100,100,0 --grid 8192x8192";

}  // namespace

TEST(run_out_of_memory_is_exit_3_with_the_size) {
  if (skip() || skip_under_asan()) return;
  // The grid itself: the engine's block is asked for without throwing.
  Result r = run_shell(std::string("ulimit -v 200000; exec {bin} run pocket.ngc") + kBigGrid);
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "dexmill: error: cannot allocate "));
  CHECK(has(r.err, " MiB for the 8192x8192 grid"));
  // The grid fits, the heightmap does not.
  r = run_shell(std::string("ulimit -v 400000; exec {bin} run pocket.ngc") + kBigGrid + " --heightmap /dev/null");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "dexmill: error: cannot allocate 128 MiB for the 8192x8192 heightmap"));
  // Anything else (here the final frame's mesh): the size, and the copy of
  // standard input removed on the way out.
  const std::string spool = tmp_dir() + "/limits-spool";
  std::system(("rm -rf '" + spool + "' && mkdir -p '" + spool + "'").c_str());
  r = run_shell("cat pocket.ngc | (ulimit -v 400000; TMPDIR='" + spool + "' exec {bin} run -" + kBigGrid +
                " --image /dev/null)");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "dexmill: error: out of memory: cannot allocate "));
  CHECK_EQ(count_prefixed(spool, "dexmill-input-"), 0);
}

TEST(run_works_in_the_stated_stack) {
  if (skip() || skip_under_asan()) return;
  // The README's figure, with an empty environment (what it counts is the
  // binary's own use), for every output and check at once, the safety
  // checks of a holder and fixture (48 KiB), and the deepest expression a
  // line holds (core/gcode/expr.h: 39 KB of it in the reader; 80 KiB in
  // all, where 64 KiB faulted).
  const std::string out = tmp_dir() + "/limits-stack";
  std::system(("rm -rf '" + out + "' && mkdir -p '" + out + "'").c_str());
  const std::string deep = "G21 G90\nG0 X0 Y0 Z5\n#1=" + std::string(120, '[') + "1" + std::string(120, ']') +
                           "\nG1 X[#1] Z-1 F100\nM2\n";
  write_tmp("limits-stack/deep.ngc", deep.c_str());
  const char* const kRuns[] = {
      "run %/deep.ngc -q --tool flat:6 --stock 0,0,-5,10,10,0 --report %/deep.json",
      "run pocket.ngc -q --material wood --check all --path-overlay --every 20 --frames % --image %/a.png --stl %/a.stl "
      "--heightmap %/h.png --report %/r.json",
      "check --simulate collision.ngc --stock 0,0,-30,40,40,0 --tool flat:6,len=12,stick=25,holder=24x12,24-40x10 "
      "--fixture 42,12,-30,50,28,4",
      "path pocket.ngc",
      "optimize pocket.ngc --material wood",
  };
  for (const char* args : kRuns) {
    std::string a;
    for (const char* p = args; *p; ++p) a += *p == '%' ? out : std::string(1, *p);
    const Result r = run_shell("ulimit -s 128; exec env -i {bin} " + a);
    CHECK(r.code == 0 || r.code == 4);  // 4: the collision program's findings
    if (r.code != 0 && r.code != 4) std::printf("  (%s: exit %d)\n", args, r.code);
  }
}
