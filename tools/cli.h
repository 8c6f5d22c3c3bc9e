// The dexmill command line (../shared/CLI.md): subcommands and exit codes.
#ifndef DEXMILL_TOOLS_CLI_H
#define DEXMILL_TOOLS_CLI_H

#include <stdint.h>

namespace dexmill {
namespace cli {

// Exit status, CLI.md: 0 success, 1 input errors, 2 usage, 3 I/O, 4 the
// program ran and failed a check the user asked for (--stop-at, --fail-on-*).
enum Exit : int { kExitOk = 0, kExitInput = 1, kExitUsage = 2, kExitIo = 3, kExitCheck = 4 };

int main(int argc, char** argv);

// Subcommands: argv[0] is the subcommand's name.
int cmd_run(int argc, char** argv);
int cmd_path(int argc, char** argv);
int cmd_check(int argc, char** argv);
int cmd_bench(int argc, char** argv);
int cmd_optimize(int argc, char** argv);
int cmd_zig(int argc, char** argv);

// The value of --units: "mm" or "inch" into *inch; else prints the usage
// error and returns false (the caller exits kExitUsage).
bool parse_units(const char* value, bool* inch);

// The value of --default-feed, mm/min, into *nm_per_min (nm/min): the
// controller's feed for moves made with no F in force. Else prints the
// usage error and returns false.
bool parse_default_feed(const char* value, int64_t* nm_per_min);

// A non-option argument of `dexmill CMD`: the one input file, into *file.
// Returns kExitOk, or prints the usage error for an unknown option or a
// second file and returns kExitUsage.
int take_input_file(const char* cmd, const char* arg, const char** file);

// `dexmill: error: MESSAGE` on stderr (printf-style); returns `code`.
int fail(int code, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

}  // namespace cli
}  // namespace dexmill

#endif
