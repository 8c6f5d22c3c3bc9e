// `dexmill optimize FILE --material M [run options] [-o OUT]` (feed
// optimisation; Vericut sells it as OptiPath): the program with every
// cutting move's feed lowered to the lowest max feed of the materials it
// removes, never raised above what was programmed, only F words changed.
// Three passes: the cut exactly as `dexmill run` makes it (tools/run/run_job.h,
// which gives each line's limit), the rewrite (tools/cam/optimize_pass.h), then
// the output, written whole or not at all.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "platform/input/file_guard.h"
#include "platform/os/output_file.h"
#include "platform/os/temp_file.h"
#include "platform/os/process.h"
#include "platform/input/program_input.h"
#include "platform/os/read_file.h"
#include "tools/cli/cli.h"
#include "tools/cam/feed_word.h"
#include "tools/run/guard_inputs.h"
#include "tools/cam/optimize_pass.h"
#include "core/safety/material_limits.h"
#include "tools/cam/optimize_target.h"
#include "tools/cli/option_values.h"
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
  OptimizeTarget target;
  bool have_min_feed = false, have_max_feed = false;
  int64_t split_min_nm = 5 * kNmPerMm;  // --split-min
  int64_t split_lines = 10000;          // --split-lines
  bool have_split = false;
};

int feed_value(const char* name, const char* v, int64_t* nm_per_min) {
  if (!parse_scaled(v, kNmPerMm, nm_per_min) || *nm_per_min <= 0 || *nm_per_min > kNoFeedLimit / 2)
    return fail(kExitUsage, "%s needs a feed in mm/min above 0, not '%s'", name, v);
  return kExitOk;
}

