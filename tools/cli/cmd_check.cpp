// `dexmill check FILE`: reads and interprets a whole program and reports
// every error it can (a bad block is skipped, the state stays as before it),
// and the warnings. Errors that may only follow from an earlier one
// (GcodeDiag::follow_on) are counted in one line at the end, not shown one by
// one, unless --follow-ons; repeated warnings are folded
// (platform/input/warning_fold.h). A program with no error ends in one line,
// "FILE: ok, N blocks, W warnings". Exit 0 when clean, 1 with errors.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/interp/interp.h"
#include "platform/input/file_guard.h"
#include "platform/input/gcode_file.h"
#include "tools/cli/cli.h"
#include "tools/run/guard_inputs.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/read_options.h"
#include "tools/run/run_job.h"
#include "tools/run/run_option_table.h"

namespace dexmill {
namespace cli {
namespace {

// Both forms' settings: check's own, and run's for --simulate.
struct CheckArgs {
  std::string file;
  ReadOptions read;
  long max_errors = 100;
  bool follow_ons = false;
  RunOptions run;
};

int max_errors(CheckArgs* a, const char* v) {
  char* end = nullptr;
  a->max_errors = std::strtol(v, &end, 10);
  if (!end || *end || a->max_errors < 0) return fail(kExitUsage, "--max-errors needs a count, not '%s'", v);
  return kExitOk;
}

const Option<CheckArgs> kCheckOptions[] = {
    {"--max-errors", "N", "stop after N errors (default 100; 0: no limit)", max_errors},
    {"--follow-ons", nullptr, "show the errors that may only follow from an earlier one too, marked (they count towards N)",
     [](CheckArgs* a, const char*) -> int { return a->follow_ons = true, kExitOk; }},
};

// Its presence picks the table (cmd_check); parsed, it does nothing more.
const Option<CheckArgs> kSimulateOption[] = {
    {"--simulate", nullptr,
     "cut the program as dexmill run does instead, with run's options (below) in place of the ones here",
     [](CheckArgs*, const char*) -> int { return kExitOk; }},
};

const CommandText kCheckText = {
    "check",
    "usage: dexmill check FILE|- [--max-errors N] [--follow-ons] [reading options]\n"
    "       dexmill check --simulate FILE|- [run options]\n\n"
    "Reads and interprets the program as `path` does, reporting every error\n"
    "(FILE:LINE:COL: error: MESSAGE) and warning on stderr. A block with an\n"
    "error is skipped and changes nothing; errors that may only follow from\n"
    "an earlier one (a G1 after the bad line that set F) are counted, not\n"
    "shown; a repeated warning is one line with its count and last line. No\n"
    "error: one line, FILE: ok, N blocks, W warnings. Exit 0 clean, 1 with errors.\n\n"
    "With --simulate it cuts the program as `run` does with the safety checks (all\n"
    "unless --check names some) and, with --design, the gouge watch; writes no image.\n"
    "The findings are warnings; exit 4 when there is one, 0 when clean, 1 with input\n"
    "errors.\n",
    nullptr,
};

CheckArgs& whole(CheckArgs& a) { return a; }
ReadOptions& read_part(CheckArgs& a) { return a.read; }
RunOptions& run_part(CheckArgs& a) { return a.run; }

const OptionTable<CheckArgs>& check_table() {
  static const OptionTable<CheckArgs> t = [] {
    OptionTable<CheckArgs> table;
    table.text = &kCheckText;
    table.sections.push_back(section<CheckArgs>(nullptr, option_list(kCheckOptions), whole));
    table.sections.push_back(section<CheckArgs>(nullptr, option_list(kSimulateOption), whole));
    table.sections.push_back(section<CheckArgs>("Reading the program", read_option_list(), read_part));
    table.operand = [](CheckArgs* a, const char* arg, int index) -> int { return take_file(&a->file, arg, index); };
    return table;
  }();
  return t;
}

const OptionTable<CheckArgs>& simulate_table() {
  static const OptionTable<CheckArgs> t = [] {
    OptionTable<CheckArgs> table;
    table.text = &kCheckText;
    table.sections.push_back(section<CheckArgs>(nullptr, option_list(kSimulateOption), whole));
    table.sections.push_back(include<CheckArgs>("With --simulate", run_option_table(), run_part));
    table.operand = [](CheckArgs* a, const char* arg, int index) -> int { return run_operand(&a->run, arg, index); };
    return table;
  }();
  return t;
}

int check_simulate(int argc, char** argv) {
  CheckArgs a;
  // The verdict: exit 4 on a finding, every check unless --check names some.
  a.run.job.fail_on_collision = true;
  bool help = false;
  const int parsed = parse_options(simulate_table(), argc, argv, &a, &help);
  if (help) print_help(check_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (const int code = finish_run_options(&a.run)) return code;
  RunOptions& o = a.run;
  if (o.job.file.empty()) return fail(kExitUsage, "check --simulate needs a program FILE (or - for stdin)");
  if (run_draws(o))
    return fail(kExitUsage, "check --simulate writes no images or models (use dexmill run); --report is fine");
  o.job.fail_on_gouge = !o.job.design.empty();
  o.out.print_summary = false;
  RunResult res;
  FileGuard guard;
  const int code = run_job(o, &guard, &res);
  if (res.finished)
    std::fprintf(stderr, "%s: %llu safety finding(s)%s\n", res.shown_name.c_str(),
                 static_cast<unsigned long long>(res.safety_findings),
                 o.job.design.empty() ? "" : (res.gouged ? ", gouged the design" : ", no gouge"));
  return code;
}

}  // namespace

CommandDoc check_doc() {
  CommandDoc d = command_doc(check_table());
  for (const SectionDoc& sec : command_doc(simulate_table()).sections)
    if (sec.see) d.sections.push_back(sec);
  return d;
}

int cmd_check(int argc, char** argv) {
  if (option_in_args(argc, argv, "--simulate")) return check_simulate(argc, argv);
  CheckArgs a;
  bool help = false;
  const int parsed = parse_options(check_table(), argc, argv, &a, &help);
  if (help) print_help(check_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (a.file.empty()) {
    print_help(check_doc(), stderr);
    return kExitUsage;
  }
  const ReadOptions& ro = a.read;
  const long max_errors = a.max_errors;
  const bool follow_ons = a.follow_ons;
  FileGuard guard;  // it writes nothing, but reads the program, its subroutines and --tools
  if (const int code = guard_read_inputs(a.file, ro, &guard)) return code;
  GcodeFile in;
  if (!in.open(a.file.c_str())) return fail(kExitIo, "%s", in.error());
  in.set_guard(&guard);
  GcodeStderrMessages msgs(in.name());
  GcodeNotes notes(in.name());
  ReadSetup setup;
  if (const int code = setup.load_tools(ro, a.file)) return code;
  InterpOptions opt;
  setup.apply(ro, &opt, &in);
  opt.warnings = &msgs;
  opt.messages = &notes;
  Interp interp(nullptr, opt);
  GcodeRunner runner(&in, &interp, &msgs, false);
  runner.show_follow_ons(follow_ons);
  bool stopped = false;
  while (!stopped && runner.step()) stopped = max_errors && msgs.errors() >= static_cast<uint32_t>(max_errors);
  msgs.finish();  // the warnings held (platform/input/warning_fold.h), before the lines that end the listing
  if (stopped) std::fprintf(stderr, "%s: too many errors, stopped after %ld\n", in.name(), max_errors);
  if (runner.io_error()) return fail(in.refused() ? kExitUsage : kExitIo, "%s", in.error());
  if (runner.follow_ons() && !follow_ons)
    std::fprintf(stderr,
                 "%s: %u more error(s) not shown: each may only follow from one above (--follow-ons shows them)\n",
                 in.name(), static_cast<unsigned>(runner.follow_ons()));
  if (msgs.errors()) return kExitInput;
  // One line for a program with no error, so that silence never has to be
  // read as success; the warnings counted as they came (not as folded).
  std::fprintf(stderr, "%s: ok, %u blocks, %u warning%s\n", in.name(), static_cast<unsigned>(runner.lines()),
               static_cast<unsigned>(msgs.warnings()), msgs.warnings() == 1 ? "" : "s");
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
