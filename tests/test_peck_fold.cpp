// The engine holds a line's vertical moves at one X and Y and cuts them as
// one plunge (core/sim/peck_fold.h). Each program here runs with the fold
// and without it (Simulation::set_fold(false): every move cut by itself),
// for every tool shape, both cut modes and budgets that stop inside a
// cycle, and everything a run gives must be the same: the grid to the bit,
// the line that last cut each column, the moves, the time. The fold must
// also be there: the peck cycles cost a fraction of the unfolded work.
#include <cstdint>
#include <string>
#include <vector>

#include "core/sim/simulation.h"
#include "core/stock/stock_file.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::box_job;
using sim_test::Engine;

namespace {

constexpr int64_t mm = 1000000;

// Peck cycles of both kinds, repeats, a plunge over several lines at one
// point (one fold a line), a side entry before a plunge (the end cap the
// next line cuts is the previous line's), and a cycle whose pecks start
// below the stock's top.
const char* const kPrograms[] = {
    ("G21 G90 G17\nG0 X2 Y2 Z5\nM3 S10000\nG98 G83 X2 Y2 Z-6.5 R0.5 Q0.37 F300\nX7.3 Y3.1\n"
    "G99 G83 X4.05 Y7 Z-3.3 R1 Q0.05\nG80\nG0 Z5\nG1 X6 Z-2 F200\nG0 Z5\nM30\n"),
    "G21 G90 G17\nG0 X5 Y5 Z3\nM3 S9000\nG98 G73 X5 Y5 Z-5.2 R0.2 Q0.3 F250\nG91 X-1.7 L2\nG90 G80\nG0 Z3\nM30\n",
    "G21 G90\nG0 X3.3 Y6.6 Z2\nM3 S8000\nG1 Z-1 F100\nG1 Z-2.5\nG0 Z1\nG1 Z-3.77\nG1 Z-3.77\nG0 Z2\nM30\n",
    "G21 G90\nG0 X-3 Y5 Z-1.5\nM3 S8000\nG1 X5 F300\nG99 G83 X5 Y5 Z-4.4 R-1.5 Q0.21 F150\nG80\nG1 X9 Y9\nG0 Z4\nM30\n",
};

const char* const kTools[] = {"flat:3", "ball:3", "bull:4:1", "vbit:4:90"};

struct Outcome {
  uint64_t hash = 0, moves = 0, sim_us = 0, updates = 0, removed = 0;
  std::vector<uint32_t> lines;
};

Outcome run(const char* program, const char* tool, CutMode mode, bool fold, uint64_t moves_budget) {
  SimJob j = box_job(0, 0, -8 * mm, 10 * mm, 10 * mm, 93700, tool);
  j.mode = mode;
  j.provenance = j.provenance_lines = true;
  Engine e(j);
  e.sim->set_fold(fold);
  SimBudget b;
  b.moves = moves_budget;
  CHECK(e.run(program, moves_budget == 1 ? 17 : 1 << 20, b) == SimState::kDone);
  CHECK_EQ(e.sim->errors(), 0u);
  Outcome o;
  o.hash = e.grid_hash();
  o.moves = e.sim->status().moves;
  o.sim_us = static_cast<uint64_t>(e.sim->status().sim_us);
  o.updates = e.sim->mill().stats().dexel_updates;
  o.removed = e.sim->removed_lsb();
  const StockColumns c = e.sim->stock_columns(kStockLayerLine);
  CHECK(c.line != nullptr);
  const size_t n = static_cast<size_t>(e.sim->grid().nx) * static_cast<size_t>(e.sim->grid().ny);
  if (c.line) o.lines.assign(c.line, c.line + n);
  return o;
}

}  // namespace

TEST(peck_fold_cuts_what_every_move_cuts) {
  int folded_less = 0, runs = 0;
  for (const char* program : kPrograms) {
    for (const char* tool : kTools) {
      for (CutMode mode : {CutMode::kSweep, CutMode::kStamp}) {
        const Outcome ref = run(program, tool, mode, false, UINT64_MAX);
        CHECK(ref.removed > 0);
        for (uint64_t budget : {UINT64_MAX, uint64_t{1}}) {
          const Outcome got = run(program, tool, mode, true, budget);
          ++runs;
          CHECK_EQ(got.hash, ref.hash);
          CHECK(got.lines == ref.lines);
          CHECK_EQ(got.moves, ref.moves);
          CHECK_EQ(got.sim_us, ref.sim_us);
          CHECK_EQ(got.removed, ref.removed);
          CHECK(got.updates <= ref.updates);
          if (got.updates < ref.updates) ++folded_less;
        }
      }
    }
  }
  CHECK_EQ(runs, 64);
  // The three peck programs in every way without a budget (a budget of one
  // move ends each step, and a fold with it, but inside a line longer than
  // the queue).
  CHECK(folded_less >= 24);
}

// The deep cycle: a thousand pecks cost about one plunge, not a thousand.
TEST(peck_fold_makes_a_peck_cycle_one_plunge) {
  const char* program = "G21 G90\nG0 X5 Y5 Z2\nM3 S9000\nG98 G83 X5 Y5 Z-6 R0 Q0.006 F300\nG80\nM30\n";
  const Outcome ref = run(program, "flat:3", CutMode::kSweep, false, UINT64_MAX);
  const Outcome got = run(program, "flat:3", CutMode::kSweep, true, UINT64_MAX);
  CHECK_EQ(got.hash, ref.hash);
  CHECK(got.lines == ref.lines);
  CHECK(got.moves > 2000);
  CHECK(got.updates * 100 < ref.updates);
}

// A watcher that judges each move by what it removed sees every move: with
// the safety checks on, the engine cuts each move by itself.
TEST(peck_fold_is_off_under_move_checks) {
  const char* program = kPrograms[0];
  SimJob j = box_job(0, 0, -8 * mm, 10 * mm, 10 * mm, 93700, "flat:3");
  j.checks.rapid = j.checks.spindle = true;
  uint64_t updates[2] = {0, 0};
  for (int fold = 0; fold < 2; ++fold) {
    Engine e(j);
    e.sim->set_fold(fold == 1);
    CHECK(e.run(program, 1 << 20) == SimState::kDone);
    updates[fold] = e.sim->mill().stats().dexel_updates;
  }
  CHECK_EQ(updates[0], updates[1]);
}
