// The embedding API's first pass (dexmill.h dm_scan_*) against `dexmill
// run`: the stock, grid and units it chooses for a program given no
// --stock or --grid are what the CLI's report says it chose (mm and inch,
// with and without a WORKPIECE or BLK FORM comment), whatever the pieces;
// a job it cannot read, bad memory, and calls out of order are statuses.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "display/api/dexmill.h"
#include "tests/run_cli_util.h"
#include "tests/api_scan_util.h"
#include "tests/runner.h"

namespace {

using api_scan::Scan;
using api_scan::grid_of;
using api_scan::tool_job;

// The text after "key": in the report, up to the first of `ends`.
std::string field(const std::string& text, const std::string& key, const char* ends = ",}") {
  const size_t at = text.find("\"" + key + "\": ");
  if (at == std::string::npos) return "?";
  const size_t from = at + key.size() + 4;
  return text.substr(from, text.find_first_of(ends, from) - from);
}

std::string mm4(int64_t nm) {  // the report's 4 decimals, rounded half away from zero
  const int64_t a = nm < 0 ? -nm : nm, u = (a + 50) / 100;
  char b[40];
  std::snprintf(b, sizeof b, "%s%lld.%04lld", nm < 0 && u ? "-" : "", static_cast<long long>(u / 10000),
                static_cast<long long>(u % 10000));
  return b;
}

// `dexmill run FILE --tool SPEC` (no stock, no grid) and the scan of the
// same text agree on the stock, its source, the grid, the pitch, the units
// and the lines; so does a simulation of the job dm_scan_apply makes.
// (arg: the file as the CLI, run in tests/run, names it.)
void check_as_run(const std::string& arg, const std::string& path, const char* spec, const char* source,
                  const char* units) {
  const std::string text = run_cli::slurp(path);
  const run_cli::Result r = run_cli::run(arg + " --tool " + spec + " --report %/scan.json");
  CHECK_EQ(r.code, 0);
  if (r.code != 0) {
    std::printf("%s\n", r.err.c_str());
    return;
  }
  const std::string rep = run_cli::slurp(run_cli::tmp_dir() + "/scan.json");
  const std::string stock = rep.substr(rep.find("\"stock\": "));
  const std::string grid = rep.substr(rep.find("\"grid\": "));
  for (const size_t piece : {size_t{1} << 20, size_t{7}}) {
    const dm_job j = tool_job(spec);
    Scan s(j);
    CHECK_EQ(s.run(text, piece, piece == 7 ? 1 : 0), DM_DONE);
    dm_scan_result res;
    CHECK_EQ(dm_scan_get_result(s.scan, &res), DM_OK);
    CHECK_EQ(field(grid, "nx"), std::to_string(res.grid_nx));
    CHECK_EQ(field(grid, "ny"), std::to_string(res.grid_ny));
    char pitch[40];
    std::snprintf(pitch, sizeof pitch, "%.6f", static_cast<double>(res.pitch_nm) / 1e6);
    CHECK_EQ(field(grid, "pitch_mm"), std::string(pitch));
    CHECK_EQ(field(stock, "min_mm", "]"), "[" + mm4(res.stock.lo_nm[0]) + ", " + mm4(res.stock.lo_nm[1]) + ", " +
                                              mm4(res.stock.lo_nm[2]));
    CHECK_EQ(field(stock, "source"), "\"" + std::string(source) + "\"");
    CHECK_EQ(field(rep, "units"), "\"" + std::string(units) + "\"");
    CHECK_EQ(field(rep, "lines"), std::to_string(res.lines));
    CHECK_EQ(res.errors, 0u);
    // The job `dexmill run` made: its simulation's grid is the report's.
    dm_job cut = tool_job(spec);
    CHECK_EQ(dm_scan_apply(s.scan, &cut), DM_OK);
    const dm_grid_info g = grid_of(cut);
    CHECK_EQ(g.nx, res.grid_nx);
    CHECK_EQ(g.ny, res.grid_ny);
    const std::string hi = "[" + mm4(g.stock.hi_nm[0]) + ", " + mm4(g.stock.hi_nm[1]) + ", " + mm4(g.stock.hi_nm[2]);
    if (!run_cli::has(field(stock, "max_mm", "]"), hi.c_str())) CHECK(false);
  }
}

void check_as_run(const char* name, const char* spec, const char* source, const char* units) {
  check_as_run(name, std::string(t::tests_dir()) + "/run/" + name, spec, source, units);
}
void check_as_run(const std::string& tmp_path, const char* spec, const char* source, const char* units) {
  check_as_run(tmp_path, tmp_path, spec, source, units);
}

}  // namespace

