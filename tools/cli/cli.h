// The dexmill command line: subcommands and exit codes.
#ifndef DEXMILL_TOOLS_CLI_CLI_H
#define DEXMILL_TOOLS_CLI_CLI_H

#include <stdint.h>

#include <string>
#include <vector>

namespace dexmill {
namespace cli {

// Exit status: 0 success, 1 input errors, 2 usage, 3 I/O, 4 the program
// ran and failed a check the user asked for (--stop-at, --fail-on-*).
enum Exit : int { kExitOk = 0, kExitInput = 1, kExitUsage = 2, kExitIo = 3, kExitCheck = 4 };

int main(int argc, char** argv);

// Subcommands: argv[0] is the subcommand's name.
int cmd_run(int argc, char** argv);
int cmd_path(int argc, char** argv);
int cmd_check(int argc, char** argv);
int cmd_bench(int argc, char** argv);
int cmd_optimize(int argc, char** argv);
int cmd_measure(int argc, char** argv);
int cmd_zig(int argc, char** argv);

// Each subcommand's help, from its option table (tools/cli/option_table.h).
struct CommandDoc;
CommandDoc run_doc();
CommandDoc path_doc();
CommandDoc check_doc();
CommandDoc bench_doc();
CommandDoc optimize_doc();
CommandDoc measure_doc();
CommandDoc zig_doc();

// Every subcommand's, in the order of `dexmill --help`: what
// `dexmill --man-options` prints.
std::vector<CommandDoc> command_docs();

// `dexmill: error: MESSAGE` on stderr (printf-style); returns `code`.
int fail(int code, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

// While one is alive, fail() begins "PLACE: error: " instead: an option
// read from a file (tools/run/setups_file.h) names its FILE:LINE:COL.
class FailPlace {
 public:
  explicit FailPlace(const std::string& place);
  ~FailPlace();
  FailPlace(const FailPlace&) = delete;
  FailPlace& operator=(const FailPlace&) = delete;

 private:
  std::string was_;
};

}  // namespace cli
}  // namespace dexmill

#endif
