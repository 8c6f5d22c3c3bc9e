// `dexmill measure STOCK.dxstock --at X,Y ...` (tools/CLI.md): measurements
// of a simulated part, from the stock a run saved (`--save-stock`): at a
// point, the column's top and bottom, whether it holds material, and the
// line of the program that last cut it (core/measure/measure_at.h); a
// section along a segment (--distance, tools/cli/cmd_measure_section.cpp);
// the thinnest floor and wall (--thickness) and the highest scallop
// (--scallop, tools/cli/cmd_measure_shape.cpp); each with its error bound.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/measure/measure_at.h"
#include "platform/format/stock_io.h"
#include "platform/input/file_guard.h"
#include "platform/report/report_json.h"
#include "tools/cli/cli.h"
#include "tools/cli/cmd_measure.h"
#include "tools/cli/measure_text.h"
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/guard_inputs.h"
#include "tools/run/run_option_table.h"
#include "tools/run/run_stock.h"

namespace dexmill {
namespace cli {
namespace {

std::string mm(int64_t nm, int decimals = 4) { return measure_mm(nm, decimals); }

// What --at reads of the stock: its grid, the layers it kept, the design.
MeasureSource source_of(const MeasuredStock& s) {
  MeasureSource src;
  src.grid = &s.grid;
  src.lines = s.line_layer();
  src.programs = s.program_layer();
  src.program_list = s.meta.programs;
  src.nprograms = s.meta.nprograms;
  src.design_top_lsb = s.design_layer();
  return src;
}

// The outputs are none of the inputs, nor one file twice.
int guard_outputs(const MeasureArgs& a) {
  FileGuard guard;
  if (const int code = guard_status(guard, guard.register_input(a.file, "stock"))) return code;
  if (const int code = guard_status(guard, guard.register_input(a.job.design, "--design"))) return code;
  if (!a.csv.empty())
    if (const int code = guard_status(guard, guard.check_output("--csv", a.csv))) return code;
  if (!a.svg.empty())
    if (const int code = guard_status(guard, guard.check_output("--svg", a.svg))) return code;
  if (!a.image.empty())
    if (const int code = guard_status(guard, guard.check_output("--image", a.image))) return code;
  return kExitOk;
}

}  // namespace

std::string measure_mm(int64_t nm, int decimals) { return nm_to_mm_text(nm, decimals); }

CommandDoc measure_doc() { return command_doc(measure_table()); }

int cmd_measure(int argc, char** argv) {
  MeasureArgs a;
  bool help = false;
  const int parsed = parse_options(measure_table(), argc, argv, &a, &help);
  if (help) print_help(measure_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (a.file.empty()) return fail(kExitUsage, "measure needs a stock file (dexmill run ... --save-stock STOCK.dxstock)");
  if (!a.any()) return fail(kExitUsage, "measure needs a query: --at X,Y, --distance, --thickness or --scallop");
  if ((!a.csv.empty() || !a.svg.empty()) && !a.distance) return fail(kExitUsage, "--csv and --svg go with --distance");
  if (!a.image.empty() && !a.thickness) return fail(kExitUsage, "--image goes with --thickness");
  if (a.distance && a.csv.empty() && !a.at.empty())
    return fail(kExitUsage, "--distance with --at: give the CSV a file (--csv FILE), standard output has the points");
  if (const int code = guard_outputs(a)) return code;
  MeasuredStock s;
  if (const int code = read_stock(a.file, &s)) return code;
  if (!a.job.design.empty())
    if (const int code = read_design(a.job, &s)) return code;
  const DexelGrid<height_t>& g = s.grid;
  const MeasureSource src = source_of(s);
  for (const auto& p : a.at) {
    std::string text;
    if (!measure_at_text(src, p.first, p.second, &text))
      return fail(kExitUsage, "X%s Y%s is off the stock's grid (X%s..%s, Y%s..%s)", mm(p.first, 3).c_str(),
                  mm(p.second, 3).c_str(), mm(g.x0_nm, 3).c_str(), mm(g.x0_nm + (g.nx - 1) * g.pitch_nm, 3).c_str(),
                  mm(g.y0_nm, 3).c_str(), mm(g.y0_nm + (g.ny - 1) * g.pitch_nm, 3).c_str());
    std::printf("%s\n", text.c_str());
  }
  if (a.distance)
    if (const int code = measure_section(s, a.segment_nm, a.csv, a.svg)) return code;
  if (a.thickness)
    if (const int code = measure_thickness(s, a.wall_height_nm, a.image, a.thin_nm)) return code;
  if (a.scallop)
    if (const int code = measure_scallop(s, a.region ? a.region_nm : nullptr)) return code;
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