TEST(api_scan_chooses_what_run_chooses) {
  if (run_cli::skip()) return;
  check_as_run("pocket.ngc", "flat:6", "program", "mm");
  check_as_run("pocket.ngc", "ball:1", "program", "mm");  // the pitch from the tool
  check_as_run("arcs_inch.ngc", "vbit:6:60", "program", "inch");
  check_as_run("tool_change.ngc", "flat:3", "program", "mm");
  check_as_run(run_cli::write_tmp("scan_workpiece.ngc",
                                  "G21 G90\n(WORKPIECE,BOX,XMIN=-5,YMIN=-4,ZMIN=-12,XMAX=40,YMAX=30,ZMAX=1)\n"
                                  "G0 Z5\nG0 X2 Y2\nG1 Z-2 F300\nG1 X20 Y10\nG0 Z5\nM2\n"),
               "flat:6", "workpiece comment", "mm");
  check_as_run(run_cli::write_tmp("scan_cylinder.ngc",
                                  "G20 G90\n(WORKPIECE,CYLINDER,AXIS=Z,X=0,Y=0,ZMIN=-0.5,ZMAX=0,DIAMETER=3)\n"
                                  "G0 Z0.2\nG0 X0.5 Y0.5\nG1 Z-0.1 F20\nG1 X1 Y-0.5\nG0 Z0.2\nM2\n"),
               "flat:3", "workpiece comment's box", "inch");
  check_as_run(run_cli::write_tmp("scan_blk.ngc",
                                  "G21 G90\n(BLK FORM 0.1 Z X+0 Y+0 Z-20)\n(BLK FORM 0.2 X+60 Y+50 Z+0)\n"
                                  "G0 Z5\nG0 X10 Y10\nG1 Z-3 F300\nG1 X30\nG0 Z5\nM2\n"),
               "flat:6", "BLK FORM comments", "mm");
}

// The counts, the extents and the tools loaded.
// A stock given and no grid: the pitch for that stock, from the program's
// smallest tool, as `dexmill run --stock` chooses it.
TEST(api_scan_pitch_for_a_given_stock) {
  if (run_cli::skip()) return;
  const run_cli::Result r = run_cli::run("tool_change.ngc --tool flat:2 --stock -5,-5,-8,95,45,1 --report %/scan.json");
  CHECK_EQ(r.code, 0);
  const std::string rep = run_cli::slurp(run_cli::tmp_dir() + "/scan.json");
  const std::string grid = rep.substr(std::min(rep.find("\"grid\": "), rep.size()));
  dm_job j = tool_job("flat:2");
  Scan s(j);
  CHECK_EQ(s.run(run_cli::slurp(std::string(t::tests_dir()) + "/run/tool_change.ngc"), 4096), DM_DONE);
  const int64_t given[6] = {-5, -5, -8, 95, 45, 1};
  for (int a = 0; a < 3; ++a) {
    j.stock.lo_nm[a] = given[a] * DM_NM_PER_MM;
    j.stock.hi_nm[a] = given[a + 3] * DM_NM_PER_MM;
  }
  CHECK_EQ(dm_scan_apply(s.scan, &j), DM_OK);
  CHECK_EQ(j.stock.hi_nm[0], 95 * DM_NM_PER_MM);  // kept
  const dm_grid_info g = grid_of(j);
  CHECK_EQ(field(grid, "nx"), std::to_string(g.nx));
  CHECK_EQ(field(grid, "ny"), std::to_string(g.ny));
  // A grid given: the pitch is left alone.
  dm_job k = tool_job("flat:2");
  k.grid_nx = k.grid_ny = 100;
  CHECK_EQ(dm_scan_apply(s.scan, &k), DM_OK);
  CHECK_EQ(k.pitch_nm, 0);
  CHECK(k.stock.hi_nm[0] > k.stock.lo_nm[0]);
}

