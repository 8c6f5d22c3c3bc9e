// The safety checks (core/safety/safety.h) on the engine
// (tests/sim_util.h), with the jobs of `dexmill run`'s options: for each
// kind a program with one offence on a known line gives one finding on that
// line with its depth exact (the stock top and the offending Z lie on the
// LSB lattice), and the same program without the offence gives none (misses
// and false alarms alike); the findings do not depend on when the cut is
// shown (frames); a tool's own description (a flute length, a holder,
// nocentre) turns its check on. The warnings' FILE:LINE form, the report's
// keys and the exit statuses stay with the CLI's tests (test_run_safety.cpp,
// test_run_safety_body.cpp); a finding's message here is the warning's.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::Run;
using sim_test::same_events;

namespace {

constexpr int64_t mm = kNmPerMm;

// 40 x 40 x 5 mm, a flat:6, 0.2 mm dexels (test_run_safety.cpp's kStock).
void small_block(Run* r) { r->stock("0,0,-5,40,40,0").tool("flat:6").pitch("0.2"); }

const char kBad[] =
    "G21 G90\nG0 X-10 Y10 Z5\nG0 Z-1\nM3 S1000\nG1 X10 F300\nG0 X30\nM5\n"
    "G1 Y20 F300\nM3\nG1 X35 Y35 Z-7 F200\nG0 Z5\nM2\n";

uint64_t total(Run& r) { return r.sim().safety() ? r.sim().safety()->total : UINT64_MAX; }

// One event of kind k, on `line`, `depth` deep (-1: any); its message
// holds `text`.
void check_one(Run& r, SafetyKind k, uint32_t line, int64_t depth_nm, const char* text) {
  const std::vector<SafetyEvent> e = r.events(k);
  CHECK_EQ(e.size(), size_t{1});
  if (e.size() != 1) return;
  CHECK_EQ(e[0].line, line);
  if (depth_nm >= 0) CHECK_EQ(e[0].depth_nm, depth_nm);
  if (text) CHECK(run_cli::has(r.message(e[0]), text));
}

}  // namespace

TEST(sim_safety_each_kind_on_its_line_and_none_without_it) {
  // Line 6 rapids 20 mm through the stock 1 mm deep; line 8 feeds after M5;
  // line 10 plunges 2 mm below the stock's bottom (1 mm into a table at -6).
  Run bad;
  small_block(&bad);
  CHECK(bad.check_all().table("-6").text("safety_bad.ngc", kBad));
  CHECK(bad.sim().state() == SimState::kDone);
  CHECK_EQ(total(bad), uint64_t{4});  // the rise out of the hole (line 11) is not a second offence
  check_one(bad, SafetyKind::kRapidIntoStock, 6, 1 * mm, "rapid into material: ");
  check_one(bad, SafetyKind::kSpindleStopped, 8, -1, "cutting with the spindle stopped (no M3/M4) from here to line 8: ");
  check_one(bad, SafetyKind::kBelowStock, 10, 2 * mm, "the tool goes 2.000 mm below the stock's bottom at X35.000 Y35.000 Z-7.000");
  check_one(bad, SafetyKind::kIntoTable, 10, 1 * mm, "the tool goes 1.000 mm into the table at X35.000 Y35.000 Z-7.000");
  for (SafetyKind k : {SafetyKind::kBelowStock, SafetyKind::kIntoTable})
    for (const SafetyEvent& e : bad.events(k)) {
      CHECK_EQ(e.at.x_nm, 35 * mm);
      CHECK_EQ(e.at.y_nm, 35 * mm);
      CHECK_EQ(e.at.z_nm, -7 * mm);
    }
  // The rapid's volume: a 20 x 6 x 1 mm slot (the disc at its start was
  // the feed's, the one at its end is its own), as the dexels hold it: the
  // slot's edges Y7 and Y13 lie on dexel axes, so 31 rows of 0.2 mm, 6.2
  // mm: 124 mm^3.
  const DexelGrid<height_t>& g = bad.sim().grid();
  const double rapid = static_cast<double>(bad.sim().safety()->rapid_removed_lsb) * static_cast<double>(g.lsb_nm) *
                       static_cast<double>(g.pitch_nm) * static_cast<double>(g.pitch_nm) * 1e-18;
  if (std::fabs(rapid - 124.0) > 0.2) std::printf("  rapid removed %.3f mm3\n", rapid);
  CHECK(std::fabs(rapid - 124.0) <= 0.2);
  // Fixed: lifted before the rapid, the spindle on, the plunge to the floor.
  Run good;
  small_block(&good);
  CHECK(good.check_all().table("-6").text("safety_good.ngc",
                                           "G21 G90\nG0 X-10 Y10 Z5\nG0 Z-1\nM3 S1000\nG1 X10 F300\nG0 Z5\nG0 X30\n"
                                           "G1 Z-1 F300\nG1 Y20 F300\nG1 X35 Y35 Z-5 F200\nG0 Z5\nM2\n"));
  CHECK_EQ(total(good), uint64_t{0});
  CHECK_EQ(good.sim().safety()->rapid_removed_lsb, uint64_t{0});
  // The cut shown after every move (as frames flush the Mill's deferred
  // end caps): the same findings (where the cut is flushed changes
  // nothing: core/cut/mill.h, tests/test_flush_cadence.cpp).
  Run framed;
  small_block(&framed);
  SimBudget one;
  one.moves = 1;
  CHECK(framed.check_all().table("-6").text("safety_bad.ngc", kBad, one, true));
  CHECK(same_events(*framed.sim().safety(), *bad.sim().safety()));
  CHECK_EQ(framed.grid_hash(), bad.grid_hash());
  // M3 with no S word: the spindle turns (at the controller's default
  // speed); a record's rpm is 0 there, as after M5 (cameo.nc's false alarm).
  Run no_s;
  small_block(&no_s);
  CHECK(no_s.check_all().text("safety_no_s.ngc", "G21 G90\nG0 X-10 Y10 Z5\nM3\nG1 Z-1 F300\nG1 X10\nG0 Z5\nM2\n"));
  CHECK_EQ(total(no_s), uint64_t{0});
  // Without checks nothing is watched.
  Run off;
  small_block(&off);
  CHECK(off.text("safety_bad.ngc", kBad));
  CHECK(off.sim().safety() == nullptr);
}

