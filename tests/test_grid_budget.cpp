// The grid's memory budget (core/sim/stock_plan.h GridBudget, `dexmill run
// --max-memory`): the plan refuses a grid whose heights need more bytes
// than the budget and takes one beyond the 64 M dexels it once capped when
// the budget allows (planned only: nothing here allocates a big grid); the
// engine's whole block is held to it too; SIZE's forms read and refused.
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/sim/stock_plan.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tools/cli/option_values.h"

namespace {

using namespace dexmill;
using namespace run_cli;

constexpr int64_t kMm = 1000000;
const StockBox kBox80{PointNm{0, 0, -10 * kMm}, PointNm{80 * kMm, 80 * kMm, 0}};

}  // namespace

TEST(grid_budget_plans_beyond_the_old_cap) {
  // 0.005 mm over 80 x 80 mm: 16003^2 = 256 M dexels, four times the old cap.
  GridBudget budget;
  budget.max_bytes = uint64_t{2} << 30;
  GridPlan plan;
  PlanRefusal why;
  CHECK(plan_grid(kBox80, 0, 0, 5000, &plan, budget, &why) == PlanError::kOk);
  CHECK_EQ(plan.geo.nx, 16003);
  CHECK_EQ(plan.geo.ny, 16003);
  const uint64_t need_bytes = uint64_t{16003} * 16003 * kGridDexelBytes;
  // At the budget: taken; a byte less: refused, saying what it needs.
  budget.max_bytes = need_bytes;
  CHECK(plan_grid(kBox80, 0, 0, 5000, &plan, budget, &why) == PlanError::kOk);
  budget.max_bytes = need_bytes - 1;
  CHECK(plan_grid(kBox80, 0, 0, 5000, &plan, budget, &why) == PlanError::kOverBudget);
  CHECK_EQ(why.nx, 16003);
  CHECK_EQ(why.ny, 16003);
  CHECK_EQ(why.need_bytes, need_bytes);
  CHECK_EQ(why.max_bytes, need_bytes - 1);
  // A caller that gives no budget keeps the 64 M dexels of heights.
  CHECK(plan_grid(kBox80, 0, 0, 5000, &plan) == PlanError::kOverBudget);
  CHECK(plan_grid(kBox80, 8192, 8192, 0, &plan) == PlanError::kOk);
  // The planes a caller keeps per dexel count; fewer than the heights do not.
  budget.max_bytes = 1000 * 1000 * 10;
  budget.dexel_bytes = 10;
  CHECK(plan_check_budget(1000, 1000, budget) == PlanError::kOk);
  CHECK(plan_check_budget(1000, 1001, budget) == PlanError::kOverBudget);
  budget.dexel_bytes = 0;
  budget.max_bytes = 1000 * 1000 * kGridDexelBytes - 1;
  CHECK(plan_check_budget(1000, 1000, budget) == PlanError::kOverBudget);
  // The bytes saturate rather than wrap.
  budget.dexel_bytes = UINT64_MAX / 2;
  budget.max_bytes = UINT64_MAX - 1;
  CHECK(plan_check_budget(65535, 65535, budget, &why) == PlanError::kOverBudget);
  CHECK_EQ(why.need_bytes, UINT64_MAX);
}

TEST(grid_budget_size_values) {
  struct Case {
    const char* text;
    bool ok;
    uint64_t bytes;
  } cases[] = {
      {"1", true, 1},
      {"4096", true, 4096},
      {"1K", true, 1024},
      {"3k", true, 3072},
      {"2M", true, uint64_t{2} << 20},
      {"12G", true, uint64_t{12} << 30},
      {"17179869183G", true, uint64_t{17179869183} << 30},
      {"18446744073709551615", true, UINT64_MAX},
      {"18446744073709551616", false, 0},
      {"17179869184G", false, 0},  // 2^64
      {"99999999999G", false, 0},
      {"0", false, 0},
      {"0K", false, 0},
      {"", false, 0},
      {"K", false, 0},
      {"1.5G", false, 0},
      {"-1", false, 0},
      {"+1", false, 0},
      {" 1", false, 0},
      {"1 ", false, 0},
      {"1KB", false, 0},
      {"1K2", false, 0},
      {"1T", false, 0},
      {"1 K", false, 0},
  };
  for (const Case& c : cases) {
    uint64_t bytes = 0;
    const bool ok = dexmill::cli::parse_size_bytes(c.text, &bytes);
    if (ok != c.ok || (ok && bytes != c.bytes)) std::printf("  '%s'\n", c.text);
    CHECK_EQ(ok, c.ok);
    if (ok) CHECK_EQ(bytes, c.bytes);
  }
}

