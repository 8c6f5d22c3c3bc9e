// The embedding API's tool tables (dexmill.h dm_tool_table_parse) read as
// `dexmill run --tools` reads them (platform/format/tool_table.h): the same
// tools, the same errors at the same places with the same words; and a
// scan with a table chooses the stock and grid `dexmill run --tools` does.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "display/api/dexmill.h"
#include "platform/format/tool_table.h"
#include "tests/api_scan_util.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using dexmill::ToolTableEntry;
using dexmill::ToolTableFile;

// The API's error as the host's reader words it: "NAME:LINE:COL: error: ...".
std::string api_error(const std::string& text, bool inch, dm_status* st) {
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  uint32_t line = 0, col = 0;
  char msg[300];
  *st = dm_tool_table_parse(text.data(), text.size(), inch ? 1 : 0, &j, &line, &col, msg, sizeof msg);
  if (*st == DM_OK) return "";
  return "t.tbl:" + std::to_string(line) + ":" + std::to_string(col) + ": error: " + msg;
}

}  // namespace

TEST(api_tool_table_reads_as_run_does) {
  const std::string text = run_cli::slurp(std::string(t::tests_dir()) + "/run/tools.tbl") +
                           "T7 D6 Z1.5 ;bull:6:1 holder\nT8 D0 ;probe\nT9 D3 ;vbit:3:60\n";
  for (const bool inch : {false, true}) {
    ToolTableFile host;
    CHECK(host.parse("t.tbl", text.data(), text.size(), inch) == ToolTableFile::Load::kOk);
    dm_job j;
    CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
    uint32_t line = 9, col = 9;
    CHECK_EQ(dm_tool_table_parse(text.data(), text.size(), inch, &j, &line, &col, nullptr, 0), DM_OK);
    CHECK_EQ(line, 0u);
    CHECK_EQ(j.ntools, 4);  // T8 (D0) cannot cut: left out
    int32_t k = 0;
    for (const ToolTableEntry& e : host.entries()) {
      if (e.tool.diameter_nm == 0) continue;
      const dm_tool& d = j.tools[k++];
      CHECK(d.spec == nullptr);
      CHECK_EQ(d.number, e.number);
      CHECK_EQ(d.shape, static_cast<int32_t>(e.tool.kind));
      CHECK_EQ(d.diameter_nm, e.tool.diameter_nm);
      CHECK_EQ(d.corner_radius_nm, e.tool.corner_radius_nm);
      CHECK_EQ(d.tip_angle_mdeg, e.tool.tip_angle_mdeg);
      CHECK_EQ(d.length_offset_nm, e.length_offset_nm);
    }
    // The job takes them: a simulation of it is made.
    j.tool.spec = "flat:6";
    j.stock.hi_nm[0] = j.stock.hi_nm[1] = 10 * DM_NM_PER_MM;
    j.stock.lo_nm[2] = -DM_NM_PER_MM;
    size_t n = 0;
    CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
  }
}

TEST(api_tool_table_errors_are_run_s) {
  const char* const bad[] = {
      "T1 D6\nK3\n",           "T1 P1 D\n",        "T1.5 D6\n",         "T1 P-1 D6\n",   "T1 D2000\n",
      "T1 D6 Z20000\n",        "D6\n",             "T4 Z3\n",           "T1 D6\nT1 D4\n", "T2 D6 ;ball:x\n",
      "T3 D6 ;bull:6:3.5\n",   "  T5 D3 ;vbit:3:0.5\n",
  };
  for (const char* text : bad) {
    ToolTableFile host;
    CHECK(host.parse("t.tbl", text, std::strlen(text), false) == ToolTableFile::Load::kInputError);
    dm_status st = DM_OK;
    CHECK_EQ(api_error(text, false, &st), host.message());
    CHECK_EQ(st, DM_E_TOOL_TABLE);
  }
  // More than the job holds: refused at the first one over, never cut short.
  std::string many;
  for (int k = 1; k <= DM_TOOLS_MAX + 1; ++k) many += "T" + std::to_string(k) + " D3\n";
  dm_status st = DM_OK;
  CHECK_EQ(api_error(many, false, &st), "t.tbl:17:1: error: more tools than the job holds (16)");
  CHECK_EQ(st, DM_E_TOOL_NUMBER);
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  uint32_t line = 0, col = 0;
  CHECK_EQ(dm_tool_table_parse(nullptr, 3, 0, &j, &line, &col, nullptr, 0), DM_E_ARGUMENT);
  CHECK_EQ(dm_tool_table_parse("", 0, 0, &j, &line, &col, nullptr, 0), DM_OK);
  CHECK_EQ(j.ntools, 0);
  CHECK(std::strcmp(dm_status_message(DM_E_TOOL_TABLE), "unknown status") != 0);
}

// A table's tools in the first pass: the stock (widened by the largest) and
// the pitch (from the smallest) are dexmill run --tools's; the units the
// table is read in are the program's at its first T.
TEST(api_scan_with_a_tool_table) {
  if (run_cli::skip()) return;
  const run_cli::Result r = run_cli::run("tool_change.ngc --tools tools.tbl --tool flat:6 --report %/tt.json");
  CHECK_EQ(r.code, 0);
  const std::string rep = run_cli::slurp(run_cli::tmp_dir() + "/tt.json");
  const std::string table = run_cli::slurp(std::string(t::tests_dir()) + "/run/tools.tbl");
  const std::string program = run_cli::slurp(std::string(t::tests_dir()) + "/run/tool_change.ngc");
  dm_job j = api_scan::tool_job("flat:6");
  uint32_t line = 0, col = 0;
  CHECK_EQ(dm_tool_table_parse(table.data(), table.size(), 0, &j, &line, &col, nullptr, 0), DM_OK);
  dm_scan_result res;
  {
    api_scan::Scan s(j);
    CHECK_EQ(s.run(program, 4096), DM_DONE);
    CHECK_EQ(dm_scan_get_result(s.scan, &res), DM_OK);
  }
  CHECK_EQ(res.table_units, DM_UNITS_MM);
  CHECK_EQ(res.bad_tool_line, 0u);
  const std::string grid = rep.substr(std::min(rep.find("\"grid\": "), rep.size()));
  CHECK(run_cli::has(grid, ("\"nx\": " + std::to_string(res.grid_nx) + ",").c_str()));
  CHECK(run_cli::has(grid, ("\"ny\": " + std::to_string(res.grid_ny) + ",").c_str()));
  // G20 before the first T: the table in inch, as the CLI reads it.
  api_scan::Scan s(api_scan::tool_job("flat:6"));
  CHECK_EQ(s.run("G20\nG0 X1\nT1 M6\nG21\nT2 M6\nM2\n", 64), DM_DONE);
  CHECK_EQ(dm_scan_get_result(s.scan, &res), DM_OK);
  CHECK_EQ(res.table_units, DM_UNITS_INCH);
}