TEST(sim_safety_end_cap_is_charged_to_the_move_that_made_it) {
  // A plunge (feed, spindle on), then a rapid straight up: the Mill cuts the
  // plunge's end cap with the rapid, but the rapid removes nothing.
  Run r;
  small_block(&r);
  CHECK(r.check_all().text("safety_cap.ngc", "G21 G90\nM3 S1000\nG0 X20 Y20 Z5\nG1 Z-2 F100\nG0 Z5\nM2\n"));
  CHECK(r.sim().state() == SimState::kDone);
  CHECK_EQ(total(r), uint64_t{0});
}

TEST(sim_safety_stops_at_the_collision) {
  Run r;
  small_block(&r);
  r.o.job.checks.rapid = true;
  r.o.job.stop_at_collision = true;
  CHECK(r.text("safety_bad.ngc", kBad));
  CHECK(r.sim().stop_reason() == SimStop::kCollision);
  CHECK_EQ(r.sim().stop_line(), 6u);
  CHECK_EQ(total(r), uint64_t{1});
}

namespace {

// A slot along X at Y20 and depth Z (a string), into a 40 x 40 x 30 block
// with `tool` (test_run_safety_body.cpp's slot and kBlock).
bool slot(Run* r, const char* name, const char* z, const char* tool) {
  return r->stock("0,0,-30,40,40,0").pitch("0.2").tool(tool).text(
      name, std::string("G21 G90\nM3 S10000\nG0 Z5\nG0 X-20 Y20\nG1 Z") + z + " F300\nG1 X60\nG0 Z5\nM2\n");
}

}  // namespace

TEST(sim_safety_shank_above_the_flutes) {
  // Flutes 5 mm long, the slot 8 deep: the shank rubs 3 mm of the wall.
  Run bad;
  CHECK(slot(&bad, "shank_bad.ngc", "-8", "flat:6,len=5"));
  CHECK_EQ(total(bad), uint64_t{1});
  check_one(bad, SafetyKind::kShank, 6, 3 * mm, "the shank touches material: 3.000 mm above the flutes");
  Run good;  // exactly the flute length
  CHECK(slot(&good, "shank_good.ngc", "-5", "flat:6,len=5"));
  CHECK_EQ(total(good), uint64_t{0});
  // Deeper than the stick-out: the dexels keep the material over the tool,
  // which the shank meets all the same.
  Run deep;
  CHECK(slot(&deep, "shank_deep.ngc", "-27", "flat:6,len=20,stick=25"));
  CHECK_EQ(total(deep), uint64_t{1});
  check_one(deep, SafetyKind::kShank, 6, 7 * mm, "the shank touches material: 7.000 mm above the flutes");
}

TEST(sim_safety_holder_touches_material) {
  // A 30 mm holder 20 mm above the tip: a slot 21 deep puts it 1 mm into the stock.
  Run bad;
  CHECK(slot(&bad, "holder_bad.ngc", "-21", "flat:6,stick=20,holder=30x10"));
  CHECK(bad.sim().state() == SimState::kDone);
  CHECK_EQ(total(bad), uint64_t{1});
  check_one(bad, SafetyKind::kHolder, 6, 1 * mm, "the holder touches material: 1.000 mm deep");
  Run good;
  CHECK(slot(&good, "holder_good.ngc", "-19.8", "flat:6,stick=20,holder=30x10"));
  CHECK_EQ(total(good), uint64_t{0});
  // A cone flaring from 10 to 40 mm over 15: over the slot's wall (3 mm
  // from the axis) its 5 mm bottom disc is at the stick-out; at 21 deep
  // it is the disc, 1 mm in, and the flank no deeper.
  Run cone;
  CHECK(slot(&cone, "cone_bad.ngc", "-21", "flat:6,stick=20,holder=10-40x15"));
  CHECK_EQ(total(cone), uint64_t{1});
  check_one(cone, SafetyKind::kHolder, 6, 1 * mm, "the holder touches material: 1.000 mm deep");
}

