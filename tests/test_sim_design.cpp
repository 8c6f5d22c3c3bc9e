// Gouges traced to their lines and the assessment against a design part
// (paper §2.5; core/assess), on the engine (tests/sim_util.h) with the jobs
// of `dexmill run --design`: pocket.ngc against its own design (the G81
// hole's gouge on line 20, the pocket's corners left; the same from a
// binary STL; a tolerance box forgiving a corner), gouge_one.ngc's one gouge
// on line 7 (stopping there cuts less; short of the floor or on it, none),
// a design from a height image (P5 and P2 alike). The figures are the
// report's own text of the assessment (platform/report/report_json.h). The warnings
// as FILE:LINE:1, the report's design key, the exit statuses and the
// images stay with the CLI's tests (test_run_cli.cpp).
#include <string>

#include "tests/pocket_part.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using run_cli::has;
using sim_test::Run;
using sim_test::run_file;

namespace {

// The assessment without the design file's name.
std::string unnamed(std::string a, const std::string& file) {
  const size_t at = a.find(file);
  if (at != std::string::npos) a.replace(at, file.size(), "DESIGN");
  return a;
}

}  // namespace

TEST(sim_design_assessment_names_the_gouge_and_the_leftover) {
  const std::string d = run_cli::tmp_dir() + "/";
  run_cli::write_file(d + "sim-pd.stl", pocket_part::ascii_stl(pocket_part::design()));
  run_cli::write_file(d + "sim-pdb.stl", pocket_part::binary_stl(pocket_part::design()));
  Run r;
  CHECK(r.design(d + "sim-pd.stl").tool("flat:6").program(run_file("pocket.ngc")));
  CHECK(r.sim().state() == SimState::kDone);
  // The one gouge, charged to the G81 line while cutting: 8 mm at
  // X28.044 Y15.130, the design at Z0, the cut at Z-8.
  const GougeWatch* w = r.sim().gouges();
  CHECK(w != nullptr);
  if (!w) return;
  CHECK_EQ(w->total, uint64_t{1});
  CHECK_EQ(w->nevents, size_t{1});
  const std::string a = r.assessment();
  CHECK(has(a, "\"gouges\": [\n      {\"line\": 20, \"x_mm\": 28.0435, \"y_mm\": 15.1305, \"depth_mm\": 8.0000, "
               "\"design_z_mm\": 0.0000, \"cut_z_mm\": -8.0000,"));
  CHECK_EQ(r.scan_warnings() + r.scan_errors(), 0u);
  // The G81 hole (flat 6 mm to Z-8 at X28 Y18) goes 8 mm below the design's
  // top beside the pocket; the pocket's four corners keep 3 mm of material.
  CHECK(has(a, "\"kind\": \"stl\", \"triangles\": 10, \"columns\": 45212}"));
  CHECK(has(a, "\"max_gouge\": {\"mm\": 8.0000, \"x_mm\": 28.0435, \"y_mm\": 15.1305}"));
  CHECK(has(a, "\"max_leftover\": {\"mm\": 3.0000, \"x_mm\": 2.0870, \"y_mm\": 2.0870}"));
  // The hole's area beyond tolerance: the 6 mm circle (28.27 mm^2) to the grid's resolution.
  CHECK(has(a, "\"gouged\": {\"area_mm2\": 28.174,"));
  CHECK(has(a, "\"E_mm2\": 104005.000000, \"E_rel\": 0.274212599, \"rms_mm\": 1.5167"));
  CHECK(has(a, "\"within_tolerance_percent\": 88.55"));
  // The same mesh as binary STL: the same assessment but for the file's name.
  Run b;
  CHECK(b.design(d + "sim-pdb.stl").program(run_file("pocket.ngc")));
  CHECK(unnamed(a, "sim-pd.stl") == unnamed(b.assessment(), "sim-pdb.stl"));
  // A tolerance of 3 mm inside a box over the pocket's corner at (2, 2) forgives its leftover.
  Run t;
  CHECK(t.design(d + "sim-pd.stl").tolerance_box("0", "0", "6", "6", "3").program(run_file("pocket.ngc")));
  const std::string at = t.assessment();
  CHECK(has(at, "\"tolerance_boxes\": 1"));
  CHECK(at.find("\"x_mm\": 2.0870, \"y_mm\": 2.0870") == std::string::npos);
}

