// `dexmill run --setups FILE` (tools/run/setups_file.h) and what a chain's
// report says of each program: its setup, its share, its findings.
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

const char* const kSide1 = "G21 G90\nG0 X5 Y5 Z5\nG1 Z-2 F300\nG1 X25 F600\nG0 Z5\nG0 X10 Y15\nG1 Z-11 F200\nG0 Z5\nM30\n";
const char* const kSide2 = "G21 G90\nG0 X3 Y3 Z5\nG1 Z-1 F300\nG1 Y17 F600\nG0 Z5\nM30\n";
const std::string kStock = " --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25 -q";

// The chain's entry of program k (from 0) in a report.
std::string program_entry(const std::string& report, int k) {
  size_t at = report.find("\"chain\": {\"programs\": [");
  for (int n = 0; n <= k && at != std::string::npos; ++n) at = report.find("{\"file\": ", at + 1);
  if (at == std::string::npos) return "";
  const size_t next = report.find("{\"file\": ", at + 1);
  return report.substr(at, next == std::string::npos ? std::string::npos : next - at);
}

}  // namespace

TEST(run_setups_file_is_the_command_line_chain) {
  if (skip()) return;
  write_tmp("s1.ngc", kSide1);
  write_tmp("s2.ngc", kSide2);
  write_tmp("job.setups", "# two sides\ns1.ngc\n  s2.ngc   setup=flip-x   # against the same stops\n");
  CHECK_EQ(run("--setups %/job.setups" + kStock + " --heightmap %/file.pgm --report %/file.json").code, 0);
  CHECK_EQ(run("%/s1.ngc" + kStock + " --setup flip-x %/s2.ngc --heightmap %/cli.pgm").code, 0);
  CHECK(slurp(tmp_dir() + "/file.pgm") == slurp(tmp_dir() + "/cli.pgm"));
  const std::string rep = slurp(tmp_dir() + "/file.json");
  CHECK(has(program_entry(rep, 0), "s1.ngc\", \"setup\": \"none\""));
  CHECK(has(program_entry(rep, 1), "s2.ngc\", \"setup\": \"flip-x\""));
  // The summary gives each setup's share.
  const Result r = run("--setups %/job.setups" + kStock);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "s1.ngc, first setup: removed "));
  CHECK(has(r.out, "s2.ngc, setup flip-x: removed "));
}

TEST(run_setups_work_offsets_and_tools_per_line) {
  if (skip()) return;
  // g54= places the coordinate system as a controller's parameters would:
  // the same cut as the program setting it with G10 L2 itself.
  write_tmp("w.ngc", "G21 G90 G54\nT1 M6\nG0 X5 Y5 Z5\nG1 Z-2 F300\nG1 X15 F600\nG0 Z5\nM30\n");
  write_tmp("w_g10.ngc", "G21 G90 G10 L2 P1 X4 Y2.5 Z-1\nG54\nT1 M6\nG0 X5 Y5 Z5\nG1 Z-2 F300\nG1 X15 F600\nG0 Z5\nM30\n");
  run_shell("mkdir -p '" + tmp_dir() + "/job'");
  write_file(tmp_dir() + "/job/mill.tbl", "T1 P1 D2.0 ;two mm\n");
  write_file(tmp_dir() + "/job/a.setups", "../w.ngc g54=4,2.5,-1 tools=mill.tbl\n");
  const std::string stock = " --stock 0,0,-10,30,20,0 --pitch 0.25 -q";
  CHECK_EQ(run("--setups %/job/a.setups" + stock + " --heightmap %/g54.pgm --report %/g54.json").code, 0);
  CHECK_EQ(run("%/w_g10.ngc --tools %/job/mill.tbl" + stock + " --heightmap %/g10.pgm").code, 0);
  CHECK(slurp(tmp_dir() + "/g54.pgm") == slurp(tmp_dir() + "/g10.pgm"));
  CHECK(has(slurp(tmp_dir() + "/g54.json"), "\"spec\": \"flat:2\""));  // the table beside the setups file
  // Without the offset the cut is elsewhere.
  CHECK_EQ(run("%/w.ngc --tools %/job/mill.tbl" + stock + " --heightmap %/none.pgm").code, 0);
  CHECK(slurp(tmp_dir() + "/none.pgm") != slurp(tmp_dir() + "/g54.pgm"));
}