TEST(api_scan_counts_and_tools) {
  const dm_job j = tool_job("flat:3");
  Scan s(j);
  CHECK_EQ(s.run("G21 G90\nG0 Z5\nG0 X1 Y2\nG1 Z-1 F100\nG2 X5 Y2 I2 J0\nG1 X7 Y-3\nT2 M6\nG0 Z5\nM2\n", 5), DM_DONE);
  dm_scan_result r;
  CHECK_EQ(dm_scan_get_result(s.scan, &r), DM_OK);
  CHECK_EQ(r.units, DM_UNITS_MM);
  CHECK_EQ(r.lines, 9u);
  CHECK_EQ(r.arcs, 1u);
  CHECK_EQ(r.tool_changes, 1u);
  CHECK(r.feeds >= 2u);
  CHECK_EQ(r.stock_from, DM_STOCK_FROM_PROGRAM);
  CHECK_EQ(r.has_extents, 1);
  CHECK_EQ(r.extents.hi_nm[0], 7 * DM_NM_PER_MM);
  CHECK_EQ(r.extents.lo_nm[1], -3 * DM_NM_PER_MM);
  CHECK_EQ(r.ntools, 2);
  dm_scan_tool t;
  CHECK_EQ(dm_scan_tool_get(s.scan, 1, &t), DM_OK);
  CHECK_EQ(t.number, 2);
  CHECK_EQ(t.diameter_nm, 3 * DM_NM_PER_MM);
  CHECK_EQ(t.first_line, 7u);
  CHECK_EQ(dm_scan_tool_get(s.scan, 2, &t), DM_E_INDEX);
  // No move: no units, no extents, the 50 x 50 x 10 mm block.
  Scan e(j);
  CHECK_EQ(e.run("(nothing)\n", 64), DM_DONE);
  CHECK_EQ(dm_scan_get_result(e.scan, &r), DM_OK);
  CHECK_EQ(r.units, DM_UNITS_NONE);
  CHECK_EQ(r.has_extents, 0);
  CHECK_EQ(r.stock.hi_nm[0] - r.stock.lo_nm[0], 50 * DM_NM_PER_MM);
}

// The first input error stops the pass at its line, as it stops `dexmill
// run`'s; a T the job's tools lack stops it at its M6.
TEST(api_scan_stops_at_bad_input) {
  const dm_job j = tool_job("flat:3");
  Scan s(j);
  CHECK_EQ(s.run("G21 G90\nG0 X1\nG1 X2 Q F100\nG1 X30\nM2\n", 64), DM_DONE);
  dm_scan_result r;
  CHECK_EQ(dm_scan_get_result(s.scan, &r), DM_OK);
  CHECK_EQ(r.errors, 1u);
  CHECK_EQ(r.error_line, 3u);
  CHECK(r.error_col > 0u);
  CHECK(r.extents.hi_nm[0] < 30 * DM_NM_PER_MM);  // the lines after it are not read
  dm_job lib = tool_job("flat:3");
  lib.ntools = 1;
  lib.tools[0].spec = "ball:2";
  lib.tools[0].number = 1;
  Scan t(lib);
  CHECK_EQ(t.run("G21\nT1 M6\nG1 X1 F100\nT5 M6\nG1 X90\nM2\n", 64), DM_DONE);
  CHECK_EQ(dm_scan_get_result(t.scan, &r), DM_OK);
  CHECK_EQ(r.bad_tool_line, 4u);
  CHECK_EQ(r.bad_tool, 5);
  CHECK_EQ(r.pitch_nm > 0, true);
  // A comment that is not read is said, at its line.
  Scan w(j);
  CHECK_EQ(w.run("G21\n(WORKPIECE,BOX,XMIN=0)\nG1 X1 F100\nM2\n", 64), DM_DONE);
  CHECK_EQ(dm_scan_get_result(w.scan, &r), DM_OK);
  CHECK_EQ(r.workpiece_bad_line, 2u);
  CHECK_EQ(r.stock_from, DM_STOCK_FROM_PROGRAM);
}

