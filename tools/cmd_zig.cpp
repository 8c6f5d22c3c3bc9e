// `dexmill zig DESIGN [options] > prog.ngc` (issue 23, paper §3): a
// zig-milling finishing program generated from a design part: the design
// sampled on the grid `dexmill run` would use for the same --stock, --pitch
// or --grid and --tool, every tool position the lowest at which the tool
// touches but does not cut into it (core/cam/zig.h), written as plain
// RS274/NGC (tools/zig_program.h). Simulating the program with the same
// options and --design reports no gouge (tests/test_zig_cli.cpp).
#include <cstdio>
#include <cstdlib>
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
#include "tools/zig_program.h"

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
               "DESIGN: an STL (mm, machine coordinates; --design-offset X,Y,Z) or a PGM height\n"
               "image over the stock's XY (--design-z ZLOW,ZHIGH).\n\n"
               "  --tool SPEC          the cutter (ball:D, flat:D, bull:D:R; default ball:3)\n"
               "  --stepover MM        between stripes (default: one dexel pitch), whole pitches\n"
               "  --step MM            between positions along a stripe (default: one pitch)\n"
               "  --direction x|y      the stripes' direction (default x)\n"
               "  --zigzag             every other stripe reversed, no lift (default: lifted\n"
               "                       returns, the paper's way)\n"
               "  --safe-z MM          rapids between stripes (default: stock top + 5)\n"
               "  --feed MM/MIN        cutting feed (default 1000); --plunge-feed (default 300)\n"
               "  --spindle RPM        (default 12000)\n"
               "  --allowance MM       stock left above the design (default 0)\n"
               "  --pitch MM, --grid NXxNY, --units mm|inch: as for run\n\n"
               "Prints the grid, positions, moves and time taken on standard error. Exit 0 ok,\n"
               "1 a design that cannot be read, 2 usage, 3 I/O.\n");
}

// Options of zig's own; the rest go to run's parser.
struct ZigArgs {
  std::string design, out = "-";
  ZigProgramOptions prog;
  int64_t stepover_nm = 0, step_nm = 0, safe_z_nm = 0;
  bool have_safe = false;
};

bool parse_mm(const char* v, int64_t* nm, bool positive) {
  char* end = nullptr;
  const double d = std::strtod(v, &end);
  if (!end || *end || !(d == d) || d < 0 || (positive && d <= 0) || d > 1e6) return false;
  *nm = static_cast<int64_t>(d * 1e6 + 0.5);
  return true;
}
bool parse_signed_mm(const char* v, int64_t* nm) {
  char* end = nullptr;
  const double d = std::strtod(v, &end);
  if (!end || *end || !(d == d) || d < -1e6 || d > 1e6) return false;
  *nm = static_cast<int64_t>(d * 1e6 + (d < 0 ? -0.5 : 0.5));
  return true;
}

}  // namespace

