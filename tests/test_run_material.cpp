// `dexmill run --material` as the CLI gives it: the process
// rules' warnings as FILE:LINE:1 on a program the test writes, the report's
// materials (null without --material), the summary's count apart from the
// G-code's warnings; an unknown preset and a bad material file's
// FILE:LINE:COL error; --color material. Which violations, on which lines,
// the spindle rule, the programs within the limits and the presets' stocks
// are the engine's (test_sim_process.cpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

int warnings_in(const std::string& s) {
  int n = 0;
  for (size_t at = s.find("warning:"); at != std::string::npos; at = s.find("warning:", at + 1)) ++n;
  return n;
}

const char* kSandwich =
    "material alu plain max_feed=1200 spindle=8000..24000 density=2.7\n"
    "material wood wood max_feed=3000 coolant=no density=0.7\n"
    "layer -20 -10 alu\n"
    "layer -10 0 wood\n";

}  // namespace

TEST(material_feed_spindle_coolant_on_their_lines) {
  if (skip()) return;
  const std::string mat = write_tmp("sandwich.txt", kSandwich);
  // Line 6 runs 2000 mm/min through both layers (over alu's 1200); line 10
  // floods the wood; line 13 runs 2000 in the wood alone (fine).
  const std::string p = write_tmp("mat.ngc",
                                  "G21 G90\nM3 S12000\nG0 Z5\nG0 X-5 Y10\nG1 Z-15 F300\nG1 X45 F2000\nG0 Z5\n"
                                  "G0 X-5 Y20\nG1 Z-4 F300\nM8 G1 X45 F1000\nM9\nG0 X-5 Y30\nG1 X45 Z-4 F2000\nG0 Z5\nM2\n");
  const std::string args = p + " --stock 0,0,-20,40,40,0 --pitch 0.2 --tool flat:6 -q --material " + mat;
  Result r = run(args + " --report " + tmp_dir() + "/mat.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "mat.ngc:6:1: warning: feed 2000 mm/min over alu's limit 1200 mm/min"));
  CHECK(has(r.err, "mat.ngc:10:1: warning: coolant on (M8) while cutting wood, which forbids it"));
  CHECK_EQ(warnings_in(r.err), 2);
  const std::string rep = slurp(tmp_dir() + "/mat.json");
  CHECK(has(rep, "\"violations_total\": 2"));
  CHECK(has(rep, "{\"name\": \"alu\""));
  // With no output, the summary counts them apart from the G-code's warnings.
  r = run(p + " --stock 0,0,-20,40,40,0 --pitch 0.2 --tool flat:6 --material " + mat);
  CHECK(has(r.out, "process  2 rule violation(s) (on standard error)"));
  CHECK(has(r.out, "warnings 0\n"));
  // Without --material the report says null.
  const std::string calm = write_tmp("calm.ngc", "G21 G90\nM3 S12000\nG0 X-5 Y10 Z5\nG1 Z-15 F300\nG1 X45 F1000\nG0 Z5\nM2\n");
  r = run(calm + " --stock 0,0,-20,40,40,0 --pitch 0.2 --tool flat:6 -q --report " + tmp_dir() + "/nomat.json");
  CHECK(has(slurp(tmp_dir() + "/nomat.json"), "\"materials\": null"));
}

TEST(material_unknown_presets_and_bad_files) {
  if (skip()) return;
  const std::string calm = write_tmp("calm2.ngc", "G21 G90\nM3 S12000\nG0 X-5 Y10 Z5\nG1 Z-5 F300\nG1 X45 F500\nG0 Z5\nM2\n");
  const std::string base = calm + " --stock 0,0,-20,40,40,0 --pitch 0.2 --tool flat:6 -q --report /dev/null";
  Result r = run(base + " --material marbel");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "is neither a preset"));
  const std::string bad = write_tmp("bad.txt", "material a plain\nlayer -5 0 b\n");
  r = run(base + " --material " + bad);
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "bad.txt:2:12: error: no material named 'b'"));
}

namespace {

// Yellowish pixels (any shade of the two-layer block's lower layer; the
// workpiece grey, the black layer and the table are not).
int yellowish(const std::vector<unsigned char>& px) {
  int n = 0;
  for (size_t k = 0; k + 2 < px.size(); k += 3) n += px[k] > 110 && px[k + 1] > 80 && px[k + 2] < 70;
  return n;
}

}  // namespace

// --color material (the default with --material): a hole drilled through
// the black upper layer of the two-layer block shows the yellow one.
TEST(material_colour_mode_shows_the_layer_cut_into) {
  if (skip()) return;
  const std::string shallow = write_tmp("shallow.ngc", "G21 G90\nM3 S12000\nG0 X20 Y20 Z5\nG1 Z-2 F300\nG0 Z5\nG0 X-40 Y-40\nM2\n");
  const std::string deep = write_tmp("deep.ngc", "G21 G90\nM3 S12000\nG0 X20 Y20 Z5\nG1 Z-15 F300\nG0 Z5\nG0 X-40 Y-40\nM2\n");
  const std::string opts = " --stock 0,0,-20,40,40,0 --pitch 0.25 --tool flat:12 --view top -q --material two-layer --image ";
  Result r = run(shallow + opts + tmp_dir() + "/shallow.ppm");
  CHECK_EQ(r.code, 0);
  r = run(deep + opts + tmp_dir() + "/deep.ppm");
  CHECK_EQ(r.code, 0);
  const std::vector<unsigned char> a = ppm_rgb(slurp(tmp_dir() + "/shallow.ppm")), b = ppm_rgb(slurp(tmp_dir() + "/deep.ppm"));
  CHECK(!a.empty() && !b.empty());
  const int yellow_a = yellowish(a), yellow_b = yellowish(b);
  std::printf("  yellow pixels: %d in the shallow hole's frame, %d in the deep one's\n", yellow_a, yellow_b);
  CHECK_EQ(yellow_a, 0);
  CHECK_GT(yellow_b, 1000);  // the 12 mm hole's floor, seen from above
  // Plain keeps the grey; material needs --material.
  r = run(deep + " --stock 0,0,-20,40,40,0 --pitch 0.25 --tool flat:12 --view top -q --material two-layer --color plain --image " +
          tmp_dir() + "/plain.ppm");
  CHECK_EQ(yellowish(ppm_rgb(slurp(tmp_dir() + "/plain.ppm"))), 0);
  CHECK_EQ(run(deep + " --color material --report /dev/null").code, 2);
}
