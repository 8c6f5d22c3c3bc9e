// `dexmill check FILE`: reads and interprets a whole program and reports
// every error it can (a bad block is skipped, the state stays as before it),
// and the warnings. Errors that may only follow from an earlier one
// (GcodeDiag::follow_on) are counted in one line at the end, not shown one by
// one, unless --follow-ons. Exit 0 when clean, 1 with errors.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/motion/interp.h"
#include "platform/gcode_file.h"
#include <vector>

#include "tools/cli.h"
#include "tools/read_options.h"
#include "tools/run_job.h"
#include "tools/run_options.h"

namespace dexmill {
namespace cli {
namespace {

void usage(std::FILE* f) {
  std::fprintf(f,
               "usage: dexmill check FILE|- [--max-errors N] [--follow-ons] [--units mm|inch]\n"
               "                            [--default-feed MM/MIN] [--subroutine-path DIR]\n"
               "                            [--max-blocks N] [--tools FILE]\n\n"
               "Reads and interprets the program as `path` does, reporting every error\n"
               "(FILE:LINE:COL: error: MESSAGE) and warning on stderr. A block with an\n"
               "error is skipped and changes nothing; errors that may only follow from\n"
               "an earlier one (a G1 after the bad line that set F) are counted, not\n"
               "shown. Exit 0 clean, 1 with errors.\n"
               "--max-errors: stop after N errors (default 100; 0 = no limit).\n"
               "--follow-ons: show those errors too, marked (they count towards N).\n"
               "%s\n"
               "       dexmill check --simulate FILE [run options]\n\n"
               "Cuts the program as `run` does with the safety checks (all unless --check\n"
               "names some) and, with --design, the gouge watch; writes no image. The findings\n"
               "are warnings; exit 4 when there is one, 0 when clean, 1 with input errors.\n",
               kReadOptionsUsage);
}

int check_simulate(int argc, char** argv) {
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i)
    if (std::strcmp(argv[i], "--simulate")) args.push_back(argv[i]);
  static char fail_on[] = "--fail-on-collision";  // the verdict: exit 4 on a finding, every check unless named
  args.push_back(fail_on);
  RunOptions o;
  bool help = false;
  const int parsed = parse_run_options(static_cast<int>(args.size()), args.data(), &o, &help);
  if (parsed != kExitOk || help) return parsed;
  if (o.file.empty()) return fail(kExitUsage, "check --simulate needs a program FILE (or - for stdin)");
  if (run_draws(o))
    return fail(kExitUsage, "check --simulate writes no images or models (use dexmill run); --report is fine");
  o.fail_on_gouge = !o.design.empty();
  o.print_summary = false;
  RunResult res;
  const int code = run_job(o, &res);
  if (res.finished)
    std::fprintf(stderr, "%s: %llu safety finding(s)%s\n", res.shown_name.c_str(),
                 static_cast<unsigned long long>(res.safety_findings),
                 o.design.empty() ? "" : (res.gouged ? ", gouged the design" : ", no gouge"));
  return code;
}

}  // namespace

int cmd_check(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--simulate")) return check_simulate(argc, argv);
  const char* file = nullptr;
  ReadOptions ro;
  long max_errors = 100;
  bool follow_ons = false;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
      usage(stdout);
      return kExitOk;
    }
    if (const int taken = take_read_option(argc, argv, &i, &ro)) {
      if (taken < 0) return kExitUsage;
      continue;
    }
    if (!std::strcmp(a, "--follow-ons")) {
      follow_ons = true;
      continue;
    }
    if (!std::strcmp(a, "--max-errors")) {
      if (i + 1 >= argc) return fail(kExitUsage, "--max-errors needs a value");
      char* end = nullptr;
      max_errors = std::strtol(argv[++i], &end, 10);
      if (!end || *end || max_errors < 0) return fail(kExitUsage, "--max-errors needs a count, not '%s'", argv[i]);
      continue;
    }
    if (const int code = take_input_file("check", a, &file)) return code;
  }
  if (!file) {
    usage(stderr);
    return kExitUsage;
  }
  GcodeFile in;
  if (!in.open(file)) return fail(kExitIo, "%s", in.error());
  GcodeStderrMessages msgs(in.name());
  GcodeNotes notes(in.name());
  ReadSetup setup;
  if (const int code = setup.load_tools(ro)) return code;
  InterpOptions opt;
  setup.apply(ro, &opt, &in);
  opt.warnings = &msgs;
  opt.messages = &notes;
  Interp interp(nullptr, opt);
  GcodeRunner runner(&in, &interp, &msgs, false);
  runner.show_follow_ons(follow_ons);
  while (runner.step()) {
    if (max_errors && msgs.errors() >= static_cast<uint32_t>(max_errors)) {
      std::fprintf(stderr, "%s: too many errors, stopped after %ld\n", in.name(), max_errors);
      break;
    }
  }
  if (runner.io_error()) return fail(kExitIo, "%s", in.error());
  if (runner.follow_ons() && !follow_ons)
    std::fprintf(stderr,
                 "%s: %u more error(s) not shown: each may only follow from one above (--follow-ons shows them)\n",
                 in.name(), static_cast<unsigned>(runner.follow_ons()));
  return msgs.errors() ? kExitInput : kExitOk;
}

}  // namespace cli
}  // namespace dexmill