int cmd_zig(int argc, char** argv) {
  ZigArgs z;
  std::vector<char*> rest{argv[0]};
  static char design_flag[] = "--design";
  bool have_tool = false;
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
        if (!parse_mm(v, &nm, true)) return fail(kExitUsage, "%s needs a length in mm above 0, not '%s'", a, v);
        (a[6] == 'o' ? z.stepover_nm : z.step_nm) = nm;
      } else if (!std::strcmp(a, "--direction")) {
        if (std::strcmp(v, "x") && std::strcmp(v, "y")) return fail(kExitUsage, "--direction must be x or y, not '%s'", v);
        z.prog.zig.along_y = v[0] == 'y';
      } else if (!std::strcmp(a, "--safe-z")) {
        if (!parse_signed_mm(v, &z.safe_z_nm)) return fail(kExitUsage, "--safe-z needs a height in mm, not '%s'", v);
        z.have_safe = true;
      } else if (!std::strcmp(a, "--feed") || !std::strcmp(a, "--plunge-feed")) {
        if (!parse_mm(v, &nm, true)) return fail(kExitUsage, "%s needs a feed in mm/min above 0, not '%s'", a, v);
        (a[2] == 'f' ? z.prog.feed_nm_per_min : z.prog.plunge_nm_per_min) = nm;
      } else if (!std::strcmp(a, "--spindle")) {
        char* end = nullptr;
        const long rpm = std::strtol(v, &end, 10);
        if (!end || *end || rpm < 1 || rpm > 1000000) return fail(kExitUsage, "--spindle needs whole rpm, not '%s'", v);
        z.prog.spindle_rpm = static_cast<int32_t>(rpm);
      } else {
        if (!parse_mm(v, &z.prog.zig.allowance_nm, false)) return fail(kExitUsage, "--allowance needs mm >= 0, not '%s'", v);
      }
      continue;
    }
    if (!std::strcmp(a, "--zigzag")) {
      z.prog.zigzag = true;
      continue;
    }
    if (!std::strcmp(a, "--tool")) have_tool = true;
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
  if (z.design.empty()) return fail(kExitUsage, "zig needs a DESIGN (an STL, or a PGM with --design-z)");
  rest.push_back(design_flag);
  rest.push_back(const_cast<char*>(z.design.c_str()));
  RunOptions o;
  bool help = false;
  const int code = parse_run_options(static_cast<int>(rest.size()), rest.data(), &o, &help);
  if (code != kExitOk || help) return code;
  if (!have_tool) (void)tool_spec_parse("ball:3", 6, &o.tool);
  if (!o.have_stock) return fail(kExitUsage, "zig needs --stock X0,Y0,Z0,X1,Y1,Z1 (the block the design is cut from)");
  if (run_draws(o) || !o.report.empty() || !o.file.empty())
    return fail(kExitUsage, "zig writes a program only (simulate it with dexmill run)");

  // The grid `run` would use for this stock and tool.
  const StockBox stock{PointNm{o.stock_nm[0], o.stock_nm[1], o.stock_nm[2]}, PointNm{o.stock_nm[3], o.stock_nm[4], o.stock_nm[5]}};
  const int64_t pitch_nm = o.pitch_nm || o.grid_nx ? o.pitch_nm : default_pitch_nm(stock, o.tool.diameter_nm);
  GridPlan plan;
  std::string err;
  if (!plan_grid(stock, o.grid_nx, o.grid_ny, pitch_nm, &plan, &err)) return fail(kExitUsage, "%s", err.c_str());
  RunDesign d;
  const int dcode = load_design(o, plan, "", &d);
  if (dcode != kExitOk) return dcode;
  if (!design_columns(d.grid)) return fail(kExitInput, "%s: the design covers no dexel of the stock", z.design.c_str());
  const int64_t p = plan.geo.pitch_nm;
  z.prog.zig.stepover_dex = static_cast<int32_t>(max_of<int64_t>(1, z.stepover_nm ? div_round(z.stepover_nm, p) : 1));
  z.prog.zig.step_dex = static_cast<int32_t>(max_of<int64_t>(1, z.step_nm ? div_round(z.step_nm, p) : 1));
  z.prog.safe_z_nm = z.have_safe ? z.safe_z_nm : stock.hi.z_nm + 5 * kNmPerMm;
  if (z.prog.safe_z_nm <= stock.hi.z_nm) return fail(kExitUsage, "--safe-z must be above the stock's top");
  // The lowest the tool goes where no design is under it: the design's
  // lowest top.
  int64_t lowest = INT64_MAX;
  for (int32_t t : d.tops)
    if (t != kNoDesign) lowest = min_of<int64_t>(lowest, t);
  const int64_t floor_nm = plan.geo.z0_nm + lowest * plan.geo.lsb_nm;
  char spec[kToolSpecTextMax];
  tool_spec_format(o.tool, spec, sizeof spec);
  z.prog.header = "dexmill zig: " + z.design + ", tool " + spec + ", stripes along " + (z.prog.zig.along_y ? "y" : "x") +
                  " every " + nm_to_mm_text(z.prog.zig.stepover_dex * p, 4) + " mm, a position every " +
                  nm_to_mm_text(z.prog.zig.step_dex * p, 4) + " mm, " + (z.prog.zigzag ? "zigzag" : "lifted returns") +
                  (z.prog.zig.allowance_nm ? ", allowance " + nm_to_mm_text(z.prog.zig.allowance_nm, 4) + " mm" : "") +
                  "\nsimulate with: dexmill run PROGRAM --stock " + nm_to_mm_text(o.stock_nm[0], 3) + "," +
                  nm_to_mm_text(o.stock_nm[1], 3) + "," + nm_to_mm_text(o.stock_nm[2], 3) + "," +
                  nm_to_mm_text(o.stock_nm[3], 3) + "," + nm_to_mm_text(o.stock_nm[4], 3) + "," +
                  nm_to_mm_text(o.stock_nm[5], 3) + " --pitch " + nm_to_mm_text(p, 4) + " --tool " + spec + " --design " +
                  z.design;
  if (o.design_pgm)
    z.prog.header += " --design-z " + nm_to_mm_text(o.design_z_nm[0], 3) + "," + nm_to_mm_text(o.design_z_nm[1], 3);
  else if (o.design_offset_nm[0] || o.design_offset_nm[1] || o.design_offset_nm[2])
    z.prog.header += " --design-offset " + nm_to_mm_text(o.design_offset_nm[0], 3) + "," +
                     nm_to_mm_text(o.design_offset_nm[1], 3) + "," + nm_to_mm_text(o.design_offset_nm[2], 3);
  std::string text;
  ZigProgramStats st;
  if (!zig_program(d.grid, tool_profile(o.tool), z.prog, floor_nm, &text, &st, &err)) return fail(kExitUsage, "%s", err.c_str());
  char e[1300];
  if (z.out == "-") {
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      return fail(kExitIo, "writing the program to standard output failed");
  } else if (!write_output(z.out.c_str(), text.data(), text.size(), e, sizeof e)) {
    return fail(kExitIo, "%s", e);
  }
  std::fprintf(stderr, "dexmill zig: grid %d x %d at %s mm, %u stripes, %llu positions, %llu moves, %.3f s (%.0f positions/s)\n",
               plan.geo.nx, plan.geo.ny, nm_to_mm_text(p, 4).c_str(), st.stripes, static_cast<unsigned long long>(st.positions),
               static_cast<unsigned long long>(st.moves), st.seconds, st.seconds > 0 ? static_cast<double>(st.positions) / st.seconds : 0.0);
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
