// The options and help of `dexmill measure` (tools/cli/cmd_measure.h,
// tools/CLI.md): each option's value read into MeasureArgs, the design's
// options run's own (tools/run/run_job_options.cpp).
#include <string>

#include "tools/cli/cli.h"
#include "tools/cli/cmd_measure.h"
#include "tools/cli/option_values.h"
#include "tools/run/run_option_table.h"

namespace dexmill {
namespace cli {

namespace {

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

int scallop(MeasureArgs* a, const char* v) {
  a->scallop = true;
  if (!v) return kExitOk;
  if (!parse_mm_list(v, 4, a->region_nm)) return fail(kExitUsage, "--scallop takes X0,Y0,X1,Y1 in mm, not '%s'", v);
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
    {"--scallop", "[X0,Y0,X1,Y1]",
     "the highest scallop (crest over the valleys beside it) across X and across Y, over the columns in the box "
     "(machine mm) when given",
     scallop},
};

const CommandText kMeasureText = {
    "measure",
    "usage: dexmill measure STOCK.dxstock [--at X,Y ...] [--distance X0,Y0,X1,Y1 [--csv FILE] [--svg FILE]]\n"
    "                       [--thickness [--wall-height MM] [--image FILE.png [--thin MM]]]\n"
    "                       [--scallop [X0,Y0,X1,Y1]] [--design FILE ...]\n\n"
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
    "scanning along X and along Y (over the box X0,Y0,X1,Y1 only, if given), within two LSB\n"
    "plus the height steps beside the crest and the valley.\n"
    "--design FILE (with run's design options) adds the design's height and\n"
    "cut - design to --at and the design's line to --distance (--tolerance and\n"
    "--tolerance-box are read and not used).\n",
    "Exit 0 ok, 1 a stock file that is not one, 2 usage (a point off the stock's\n"
    "grid), 3 I/O.\n",
};

MeasureArgs& whole(MeasureArgs& a) { return a; }

}  // namespace

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
}  // namespace cli
}  // namespace dexmill