TEST(grid_budget_on_the_command_line) {
  if (skip()) return;
  const std::string job = "pocket.ngc -q --stock 0,0,-10,50,50,0 --grid 100x100 ";
  // The heights alone: 100 x 100 dexels of 2 x 2 bytes.
  Result r = run(job + "--max-memory 1K");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "dexmill: error: the grid would be 100x100 dexels, whose heights need 39 KiB (40000 bytes), more "
                   "than --max-memory's 1 KiB (1024 bytes); give a coarser --pitch or --grid, or a larger "
                   "--max-memory\n"));
  // The heights fit (no false alarm at the plan); the engine's block does not.
  r = run(job + "--max-memory 40000");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "dexmill: error: the 100x100 grid and the engine that cuts it (with the planes this run keeps per "
                   "dexel) need "));
  CHECK(has(r.err, "more than --max-memory's 39 KiB (40000 bytes); give a coarser --pitch or --grid, or a larger "
                   "--max-memory\n"));
  CHECK(lacks(r.err, "whose heights"));
  // Enough: the run goes, with the budget in M or as a plain count of bytes.
  CHECK_EQ(run(job + "--max-memory 64M").code, 0);
  CHECK_EQ(run(job + "--max-memory=" + std::to_string(64 << 20)).code, 0);
  // A saved stock's grid is held to the budget of the run that continues it.
  CHECK_EQ(run(job + "--save-stock %/budget.dxstock").code, 0);
  r = run("pocket.ngc -q --stock %/budget.dxstock --max-memory 1K");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "the grid would be 100x100 dexels, whose heights need 39 KiB (40000 bytes)"));
  CHECK_EQ(run("pocket.ngc -q --stock %/budget.dxstock --max-memory 1G").code, 0);
  // A grid past the stock file's 64 M dexels is not refused by a budget
  // that holds it, but --save-stock is, before anything is allocated.
  const std::string big = "pocket.ngc -q --stock 0,0,-10,50,50,0 --grid 8195x8195";
  r = run(big + " --save-stock %/big.dxstock");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "dexmill: error: --save-stock: the grid would be 8195x8195 dexels, more than the 67108864 a stock "
                   "file holds (64 M); give a coarser --pitch or --grid\n"));
  CHECK(has(run(big + " --max-memory 1K").err, "the grid would be 8195x8195 dexels, whose heights need"));
  // zig plans the grid run would, within the same budget.
  r = run_command("zig --stock 0,0,-10,10,10,0 --pitch 0.1 --max-memory 1K panel");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "dexmill: error: the grid would be 103x103 dexels, whose heights need 41 KiB (42436 bytes), more "
                   "than --max-memory's 1 KiB (1024 bytes)"));
  CHECK_EQ(run_command("zig --stock 0,0,-10,10,10,0 --pitch 0.1 --max-memory 1M panel").code, 0);
  // A bad SIZE is the usual option error.
  for (const char* bad : {"0", "99999999999G", "1.5G", "lots", "-1"}) {
    r = run(job + "--max-memory " + bad);
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, ("dexmill: error: --max-memory needs a size: a whole number of bytes, or of K, M or G (1024, "
                      "1024^2, 1024^3 bytes), from 1 to 2^64 - 1 bytes, not '" + std::string(bad) + "'\n").c_str()));
  }
}
