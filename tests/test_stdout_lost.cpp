// An output on standard output that is lost is an I/O error (exit 3,
// tools/CLI.md):
// closed (`>&-`, which platform/os/process.cpp used to fill with a writable
// /dev/null, so that every write "succeeded") or full (/dev/full, where the
// summary's failed flush went unchecked). Each command that writes to
// standard output, both ways: exit 3 and a message saying so, where all
// exited 0 with `>&-`.
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

struct Case {
  const char* args;
  const char* closed;  // the message with >&-
};

const Case kCases[] = {
    {"run pocket.ngc -q --report -", "cannot write --report -: standard output is closed"},
    {"run pocket.ngc -q --size 32x24 --image -", "cannot write --image -: standard output is closed"},
    {"run pocket.ngc -q", "cannot print the summary: standard output is closed"},
    {"path pocket.ngc", "cannot print the path: standard output is closed"},
    {"optimize pocket.ngc --material wood", "cannot write the program: standard output is closed"},
    {"zig smiley --grid 64x64", "cannot write the program: standard output is closed"},
    {"--help", "cannot write standard output: it is closed"},
};

}  // namespace

TEST(stdout_closed_is_an_io_error) {
  if (skip()) return;
  for (const Case& c : kCases) {
    const Result r = run_shell(std::string("{bin} ") + c.args + " >&-");
    CHECK_EQ(r.code, 3);
    CHECK(has(r.err, (std::string("dexmill: error: ") + c.closed).c_str()));
    if (r.code != 3) std::printf("  (%s)\n", c.args);
  }
}

TEST(stdout_full_is_an_io_error) {
  if (skip()) return;
  for (const Case& c : kCases) {
    const Result r = run_shell(std::string("{bin} ") + c.args + " >/dev/full");
    CHECK_EQ(r.code, 3);
    CHECK(has(r.err, "standard output: No space left on device"));
    if (r.code != 3) std::printf("  (%s)\n", c.args);
  }
}

TEST(stdout_closed_does_not_matter_when_nothing_goes_there) {
  if (skip()) return;
  const Result r = run_shell("{bin} run pocket.ngc -q --tool flat:6 --size 32x24 --image %/closed.png >&-");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.err, std::string());
}
