// The stock, the grid and the time estimate planned as `dexmill run` plans
// them, on the engine (tests/sim_util.h): the harness's plan of pocket.ngc
// is the one tests/run/pocket.report.golden pins; the default pitch follows
// the job's smallest tool within 256..1024 dexels across; an STL
// blank is the stock (less to remove than its box); the rapid rate and the
// acceleration in the estimate. That the options reach the plan and the
// report stays with the CLI's tests (test_run_defaults.cpp, test_run_cli.cpp).
#include <string>

#include "core/math/fixed.h"
#include "platform/report/report_json.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::Run;
using sim_test::run_file;

namespace {

std::string mm4(int64_t nm) { return nm_to_mm_text(nm, 4); }
// A time as the report rounds it, ms.
int64_t ms(int64_t us) { return div_round(us, 1000); }

}  // namespace

// The same plan and cut as the report of `dexmill run pocket.ngc`.
TEST(sim_plan_of_the_pocket_is_the_reports) {
  Run r;
  CHECK(r.program(run_file("pocket.ngc")));
  const GridPlan& p = r.plan();
  CHECK_EQ(mm4(p.stock.lo.x_nm) + " " + mm4(p.stock.lo.y_nm) + " " + mm4(p.stock.lo.z_nm),
           std::string("0.0000 0.0000 -10.0000"));
  CHECK_EQ(mm4(p.stock.hi.x_nm) + " " + mm4(p.stock.hi.y_nm) + " " + mm4(p.stock.hi.z_nm),
           std::string("33.0001 23.0870 0.0000"));
  CHECK_EQ(p.geo.nx, 256);
  CHECK_EQ(p.geo.ny, 180);
  CHECK_EQ(p.geo.pitch_nm, int64_t{130435});
  CHECK_EQ(p.geo.lsb_nm, int64_t{200});
  CHECK(r.sim().state() == SimState::kDone);
  CHECK_EQ(r.removed_mm3(), std::string("1341.719"));
  CHECK_EQ(r.sim().mill().stats().instances, uint64_t{20});
  CHECK_EQ(r.sim().mill().stats().dexel_updates, uint64_t{80726});
  CHECK_EQ(ms(r.scan().summary.estimated_time_us()), int64_t{16779});
}

TEST(sim_default_pitch_follows_the_smallest_tool) {
  const char* stock = "0,0,-5,50,30,0";
  // flat:6 on a 50 mm stock: 6/32 = 0.1875 mm (50 / 0.1875 = 267 across).
  {
    Run r;
    CHECK(r.tool("flat:6").stock(stock).program(run_file("pocket.ngc")));
    CHECK_EQ(r.plan().geo.pitch_nm, int64_t{187500});
  }
  // A 1 mm ball would ask for 0.03125; 1024 across is the finest: 50 / 1021.
  {
    Run r;
    CHECK(r.tool("ball:1").stock(stock).program(run_file("pocket.ngc")));
    CHECK_EQ(r.plan().geo.pitch_nm, int64_t{48972});
    CHECK_EQ(r.plan().geo.nx, 1024);
  }
  // A 20 mm face mill: 256 across at the coarsest (50 / 253).
  {
    Run r;
    CHECK(r.tool("flat:20").stock(stock).program(run_file("pocket.ngc")));
    CHECK_EQ(r.plan().geo.pitch_nm, int64_t{197629});
    CHECK_EQ(r.plan().geo.nx, 256);
  }
  // The table's tools count: tool_change.ngc uses flat:4 and ball:6.
  {
    Run r;
    CHECK(r.tools(run_file("tools.tbl")).stock(stock).program(run_file("tool_change.ngc")));
    CHECK_EQ(r.plan().geo.pitch_nm, int64_t{125000});
  }
}

TEST(sim_rapid_rate_and_acceleration_set_the_time_estimate) {
  const char* prog = "G21 G90 G0 X0 Y0 Z0\nG0 X100\nM2\n";
  // 100 mm of rapid: 1.2 s at the default 5000 mm/min, 0.6 s at 10000;
  // with 100 mm/s^2 ramps (at 83.3 mm/s): 1.2 + 0.833 s; at 166.7 mm/s the
  // ramps meet, 2 x sqrt(50 mm / 100 mm/s^2). The cut's own estimate
  // agrees with the first pass's (the report's).
  struct Case {
    int64_t rapid_mm_per_min, accel_mm_per_s2, want_ms;
  } cases[] = {{5000, 0, 1200}, {10000, 0, 600}, {5000, 100, 2033}, {10000, 100, 2000}};
  for (const Case& c : cases) {
    Run r;
    r.o.job.rapid_nm_per_min = c.rapid_mm_per_min * kNmPerMm;
    r.o.job.accel_nm_per_s2 = c.accel_mm_per_s2 * kNmPerMm;
    CHECK(r.text("rapid.ngc", prog));
    CHECK_EQ(ms(r.scan().summary.estimated_time_us()), c.want_ms);
    CHECK_EQ(r.sim().time().estimated_time_us(), r.scan().summary.estimated_time_us());
  }
}

TEST(sim_stock_from_an_stl_blank) {
  // tests/run/blank_step.stl: a closed 36 x 26 x 10 mm block whose right
  // third (X > 24) is 3 mm lower; the pocket there meets the step.
  Run blank;
  CHECK(blank.stock_stl(run_file("blank_step.stl")).program(run_file("pocket.ngc")));
  const GridPlan& p = blank.plan();
  CHECK_EQ(mm4(p.stock.lo.x_nm) + " " + mm4(p.stock.lo.y_nm) + " " + mm4(p.stock.lo.z_nm),
           std::string("-2.0000 -2.0000 -10.0000"));
  CHECK_EQ(mm4(p.stock.hi.x_nm) + " " + mm4(p.stock.hi.y_nm) + " " + mm4(p.stock.hi.z_nm),
           std::string("34.0001 24.0396 0.0000"));
  // Less to remove than from the full box: the step was never there.
  CHECK_EQ(blank.removed_mm3(), std::string("1090.985"));
  Run box;
  CHECK(box.stock("-2,-2,-10,34,24.0396,0").program(run_file("pocket.ngc")));
  CHECK(box.removed_mm3() != "1090.985");
  CHECK_GT(box.sim().removed_lsb(), blank.sim().removed_lsb());
}
