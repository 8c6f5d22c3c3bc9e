// `dexmill run --color tool|slope|thin` on programs the test
// writes, seen from above: two slots by T1 and T2 in their own colours
// (and none of them with --color plain; the classes, and that they do not
// depend on when frames flush the cut, are the engine's:
// test_sim_provenance.cpp); a 45-degree V groove in the steep band; a floor
// 0.4 mm thick red under --thin 1, 0.7 mm orange, 1.5 mm neither; the
// options' usage errors.
#include <cstdio>
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// The legend's strip at the frames' 240 rows (scale 1): left out of counts
// (and the axis triad's red X: the runs say --no-decorations).
constexpr int kLegendRows = 24;

using Pixels = std::vector<unsigned char>;

template <class Pred>
int count(const Pixels& px, Pred p) {
  int n = 0;
  for (size_t k = 0; k + 2 < px.size(); k += 3) n += p(px[k], px[k + 1], px[k + 2]);
  return n;
}
// Shades of the tool palette's first two colours (T1 orange, T2 sky blue),
// the thin mode's red and orange, and the slope mode's steep orange.
bool orange(int r, int g, int b) { return r > 150 && g > 80 && g < 210 && b < 70 && r > g + 40; }
bool sky_blue(int r, int g, int b) { return b > 150 && g > 110 && r < 150 && b > r + 60; }
bool red(int r, int g, int b) { return r > 140 && g < 80 && b < 80; }

Pixels frame(const std::string& path) { return ppm_rgb(slurp(path), kLegendRows); }

const char* kTwoTools =
    "G21 G90\nT1 M6\nM3 S10000\nG0 X-5 Y10 Z5\nG1 Z-3 F300\nG1 X45 F1000\nG0 Z5\n"
    "T2 M6\nM3 S10000\nG0 X-5 Y30\nG1 Z-3 F300\nG1 X45 F1000\nG0 Z5\nG0 X-40 Y-40\nM2\n";

}  // namespace

TEST(tool_colour_mode_gives_each_tool_its_colour) {
  if (skip()) return;
  const std::string prog = write_tmp("two_tools.ngc", kTwoTools);
  const std::string table = write_tmp("two_tools.tbl", "T1 P1 D6 ;flat:6\nT2 P2 D6 ;ball:6\n");
  const std::string base = prog + " --tools " + table + " --stock 0,0,-10,40,40,0 --pitch 0.25 --view top --size 320x240 -q --no-decorations ";
  Result r = run(base + "--color tool --image " + tmp_dir() + "/tool.ppm");
  CHECK_EQ(r.code, 0);
  const Pixels tool = frame(tmp_dir() + "/tool.ppm");
  CHECK(!tool.empty());
  const int t1 = count(tool, orange), t2 = count(tool, sky_blue);
  std::printf("  T1 orange pixels %d, T2 blue %d\n", t1, t2);
  CHECK_GT(t1, 2000);  // a 6 mm slot 40 mm long, about 20 x 140 pixels
  CHECK_GT(t2, 2000);
  r = run(base + "--color plain --image " + tmp_dir() + "/plain.ppm");
  const Pixels plain = frame(tmp_dir() + "/plain.ppm");
  CHECK_EQ(count(plain, orange), 0);
  CHECK_EQ(count(plain, sky_blue), 0);
  // That the classes do not depend on when frames flush the deferred end
  // caps is the engine's (test_sim_provenance.cpp).
}

TEST(thin_colour_mode_marks_thin_floors_only) {
  if (skip()) return;
  auto floor_frame = [](const char* name, const char* depth, const std::string& opts) {
    const std::string prog = write_tmp(name, (std::string("G21 G90\nM3 S12000\nG0 X20 Y20 Z5\nG1 Z") + depth +
                                              " F300\nG0 Z5\nG0 X-40 Y-40\nM2\n").c_str());
    const std::string img = tmp_dir() + "/" + name + ".ppm";
    CHECK_EQ(run(prog + " --stock 0,0,-6,40,40,0 --pitch 0.25 --tool flat:12 --view top --size 320x240 -q --no-decorations " + opts +
                 " --image " + img).code, 0);
    return frame(img);
  };
  // A 12 mm hole's floor, seen from above, over about 48 x 48 pixels.
  const Pixels thin04 = floor_frame("floor04.ngc", "-5.6", "--thin 1");  // --thin alone: --color thin
  const Pixels thin07 = floor_frame("floor07.ngc", "-5.3", "--color thin --thin 1");
  const Pixels thin15 = floor_frame("floor15.ngc", "-4.5", "--color thin");  // the default 1 mm
  std::printf("  0.4 mm: red %d orange %d; 0.7 mm: red %d orange %d; 1.5 mm: red %d orange %d\n", count(thin04, red),
              count(thin04, orange), count(thin07, red), count(thin07, orange), count(thin15, red), count(thin15, orange));
  CHECK_GT(count(thin04, red), 1000);
  CHECK_EQ(count(thin04, orange), 0);
  CHECK_EQ(count(thin07, red), 0);
  CHECK_GT(count(thin07, orange), 1000);
  CHECK_EQ(count(thin15, red), 0);  // no false alarm
  CHECK_EQ(count(thin15, orange), 0);
  // --thin 2: 1.5 mm is under it, 0.4 under half.
  CHECK_GT(count(floor_frame("floor15b.ngc", "-4.5", "--thin 2"), orange), 1000);
}

TEST(slope_colour_mode_puts_a_45_degree_groove_in_the_steep_band) {
  if (skip()) return;
  const std::string prog = write_tmp("groove.ngc", "G21 G90\nM3 S12000\nG0 X-8 Y20 Z5\nG1 Z-4 F300\nG1 X48 F1000\nG0 Z5\nG0 X-40 Y-40\nM2\n");
  const std::string base = prog + " --stock 0,0,-10,40,40,0 --pitch 0.2 --tool vbit:12:90 --view top --size 320x240 -q --no-decorations ";
  CHECK_EQ(run(base + "--color slope --image " + tmp_dir() + "/slope.ppm").code, 0);
  CHECK_EQ(run(base + "--image " + tmp_dir() + "/slope_plain.ppm").code, 0);
  const Pixels slope = frame(tmp_dir() + "/slope.ppm"), plain = frame(tmp_dir() + "/slope_plain.ppm");
  // The flanks: 8 mm of the groove's width across the 40 mm block, about 50 x 240 pixels.
  std::printf("  steep pixels %d (plain %d)\n", count(slope, orange), count(plain, orange));
  CHECK_GT(count(slope, orange), 3000);
  CHECK_EQ(count(plain, orange), 0);
}

TEST(colour_mode_usage_errors) {
  if (skip()) return;
  const std::string prog = write_tmp("usage.ngc", "G21 G90\nG0 X0 Y0 Z5\nM2\n");
  Result r = run(prog + " --color rainbow --report /dev/null");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--color must be plain, error, material, tool, slope, thin or engagement, not 'rainbow'"));
  r = run(prog + " --color tool --thin 1 --report /dev/null");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--thin is the limit of --color thin"));
  r = run(prog + " --thin 0 --report /dev/null");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--thin needs a thickness in mm"));
  r = run(prog + " --thin thick --report /dev/null");
  CHECK_EQ(r.code, 2);
  for (const char* mode : {"tool", "slope", "thin"}) CHECK_EQ(run(prog + " --color " + mode + " --report /dev/null").code, 0);
  r = run_command("run --help");
  CHECK(has(r.out + r.err, "--thin MM"));
}
