// Subcommand dispatch, --help and --version.
#include "tools/cli.h"

#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "core/math/decimal.h"
#include "platform/process.h"

namespace dexmill {
namespace cli {
namespace {

struct Command {
  const char* name;
  int (*fn)(int, char**);
  const char* summary;
};

const Command kCommands[] = {
    {"run", cmd_run, "simulate a program; with no FILE, the built-in demo"},
    {"path", cmd_path, "print the interpreted motion as a polyline"},
    {"check", cmd_check, "read and interpret a program, report errors only"},
    {"bench", cmd_bench, "run benchmarks, one result line each"},
    {"optimize", cmd_optimize, "the program with feeds lowered to its materials' limits"},
    {"zig", cmd_zig, "a zig-milling finishing program from a design part"},
};

void usage(FILE* f) {
  std::fprintf(f,
               "usage: dexmill COMMAND [ARGS]\n\n"
               "  dexmill run [FILE|-] [options]     simulate a program; with no FILE, the built-in demo\n"
               "  dexmill path FILE [--chord MM]     print the interpreted motion as a polyline\n"
               "  dexmill check FILE                 read and interpret a program, report errors only\n"
               "  dexmill bench [NAME...]            run benchmarks, one result line each\n"
               "  dexmill optimize FILE --material M the program with feeds lowered to its materials' limits\n"
               "  dexmill zig DESIGN --stock ...     a zig-milling finishing program from a design part\n"
               "  dexmill --help | --version         (also `dexmill COMMAND --help`)\n\n"
               "Exit status: 0 success, 1 input errors, 2 usage error, 3 I/O error, 4 a check\n"
               "you asked for failed (run --stop-at, --fail-on-gouge).\n");
}

}  // namespace

int fail(int code, const char* fmt, ...) {
  std::fprintf(stderr, "dexmill: error: ");
  va_list ap;
  va_start(ap, fmt);
  std::vfprintf(stderr, fmt, ap);
  va_end(ap);
  std::fputc('\n', stderr);
  return code;
}

bool parse_units(const char* value, bool* inch) {
  if (!std::strcmp(value, "mm")) *inch = false;
  else if (!std::strcmp(value, "inch")) *inch = true;
  else return fail(kExitUsage, "--units must be mm or inch, not '%s'", value), false;
  return true;
}

bool parse_default_feed(const char* value, int64_t* nm_per_min) {
  Decimal d;
  std::size_t pos = 0, n = std::strlen(value);
  const bool number = n && decimal_parse(value, n, &pos, &d) == DecimalParse::kOk && pos == n;
  *nm_per_min = number ? decimal_to_nm(d, false) : 0;
  if (*nm_per_min < 1000 || *nm_per_min > 1000000 * 1000000LL)
    return fail(kExitUsage, "--default-feed needs a feed in mm/min, from 0.001 to 1000000, not '%s'", value), false;
  return true;
}

int take_input_file(const char* cmd, const char* arg, const char** file) {
  if (arg[0] == '-' && arg[1]) return fail(kExitUsage, "unknown option '%s' (try 'dexmill %s --help')", arg, cmd);
  if (*file) return fail(kExitUsage, "more than one input file ('%s' and '%s')", *file, arg);
  *file = arg;
  return kExitOk;
}

int main(int argc, char** argv) {
  // Before any file is opened: a closed standard descriptor must not be
  // taken by one (platform/process.h), and a signal must not leave debris.
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

}  // namespace cli
}  // namespace dexmill
