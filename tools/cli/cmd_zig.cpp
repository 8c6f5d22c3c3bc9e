// `dexmill zig DESIGN [options] > prog.ngc` (paper §3): a
// zig-milling finishing program generated from a design part: the design
// sampled on the grid `dexmill run` would use for the same --stock, --pitch
// or --grid and --tool, every tool position the lowest at which the tool
// touches but does not cut into it (core/cam/zig.h), written as plain
// RS274/NGC (tools/cam/zig_program.h). Simulating the program with the same
// options and --design reports no gouge (tests/test_zig_cli.cpp).
#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "platform/input/file_guard.h"
#include "platform/os/output_file.h"
#include "platform/os/process.h"
#include "platform/report/run_report.h"
#include "tools/cli/cli.h"
#include "tools/run/guard_inputs.h"
#include "tools/run/run_assess.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/run_option_table.h"
#include "tools/run/run_stock.h"
#include "tools/run/zig_job.h"

namespace dexmill {
namespace cli {
namespace {

// Options of zig's own; run's go to run's part.
struct ZigArgs {
  std::string design, out = "-";
  ZigJob job;
  bool feeds_given = false;  // --feed, --plunge-feed or --spindle
  RunOptions run;
};

// A length or feed in mm (mm/min) as written, within [min_nm, 1e6 mm].
bool parse_mm(const char* v, int64_t min_nm, int64_t* nm) {
  return parse_scaled(v, kNmPerMm, nm) && *nm >= min_nm && *nm <= 1000000 * kNmPerMm;
}

int positive_mm(const char* name, const char* v, int64_t* nm) {
  if (!parse_mm(v, 1, nm)) return fail(kExitUsage, "%s needs a length in mm above 0, not '%s'", name, v);
  return kExitOk;
}

int feed(const char* name, ZigArgs* z, const char* v, int64_t* nm) {
  z->feeds_given = true;
  if (!parse_mm(v, 1, nm)) return fail(kExitUsage, "%s needs a feed in mm/min above 0, not '%s'", name, v);
  return kExitOk;
}

int spindle(ZigArgs* z, const char* v) {
  z->feeds_given = true;
  int64_t rpm = 0;
  if (!parse_scaled(v, 1, &rpm) || std::strchr(v, '.') || rpm < 1 || rpm > 1000000)
    return fail(kExitUsage, "--spindle needs whole rpm, not '%s'", v);
  z->job.prog.spindle_rpm = static_cast<int32_t>(rpm);
  return kExitOk;
}

const Option<ZigArgs> kZigOptions[] = {
    {"-o", "OUT", "write the program to OUT instead of standard output",
     [](ZigArgs* z, const char* v) -> int { return z->out = v, kExitOk; }},
    {"--stepover", "MM", "between stripes (default: one dexel pitch), whole pitches",
     [](ZigArgs* z, const char* v) -> int { return positive_mm("--stepover", v, &z->job.stepover_nm); }},
    {"--step", "MM", "between positions along a stripe (default: one pitch)",
     [](ZigArgs* z, const char* v) -> int { return positive_mm("--step", v, &z->job.step_nm); }},
    {"--direction", "x|y", "the stripes' direction (default x)",
     [](ZigArgs* z, const char* v) -> int {
       if (std::strcmp(v, "x") && std::strcmp(v, "y")) return fail(kExitUsage, "--direction must be x or y, not '%s'", v);
       z->job.prog.zig.along_y = v[0] == 'y';
       return kExitOk;
     }},
    {"--zigzag", nullptr, "every other stripe reversed, no lift (default: lifted returns, the paper's way)",
     [](ZigArgs* z, const char*) -> int { return z->job.prog.zigzag = true, kExitOk; }},
    {"--safe-z", "MM", "rapids between stripes (default: stock top + 5)",
     [](ZigArgs* z, const char* v) -> int {
       if (!parse_mm(v, -1000000 * kNmPerMm, &z->job.safe_z_nm))
         return fail(kExitUsage, "--safe-z needs a height in mm, not '%s'", v);
       z->job.have_safe = true;
       return kExitOk;
     }},
    {"--feed", "MM/MIN", "cutting feed (default 1000)",
     [](ZigArgs* z, const char* v) -> int { return feed("--feed", z, v, &z->job.prog.feed_nm_per_min); }},
    {"--plunge-feed", "MM/MIN", "plunging feed (default 300)",
     [](ZigArgs* z, const char* v) -> int { return feed("--plunge-feed", z, v, &z->job.prog.plunge_nm_per_min); }},
    {"--spindle", "RPM",
     "spindle speed (default 12000); with --material PRESET (a built-in part brings its own) and none of "
     "--feed, --plunge-feed and --spindle, all three within its limits",
     spindle},
    {"--allowance", "MM", "stock left above the design (default 0)",
     [](ZigArgs* z, const char* v) -> int {
       if (!parse_mm(v, 0, &z->job.prog.zig.allowance_nm)) return fail(kExitUsage, "--allowance needs mm >= 0, not '%s'", v);
       return kExitOk;
     }},
};

const CommandText kZigText = {
    "zig",
    "usage: dexmill zig DESIGN --stock X0,Y0,Z0,X1,Y1,Z1 [options] [-o OUT]\n\n"
    "Writes a zig-milling finishing program for the design part to standard output\n"
    "(or OUT): stripes along x (or y) one --stepover apart, a position every --step,\n"
    "each the lowest at which the tool touches but does not cut into the design\n"
    "sampled on the grid `dexmill run` uses for the same --stock, --pitch/--grid and\n"
    "--tool (default here ball:3); straight moves between positions never dip into\n"
    "the design. DESIGN: an STL (mm, machine coordinates; --design-offset X,Y,Z), a\n"
    "PGM height image over the stock's XY (--design-z ZLOW,ZHIGH), or a built-in part\n"
    "(panel, smiley, freeform, tsuba: its block, pitch and ball unless given, the part\n"
    "staying at its place in a --stock box given; see run --demo).\n",
    "Prints the grid, positions, moves and time taken on standard error. Exit 0 ok,\n"
    "1 a design that cannot be read, 2 usage, 3 I/O.\n",
};

ZigArgs& whole(ZigArgs& z) { return z; }
RunOptions& run_part(ZigArgs& z) { return z.run; }

// The first operand that is not "-" is the design; the rest are run's.
int operand(ZigArgs* z, const char* arg, int index) {
  if (z->design.empty() && std::strcmp(arg, "-")) return z->design = arg, kExitOk;
  return run_operand(&z->run, arg, z->design.empty() ? index : index - 1);
}

const OptionTable<ZigArgs>& zig_table() {
  static const OptionTable<ZigArgs> t = [] {
    OptionTable<ZigArgs> table;
    table.text = &kZigText;
    table.sections.push_back(section<ZigArgs>(nullptr, option_list(kZigOptions), whole));
    table.sections.push_back(include<ZigArgs>("The stock, grid, tool and design", run_option_table(), run_part));
    table.operand = operand;
    return table;
  }();
  return t;
}

}  // namespace

CommandDoc zig_doc() { return command_doc(zig_table()); }

int cmd_zig(int argc, char** argv) {
  ZigArgs z;
  bool help = false;
  const int parsed = parse_options(zig_table(), argc, argv, &z, &help);
  if (help) print_help(zig_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (z.design.empty()) return fail(kExitUsage, "zig needs a DESIGN (an STL, a PGM with --design-z, or a built-in part)");
  // A built-in part's name, unless a file of that name is there; a file is
  // the design as --design would give it.
  struct stat sb;
  const BuiltinDesign* builtin = stat(z.design.c_str(), &sb) != 0 ? builtin_design_find(z.design.c_str()) : nullptr;
  RunOptions& o = z.run;
  if (!builtin) {
    if (const int code = apply_option(run_option_table(), "--design", z.design.c_str(), &o)) return code;
  }
  if (const int code = finish_run_options(&o)) return code;
  if (builtin) {
    if (const int code = builtin_setup(*builtin, o.job.tool_given, &o.job)) return code;
  } else if (!o.job.tool_given) (void)tool_spec_parse("ball:3", 6, &o.job.tool);
  if (!z.feeds_given) zig_fit_to_material(o.job, &z.job.prog);
  if (run_draws(o) || !o.out.report.empty() || !o.job.file.empty())
    return fail(kExitUsage, "zig writes a program only (simulate it with dexmill run)");

  if (!o.job.have_stock) return fail(kExitUsage, "zig needs --stock X0,Y0,Z0,X1,Y1,Z1 (the block the design is cut from)");
  std::string err;
  if (z.out == "-" && !standard_output_usable(&err)) return fail(kExitIo, "cannot write the program: %s", err.c_str());
  FileGuard guard;  // the program is never the design, nor another file the options name
  if (const int code = guard_job_inputs(o.job, "", &guard)) return code;
  if (const int code = guard_status(guard, guard.check_output(z.out == "-" ? "" : "-o", z.out))) return code;
  std::string text;
  ZigProgramStats st;
  GridPlan plan;
  const int gcode = zig_generate(o.job, &z.job, &text, &st, &plan);
  if (gcode != kExitOk) return gcode;
  char e[1300];
  if (!write_output(z.out.c_str(), text.data(), text.size(), e, sizeof e)) return fail(kExitIo, "%s", e);
  zig_print_stats(plan, st);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
