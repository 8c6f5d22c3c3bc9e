// `dexmill path` and `dexmill check` as users run them: exit codes (tools/CLI.md:
// 0 ok, 1 input errors, 2 usage, 3 I/O) and the FILE:LINE:COL messages.
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "tests/runner.h"

namespace {

struct Result {
  int code = -1;
  std::string out;  // stdout and stderr together
};

Result sh(const std::string& args, const char* input = nullptr) {
  Result r;
  const char* bin = t::dexmill_binary();
  if (!bin) return r;
  std::string cmd;
  if (input) {
    std::FILE* f = std::fopen("/tmp/dexmill_cli_input.ngc", "wb");
    std::fputs(input, f);
    std::fclose(f);
  }
  cmd = std::string("'") + bin + "' " + args + " 2>&1";
  if (std::FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    int st = pclose(p);
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  }
  return r;
}

bool has(const std::string& s, const char* sub) { return s.find(sub) != std::string::npos; }

const char* kIn = "/tmp/dexmill_cli_input.ngc";

}  // namespace

TEST(cli_path_ok) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  Result r = sh(std::string("path ") + kIn, "G21\nG0 X1 Y2 Z3\nG1 X-0.000005 F100\nM2\n");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.out, std::string("# dexmill-path v1 units=mm frame=machine tol=0.001\n"
                              "# start 0.00000 0.00000 0.00000\n"
                              "rapid 1.00000 2.00000 3.00000\n"
                              "feed -0.00001 2.00000 3.00000\n"));
  r = sh(std::string("path --chord 0.5 ") + kIn, "G21 F1\nG0 X10\nG3 X-10 I-10\n");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "tol=0.5\n"));
  CHECK(has(r.out, "feed -10.00000 0.00000 0.00000\n"));
}

TEST(cli_path_errors) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  Result r = sh(std::string("path ") + kIn, "G21\nG0 X1\nG1 X2 Y\nG0 X5\n");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, "dexmill_cli_input.ngc:3:7: error: 'Y' is not followed by a number\n"));
  CHECK(!has(r.out, "rapid 5.0"));  // stops at the first error
  r = sh("path /nonexistent/file.ngc");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.out, "dexmill: error: cannot open '/nonexistent/file.ngc'"));
  r = sh("path");
  CHECK_EQ(r.code, 2);
  r = sh(std::string("path --chord 0 ") + kIn);
  CHECK_EQ(r.code, 2);
  r = sh(std::string("path --bogus ") + kIn);
  CHECK_EQ(r.code, 2);
  r = sh(std::string("path < ") + kIn + " -", "G21\nG0 X7\n");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "rapid 7.00000 0.00000 0.00000\n"));
}

TEST(cli_check_reports_all_errors) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  Result r = sh(std::string("check ") + kIn, "G21\nG0 X1\nM2\n");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.out, std::string("/tmp/dexmill_cli_input.ngc: ok, 3 blocks, 0 warnings\n"));  // one line, not silence
  r = sh(std::string("check ") + kIn, "G21\nG1 X1\nG0 X1 A1\n$H\nG2 X3 Y4 (no centre)\nM2\n");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, ":2:1: error: G1: feed move with zero feed rate"));
  CHECK(has(r.out, ":3:7: error: A axis is not supported"));
  CHECK(has(r.out, ":4:1: warning: grbl command '$H' skipped"));
  CHECK(has(r.out, ":5:1: error: G2: R, I, J and K words all missing for arc"));
  r = sh("check --help");
  CHECK_EQ(r.code, 0);
  r = sh("check a b");
  CHECK_EQ(r.code, 2);
}

// Odd input files: each gives one clear error and exit 1, or reads
// as the text it is.
TEST(cli_odd_input_files) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  // Endless input with no line end: the over-long line, not a hang.
  Result r = sh("check /dev/zero");
  CHECK_EQ(r.code, 1);
  CHECK_EQ(r.out, std::string("/dev/zero:1:257: error: line is longer than 256 characters\n"));
  r = sh("path - < /dev/zero");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, "<stdin>:1:257: error: line is longer than 256 characters\n"));
  // An executable is not a text file: one error, not one per line.
  r = sh(std::string("check '") + t::dexmill_binary() + "'");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, ":1:1: error: not a text file (binary data, such as the byte \\x7F; G-code is plain text)\n"));
  CHECK_EQ(r.out.find('\n'), r.out.size() - 1);
  // Old Mac line ends, and a UTF-8 byte-order mark.
  r = sh(std::string("path ") + kIn, "\xEF\xBB\xBFG21\rG0 X1\rG1 Y2 F100\rM2\r");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.out, std::string("# dexmill-path v1 units=mm frame=machine tol=0.001\n"
                              "# start 0.00000 0.00000 0.00000\n"
                              "rapid 1.00000 0.00000 0.00000\n"
                              "feed 1.00000 2.00000 0.00000\n"));
  r = sh(std::string("check ") + kIn, "G21\rG0 X1\rG1 Y2 Q\rM2\r");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, "dexmill_cli_input.ngc:3:7: error: 'Q' is not followed by a number\n"));
  // Typos, not missing features.
  r = sh(std::string("check ") + kIn, "G21\nG1 Y1O F100\nG1 @ F100\nM2\n");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, ":2:6: error: 'O' in the middle of a block: o-words start their line (a 0 typed as O?)\n"));
  CHECK(has(r.out, ":3:4: error: '@' is not followed by a number\n"));
}