const Option<OptimizeArgs> kOptimizeOptions[] = {
    {"--output", "OUT", "write the program to OUT (replaced whole; it may be FILE itself) instead of standard output",
     [](OptimizeArgs* a, const char* v) -> int { return a->out = v, kExitOk; }, "-o", "a file (or - for standard output)"},
    {"--target", "chip-load[=MM]|power W|mrr MM3/MIN",
     "set each feed move's F by its measured load, raised in light cuts and lowered in heavy ones: the "
     "thickest chip at MM (or each material's max_chip), the spindle power at W, or the removal rate; moves "
     "in air get the highest feed, plunges keep theirs",
     [](OptimizeArgs* a, const char* v) -> int { return parse_target(v, &a->target); }},
    {"--min-feed", "MM/MIN", "with --target: the lowest feed it sets (10 unless given)",
     [](OptimizeArgs* a, const char* v) -> int {
       a->have_min_feed = true;
       return feed_value("--min-feed", v, &a->target.target.min_feed_nm_per_min);
     }},
    {"--max-feed", "MM/MIN", "with --target: the machine's highest feed (without it, the material's max_feed)",
     [](OptimizeArgs* a, const char* v) -> int {
       a->have_max_feed = true;
       return feed_value("--max-feed", v, &a->target.target.max_feed_nm_per_min);
     }},
    {"--split-min", "MM",
     "with --target: a straight move whose load changes along it is split into pieces (at most 8) at its "
     "changes, none shorter than MM (default 5)",
     [](OptimizeArgs* a, const char* v) -> int {
       a->have_split = true;
       if (!parse_scaled(v, kNmPerMm, &a->split_min_nm) || a->split_min_nm <= 0 || a->split_min_nm > 1000 * kNmPerMm)
         return fail(kExitUsage, "--split-min needs a length in mm above 0 and at most 1000, not '%s'", v);
       return kExitOk;
     }},
    {"--split-lines", "N",
     "with --target: the most lines the pieces add to the program (default 10000; 0: no move is split)",
     [](OptimizeArgs* a, const char* v) -> int {
       a->have_split = true;
       if (!parse_scaled(v, 1, &a->split_lines) || a->split_lines < 0 || a->split_lines > 100000000)
         return fail(kExitUsage, "--split-lines needs a whole number from 0 to 100000000, not '%s'", v);
       return kExitOk;
     }},
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
    "scaled by limit / rate, with 6 decimals, rounded down.\n\n"
    "With --target, each line's F is the feed that meets the target at its moves'\n"
    "engagement, measured on the stock before them (the lowest of its moves'),\n"
    "raised or lowered, at most --max-feed and the materials' max_feed, at least\n"
    "--min-feed, in whole mm/min (hundredths of inch/min) rounded down. A line\n"
    "whose moves removed nothing gets the highest feed; a plunge keeps its feed.\n"
    "A straight move whose load changes along it (it leaves the stock, breaks into\n"
    "a pocket) is written in pieces at its changes, before its own line: G91 G1\n"
    "lines at their feeds, then G90 and the line as written (--split-min,\n"
    "--split-lines). The output is then cut again, and a split whose pieces leave\n"
    "a dexel apart from the whole move's (the sweep's rounding) is undone: the\n"
    "output cuts the same stock, byte for byte.\n",
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

// What --target did: the lines raised and lowered, those whose moves
// kept their feed (plunges, moves with no spindle speed or coefficients
// to measure by), and the program's largest load it was measured at.
void print_target_summary(const std::string& name, const OptimizeTarget& t, const RunResult& cut, const OptimizeResult& r) {
  uint32_t kept = 0;
  for (size_t k = 0; k < cut.line_target_kept.size(); ++k) kept += cut.line_target_kept[k];
  std::fprintf(stderr, "%s: target %s: %u line(s) raised, %u lowered", name.c_str(), t.text.c_str(), r.lines_raised,
               r.lines_lowered);
  if (kept) std::fprintf(stderr, "; %u line(s) kept their feed (plunges, or moves the load cannot be measured on)", kept);
  std::fputc('\n', stderr);
  if (r.splits_undone)
    std::fprintf(stderr, "%s: %u split(s) undone where the pieces' sweep rounded a dexel apart from the whole move's: "
                 "the output cuts the same stock\n", name.c_str(), r.splits_undone);
  if (r.moves_split || r.splits_kept_whole || cut.splits_left)
    std::fprintf(stderr, "%s: %u long move(s) split where their load changes (%u line(s) added)%s\n", name.c_str(),
                 r.moves_split, r.lines_added,
                 r.splits_kept_whole || cut.splits_left
                     ? ("; " + std::to_string(r.splits_kept_whole + cut.splits_left) +
                        " left whole (a line with more than the move, or past --split-lines)").c_str()
                     : "");
  const EngageSummary& e = cut.engagement;
  if (cut.have_engagement)
    std::fprintf(stderr, "%s: before: thickest chip %.4f mm (line %u)%s\n", name.c_str(),
                 static_cast<double>(e.chip.chip.max_nm) * 1e-6, e.chip.line,
                 e.power.has_load ? (", largest power " + std::to_string((e.power.power_mw + 500) / 1000) + " W (line " +
                                     std::to_string(e.power.line) + ")").c_str()
                                  : "");
  if (r.lines_raised == 0 && r.lines_lowered == 0)
    std::fprintf(stderr, "%s: every feed move is already at the target or a limit: nothing to gain\n", name.c_str());
}

// The horizontal distance from (x, y) to the segment a-b (a reach test).
int64_t segment_distance_nm(const PointNm& a, const PointNm& b, int64_t x, int64_t y) {
  const double dx = static_cast<double>(b.x_nm - a.x_nm), dy = static_cast<double>(b.y_nm - a.y_nm);
  const double px = static_cast<double>(x - a.x_nm), py = static_cast<double>(y - a.y_nm);
  const double l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::min(1.0, std::max(0.0, (px * dx + py * dy) / l2)) : 0.0;
  return static_cast<int64_t>(std::hypot(px - t * dx, py - t * dy));
}

// Cuts `text` (the output) as the input was cut and lists the split lines
// whose move reaches a dexel where the two stocks differ (every split
// line when a difference is near none of them).
int split_differences(const RunOptions& o, const std::string& text, const RunResult& before, const OptimizeResult& res,
                      std::vector<uint32_t>* lines) {
  LockedTemp t;
  const char* dir = std::getenv("TMPDIR");
  if (!make_locked_temp(dir && *dir ? dir : "/tmp", "dexmill-optimize-", 0600, &t))
    return fail(kExitIo, "cannot make a temporary file to check the output: %s", std::strerror(errno));
  struct Remove {
    LockedTemp* t;
    ~Remove() {
      std::remove(t->path.c_str());
      release_locked_temp(t);
    }
  } remove{&t};
  const bool wrote = ::write(t.fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  if (::close(t.fd) != 0 || !wrote) return t.fd = -1, fail(kExitIo, "cannot write the output's check copy %s", t.path.c_str());
  t.fd = -1;
  RunOptions c = o;
  c.job.file = t.path;
  c.job.shown_name = "the output";
  c.job.engage_target = nullptr;
  c.job.feed_limits = false;
  c.job.split_rule = EngageSplitRule();
  c.job.keep_tops = c.job.silent = true;
  c.job.fail_on_load = c.job.fail_on_travel = false;  // the check compares stocks; its findings are the input's
  FileGuard guard;
  if (const int code = guard_status(guard, guard.register_input(c.job.file, FileGuard::kProgram))) return code;
  RunResult after;
  if (const int code = run_job(c, &guard, &after)) return code;
  if (after.tops.size() != before.tops.size()) return fail(kExitIo, "the output's check cut another grid");
  const GridGeometry& g = before.grid;
  const int64_t reach = before.max_tool_radius_nm + 2 * g.pitch_nm;
  bool any = false;
  for (size_t k = 0; k < before.tops.size(); ++k) {
    if (before.tops[k] == after.tops[k]) continue;
    any = true;
    const int64_t x = g.x0_nm + static_cast<int64_t>(k % static_cast<size_t>(g.nx)) * g.pitch_nm;
    const int64_t y = g.y0_nm + static_cast<int64_t>(k / static_cast<size_t>(g.nx)) * g.pitch_nm;
    for (const auto& m : res.split_moves)
      if (segment_distance_nm(m.second.start, m.second.end, x, y) <= reach &&
          std::find(lines->begin(), lines->end(), m.first) == lines->end())
        lines->push_back(m.first);
  }
  if (any && lines->empty())
    for (const auto& m : res.split_moves) lines->push_back(m.first);
  return kExitOk;
}

// Split moves: the output cut again, and every split whose pieces the
// sweep rounded differently from the whole move (a dexel one LSB apart
// within its reach) undone, until the output cuts the input's stock
// exactly (*splits, *res and *text the pass's again).
int check_splits(const RunOptions& o, const RunResult& cut, const std::string& program, OptimizeInput* in,
                 std::vector<EngageSplitPiece>* splits, OptimizeResult* res, std::string* text) {
  uint32_t undone = 0;
  for (int round = 0; res->moves_split > 0; ++round) {
    std::vector<uint32_t> lines;
    const int v = split_differences(o, *text, cut, *res, &lines);
    if (v != kExitOk) return v;
    if (lines.empty()) break;
    if (round == 2) lines.clear();  // still apart: no split at all
    auto undo = [&](uint32_t line) { return lines.empty() || std::find(lines.begin(), lines.end(), line) != lines.end(); };
    for (const auto& m : res->split_moves) undone += undo(m.first);
    std::vector<EngageSplitPiece> next;
    for (const EngageSplitPiece& p : *splits)
      if (!undo(p.line)) next.push_back(p);
    splits->swap(next);
    in->splits = splits;
    *res = OptimizeResult();
    if (const int again = optimize_pass(*in, res)) return again;
    *text = apply_splices(program, res->splices);
  }
  res->splits_undone = undone;
  return kExitOk;
}

}  // namespace

CommandDoc optimize_doc() { return command_doc(optimize_table()); }

int cmd_optimize(int argc, char** argv) {
  OptimizeArgs a;
  a.target.target.min_feed_nm_per_min = 10 * kNmPerMm;
  a.target.target.max_feed_nm_per_min = kNoFeedLimit;
  bool help = false;
  std::vector<std::string> words = join_target_words(argc, argv);
  std::vector<char*> args;
  for (std::string& w : words) args.push_back(&w[0]);
  args.push_back(nullptr);
  const int parsed = parse_options(optimize_table(), static_cast<int>(words.size()), args.data(), &a, &help);
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
  if (o.job.stop_at_gouge || o.job.stop_at_collision || o.job.fail_on_gouge || o.job.fail_on_collision ||
      o.job.fail_on_load || o.job.fail_on_travel)
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
  if (a.target.given) {
    o.job.engage_target = &a.target.target;
    o.job.keep_tops = true;  // the output's check compares its stock with this one
    o.job.split_rule.min_segment_nm = a.split_min_nm;
    o.job.split_rule.max_segments = a.split_lines > 0 ? kEngageMaxSegments : 0;
    o.job.split_pieces = static_cast<size_t>(a.split_lines);
  } else if (a.have_min_feed || a.have_max_feed || a.have_split) {
    return fail(kExitUsage, "--min-feed, --max-feed, --split-min and --split-lines are --target's: give --target");
  }
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
  in.feed_in_line_units = o.job.read.feed_in_line_units;
  in.default_feed_nm_per_min = o.job.read.default_feed_nm_per_min;
  {  // the first line's end says the program's
    const auto nl = std::find(bytes.begin(), bytes.end(), static_cast<unsigned char>('\n'));
    in.crlf = nl != bytes.begin() && nl != bytes.end() && *(nl - 1) == '\r';
  }
  SingleToolLibrary single(o.job.tool);  // without a table: the --tool radius for G41/G42, as the cut had it
  in.tools = o.job.read.tools_file.empty() ? static_cast<const ToolTable*>(&single) : &table;
  in.limits = &limits;
  if (a.target.given) {
    in.targets = &cut_result.line_target_feeds;
    in.splits = &cut_result.target_splits;
  }
  in.time_model.rapid_nm_per_min = o.job.rapid_nm_per_min;
  in.time_model.accel_nm_per_s2 = o.job.accel_nm_per_s2;
  in.time_model.blend = true;  // with --accel, as run's estimate
  OptimizeResult res;
  const int pass = optimize_pass(in, &res);
  if (pass != kExitOk) return pass;
  // The splices are at offsets of the file the passes read: it must be the
  // one read into memory.
  if (!input.unchanged(&err)) return fail(kExitIo, "%s", err.c_str());
  const std::string program(bytes.begin(), bytes.end());
  std::string text = apply_splices(program, res.splices);
  std::vector<EngageSplitPiece> kept_splits = cut_result.target_splits;
  if (const int code = check_splits(o, cut_result, program, &in, &kept_splits, &res, &text)) return code;
  char e[1300];
  if (!write_output(out_path.c_str(), text.data(), text.size(), e, sizeof e)) return fail(kExitIo, "%s", e);
  print_summary(shown, res);
  if (a.target.given) print_target_summary(shown, a.target, cut_result, res);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
