// The embedding API's built-in demo (dexmill.h dm_demo_program,
// dm_demo_text): the program `dexmill run --demo pocket` writes to
// out/demo.ngc, byte for byte, and its job's texts, which the API reads
// into the stock and the grid the CLI's report gives.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "display/api/dexmill.h"
#include "tests/api_scan_util.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

TEST(api_demo_is_run_s_demo) {
  if (run_cli::skip()) return;
  const run_cli::Result r = run_cli::run("--demo pocket -q --size 64x48 --report %/demo.json", nullptr, true);
  CHECK_EQ(r.code, 0);
  const std::string cli = run_cli::slurp(run_cli::tmp_dir() + "/out/demo.ngc");
  const size_t n = dm_demo_program(nullptr, 0);
  CHECK_EQ(n, cli.size());
  std::string text(n + 1, 'x');
  CHECK_EQ(dm_demo_program(&text[0], 10), n);  // the whole length, what fits written
  CHECK_EQ(text.substr(0, 10), cli.substr(0, 9) + std::string(1, '\0'));
  CHECK_EQ(dm_demo_program(&text[0], n + 1), n);
  text.resize(n);
  CHECK(text == cli);
  CHECK_EQ(dm_demo_program(nullptr, 5), n);
  // Its job: the stock, the table, and the grid the scan chooses with them.
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  j.tool.spec = "flat:6";
  const char* stock = dm_demo_text(DM_DEMO_STOCK);
  for (int k = 0; k < 6; ++k) {
    const char* end = std::strchr(stock, ',');
    const size_t len = end ? static_cast<size_t>(end - stock) : std::strlen(stock);
    CHECK_EQ(dm_mm_to_nm(stock, len, k < 3 ? &j.stock.lo_nm[k] : &j.stock.hi_nm[k - 3]), DM_OK);
    stock += len + (end ? 1 : 0);
  }
  const char* table = dm_demo_text(DM_DEMO_TOOL_TABLE);
  uint32_t line = 0, col = 0;
  CHECK_EQ(dm_tool_table_parse(table, std::strlen(table), 0, &j, &line, &col, nullptr, 0), DM_OK);
  CHECK_EQ(j.ntools, 3);
  CHECK(std::strcmp(dm_demo_text(DM_DEMO_MATERIAL), "wood-on-aluminium") == 0);
  CHECK(dm_demo_text(3) == nullptr);
  {
    api_scan::Scan s(j);
    CHECK_EQ(s.run(text, 65536), DM_DONE);
    CHECK_EQ(dm_scan_apply(s.scan, &j), DM_OK);
  }
  const std::string rep = run_cli::slurp(run_cli::tmp_dir() + "/demo.json");
  const std::string grid = rep.substr(std::min(rep.find("\"grid\": "), rep.size()));
  const dm_grid_info g = api_scan::grid_of(j);
  CHECK(run_cli::has(grid, ("\"nx\": " + std::to_string(g.nx) + ", \"ny\": " + std::to_string(g.ny)).c_str()));
}