TEST(run_setups_findings_name_their_program_and_setup) {
  if (skip()) return;
  // The first program moves before it sets its units (a warning at line 1)
  // and rapids into the stock (a safety finding at line 2): the last
  // program's report keeps both under the first program's entry.
  write_tmp("f1.ngc", "G0 X5 Y5 Z5\nG0 Z-1\nG0 Z5\nM30\n");
  write_tmp("f2.ngc", kSide2);
  write_tmp("f.setups", "f1.ngc\nf2.ngc setup=flip-y\n");
  const Result r = run("--setups %/f.setups" + kStock + " --check rapid --report %/f.json");
  CHECK_EQ(r.code, 0);
  const std::string rep = slurp(tmp_dir() + "/f.json");
  const std::string first = program_entry(rep, 0), second = program_entry(rep, 1);
  CHECK(has(first, "{\"kind\": \"warning\", \"line\": 1"));
  CHECK(has(first, "{\"kind\": \"collision\", \"line\": 2"));
  CHECK(has(second, "\"setup\": \"flip-y\""));
  CHECK(has(second, "\"findings\": {\"total\": 0"));
  // Standard error says which program and setup each message is under.
  CHECK(lacks(r.err, "program 1 of 2"));  // -q
  const Result loud = run("--setups %/f.setups --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25 --report %/g.json");
  CHECK(has(loud.err, ("program 2 of 2, " + tmp_dir() + "/f2.ngc, setup flip-y").c_str()));
  // A stock saved by the chain keeps each program's setup for later runs.
  CHECK_EQ(run("--setups %/f.setups" + kStock + " --save-stock %/f.dxstock").code, 0);
  CHECK_EQ(run("%/f2.ngc" + kStock.substr(0, kStock.find(" --stock")) +
               " -q --stock %/f.dxstock --setup flip-x+rotate-90 --setup offset=0.5,0,0 --report %/h.json").code, 0);
  const std::string later = slurp(tmp_dir() + "/h.json");
  CHECK(has(program_entry(later, 1), "\"setup\": \"flip-y\""));
  CHECK(has(program_entry(later, 2), "\"setup\": \"flip-x+rotate-90+offset=0.5,0,0\""));
  CHECK(has(program_entry(later, 0), "\"findings\": null"));  // an earlier run's: not kept in the stock
}

TEST(run_setups_file_errors_have_their_place) {
  if (skip()) return;
  write_tmp("e.ngc", kSide2);
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"e.ngc colour=red\n", "e.setups:1:7: error: unknown key 'colour'"},
      {"e.ngc\ne.ngc setup=flip-z\n", "e.setups:2:13: error: setup=flip-z: a setup is flip-x"},
      {"e.ngc g55=1,2\n", "e.setups:1:11: error: g55= needs the origin's X,Y,Z in mm"},
      {"e.ngc design=\"a b.stl\n", "e.setups:1:14: error: a quote that is not closed"},
      {"# nothing\n\n", "e.setups:1:1: error: no program"},
      {"setup=flip-x e.ngc\n", "e.setups:1:1: error: 'setup=flip-x': a line starts with its program's file"},
      {"e.ngc fixture=1,2,3\n", "e.setups:1:15: error: --fixture"},
      {"e.ngc\n e.ngc design=part.pgm\n", "e.setups:2:1: error: a PGM design needs --design-z"},
  };
  for (const Case& c : cases) {
    write_tmp("e.setups", c.text);
    const Result r = run("--setups %/e.setups" + kStock);
    CHECK_EQ(r.code, 1);
    if (!has(r.err, c.message)) std::printf("  case '%s': %s\n", c.text, r.err.c_str());
    CHECK(has(r.err, c.message));
  }
  write_file(tmp_dir() + "/e.setups", std::string("e.ngc\n\0\n", 8));
  CHECK(has(run("--setups %/e.setups" + kStock).err, "e.setups:2:1: error: a NUL byte"));
  std::string many;
  for (int k = 0; k < 33; ++k) many += "e.ngc\n";
  write_tmp("e.setups", many.c_str());
  CHECK(has(run("--setups %/e.setups" + kStock).err, "e.setups:33:1: error: more than 32 programs"));
  // The programs are the file's: no FILE beside it, no --setup.
  write_tmp("e.setups", "e.ngc\n");
  Result r = run("%/e.ngc --setups %/e.setups" + kStock);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "names the programs: give no FILE"));
  r = run("--setups %/e.setups --stock x.dxstock --setup flip-x -q");
  CHECK_EQ(r.code, 2);
  // No output replaces the setups file.
  const std::string before = slurp(tmp_dir() + "/e.setups");
  CHECK_EQ(run("--setups %/e.setups" + kStock + " --report %/e.setups").code, 2);
  CHECK(slurp(tmp_dir() + "/e.setups") == before);
}

