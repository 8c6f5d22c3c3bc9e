// Subcommand dispatch, --help and --version, and the hidden
// --man-options (the man page's option lists, tools/cli/option_help.h).
#include "tools/cli/cli.h"

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>

#include "platform/os/process.h"
#include "tools/cli/option_help.h"

namespace dexmill {
namespace cli {
namespace {

struct Command {
  const char* name;
  int (*fn)(int, char**);
  CommandDoc (*doc)();
};

const Command kCommands[] = {
    {"run", cmd_run, run_doc},
    {"path", cmd_path, path_doc},
    {"check", cmd_check, check_doc},
    {"bench", cmd_bench, bench_doc},
    {"optimize", cmd_optimize, optimize_doc},
    {"measure", cmd_measure, measure_doc},
    {"zig", cmd_zig, zig_doc},
};

void usage(FILE* f) {
  std::fprintf(f,
               "usage: dexmill COMMAND [ARGS]\n\n"
               "  dexmill run [FILE|-] [options]     simulate a program; no FILE: stdin, or the demo on a terminal\n"
               "  dexmill path FILE [--chord MM]     print the interpreted motion as a polyline\n"
               "  dexmill check FILE                 read and interpret a program, report errors only\n"
               "  dexmill bench [NAME...]            run benchmarks, one result line each\n"
               "  dexmill optimize FILE --material M the program with feeds set by its load or its materials' limits\n"
               "  dexmill measure STOCK --at X,Y     the simulated part a run saved (--save-stock), at a point\n"
               "  dexmill zig DESIGN --stock ...     a zig-milling finishing program from a design part\n"
               "  dexmill --help | --version         (also `dexmill COMMAND --help`)\n\n"
               "Exit status: 0 success, 1 input errors, 2 usage error, 3 I/O error, 4 a check\n"
               "you asked for failed (run --stop-at, --fail-on-gouge).\n");
}

}  // namespace

namespace {
std::string g_fail_place;  // FailPlace's; empty: "dexmill"
}  // namespace

FailPlace::FailPlace(const std::string& place) : was_(g_fail_place) { g_fail_place = place; }
FailPlace::~FailPlace() { g_fail_place = was_; }

int fail(int code, const char* fmt, ...) {
  std::fprintf(stderr, "%s: error: ", g_fail_place.empty() ? "dexmill" : g_fail_place.c_str());
  va_list ap;
  va_start(ap, fmt);
  std::vfprintf(stderr, fmt, ap);
  va_end(ap);
  std::fputc('\n', stderr);
  return code;
}

std::vector<CommandDoc> command_docs() {
  std::vector<CommandDoc> docs;
  for (const Command& c : kCommands) docs.push_back(c.doc());
  return docs;
}

namespace {

int dispatch(int argc, char** argv) {
  // Before any file is opened: a closed standard descriptor must not be
  // taken by one (platform/os/process.h), and a signal must not leave debris.
  fix_standard_descriptors();
  install_cleanup_handlers();
  if (argc < 2) {
    usage(stderr);
    return kExitUsage;
  }
  const char* sub = argv[1];
  if (!std::strcmp(sub, "--help") || !std::strcmp(sub, "-h") || !std::strcmp(sub, "help")) {
    usage(stdout);
    return kExitOk;
  }
  if (!std::strcmp(sub, "--man-options")) {
    print_man_options(command_docs(), stdout);
    return kExitOk;
  }
  if (!std::strcmp(sub, "--version")) {
    std::printf("dexmill 0.1\n");
    return kExitOk;
  }
  for (const Command& c : kCommands) {
    if (!std::strcmp(sub, c.name)) return c.fn(argc - 1, argv + 1);
  }
  fail(kExitUsage, "unknown command '%s' (try 'dexmill --help')", sub);
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  int code = dispatch(argc, argv);
  // Whatever wrote to standard output (a listing, the help, the summary),
  // a failed write, flush or close loses it: an I/O error (unless one was
  // reported already).
  std::string err;
  if (!close_standard_output(&err) && code != kExitIo) code = fail(kExitIo, "%s", err.c_str());
  return code;
}

}  // namespace cli
}  // namespace dexmill
