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
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/guard_inputs.h"
#include "tools/run/run_option_table.h"
#include "tools/run/run_stock.h"

namespace dexmill {
namespace cli {
namespace {

struct MeasureArgs {
  std::string file;
  std::vector<std::pair<int64_t, int64_t>> at;  // --at, nm
  bool distance = false;
  int64_t segment_nm[4] = {};  // --distance X0,Y0,X1,Y1
  std::string csv, svg;        // --csv, --svg
  JobOptions job;              // --design and its options (run's: tools/run/run_job_options.cpp)
  bool thickness = false;
  int64_t wall_height_nm = 1000000;  // --wall-height, 1 mm
  std::string image;                 // --image
  int64_t thin_nm = 1000000;         // --thin, 1 mm (as dexmill run's)
  bool scallop = false;
  bool region = false;
  int64_t region_nm[4] = {};  // --region X0,Y0,X1,Y1
  bool any() const { return !at.empty() || distance || thickness || scallop; }
};

int at(MeasureArgs* a, const char* v) {
  int64_t xy[2];
  if (!parse_mm_list(v, 2, xy)) return fail(kExitUsage, "--at needs X,Y in mm, not '%s'", v);
  a->at.emplace_back(xy[0], xy[1]);
  return kExitOk;
}

int distance(MeasureArgs* a, const char* v) {
  if (!parse_mm_list(v, 4, a->segment_nm)) return fail(kExitUsage, "--distance needs X0,Y0,X1,Y1 in mm, not '%s'", v);
  a->distance = true;
  return kExitOk;
}

int region(MeasureArgs* a, const char* v) {
  if (!parse_mm_list(v, 4, a->region_nm)) return fail(kExitUsage, "--region needs X0,Y0,X1,Y1 in mm, not '%s'", v);
  a->region = true;
  return kExitOk;
}

int wall_height(MeasureArgs* a, const char* v) {
  if (!parse_scaled(v, 1000000, &a->wall_height_nm) || a->wall_height_nm <= 0 ||
      a->wall_height_nm > 1000000000)
    return fail(kExitUsage, "--wall-height needs a height in mm above 0 and up to 1000, not '%s'", v);
  return kExitOk;
}

int thin(MeasureArgs* a, const char* v) {
  if (!parse_scaled(v, 1000000, &a->thin_nm) || a->thin_nm <= 0 || a->thin_nm > 1000000000)
    return fail(kExitUsage, "--thin needs a thickness in mm above 0 and up to 1000, not '%s'", v);
  return kExitOk;
}

const Option<MeasureArgs> kMeasureOptions[] = {
    {"--at", "X,Y", "the part at a point (machine mm): top and bottom, material, the line that last cut it (repeatable)",
     at},
    {"--distance", "X0,Y0,X1,Y1", "a section along the segment (machine mm), about a sample a pitch, as CSV", distance},
    {"--csv", "FILE", "--distance's CSV into FILE (default: standard output)",
     [](MeasureArgs* a, const char* v) -> int { a->csv = v; return kExitOk; }},
    {"--svg", "FILE", "--distance's section as an SVG chart",
     [](MeasureArgs* a, const char* v) -> int { a->svg = v; return kExitOk; }},
    {"--thickness", nullptr, "the thinnest floor (top - bottom) and the thinnest wall, with where",
     [](MeasureArgs* a, const char*) -> int { a->thickness = true; return kExitOk; }},
    {"--wall-height", "MM", "a wall stands at least MM above the floor on both sides (default 1)", wall_height},
    {"--image", "FILE.png", "--thickness's picture: the part coloured as run --color thin draws it, the thinnest places marked",
     [](MeasureArgs* a, const char* v) -> int { a->image = v; return kExitOk; }},
    {"--thin", "MM", "--image highlights floors thinner than MM (default 1)", thin},
    {"--scallop", nullptr, "the highest scallop (crest over the valleys beside it) across X and across Y",
     [](MeasureArgs* a, const char*) -> int { a->scallop = true; return kExitOk; }},
    {"--region", "X0,Y0,X1,Y1", "--scallop over the columns in this box only (machine mm; default: all)", region},
};

const CommandText kMeasureText = {
    "measure",
    "usage: dexmill measure STOCK.dxstock [--at X,Y ...] [--distance X0,Y0,X1,Y1 [--csv FILE] [--svg FILE]]\n"
    "                       [--thickness [--wall-height MM] [--image FILE.png [--thin MM]]]\n"
    "                       [--scallop [--region X0,Y0,X1,Y1]] [--design FILE ...]\n\n"
    "Measures the simulated part a run saved (dexmill run ... --save-stock\n"
    "STOCK.dxstock). --at X,Y gives the column nearest the point (machine mm):\n"
    "its top and bottom, or that it is cut through, and the program line that\n"
    "last lowered it (when the stock kept lines, as --save-stock does), with how\n"
    "far the column is from the point and the heights' bound (one LSB).\n"
    "--distance samples the part along a segment, about one sample a pitch, as\n"
    "CSV (standard output, or --csv FILE) and as a chart (--svg FILE).\n"
    "--thickness gives the thinnest floor (top - bottom of a column) and the\n"
    "thinnest wall: a run of columns along a row, a column or a diagonal whose\n"
    "tops all stand --wall-height above the floor on both sides (a hole or the\n"
    "grid's edge is air), its width the run's length, within one step.\n"
    "--scallop gives the highest crest over the higher of the valleys beside it,\n"
    "scanning along X and along Y (over --region only, if given), within two LSB\n"
    "plus the height steps beside the crest and the valley.\n"
    "--design FILE (with run's design options) adds the design's height and\n"
    "cut - design to --at and the design's line to --distance (--tolerance and\n"
    "--tolerance-box are read and not used).\n",
    "Exit 0 ok, 1 a stock file that is not one, 2 usage (a point off the stock's\n"
    "grid), 3 I/O.\n",
};

MeasureArgs& whole(MeasureArgs& a) { return a; }

const OptionTable<MeasureArgs>& measure_table() {
  static const OptionTable<MeasureArgs> t = [] {
    OptionTable<MeasureArgs> table;
    table.text = &kMeasureText;
    table.sections.push_back(section<MeasureArgs>(nullptr, option_list(kMeasureOptions), whole));
    table.sections.push_back(section<MeasureArgs>("The design part (as dexmill run takes it)", run_design_options(),
                                                  [](MeasureArgs& a) -> JobOptions& { return a.job; }));
    table.operand = [](MeasureArgs* a, const char* arg, int index) -> int { return take_file(&a->file, arg, index); };
    return table;
  }();
  return t;
}

std::string mm(int64_t nm, int decimals = 4) { return measure_mm(nm, decimals); }

// One answer: "X12.000 Y8.000: top Z-3.0000, bottom Z-10.0000 mm (...)".
void print_at(const MeasuredStock& s, const MeasureAt& r, int64_t x, int64_t y) {
  const StockMeta& m = s.meta;
  std::string o = "X" + mm(x, 3) + " Y" + mm(y, 3) + ": ";
  if (r.material)
    o += "top Z" + mm(r.top_nm) + ", bottom Z" + mm(r.bottom_nm) + " mm";
  else
    o += "no material (cut through)";
  o += " (the column at X" + mm(r.column_x_nm, 3) + " Y" + mm(r.column_y_nm, 3) + ", " + mm(r.distance_nm, 3) +
       " mm away; heights within " + mm(r.height_error_nm) + " mm)";
  if (!(m.layers & kStockLayerLine)) {
    o += "; the stock kept no lines";
  } else if (r.line == 0) {
    o += "; uncut";
  } else {
    o += "; last cut by line " + std::to_string(r.line);
    if ((m.layers & kStockLayerProgram) && r.program < m.nprograms) o += std::string(" of ") + m.programs[r.program].name;
  }
  if (s.have_design) o += "; " + measure_design_at(s, r);
  std::printf("%s\n", o.c_str());
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
  if (a.region && !a.scallop) return fail(kExitUsage, "--region goes with --scallop");
  if (!a.image.empty() && !a.thickness) return fail(kExitUsage, "--image goes with --thickness");
  if (a.distance && a.csv.empty() && !a.at.empty())
    return fail(kExitUsage, "--distance with --at: give the CSV a file (--csv FILE), standard output has the points");
  if (const int code = guard_outputs(a)) return code;
  MeasuredStock s;
  if (const int code = read_stock(a.file, &s)) return code;
  if (!a.job.design.empty())
    if (const int code = read_design(a.job, &s)) return code;
  const DexelGrid<height_t>& g = s.grid;
  for (const auto& p : a.at) {
    const MeasureAt r = measure_at(g, s.line_layer(), s.program_layer(), p.first, p.second);
    if (!r.on_grid)
      return fail(kExitUsage, "X%s Y%s is off the stock's grid (X%s..%s, Y%s..%s)", mm(p.first, 3).c_str(),
                  mm(p.second, 3).c_str(), mm(g.x0_nm, 3).c_str(), mm(g.x0_nm + (g.nx - 1) * g.pitch_nm, 3).c_str(),
                  mm(g.y0_nm, 3).c_str(), mm(g.y0_nm + (g.ny - 1) * g.pitch_nm, 3).c_str());
    print_at(s, r, p.first, p.second);
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
