// `dexmill run`'s defaults and the options that tune them, as
// the report gives them: --grid keeping the stock's shape, the default rapid
// rate and --rapid, --accel in the report, their usage errors, the warning
// about a tool narrower than the pitch. The default pitch from the job's
// smallest tool and the estimates themselves are the engine's
// (test_sim_plan.cpp).
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// The value after `key` in a report ("nx": 256 -> "256").
std::string value_of(const std::string& report, const char* key) {
  const size_t at = report.find(std::string("\"") + key + "\": ");
  if (at == std::string::npos) return "";
  const size_t from = at + std::string(key).size() + 4;
  return report.substr(from, report.find_first_of(",}", from) - from);
}

std::string report_of(const std::string& args) {
  const std::string path = tmp_dir() + "/defaults.json";
  if (run(args + " -q --report " + path).code != 0) return "";
  return slurp(path);
}

}  // namespace

TEST(run_grid_keeps_the_stock_shape) {
  if (skip()) return;
  // A 204 x 44 mm stock in at most 100 x 100 dexels: 100 across, the short
  // side as many as it needs (it was padded to a square).
  const std::string r = report_of("pocket.ngc --stock 0,0,-5,204,44,0 --grid 100x100");
  CHECK_EQ(value_of(r, "nx"), std::string("100"));
  CHECK_EQ(value_of(r, "ny"), std::string("24"));
  CHECK_EQ(value_of(r, "pitch_mm"), std::string("2.103093"));
}

TEST(run_rapid_rate_sets_the_time_estimate) {
  if (skip()) return;
  const std::string d = tmp_dir() + "/";
  std::FILE* f = std::fopen((d + "rapid.ngc").c_str(), "wb");
  if (f) {
    std::fputs("G21 G90 G0 X0 Y0 Z0\nG0 X100\nM2\n", f);
    std::fclose(f);
  }
  // 100 mm of rapid: 1.2 s at the default 5000 mm/min (the rates'
  // estimates: test_sim_plan.cpp).
  std::string r = report_of(d + "rapid.ngc");
  CHECK_EQ(value_of(r, "estimated_time_s"), std::string("1.200"));
  CHECK_EQ(value_of(r, "rapid_mm_per_min"), std::string("5000"));
  // The options reach the time model: at 166.7 mm/s with 100 mm/s^2 ramps
  // the move never reaches its rate, 2 x sqrt(50 mm / 100 mm/s^2).
  r = report_of(d + "rapid.ngc --rapid 10000 --accel 100");
  CHECK_EQ(value_of(r, "rapid_mm_per_min"), std::string("10000"));
  CHECK_EQ(value_of(r, "accel_mm_per_s2"), std::string("100.000"));
  CHECK_EQ(value_of(r, "estimated_time_s"), std::string("2.000"));
  CHECK_EQ(run(d + "rapid.ngc --accel 0").code, 2);
  CHECK_EQ(run(d + "rapid.ngc --rapid 0").code, 2);
  CHECK_EQ(run(d + "rapid.ngc --rapid fast").code, 2);
}

TEST(run_warns_about_a_tool_narrower_than_the_pitch) {
  if (skip()) return;
  // A 0.1 mm tool on a 0.5 mm grid can fall between the dexel axes.
  Result r = run("pocket.ngc -q --tool flat:0.1 --pitch 0.5 --report /dev/null");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "dexmill: warning: the tool flat:0.1 is narrower than the grid's pitch (0.5000 mm)"));
  r = run("pocket.ngc -q --tool flat:1 --pitch 0.5 --report /dev/null");
  CHECK(r.err.find("narrower") == std::string::npos);
}
