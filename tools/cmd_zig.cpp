// `dexmill zig DESIGN [options] > prog.ngc` (issue 23, paper §3): a
// zig-milling finishing program generated from a design part: the design
// sampled on the grid `dexmill run` would use for the same --stock, --pitch
// or --grid and --tool, every tool position the lowest at which the tool
// touches but does not cut into it (core/cam/zig.h), written as plain
// RS274/NGC (tools/zig_program.h). Simulating the program with the same
// options and --design reports no gouge (tests/test_zig_cli.cpp).
#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "platform/output_file.h"
#include "platform/report_json.h"
#include "tools/cli.h"
#include "tools/run_assess.h"
#include "tools/run_options.h"
#include "tools/run_stock.h"
#include "tools/zig_job.h"

namespace dexmill {
namespace cli {
namespace {

void usage(std::FILE* f) {
  std::fprintf(f,
               "usage: dexmill zig DESIGN --stock X0,Y0,Z0,X1,Y1,Z1 [options] [-o OUT]\n\n"
               "Writes a zig-milling finishing program for the design part to standard output\n"
               "(or OUT): stripes along x (or y) one --stepover apart, a position every --step,\n"
               "each the lowest at which the tool touches but does not cut into the design\n"
               "sampled on the grid `dexmill run` uses for the same --stock, --pitch/--grid and\n"
               "--tool; straight moves between positions never dip into the design.\n"
               "DESIGN: an STL (mm, machine coordinates; --design-offset X,Y,Z), a PGM height\n"
               "image over the stock's XY (--design-z ZLOW,ZHIGH), or a built-in part (panel,\n"
               "smiley, freeform, tsuba: its block, pitch and ball unless given; see run --demo).\n\n"
               "  --tool SPEC          the cutter (ball:D, flat:D, bull:D:R; default ball:3)\n"
               "  --stepover MM        between stripes (default: one dexel pitch), whole pitches\n"
               "  --step MM            between positions along a stripe (default: one pitch)\n"
               "  --direction x|y      the stripes' direction (default x)\n"
               "  --zigzag             every other stripe reversed, no lift (default: lifted\n"
               "                       returns, the paper's way)\n"
               "  --safe-z MM          rapids between stripes (default: stock top + 5)\n"
               "  --feed MM/MIN        cutting feed (default 1000); --plunge-feed (default 300)\n"
               "  --spindle RPM        (default 12000); with --material PRESET (a built-in part\n"
               "                       brings its own) and none of these three, within its limits\n"
               "  --allowance MM       stock left above the design (default 0)\n"
               "  --pitch MM, --grid NXxNY, --units mm|inch: as for run\n\n"
               "Prints the grid, positions, moves and time taken on standard error. Exit 0 ok,\n"
               "1 a design that cannot be read, 2 usage, 3 I/O.\n");
}

// Options of zig's own; the rest go to run's parser.
struct ZigArgs {
  std::string design, out = "-";
  ZigJob job;
  bool feeds_given = false;  // --feed, --plunge-feed or --spindle
};

// A length or feed in mm (mm/min) as written, within [min_nm, 1e6 mm].
bool parse_mm(const char* v, int64_t min_nm, int64_t* nm) {
  return parse_scaled(v, kNmPerMm, nm) && *nm >= min_nm && *nm <= 1000000 * kNmPerMm;
}

}  // namespace

int cmd_zig(int argc, char** argv) {
  ZigArgs z;
  std::vector<char*> rest{argv[0]};
  static char design_flag[] = "--design";
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
      usage(stdout);
      return kExitOk;
    }
    const bool takes = !std::strcmp(a, "-o") || !std::strcmp(a, "--stepover") || !std::strcmp(a, "--step") ||
                       !std::strcmp(a, "--direction") || !std::strcmp(a, "--safe-z") || !std::strcmp(a, "--feed") ||
                       !std::strcmp(a, "--plunge-feed") || !std::strcmp(a, "--spindle") || !std::strcmp(a, "--allowance");
    if (takes) {
      if (i + 1 >= argc) return fail(kExitUsage, "%s needs a value", a);
      const char* v = argv[++i];
      int64_t nm = 0;
      if (!std::strcmp(a, "-o")) {
        z.out = v;
      } else if (!std::strcmp(a, "--stepover") || !std::strcmp(a, "--step")) {
        if (!parse_mm(v, 1, &nm)) return fail(kExitUsage, "%s needs a length in mm above 0, not '%s'", a, v);
        (!std::strcmp(a, "--stepover") ? z.job.stepover_nm : z.job.step_nm) = nm;
      } else if (!std::strcmp(a, "--direction")) {
        if (std::strcmp(v, "x") && std::strcmp(v, "y")) return fail(kExitUsage, "--direction must be x or y, not '%s'", v);
        z.job.prog.zig.along_y = v[0] == 'y';
      } else if (!std::strcmp(a, "--safe-z")) {
        if (!parse_mm(v, -1000000 * kNmPerMm, &z.job.safe_z_nm))
          return fail(kExitUsage, "--safe-z needs a height in mm, not '%s'", v);
        z.job.have_safe = true;
      } else if (!std::strcmp(a, "--feed") || !std::strcmp(a, "--plunge-feed")) {
        z.feeds_given = true;
        if (!parse_mm(v, 1, &nm)) return fail(kExitUsage, "%s needs a feed in mm/min above 0, not '%s'", a, v);
        (!std::strcmp(a, "--feed") ? z.job.prog.feed_nm_per_min : z.job.prog.plunge_nm_per_min) = nm;
      } else if (!std::strcmp(a, "--spindle")) {
        z.feeds_given = true;
        int64_t rpm = 0;
        if (!parse_scaled(v, 1, &rpm) || std::strchr(v, '.') || rpm < 1 || rpm > 1000000)
          return fail(kExitUsage, "--spindle needs whole rpm, not '%s'", v);
        z.job.prog.spindle_rpm = static_cast<int32_t>(rpm);
      } else {
        if (!parse_mm(v, 0, &z.job.prog.zig.allowance_nm)) return fail(kExitUsage, "--allowance needs mm >= 0, not '%s'", v);
      }
      continue;
    }
    if (!std::strcmp(a, "--zigzag")) {
      z.job.prog.zigzag = true;
      continue;
    }
    if (run_option_takes_value(a) && i + 1 < argc) {  // run's, with its value
      rest.push_back(argv[i]);
      rest.push_back(argv[++i]);
      continue;
    }
    if (a[0] != '-' && z.design.empty()) {
      z.design = a;
      continue;
    }
    rest.push_back(argv[i]);
  }
  if (z.design.empty()) return fail(kExitUsage, "zig needs a DESIGN (an STL, a PGM with --design-z, or a built-in part)");
  // A built-in part's name, unless a file of that name is there.
  struct stat sb;
  const BuiltinDesign* builtin = stat(z.design.c_str(), &sb) != 0 ? builtin_design_find(z.design.c_str()) : nullptr;
  if (!builtin) {
    rest.push_back(design_flag);
    rest.push_back(const_cast<char*>(z.design.c_str()));
  }
  RunOptions o;
  bool help = false;
  const int code = parse_run_options(static_cast<int>(rest.size()), rest.data(), &o, &help);
  if (code != kExitOk || help) return code;
  if (builtin) builtin_setup(*builtin, o.tool_given, &o);
  else if (!o.tool_given) (void)tool_spec_parse("ball:3", 6, &o.tool);
  if (!z.feeds_given) zig_fit_to_material(o, &z.job.prog);
  if (run_draws(o) || !o.report.empty() || !o.file.empty())
    return fail(kExitUsage, "zig writes a program only (simulate it with dexmill run)");

  if (!o.have_stock) return fail(kExitUsage, "zig needs --stock X0,Y0,Z0,X1,Y1,Z1 (the block the design is cut from)");
  std::string text;
  ZigProgramStats st;
  GridPlan plan;
  const int gcode = zig_generate(o, &z.job, &text, &st, &plan);
  if (gcode != kExitOk) return gcode;
  char e[1300];
  if (z.out == "-") {
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      return fail(kExitIo, "writing the program to standard output failed");
  } else if (!write_output(z.out.c_str(), text.data(), text.size(), e, sizeof e)) {
    return fail(kExitIo, "%s", e);
  }
  zig_print_stats(plan, st);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
