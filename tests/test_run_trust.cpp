// Trust in the input: the program is read once whatever it is (a pipe by
// name, a FIFO), a closed standard input is an error, a file changed
// between the passes is caught, and an interrupted run leaves no debris
// (a real signal to a real run); what a killed one leaves is
// tests/test_output_temps.cpp's.
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "platform/input/program_input.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

std::string binary_path() {
  char abs[4096];
  const char* bin = t::dexmill_binary();
  return realpath(bin, abs) ? abs : bin;
}

// Runs a shell command line; its exit status (128 + signal if killed).
int shell(const std::string& cmd) {
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

std::string fresh_dir(const char* name) {
  const std::string d = tmp_dir() + "/trust-" + name;
  std::system(("rm -rf '" + d + "' && mkdir -p '" + d + "'").c_str());
  return d;
}

// A program long enough to interrupt: 40 000 short zig moves.
std::string long_program(const std::string& dir) {
  const std::string path = dir + "/long.ngc";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return path;
  std::fputs("G21 G90 G0 X0 Y0 Z1\nG1 Z-1 F1000\n", f);
  for (int k = 0; k < 40000; ++k) std::fprintf(f, "G1 X%d Y%d.%d\n", (k % 2) * 40, k / 100, k % 100 / 10);
  std::fputs("M2\n", f);
  std::fclose(f);
  return path;
}

}  // namespace

TEST(run_reads_a_pipe_or_fifo_once) {
  if (skip()) return;
  const std::string d = fresh_dir("pipe"), bin = binary_path();
  const std::string prog = std::string(t::tests_dir()) + "/run/pocket.ngc";
  CHECK_EQ(run("pocket.ngc -q --report " + d + "/file.json").code, 0);
  const std::string want = report_body(d + "/file.json");
  auto removed = [](const std::string& report) {
    const size_t at = report.find("\"removed_mm3\"");
    return at == std::string::npos ? std::string() : report.substr(at, report.find(',', at) - at);
  };
  // A pipe by name: it was scanned, then read again empty (0 mm^3, exit 0).
  CHECK_EQ(shell("cat '" + prog + "' | '" + bin + "' run /dev/stdin -q --report '" + d + "/pipe.json' 2>'" + d + "/pipe.err'"), 0);
  CHECK(!removed(want).empty());
  CHECK_EQ(removed(slurp(d + "/pipe.json")), removed(want));
  // A FIFO: the second open() used to wait for a writer forever.
  CHECK_EQ(shell("mkfifo '" + d + "/fifo' && { cat '" + prog + "' > '" + d + "/fifo' & timeout 20 '" + bin + "' run '" + d +
                 "/fifo' -q --report '" + d + "/fifo.json' 2>'" + d + "/fifo.err'; r=$?; wait; exit $r; }"),
           0);
  CHECK_EQ(removed(slurp(d + "/fifo.json")), removed(want));
  // A closed standard input has no program: exit 3, not an empty cut.
  CHECK_EQ(shell("'" + bin + "' run - -q --report '" + d + "/closed.json' <&- 2>'" + d + "/closed.err'"), 3);
  CHECK(has(slurp(d + "/closed.err"), "standard input is closed"));
}

TEST(program_input_notices_a_changed_file) {
  const std::string d = fresh_dir("changed"), path = d + "/p.ngc";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f) {
    std::fputs("G0 X1\n", f);
    std::fclose(f);
  }
  dexmill::ProgramInput in;
  std::string err;
  CHECK(in.open(path, &err));
  CHECK(in.unchanged(&err));
  f = std::fopen(path.c_str(), "ab");
  if (f) {
    std::fputs("G0 X2\n", f);
    std::fclose(f);
  }
  CHECK(!in.unchanged(&err));
  CHECK(has(err, "changed while dexmill read it"));
  // Replaced by another file under the same name: caught too.
  dexmill::ProgramInput again;
  CHECK(again.open(path, &err));
  CHECK_EQ(shell("cp '" + path + "' '" + path + ".new' && mv '" + path + ".new' '" + path + "'"), 0);
  CHECK(!again.unchanged(&err));
}

TEST(run_interrupted_leaves_no_debris) {
  if (skip()) return;
  const std::string d = fresh_dir("signal"), bin = binary_path(), prog = long_program(d);
  for (const char* sig : {"INT", "TERM"}) {
    const std::string spool = d + "/spool-" + sig, frames = d + "/frames-" + sig;
    std::system(("mkdir -p '" + spool + "'").c_str());
    // Standard input (spooled), frames and an STL being written when the
    // signal comes.
    const std::string cmd = "cd '" + d + "' && { TMPDIR='" + spool + "' '" + bin + "' run - -q --size 64x48 --every 1 --frames '" +
                            frames + "' --stl '" + d + "/out.stl' < '" + prog + "' 2>/dev/null & pid=$!; " +
                            // Signalled once its first frame is out (at most 30 s), not after a
                            // fixed time a loaded machine may not keep.
                            "i=0; until ls '" + frames + "' 2>/dev/null | grep -q '^frame-' || [ $i -ge 300 ]; do " +
                            "sleep 0.1; i=$((i+1)); done; kill -" +
                            sig + " $pid; { wait $pid; } 2>/dev/null; exit $?; }";  // the shell's own "Terminated" notice is not ours
    const int code = shell(cmd);
    CHECK_EQ(code, std::string(sig) == "INT" ? 130 : 143);
    CHECK_EQ(count_names(frames, "tmp"), 0);
    CHECK(count_names(frames, "frame-") > 0);  // it was interrupted mid-run
    CHECK_EQ(count_names(d, "tmp"), 0);
    CHECK_EQ(count_names(spool, "dexmill-"), 0);
  }
}
