// The copy of a program that cannot be read twice
// (platform/input/program_input.h): bounded where the reading stops (/dev/zero,
// binary data), by --max-input beyond that, its write errors said with
// their cause, and what a killed run left removed by the next copy. Each
// run here is under `ulimit -f` so that a copy without bound fails fast
// instead of filling the disk.
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

std::string fresh_dir(const char* name) {
  const std::string d = tmp_dir() + "/spool-" + name;
  std::system(("rm -rf '" + d + "' && mkdir -p '" + d + "'").c_str());
  return d;
}

// `dexmill run ARGS` with TMPDIR=dir, its files at most about 10 MB
// (ulimit -f counts 512-byte blocks in sh), fed by `feed |` when given.
Result spooled_run(const std::string& dir, const std::string& feed, const std::string& args) {
  return run_shell((feed.empty() ? "" : feed + " | ") + "(ulimit -f 20000; TMPDIR='" + dir + "' exec timeout 60 {bin} run " +
                   args + ")");
}

}  // namespace

TEST(run_copy_of_endless_or_binary_input_stops_early) {
  if (skip()) return;
  const std::string d = fresh_dir("endless");
  // /dev/zero is one line with no end: the reading stops after 1 MiB, the
  // copy with it (it used to copy 1.17 GB in 2 s, and on).
  Result r = spooled_run(d, "cat /dev/zero", "- -q");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "<stdin>:1:257: error: line is longer than 256 characters"));
  r = spooled_run(d, "", "/dev/zero -q");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "/dev/zero:1:257: error: line is longer than 256 characters"));
  // Binary data is "not a text file" on its first 64 KiB; nothing more is copied.
  r = spooled_run(d, "head -c 30000000 /dev/zero | tr '\\000' '\\001'", "- -q");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "<stdin>:1:1: error: not a text file"));
  CHECK_EQ(count_prefixed(d, "dexmill-input-"), 0);
}

TEST(run_copy_beyond_max_input_is_refused) {
  if (skip()) return;
  const std::string d = fresh_dir("limit");
  Result r = spooled_run(d, "yes 'G1 X1 Y1 F100'", "- -q --max-input 1");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "dexmill: error: standard input is larger than 1 MiB"));
  CHECK(has(r.err, "--max-input MIB raises it"));
  CHECK_EQ(count_prefixed(d, "dexmill-input-"), 0);
  // Within the limit it runs (60 000 lines, about 0.9 MB).
  r = spooled_run(d, "yes 'G1 X1 Y1 F100' | head -n 60000", "- -q --max-input 1 --grid 32x32");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(run("- --max-input 0").code, 2);
  CHECK_EQ(count_prefixed(d, "dexmill-input-"), 0);
}

TEST(run_copy_write_error_says_why) {
  if (skip()) return;
  const std::string d = fresh_dir("efbig");
  // Past `ulimit -f` (50 KiB): EFBIG, reported, and the copy removed (SIGXFSZ
  // used to kill the run and leave it; a short write said "Success").
  const Result r = run_shell("yes 'G1 X1 Y1 F100' | (ulimit -f 100; TMPDIR='" + d + "' exec {bin} run - -q)");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, ("dexmill: error: cannot keep standard input in '" + d + "/dexmill-input-").c_str()));
  CHECK(has(r.err, "': File too large"));
  CHECK_EQ(count_prefixed(d, "dexmill-input-"), 0);
}

TEST(run_copy_removes_what_a_killed_run_left) {
  if (skip()) return;
  const std::string d = fresh_dir("killed");
  // A run killed while it copies leaves its copy (SIGKILL has no handler) ...
  Result r = run_shell("{ echo 'G0 X1'; sleep 2; } | TMPDIR='" + d + "' {bin} run - -q & pid=$!; sleep 0.5; kill -KILL $pid; { wait $pid; } 2>/dev/null");  // dead, its lock gone, before the next run looks
  CHECK_EQ(count_prefixed(d, "dexmill-input-"), 1);
  // ... which the next copy removes, but not a live run's (held: its lock).
  const std::string live = d + "/dexmill-input-Live1234";
  const int fd = open(live.c_str(), O_RDWR | O_CREAT, 0600);
  CHECK(fd >= 0 && flock(fd, LOCK_EX) == 0);
  r = run_shell("echo 'G0 X1' | TMPDIR='" + d + "' {bin} run - -q");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(count_prefixed(d, "dexmill-input-"), 1);
  CHECK_EQ(access(live.c_str(), F_OK), 0);
  if (fd >= 0) close(fd);
  unlink(live.c_str());
}