// Programs that read without an error but are not what was meant: warnings
// (exit 0), in LinuxCNC's place an error for the first one.
TEST(cli_check_warns_about_cut_short_and_empty_programs) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  Result r = sh(std::string("check ") + kIn, "G21\nG0 X1\nG1 X2 F100\nG1 Y");
  CHECK_EQ(r.code, 1);  // the cut-off word is an error; the missing end a warning
  CHECK(has(r.out, "dexmill_cli_input.ngc:4:4: error: 'Y' is not followed by a number\n"));
  CHECK(has(r.out, "dexmill_cli_input.ngc:4:1: warning: the program ends without M2 or M30 (or a closing %): was the "
                   "file cut short?\n"));
  r = sh(std::string("check ") + kIn, "G21\nG0 X1\nG1 X2 F100\n");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, ":3:1: warning: the program ends without M2 or M30"));
  r = sh(std::string("check ") + kIn, "(nothing but a comment)\n\n");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(r.out, std::string("/tmp/dexmill_cli_input.ngc:1:1: warning: the program is empty (no G-code in it)\n"
                              "/tmp/dexmill_cli_input.ngc: ok, 2 blocks, 1 warning\n"));
  r = sh(std::string("path ") + kIn, "G21 M3 S1000\nG4 P1\nM30\n");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "dexmill_cli_input.ngc:1:1: warning: the program makes no move\n"));
}

// `check` reports each root error once; what follows from it is
// counted (and shown, marked, with --follow-ons).
TEST(cli_check_reports_each_root_error_once) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  const char* program = "G21\nG0 X1\nG1 X2\nG1 X3\nG1 X4\nM2\n";
  Result r = sh(std::string("check ") + kIn, program);
  CHECK_EQ(r.code, 1);
  CHECK_EQ(r.out, std::string("/tmp/dexmill_cli_input.ngc:3:1: error: G1: feed move with zero feed rate (set F first; "
                              "G93 and G94 set F to 0)\n"
                              "/tmp/dexmill_cli_input.ngc: 2 more error(s) not shown: each may only follow from one "
                              "above (--follow-ons shows them)\n"));
  r = sh(std::string("check --follow-ons ") + kIn, program);
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, ":5:1: error: G1: feed move with zero feed rate (set F first; G93 and G94 set F to 0) (may follow "
                   "from an earlier error)\n"));
  CHECK(!has(r.out, "not shown"));
  // An over-long line may have held anything (here the F).
  const std::string long_line = "G1 X1 F100 (" + std::string(300, 'x') + ")\nG1 X2\nM2\n";
  r = sh(std::string("check ") + kIn, long_line.c_str());
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, ":1:257: error: line is longer than 256 characters\n"));
  CHECK(has(r.out, ": 1 more error(s) not shown"));
}

TEST(cli_default_feed) {
  if (!CHECK(t::dexmill_binary() != nullptr)) return;
  // A grbl-style program that cuts before any F (it counts on the
  // controller's default feed: --default-feed).
  const char* prog = "G21\nG0 X1\nG1 X2\nG1 X3\nM2\n";
  Result r = sh(std::string("path ") + kIn, prog);
  CHECK_EQ(r.code, 1);
  CHECK(has(r.out, ":3:1: error: G1: feed move with zero feed rate"));
  r = sh(std::string("path --default-feed 800 ") + kIn, prog);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, ":3:1: warning: G1: feed move with no F in force: it and any later one take --default-feed "
                   "(800.0000 mm/min)\n"));
  CHECK(has(r.out, "feed 3.00000 0.00000 0.00000\n"));
  r = sh(std::string("check --default-feed 800 ") + kIn, prog);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "warning: G1: feed move with no F"));
  r = sh(std::string("run ") + kIn + " --default-feed 800 --stock 0,-5,-5,10,5,0 --grid 16x16 -q", prog);
  CHECK_EQ(r.code, 0);
  for (const char* bad : {"0", "-5", "fast", "1000001"}) {
    r = sh(std::string("path --default-feed ") + bad + " " + kIn, prog);
    CHECK_EQ(r.code, 2);
    CHECK(has(r.out, "--default-feed needs a feed in mm/min"));
  }
  r = sh(std::string("run --default-feed x ") + kIn);
  CHECK_EQ(r.code, 2);
}
