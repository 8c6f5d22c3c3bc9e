// Running `dexmill run` from tests: a command line with % for a temporary
// folder, its exit status, standard error and standard output; file hashes
// (the pinned ones are checked by tests/golden_check.h).
#ifndef DEXMILL_TESTS_RUN_CLI_UTIL_H
#define DEXMILL_TESTS_RUN_CLI_UTIL_H

#include <cstdint>
#include <string>
#include <vector>

namespace run_cli {

struct Result {
  int code = -1;
  std::string err, out;
};

// A temporary folder made once per test binary.
std::string tmp_dir();
std::string slurp(const std::string& path);
uint64_t fnv(const std::string& s);
uint64_t file_hash(const std::string& path);
// Runs `dexmill run ARGS` in the tests/run folder (so reports name the
// inputs without a path), or in the temporary folder when `in_tmp`; % in
// ARGS stands for the temporary folder. `prefix` goes before the command
// (e.g. a `setpriv` to run as another user).
Result run(const std::string& args, const char* stdin_file = nullptr, bool in_tmp = false, const std::string& prefix = "");
// Writes text to tmp_dir()/name; returns the path.
std::string write_tmp(const char* name, const char* text);
// Writes bytes (any, NULs too) to path.
void write_file(const std::string& path, const std::string& bytes);
// The same for any subcommand: args begin with it ("check --simulate ...").
Result run_command(const std::string& args, const char* stdin_file = nullptr, bool in_tmp = false,
                   const std::string& prefix = "");
// Runs a shell script in the tests/run folder, `{bin}` in it standing for
// the binary to test and % for the temporary folder: its exit status (-1
// when killed by a signal), standard error and standard output (what the
// script does not redirect itself).
Result run_shell(const std::string& script);
// How many names in folder dir hold `part` (0 without the folder), and how
// many begin with `prefix` (-1 without the folder).
int count_names(const std::string& dir, const char* part);
int count_prefixed(const std::string& dir, const char* prefix);
// True when s holds part; else prints both and returns false.
bool has(const std::string& s, const char* part);
// True when part is not in s; prints s when it is (has() prints when it is not).
bool lacks(const std::string& s, const char* part);
// The report without its wall-clock timing.
std::string report_body(const std::string& path);
// True (with a note) when the binary to test is unknown.
bool skip();
// The report's assessment object, from its key to the line before timing.
std::string assessment_of(const std::string& report);
// Pixels of a binary PPM (P6, maxval 255) as RGB triples, row by row,
// without its last `skip_bottom_rows` rows (a legend); empty if not one.
std::vector<unsigned char> ppm_rgb(const std::string& bytes, int skip_bottom_rows = 0);

// A PPM file's pixels with its size (w = h = 0, no pixels: not one).
struct Image {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * w + x) * 3]; }
};
Image read_ppm(const std::string& path);

}  // namespace run_cli

#endif