TEST(sim_safety_fixtures_are_never_entered) {
  const char* prog = "G21 G90\nM3 S10000\nG0 Z5\nG0 X-5 Y20\nG1 Z-2 F300\nG1 X38\nG1 X48\nG0 Z5\nM2\n";
  auto block = [](Run* r, const char* tool) { r->stock("0,0,-30,40,40,0").pitch("0.2").tool(tool); };
  // A clamp from X42 with its top at Z3: line 7 runs 5 mm into it (the
  // rise out of it, line 8, is not a second offence).
  Run clamp;
  block(&clamp, "ball:6");
  CHECK(clamp.fixture("42,10,-30,50,30,3").text("fixture.ngc", prog));
  CHECK(clamp.sim().state() == SimState::kDone);
  CHECK_EQ(total(clamp), uint64_t{1});
  check_one(clamp, SafetyKind::kFixture, 7, 5 * mm, "the tool enters a fixture: 5.000 mm deep");
  // Past the ball's reach (X48 + 3): nothing; the holder reaches it.
  Run past;
  block(&past, "ball:6");
  CHECK(past.fixture("51.2,10,-30,60,30,3").text("fixture.ngc", prog));
  CHECK_EQ(total(past), uint64_t{0});
  Run holder;
  block(&holder, "ball:6,stick=4,holder=20x10");
  CHECK(holder.fixture("51.2,10,-30,60,30,3").text("fixture.ngc", prog));
  const std::vector<SafetyEvent> e = holder.events(SafetyKind::kFixture);
  CHECK(!e.empty());
  if (!e.empty()) {
    CHECK_EQ(e[0].line, 7u);
    CHECK(run_cli::has(holder.message(e[0]), "the tool enters a fixture: 1.000 mm deep"));
  }
  // Stopping at collisions stops there.
  Run stop;
  block(&stop, "ball:6");
  stop.o.job.stop_at_collision = true;
  CHECK(stop.fixture("42,10,-30,50,30,3").text("fixture.ngc", prog));
  CHECK(stop.sim().stop_reason() == SimStop::kCollision);
  CHECK_EQ(stop.sim().stop_line(), 7u);
}

TEST(sim_safety_plunge_without_centre_cutting) {
  const char* plunge = "G21 G90\nM3 S10000\nG0 Z5\nG0 X10 Y20\nG1 Z-3 F100\nG1 X30 F300\nG0 Z5\nM2\n";
  Run nocentre;
  CHECK(nocentre.stock("0,0,-30,40,40,0").pitch("0.2").tool("flat:6,nocentre").text("plunge_bad.ngc", plunge));
  CHECK_EQ(total(nocentre), uint64_t{1});
  check_one(nocentre, SafetyKind::kPlunge, 5, 3 * mm,
            "a tool that is not centre cutting plunges 3.000 mm straight down into material at X10.000 Y20.000");
  Run centre;  // centre cutting: fine
  CHECK(centre.stock("0,0,-30,40,40,0").pitch("0.2").tool("flat:6").text("plunge_bad.ngc", plunge));
  CHECK(centre.sim().safety() == nullptr);  // nothing asks for a check
  Run ramp;
  CHECK(ramp.stock("0,0,-30,40,40,0").pitch("0.2").tool("flat:6,nocentre").text(
      "plunge_ramp.ngc", "G21 G90\nM3 S10000\nG0 Z5\nG0 X10 Y20 Z1\nG1 X20 Z-3 F100\nG1 X30 F300\nG0 Z5\nM2\n"));
  CHECK_EQ(total(ramp), uint64_t{0});
}

TEST(sim_safety_findings_past_the_list_are_counted_once_each) {
  // 70 rapids, each through fresh stock on its own line: 64 kept, 70 in all.
  const std::string text = sim_test::seventy_rapids();
  Run r;
  r.o.job.checks.rapid = true;
  CHECK(r.stock("0,0,-30,40,40,0").pitch("0.2").text("many.ngc", text));
  CHECK_EQ(total(r), uint64_t{70});
  CHECK_EQ(r.sim().safety()->nevents, kSafetyEventsMax);
  // Each on its own line: the 64 kept are lines 5 to 68.
  const std::vector<SafetyEvent> e = r.events(SafetyKind::kRapidIntoStock);
  CHECK_EQ(e.size(), kSafetyEventsMax);
  for (size_t k = 0; k < e.size(); ++k) CHECK_EQ(e[k].line, static_cast<uint32_t>(5 + k));
}