TEST(run_setup_materials_follow_the_part) {
  if (skip()) return;
  // Beech on aluminium, glued at mid height: a pocket 2 mm into the top
  // takes beech; turned over, the same pocket takes aluminium (the old
  // bottom is the new top), and turned over twice (a half turn), beech.
  write_tmp("air.ngc", "G21 G90\nG0 X5 Y5 Z5\nM30\n");
  write_tmp("pocket.ngc", "G21 G90\nG0 X6 Y6 Z5\nG1 Z-2 F300\nG1 X24 F600\nG0 Z5\nM30\n");
  const std::string m = " --tool flat:3 -q --material wood-on-aluminium";
  CHECK_EQ(run("%/air.ngc --stock 0,0,-10,30,20,0 --pitch 0.25" + m + " --save-stock %/glued.dxstock").code, 0);
  auto removed = [](const std::string& report, const char* name) {
    const size_t at = report.find(std::string("{\"name\": \"") + name + "\"");
    if (at == std::string::npos) return std::string("?");
    const size_t v = report.find("\"removed_mm3\": ", at) + 15;
    return report.substr(v, report.find_first_of(",}", v) - v);
  };
  CHECK_EQ(run("%/pocket.ngc --stock %/glued.dxstock" + m + " --report %/up.json").code, 0);
  CHECK_EQ(run("%/pocket.ngc --stock %/glued.dxstock --setup flip-x" + m + " --report %/down.json").code, 0);
  CHECK_EQ(run("%/pocket.ngc --stock %/glued.dxstock --setup flip-x+flip-y" + m + " --report %/back.json").code, 0);
  const std::string up = slurp(tmp_dir() + "/up.json"), down = slurp(tmp_dir() + "/down.json"),
                    back = slurp(tmp_dir() + "/back.json");
  CHECK(removed(up, "beech") != "0.000" && removed(up, "aluminium") == "0.000");
  CHECK(removed(down, "aluminium") == removed(up, "beech") && removed(down, "beech") == "0.000");
  CHECK(removed(back, "beech") == removed(up, "beech") && removed(back, "aluminium") == "0.000");
  // The picture of the turned part is aluminium on top.
  CHECK_EQ(run("%/air.ngc --stock %/glued.dxstock --setup flip-x" + m + " --view top --image %/down.ppm").code, 0);
  CHECK_EQ(run("%/air.ngc --stock 0,0,-10,30,20,0 --tool flat:3 --pitch 0.25 -q --material aluminium --view top "
               "--image %/alu.ppm").code, 0);
  CHECK_EQ(run("%/air.ngc --stock %/glued.dxstock" + m + " --view top --image %/beech.ppm").code, 0);
  CHECK(slurp(tmp_dir() + "/down.ppm") != slurp(tmp_dir() + "/beech.ppm"));
}

namespace {

// A rectangle at height z as two facets of an ASCII STL.
std::string facet_rect(double x0, double y0, double x1, double y1, double z) {
  char b[600];
  std::snprintf(b, sizeof b,
                "facet normal 0 0 1\nouter loop\nvertex %g %g %g\nvertex %g %g %g\nvertex %g %g %g\nendloop\nendfacet\n"
                "facet normal 0 0 1\nouter loop\nvertex %g %g %g\nvertex %g %g %g\nvertex %g %g %g\nendloop\nendfacet\n",
                x0, y0, z, x1, y0, z, x1, y1, z, x0, y0, z, x1, y1, z, x0, y1, z);
  return b;
}

}  // namespace

TEST(run_setup_design_is_compared_in_the_part_frame) {
  if (skip()) return;
  // The design: a 30 x 20 x 10 block with a pocket 2 mm up into its bottom
  // at X5..25 Y3..9 (the part's frame, as first set up). Turned over about
  // X, that pocket faces up at Y11..17: a second side cutting it there
  // cuts no design; cutting at Y3..9, where the part is now solid, gouges.
  std::string stl = "solid part\n" + facet_rect(0, 0, 30, 20, 0) + facet_rect(5, 3, 25, 9, -8) +
                    facet_rect(0, 0, 30, 3, -10) + facet_rect(0, 9, 30, 20, -10) + facet_rect(0, 3, 5, 9, -10) +
                    facet_rect(25, 3, 30, 9, -10) + "endsolid part\n";
  write_tmp("part.stl", stl.c_str());
  write_tmp("air.ngc", "G21 G90\nG0 X5 Y5 Z5\nM30\n");
  write_tmp("right.ngc", "G21 G90\nG0 X7 Y13 Z5\nG1 Z-2 F300\nG1 X23 F600\nG1 Y15\nG1 X7\nG0 Z5\nM30\n");
  write_tmp("wrong.ngc", "G21 G90\nG0 X7 Y5 Z5\nG1 Z-2 F300\nG1 X23 F600\nG1 Y7\nG1 X7\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/air.ngc --stock 0,0,-10,30,20,0 --pitch 0.25 --tool flat:3 -q --save-stock %/blank.dxstock").code, 0);
  const std::string side2 = " --stock %/blank.dxstock --setup flip-x --tool flat:3 -q --design %/part.stl";
  CHECK_EQ(run("%/right.ngc" + side2 + " --report %/right.json").code, 0);
  CHECK_EQ(run("%/wrong.ngc" + side2 + " --report %/wrong.json").code, 0);
  const std::string right = assessment_of(slurp(tmp_dir() + "/right.json")),
                    wrong = assessment_of(slurp(tmp_dir() + "/wrong.json"));
  CHECK(has(right, "\"gouges_total\": 0}"));
  CHECK(lacks(wrong, "\"gouges_total\": 0}"));
  // A height-field design has no other side to face.
  write_file(tmp_dir() + "/top.pgm", std::string("P5 2 2 255\n") + std::string(4, '\xff'));
  const Result r = run("%/right.ngc --stock %/blank.dxstock --setup flip-x --tool flat:3 -q --design %/top.pgm "
                       "--design-z -10,0");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "upside down; give the design as an STL mesh"));
}
