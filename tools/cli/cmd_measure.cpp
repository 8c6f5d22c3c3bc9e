// `dexmill measure STOCK.dxstock --at X,Y ...` (tools/CLI.md): measurements
// of a simulated part, from the stock a run saved (`--save-stock`): at a
// point, the column's top and bottom, whether it holds material, and the
// line of the program that last cut it, each with its error bound
// (core/measure/measure_at.h). The queries along a segment, of thickness and
// of scallops come next.
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
#include "tools/cli/option_help.h"
#include "tools/cli/option_parse.h"
#include "tools/cli/option_values.h"
#include "tools/run/run_stock.h"

namespace dexmill {
namespace cli {
namespace {

struct MeasureArgs {
  std::string file;
  std::vector<std::pair<int64_t, int64_t>> at;  // --at, nm
};

int at(MeasureArgs* a, const char* v) {
  int64_t xy[2];
  if (!parse_mm_list(v, 2, xy)) return fail(kExitUsage, "--at needs X,Y in mm, not '%s'", v);
  a->at.emplace_back(xy[0], xy[1]);
  return kExitOk;
}

const Option<MeasureArgs> kMeasureOptions[] = {
    {"--at", "X,Y", "the part at a point (machine mm): top and bottom, material, the line that last cut it (repeatable)",
     at},
};

const CommandText kMeasureText = {
    "measure",
    "usage: dexmill measure STOCK.dxstock --at X,Y [--at X,Y ...]\n\n"
    "Measures the simulated part a run saved (dexmill run ... --save-stock\n"
    "STOCK.dxstock). --at X,Y gives the column nearest the point (machine mm):\n"
    "its top and bottom, or that it is cut through, and the program line that\n"
    "last lowered it (when the stock kept lines, as --save-stock does), with how\n"
    "far the column is from the point and the heights' bound (one LSB).\n",
    "Exit 0 ok, 1 a stock file that is not one, 2 usage (a point off the stock's\n"
    "grid), 3 I/O.\n",
};

MeasureArgs& whole(MeasureArgs& a) { return a; }

const OptionTable<MeasureArgs>& measure_table() {
  static const OptionTable<MeasureArgs> t = [] {
    OptionTable<MeasureArgs> table;
    table.text = &kMeasureText;
    table.sections.push_back(section<MeasureArgs>(nullptr, option_list(kMeasureOptions), whole));
    table.operand = [](MeasureArgs* a, const char* arg, int index) -> int { return take_file(&a->file, arg, index); };
    return table;
  }();
  return t;
}

std::string mm(int64_t nm, int decimals = 4) { return nm_to_mm_text(nm, decimals); }

// One answer: "X12.000 Y8.000: top Z-3.0000, bottom Z-10.0000 mm (...)".
void print_at(const StockMeta& m, const MeasureAt& r, int64_t x, int64_t y) {
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
  std::printf("%s\n", o.c_str());
}

}  // namespace

CommandDoc measure_doc() { return command_doc(measure_table()); }

int cmd_measure(int argc, char** argv) {
  MeasureArgs a;
  bool help = false;
  const int parsed = parse_options(measure_table(), argc, argv, &a, &help);
  if (help) print_help(measure_doc(), stdout);
  if (parsed != kExitOk || help) return parsed;
  if (a.file.empty()) return fail(kExitUsage, "measure needs a stock file (dexmill run ... --save-stock STOCK.dxstock)");
  if (a.at.empty()) return fail(kExitUsage, "measure needs a query: --at X,Y");
  StockFileReader in;
  std::string err;
  if (!in.open(a.file, &err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return in.io_error() ? kExitIo : kExitInput;
  }
  const StockMeta m = in.meta();
  if (const int code = stock_heights_fit(m, a.file)) return code;
  const size_t cells = static_cast<size_t>(m.geo.nx) * static_cast<size_t>(m.geo.ny);
  std::vector<height_t> top(cells), bottom(cells);
  std::vector<uint32_t> lines((m.layers & kStockLayerLine) ? cells : 0);
  std::vector<uint8_t> programs((m.layers & kStockLayerProgram) ? cells : 0), cls((m.layers & kStockLayerClass) ? cells : 0);
  StockColumns c;
  c.top = top.data();
  c.bottom = bottom.data();
  c.cls = cls.empty() ? nullptr : cls.data();
  c.line = lines.empty() ? nullptr : lines.data();
  c.program = programs.empty() ? nullptr : programs.data();
  if (!in.read_columns(c, &err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return in.io_error() ? kExitIo : kExitInput;
  }
  DexelGrid<height_t> g;
  if (!ok(grid_init(&g, m.geo, top.data(), bottom.data(), cells))) return fail(kExitInput, "%s: a grid this build cannot hold", a.file.c_str());
  for (const auto& p : a.at) {
    const MeasureAt r = measure_at(g, c.line, c.program, p.first, p.second);
    if (!r.on_grid)
      return fail(kExitUsage, "X%s Y%s is off the stock's grid (X%s..%s, Y%s..%s)", mm(p.first, 3).c_str(),
                  mm(p.second, 3).c_str(), mm(g.x0_nm, 3).c_str(), mm(g.x0_nm + (g.nx - 1) * g.pitch_nm, 3).c_str(),
                  mm(g.y0_nm, 3).c_str(), mm(g.y0_nm + (g.ny - 1) * g.pitch_nm, 3).c_str());
    print_at(m, r, p.first, p.second);
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
