// `dexmill optimize FILE --material M [run options] [-o OUT]` (feed
// optimisation; Vericut sells it as OptiPath): the program with every
// cutting move's feed lowered to the lowest max feed of the materials it
// removes, never raised above what was programmed, only F words changed.
// Three passes: the cut exactly as `dexmill run` makes it (tools/run/run_job.h,
// which gives each line's limit), the rewrite (tools/cam/optimize_pass.h), then
// the output, written whole or not at all.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "platform/input/file_guard.h"
#include "platform/os/output_file.h"
#include "platform/os/process.h"
#include "platform/input/program_input.h"
#include "platform/os/read_file.h"
#include "tools/cli/cli.h"
#include "tools/cam/feed_word.h"
#include "tools/run/guard_inputs.h"
#include "tools/cam/optimize_pass.h"
#include "tools/run/run_job.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/run/run_option_table.h"
#include "tools/run/run_tool_table.h"

namespace dexmill {
namespace cli {
namespace {

constexpr std::size_t kMaxProgramBytes = std::size_t(1) << 30;

struct OptimizeArgs {
  RunOptions run;
  std::string out = "-";
};

const Option<OptimizeArgs> kOptimizeOptions[] = {
    {"--output", "OUT", "write the program to OUT (replaced whole; it may be FILE itself) instead of standard output",
     [](OptimizeArgs* a, const char* v) -> int { return a->out = v, kExitOk; }, "-o", "a file (or - for standard output)"},
};

const CommandText kOptimizeText = {
    "optimize",
    "usage: dexmill optimize FILE|- --material PRESET|FILE [run options] [-o OUT]\n\n"
    "Writes the program to standard output (or OUT, replaced whole, which may be FILE\n"
    "itself) with each cutting move's feed lowered to the lowest max_feed among the\n"
    "materials it removes, as `dexmill run` cuts it with the same options (--stock,\n"
    "--grid/--pitch, --tool/--tools, --units, --mode ...). A feed is never raised:\n"
    "moves through air, rapids and moves within the limits keep theirs. Only F words\n"
    "change: a lowered line gets its F changed or one added, and the next line that\n"
    "runs at the programmed feed gets it back; every other byte stays as written.\n"
    "A line's moves share one F, so a canned cycle's line runs at its slowest hole's\n"
    "limit. Lowered feeds are written with at most 3 decimals (mm/min) or 4\n"
    "(inch/min, under G20), rounded down; an inverse-time move (G93) gets its F\n"
    "scaled by limit / rate, with 6 decimals, rounded down.\n",
    "Prints on standard error the lines changed and the estimated time before and\n"
    "after (--rapid, --accel as for run). Exit 0 ok, 1 input errors (the program, the\n"
    "material file, the tool table: nothing is written), 2 usage, 3 I/O.\n",
};

OptimizeArgs& whole(OptimizeArgs& a) { return a; }
RunOptions& run_part(OptimizeArgs& a) { return a.run; }

const OptionTable<OptimizeArgs>& optimize_table() {
  static const OptionTable<OptimizeArgs> t = [] {
    OptionTable<OptimizeArgs> table;
    table.text = &kOptimizeText;
    table.sections.push_back(section<OptimizeArgs>(nullptr, option_list(kOptimizeOptions), whole));
    table.sections.push_back(include<OptimizeArgs>("The cut", run_option_table(), run_part));
    table.operand = [](OptimizeArgs* a, const char* arg, int index) -> int { return run_operand(&a->run, arg, index); };
    return table;
  }();
  return t;
}

// "1:23.4" (minutes, seconds), or "h:mm:ss" from an hour.
std::string duration_text(int64_t us) {
  char b[48];
  const int64_t ds = (us + 50000) / 100000;  // tenths of a second
  if (ds >= 36000)
    std::snprintf(b, sizeof b, "%lld:%02lld:%02lld", static_cast<long long>(ds / 36000),
                  static_cast<long long>(ds / 600 % 60), static_cast<long long>(ds / 10 % 60));
  else
    std::snprintf(b, sizeof b, "%lld:%02lld.%lld", static_cast<long long>(ds / 600), static_cast<long long>(ds / 10 % 60),
                  static_cast<long long>(ds % 10));
  return b;
}

void print_summary(const std::string& name, const OptimizeResult& r) {
  std::string to;  // "2 to 1200 mm/min, 1 to 400 mm/min"
  for (auto it = r.lowered_to.rbegin(); it != r.lowered_to.rend(); ++it)
    to += std::string(to.empty() ? "" : ", ") + std::to_string(it->second) + " to " +
          feed_number(it->first, false, 3).text + " mm/min";
  std::fprintf(stderr, "%s: %u line(s) changed: %u feed(s) lowered%s, %u programmed feed(s) restored\n", name.c_str(),
               r.lines_changed, r.lines_lowered, to.empty() ? "" : (" (" + to + ")").c_str(), r.lines_restored);
  const double pct = r.before_us > 0 ? 100.0 * static_cast<double>(r.after_us - r.before_us) / static_cast<double>(r.before_us) : 0;
  if (r.left_over)
    std::fprintf(stderr, "%s: %u line(s) left over a limit (warned above)\n", name.c_str(), r.left_over);
  std::fprintf(stderr, "%s: estimated time %s before, %s after (%+.1f%%)\n", name.c_str(), duration_text(r.before_us).c_str(),
               duration_text(r.after_us).c_str(), pct);
}

}  // namespace

CommandDoc optimize_doc() { return command_doc(optimize_table()); }

int cmd_optimize(int argc, char** argv) {
  OptimizeArgs a;
  bool help = false;
  const int parsed = parse_options(optimize_table(), argc, argv, &a, &help);
  if (help) print_help(optimize_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (const int code = finish_run_options(&a.run)) return code;
  RunOptions& o = a.run;
  const std::string& out_path = a.out;
  if (o.job.file.empty()) return fail(kExitUsage, "optimize needs a program FILE (or - for standard input)");
  if (o.job.material.empty())
    return fail(kExitUsage, "optimize needs --material PRESET|FILE: the feeds are lowered to its materials' limits");
  if (run_draws(o) || !o.out.report.empty())
    return fail(kExitUsage, "optimize writes the program only (use dexmill run for images, models and reports)");
  if (o.job.stop_at_gouge || o.job.stop_at_collision || o.job.fail_on_gouge || o.job.fail_on_collision)
    return fail(kExitUsage, "optimize cuts the whole program: --stop-at and --fail-on-* are run's");
  // The output may be the program (read whole before it is written), no
  // other input; the cut registers the rest (platform/input/file_guard.h).
  FileGuard guard;
  if (const int code = guard_status(guard, guard.register_input(o.job.file, FileGuard::kProgram))) return code;
  if (const int code = guard_status(guard, guard.check_output(out_path == "-" ? "" : "-o", out_path, FileGuard::kProgram)))
    return code;

  std::string err;
  if (out_path == "-" && !standard_output_usable(&err)) return fail(kExitIo, "cannot write the program: %s", err.c_str());

  // The program as every pass reads it: a copy when it cannot be read twice.
  ProgramInput input;
  input.set_copy_limit(o.job.max_input_bytes);
  if (!input.open(o.job.file, &err)) return fail(input.too_large() ? kExitInput : kExitIo, "%s", err.c_str());
  const std::string shown = o.job.file == "-" ? "<stdin>" : o.job.file;
  o.job.shown_name = shown;
  o.job.file = input.read_path();
  o.job.strict = true;  // a program with an error is not rewritten
  o.job.feed_limits = true;
  o.out.print_summary = false;
  o.view.material_warnings = false;
  RunResult cut_result;
  const int cut = run_job(o, &guard, &cut_result);
  if (cut != kExitOk) return cut;
  const std::vector<int64_t>& limits = cut_result.line_feed_limits;

  std::vector<unsigned char> bytes;
  const ReadFile rf = read_whole_file(input.read_path(), kMaxProgramBytes, &bytes, &err);
  if (rf != ReadFile::kOk) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return rf == ReadFile::kTooLarge ? kExitInput : kExitIo;
  }
  ToolTableFile table;
  if (!o.job.read.tools_file.empty()) {
    const int t = load_read_tool_table(o.job.read, input.read_path(), &table);
    if (t != kExitOk) return t;
  }
  OptimizeInput in;
  in.read_path = input.read_path();
  in.shown_name = shown;
  in.inch = o.job.read.inch;
  SingleToolLibrary single(o.job.tool);  // without a table: the --tool radius for G41/G42, as the cut had it
  in.tools = o.job.read.tools_file.empty() ? static_cast<const ToolTable*>(&single) : &table;
  in.limits = &limits;
  in.time_model.rapid_nm_per_min = o.job.rapid_nm_per_min;
  in.time_model.accel_nm_per_s2 = o.job.accel_nm_per_s2;
  OptimizeResult res;
  const int pass = optimize_pass(in, &res);
  if (pass != kExitOk) return pass;
  // The splices are at offsets of the file the passes read: it must be the
  // one read into memory.
  if (!input.unchanged(&err)) return fail(kExitIo, "%s", err.c_str());
  const std::string program(bytes.begin(), bytes.end());
  const std::string text = apply_splices(program, res.splices);
  char e[1300];
  if (!write_output(out_path.c_str(), text.data(), text.size(), e, sizeof e)) return fail(kExitIo, "%s", e);
  print_summary(shown, res);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
