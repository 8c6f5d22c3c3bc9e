// The process rules of a stock's materials (core/safety/material_limits.h)
// on the engine (tests/sim_util.h), with the jobs of `dexmill run
// --material`: a feed over a material's limit on exactly one line is one
// violation on that line, coolant in wood one on its line, a spindle speed
// outside a range one, a program within the limits none; every preset
// makes a stock the engine cuts. The warnings' FILE:LINE form, the report's
// materials and the summary stay with the CLI's tests (test_run_material.cpp);
// a violation's message here is the warning's.
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::Run;

namespace {

const char* kSandwich =
    "material alu plain max_feed=1200 spindle=8000..24000 density=2.7\n"
    "material wood wood max_feed=3000 coolant=no density=0.7\n"
    "layer -20 -10 alu\n"
    "layer -10 0 wood\n";

// 40 x 40 x 20 mm of `material`, a flat:6, 0.2 mm dexels.
bool cut(Run* r, const std::string& material, const char* name, const char* text) {
  return r->stock("0,0,-20,40,40,0").pitch("0.2").tool("flat:6").material(material).text(name, text);
}

uint64_t total(Run& r) { return r.sim().process() ? r.sim().process()->total : UINT64_MAX; }

}  // namespace

TEST(sim_material_feed_spindle_coolant_on_their_lines) {
  const std::string mat = run_cli::write_tmp("sim-sandwich.txt", kSandwich);
  // Line 6 runs 2000 mm/min through both layers (over alu's 1200); line 10
  // floods the wood; line 13 runs 2000 in the wood alone (fine).
  Run r;
  CHECK(cut(&r, mat, "mat.ngc",
            "G21 G90\nM3 S12000\nG0 Z5\nG0 X-5 Y10\nG1 Z-15 F300\nG1 X45 F2000\nG0 Z5\n"
            "G0 X-5 Y20\nG1 Z-4 F300\nM8 G1 X45 F1000\nM9\nG0 X-5 Y30\nG1 X45 Z-4 F2000\nG0 Z5\nM2\n"));
  CHECK(r.sim().state() == SimState::kDone);
  CHECK_EQ(total(r), uint64_t{2});
  CHECK_EQ(r.sim().process()->nkept, size_t{2});
  const std::vector<ProcessViolation> feed = r.violations(ProcessRule::kFeed), coolant = r.violations(ProcessRule::kCoolant);
  CHECK_EQ(feed.size(), size_t{1});
  CHECK_EQ(coolant.size(), size_t{1});
  if (feed.size() == 1) {
    CHECK_EQ(feed[0].line, 6u);
    CHECK_EQ(feed[0].value, 2000 * kNmPerMm);
    CHECK(run_cli::has(r.message(feed[0]), "feed 2000 mm/min over alu's limit 1200 mm/min"));
  }
  if (coolant.size() == 1) {
    CHECK_EQ(coolant[0].line, 10u);
    CHECK(run_cli::has(r.message(coolant[0]), "coolant on (M8) while cutting wood, which forbids it"));
  }
  CHECK_EQ(r.scan_warnings(), 0u);  // apart from the G-code's warnings: there are none
  // The spindle over alu's range.
  Run fast;
  CHECK(cut(&fast, mat, "fast.ngc", "G21 G90\nM3 S30000\nG0 X-5 Y10 Z5\nG1 Z-15 F300\nG1 X45 F1000\nG0 Z5\nM2\n"));
  const std::vector<ProcessViolation> spindle = fast.violations(ProcessRule::kSpindle);
  CHECK(!spindle.empty());
  if (!spindle.empty()) {
    CHECK_EQ(spindle[0].line, 5u);
    CHECK(run_cli::has(fast.message(spindle[0]), "spindle 30000 rpm outside alu's range 8000..24000 rpm"));
  }
  // Within every limit: nothing.
  Run calm;
  CHECK(cut(&calm, mat, "calm.ngc", "G21 G90\nM3 S12000\nG0 X-5 Y10 Z5\nG1 Z-15 F300\nG1 X45 F1000\nG0 Z5\nM2\n"));
  CHECK_EQ(total(calm), uint64_t{0});
  // Without a material nothing is watched.
  Run none;
  CHECK(none.stock("0,0,-20,40,40,0").pitch("0.2").tool("flat:6").text("calm.ngc",
        "G21 G90\nM3 S12000\nG0 X-5 Y10 Z5\nG1 Z-15 F300\nG1 X45 F1000\nG0 Z5\nM2\n"));
  CHECK(none.sim().process() == nullptr);
}

// One finding per (line, rule, material) however the cut reaches it:
// short moves whose end caps the next line cuts (charged back to the
// line before, column by column, alternating with the next line's own),
// and a line an o-word loop runs four times, each through fresh wood. The
// spindle (900 rpm, under beech's 12000) and the coolant (M8 in wood) are
// broken on every line that removes wood: lines 5, 6, 7 and 10, two each.
// Before, this 14-line program counted 17 (all kept: 8 distinct, line 10's
// three times each).
TEST(sim_material_one_finding_per_line_rule_material) {
  Run r;
  CHECK(r.stock("0,0,-20,40,40,0").pitch("0.2").tool("flat:6").material("wood").text("once.ngc",
        "G21 G90\n"
        "M3 S900 M8\n"
        "G0 X-5 Y10 Z5\n"
        "G1 Z-2 F300\n"
        "G1 X10 F500\n"
        "G1 X20\n"
        "G1 X30\n"
        "#1 = 0\n"
        "o100 repeat [4]\n"
        "  G1 Y[12 + #1] X35\n"
        "  #1 = [#1 + 2]\n"
        "o100 endrepeat\n"
        "G0 Z5\n"
        "M2\n"));
  CHECK(r.sim().state() == SimState::kDone);
  const ProcessWatch* w = r.sim().process();
  CHECK(w != nullptr);
  if (!w) return;
  std::set<std::tuple<uint32_t, int, int>> distinct;
  std::set<uint32_t> lines;
  for (size_t k = 0; k < w->nkept; ++k) {
    distinct.insert(std::make_tuple(w->kept[k].line, int(w->kept[k].rule), int(w->kept[k].material)));
    lines.insert(w->kept[k].line);
  }
  CHECK_EQ(distinct.size(), w->nkept);  // none kept twice
  CHECK_EQ(w->total, uint64_t(w->nkept));  // and the count is the findings
  CHECK_EQ(w->total, uint64_t{8});
  CHECK(lines == (std::set<uint32_t>{5, 6, 7, 10}));
  CHECK_EQ(w->tally[0].violations, uint64_t{8});
  if (w->total != 8 || w->nkept != distinct.size())
    for (size_t k = 0; k < w->nkept; ++k) std::printf("  kept: line %u rule %d\n", w->kept[k].line, int(w->kept[k].rule));
}

TEST(sim_material_presets_make_a_stock) {
  for (const char* preset : {"two-layer", "marble", "wood", "bronze", "aluminium", "wood-on-aluminium"}) {
    Run r;
    CHECK(cut(&r, preset, "calm2.ngc", "G21 G90\nM3 S12000\nG0 X-5 Y10 Z5\nG1 Z-5 F300\nG1 X45 F500\nG0 Z5\nM2\n"));
    CHECK(r.sim().state() == SimState::kDone);
    CHECK(r.sim().process() != nullptr);
    CHECK_GT(r.sim().removed_lsb(), uint64_t{0});
  }
}