TEST(api_scan_bad_calls_are_statuses) {
  dm_job j = tool_job("flat:3");
  size_t n = 0;
  CHECK_EQ(dm_scan_bytes(nullptr, &n), DM_E_ARGUMENT);
  CHECK_EQ(dm_scan_bytes(&j, nullptr), DM_E_ARGUMENT);
  dm_job bad = tool_job("flat:");
  CHECK_EQ(dm_scan_bytes(&bad, &n), DM_E_TOOL_SPEC);
  dm_job old = j;
  old.api_version = 0;
  CHECK_EQ(dm_scan_bytes(&old, &n), DM_E_VERSION);
  CHECK_EQ(dm_scan_bytes(&j, &n), DM_OK);
  std::vector<uint64_t> mem(n / 8 + 2);
  dm_scan* s = nullptr;
  CHECK_EQ(dm_scan_create(&j, mem.data(), n - 1, &s), DM_E_MEMORY);
  CHECK_EQ(dm_scan_create(&j, reinterpret_cast<char*>(mem.data()) + 4, n, &s), DM_E_MEMORY);
  CHECK(s == nullptr);
  CHECK_EQ(dm_scan_create(&j, mem.data(), n, &s), DM_OK);
  dm_scan_result r;
  CHECK_EQ(dm_scan_get_result(s, &r), DM_E_STATE);  // not read yet
  CHECK_EQ(dm_scan_apply(s, &j), DM_E_STATE);
  CHECK_EQ(dm_scan_feed(s, nullptr, 3), DM_E_ARGUMENT);
  const char text[] = "G1 X1 F100\n";
  CHECK_EQ(dm_scan_feed(s, text, sizeof text - 1), DM_OK);
  CHECK_EQ(dm_scan_feed(s, text, sizeof text - 1), DM_E_BUSY);  // the first piece is still lent
  int32_t state = -1;
  CHECK_EQ(dm_scan_step(s, nullptr, &state), DM_OK);
  CHECK_EQ(state, DM_NEED_INPUT);
  CHECK_EQ(dm_scan_input_taken(s), 1);
  CHECK_EQ(dm_scan_end_input(s), DM_OK);
  CHECK_EQ(dm_scan_feed(s, text, 1), DM_E_STATE);
  CHECK_EQ(dm_scan_step(s, nullptr, nullptr), DM_E_ARGUMENT);
  CHECK_EQ(dm_scan_step(s, nullptr, &state), DM_OK);
  CHECK_EQ(state, DM_DONE);
  CHECK_EQ(dm_scan_get_result(s, &r), DM_OK);
  CHECK_EQ(dm_scan_apply(s, nullptr), DM_E_ARGUMENT);
  dm_scan_destroy(s);
  CHECK_EQ(dm_scan_step(s, nullptr, &state), DM_E_ARGUMENT);  // destroyed
  CHECK_EQ(dm_scan_get_result(s, &r), DM_E_ARGUMENT);
  dm_scan_destroy(nullptr);
  CHECK_EQ(dm_struct_bytes(DM_STRUCT_SCAN_RESULT), sizeof(dm_scan_result));
  CHECK_EQ(dm_struct_bytes(DM_STRUCT_SCAN_TOOL), sizeof(dm_scan_tool));
}