TEST(sim_gouges_are_traced_to_their_line) {
  // One line gouges: one gouge, on that line, as deep as the ramp's end
  // below the floor (0.4 mm; the grid's LSB is 0.2 um); the end cap the Mill
  // cuts with the next record (G0 Z5) is charged to line 7 too.
  auto against_design = [](Run* r) { r->design(run_file("pocket_design.stl")).stock("0,0,-10,33,23,0").tool("flat:6"); };
  Run full;
  against_design(&full);
  CHECK(full.program(run_file("gouge_one.ngc")));
  CHECK(full.sim().stop_reason() == SimStop::kNone);
  CHECK(full.sim().gouged());
  CHECK_EQ(full.sim().gouges()->total, uint64_t{1});
  CHECK_EQ(full.sim().gouges()->nevents, size_t{1});
  CHECK_EQ(full.scan_warnings() + full.scan_errors(), 0u);
  const std::string a = full.assessment();
  CHECK(has(a, "\"gouges\": [\n      {\"line\": 7, \"x_mm\": 21.5218, \"y_mm\": 7.0435, \"depth_mm\": 0.4000, \"design_z_mm\": -3.0000, \"cut_z_mm\": -3.4000, \"tool_mm\": [22.0000, 10.0000, -3.4000],"));
  CHECK(has(a, "\"gouges_total\": 1"));
  // Stopped at line 7: the cut of lines 11-12 is not in it (less material
  // removed than the whole run).
  Run stopped;
  against_design(&stopped);
  stopped.o.job.stop_at_gouge = true;
  CHECK(stopped.program(run_file("gouge_one.ngc")));
  CHECK(stopped.sim().stop_reason() == SimStop::kGouge);
  CHECK_EQ(stopped.sim().stop_line(), 7u);
  CHECK_GT(stopped.sim().removed_lsb(), uint64_t{0});
  CHECK_LT(stopped.sim().removed_lsb(), full.sim().removed_lsb());
  // Stopping short of the floor leaves material and no gouge; reaching it
  // exactly is no gouge either (within the 0.05 mm tolerance).
  const std::string text = run_cli::slurp(run_file("gouge_one.ngc"));
  for (const char* z : {"Z-2.5", "Z-3.0"}) {
    std::string t2 = text;
    t2.replace(t2.find("Z-3.4"), 5, z);
    Run nog;
    against_design(&nog);
    CHECK(nog.text("nog.ngc", t2));
    CHECK(nog.sim().state() == SimState::kDone);
    CHECK(!nog.sim().gouged());
    CHECK_EQ(nog.scan_warnings() + nog.scan_errors(), 0u);
    CHECK(has(nog.assessment(), "\"gouges\": [], \"gouges_total\": 0"));
  }
}

TEST(sim_design_from_a_height_image) {
  // A 2 x 1 image: the left half of the stock is to stay at Z0 (white), the
  // right half may go to Z-3 (black): the pocket's left part is a 3 mm
  // gouge, the G81 hole on the right 5 mm. P5 and P2 alike.
  const std::string d = run_cli::tmp_dir() + "/";
  run_cli::write_file(d + "sim-half.pgm", std::string("P5\n# design\n2 1\n255\n") + '\xff' + '\x00');
  run_cli::write_file(d + "sim-half2.pgm", "P2\n2 1\n255\n255 0\n");
  Run p5, p2;
  CHECK(p5.design(d + "sim-half.pgm").design_z("-3", "0").program(run_file("pocket.ngc")));
  CHECK(p2.design(d + "sim-half2.pgm").design_z("-3", "0").program(run_file("pocket.ngc")));
  const std::string a = p5.assessment();
  CHECK(has(a, "\"kind\": \"pgm\", \"triangles\": 0"));
  CHECK(has(a, "\"max_gouge\": {\"mm\": 5.0000, \"x_mm\": 27.1305, \"y_mm\": 15.1305}"));
  CHECK(has(a, "\"gouged\": {\"area_mm2\": 239.037,"));
  CHECK(unnamed(a, "sim-half.pgm") == unnamed(p2.assessment(), "sim-half2.pgm"));
}
