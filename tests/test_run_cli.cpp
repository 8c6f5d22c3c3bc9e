// `dexmill run` end to end on the programs in tests/run/: outputs pinned by
// hashes in tests/golden/hashes.txt (frames and final images, with their
// pictures in tests/golden/frames/; heightmap, STL) and the report's text
// (tests/run/pocket.report.golden), and every error path of tools/CLI.md
// with its exit status and message. Golden values change only through make
// bless, in a commit that says why (tests/golden/README.md).
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "tests/golden_check.h"
#include "tests/pocket_part.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;
using pocket_part::ascii_stl;
using pocket_part::binary_stl;
using pocket_part::Facet;

}  // namespace

TEST(run_golden_pocket_outputs) {
  if (skip()) return;
  const Result r = run("pocket.ngc -q --size 160x120 --image %/p.ppm --frames %/pf --frame-format ppm --every 4 --heightmap %/p.pgm "
                       "--stl %/p.stl --report %/p.json");
  CHECK_EQ(r.code, 0);
  // pocket.ngc names no tool: the default is a guess, and says so.
  CHECK(r.err == "pocket.ngc:5:1: warning: the tool before any M6 is cut as flat:6, a guess: no --tool, --tools table "
                 "or tool comment of the program gives it (give one with --tool SPEC or --tools FILE)\n");
  const std::string d = tmp_dir() + "/";
  CHECK_GOLDEN_FILE("run-pocket-image", d + "p.ppm");
  CHECK_GOLDEN_FILE("run-pocket-heightmap", d + "p.pgm");
  CHECK_GOLDEN_FILE("run-pocket-stl", d + "p.stl");
  CHECK_GOLDEN_FILE("run-pocket-frame-1", d + "pf/frame-000001.ppm");
  CHECK_GOLDEN_FILE("run-pocket-frame-4", d + "pf/frame-000004.ppm");
  // The untouched stock, then every 4 of the 22 moves, then the last.
  struct stat st;
  CHECK_EQ(stat((d + "pf/frame-000007.ppm").c_str(), &st), 0);
  CHECK(stat((d + "pf/frame-000008.ppm").c_str(), &st) != 0);
  // The frames are anti-aliased as the final image is, so the last frame
  // is the final image (so it is with --no-antialias:
  // run_golden_color_error_frames_and_image).
  CHECK_EQ(file_hash(d + "pf/frame-000007.ppm"), file_hash(d + "p.ppm"));
  CHECK_GOLDEN_TEXT(std::string(t::tests_dir()) + "/run/pocket.report.golden", report_body(d + "p.json"));
}

TEST(run_golden_inch_arcs_and_tool_table) {
  if (skip()) return;
  Result r = run("arcs_inch.ngc -q --size 120x90 --image %/a.ppm --report %/a.json");
  CHECK_EQ(r.code, 0);
  CHECK_GOLDEN_FILE("run-arcs-inch-image", tmp_dir() + "/a.ppm");
  CHECK(has(slurp(tmp_dir() + "/a.json"), "\"dwell\": 1"));
  r = run("tool_change.ngc --tools tools.tbl -q --size 120x90 --image %/t.ppm --report %/t.json --mode stamp");
  CHECK_EQ(r.code, 0);
  CHECK_GOLDEN_FILE("run-tool-change-image", tmp_dir() + "/t.ppm");
  CHECK(has(slurp(tmp_dir() + "/t.json"), "\"used\": [{\"number\": 1, \"spec\": \"flat:4\", \"source\": \"table\", "
                                          "\"line\": null, \"form\": null}, {\"number\": 2, \"spec\": \"ball:6\", "
                                          "\"source\": \"table\", \"line\": null, \"form\": null}]"));
  CHECK(has(slurp(tmp_dir() + "/t.json"), "\"mode\": \"stamp\""));
}

TEST(run_golden_stdin_and_demo) {
  if (skip()) return;
  const std::string in = std::string(t::tests_dir()) + "/run/pocket.ngc";
  Result r = run("- -q --size 160x120 --image %/s.ppm --report %/s.json", in.c_str());
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/s.json"), "\"file\": \"<stdin>\""));
  // Same program, same picture, whether from a file or a pipe.
  r = run("pocket.ngc -q --size 160x120 --image %/f.ppm");
  CHECK_EQ(file_hash(tmp_dir() + "/s.ppm"), file_hash(tmp_dir() + "/f.ppm"));
  // The demo: its program, final image and frames in out/ (its standard
  // input is no terminal here: asked for by name, tests/test_run_stdin.cpp).
  r = run("--demo pocket -q --size 80x60 --report out/demo.json", nullptr, true);
  CHECK_EQ(r.code, 0);
  CHECK(r.err.empty());  // no gouge of the demo's own part
  struct stat st;
  CHECK_EQ(stat((tmp_dir() + "/out/demo.ngc").c_str(), &st), 0);
  CHECK_EQ(stat((tmp_dir() + "/out/final.ppm").c_str(), &st), 0);
  CHECK_EQ(stat((tmp_dir() + "/out/frames/frame-000050.png").c_str(), &st), 0);
  CHECK_GOLDEN_FILE("run-demo-final", tmp_dir() + "/out/final.ppm");  // in its beech-over-aluminium block
  // And the error view of its own part (tools/run/demo_program.h): the corners
  // the roughing rows stop short of and the dome's base are left green.
  CHECK_GOLDEN_FILE("run-demo-error", tmp_dir() + "/out/error.ppm");
  const std::string a = assessment_of(slurp(tmp_dir() + "/out/demo.json"));
  CHECK(has(a, "\"kind\": \"demo\""));
  CHECK(has(a, "\"max_gouge\": null"));
}

TEST(run_usage_errors_exit_2) {
  if (skip()) return;
  struct Case {
    const char* args;
    const char* message;
  } cases[] = {
      {"pocket.ngc --frobnicate", "dexmill: error: unknown option '--frobnicate'"},
      {"pocket.ngc --grid 3x3", "dexmill: error: --grid needs NXxNY"},
      {"pocket.ngc --grid 10x", "dexmill: error: --grid needs NXxNY"},
      {"pocket.ngc --pitch 0", "dexmill: error: --pitch needs"},
      {"pocket.ngc --grid 10x10 --pitch 1", "dexmill: error: give --grid or --pitch, not both"},
      {"pocket.ngc --size 0x0", "dexmill: error: --size needs WxH"},
      {"pocket.ngc --tool ball:", "dexmill: error: bad --tool 'ball:'"},
      {"pocket.ngc --tool bull:6:4", "dexmill: error: bad --tool 'bull:6:4': tool out of range"},
      {"pocket.ngc --units furlong", "dexmill: error: --units must be mm or inch"},
      {"pocket.ngc --mode carve", "dexmill: error: --mode must be sweep or stamp"},
      {"pocket.ngc --every 5", "dexmill: error: --every needs --frames DIR"},
      {"pocket.ngc --frames % --every 0", "dexmill: error: --every needs a whole number"},
      {"pocket.ngc --stock 1,2,3", "dexmill: error: --stock needs X0,Y0,Z0,X1,Y1,Z1"},
      {"pocket.ngc --stock 0,0,0,10,10,-5", "dexmill: error: --stock needs"},
      {"pocket.ngc --view sideways", "dexmill: error: --view must be iso, top, front or right"},
      {"pocket.ngc --view top --azimuth 30", "dexmill: error: give --view or --azimuth/--elevation"},
      {"pocket.ngc --elevation 95", "dexmill: error: --elevation needs degrees"},
      {"pocket.ngc --image", "dexmill: error: --image needs a value"},
      {"pocket.ngc --pitch 0.0001", "dexmill: error: the grid would be"},
  };
  for (const Case& c : cases) {
    const Result r = run(c.args);
    if (r.code != 2) std::printf("  %s: exit %d\n", c.args, r.code);
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, c.message));
  }
}

TEST(run_io_errors_exit_3) {
  if (skip()) return;
  std::FILE* f = std::fopen((tmp_dir() + "/plain").c_str(), "wb");
  if (f) std::fclose(f);
  struct Case {
    const char* args;
    const char* message;
  } cases[] = {
      {"nope.ngc", "dexmill: error: cannot open 'nope.ngc': No such file or directory"},
      {".", "dexmill: error: cannot read '.': Is a directory"},
      {"pocket.ngc --image %/nodir/x.ppm", "dexmill: error: cannot write --image '"},
      {"pocket.ngc --report %", "dexmill: error: cannot write --report '"},
      {"pocket.ngc --frames %/plain/sub", "dexmill: error: cannot create directory '"},
      {"pocket.ngc --tools nope.tbl", "dexmill: error: cannot read 'nope.tbl'"},
      {"pocket.ngc --fbdev %/plain", "not a framebuffer device"},
  };
  for (const Case& c : cases) {
    const Result r = run(c.args);
    if (r.code != 3) std::printf("  %s: exit %d\n", c.args, r.code);
    CHECK_EQ(r.code, 3);
    CHECK(has(r.err, c.message));
  }
  // No partial file is left behind by a refused run.
  struct stat st;
  CHECK(stat((tmp_dir() + "/nodir").c_str(), &st) != 0);
}

TEST(run_input_errors_exit_1) {
  if (skip()) return;
  // --strict: a program with an error is not cut at all.
  Result r = run("bad_word.ngc --strict --report %/bad.json --image %/bad.ppm");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "bad_word.ngc:4:8: error: 'Q' is not followed by a number"));
  const std::string rep = slurp(tmp_dir() + "/bad.json");
  CHECK(has(rep, "\"status\": \"error\""));
  CHECK(has(rep, "{\"line\": 4, \"column\": 8, \"message\": \"'Q' is not followed by a number\"}"));
  struct stat st;
  CHECK(stat((tmp_dir() + "/bad.ppm").c_str(), &st) != 0);
  r = run("unknown_tool.ngc --strict --tools tools.tbl");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "unknown_tool.ngc:4:1: error: tool T7 is not in the tool table 'tools.tbl'"));
  std::FILE* f = std::fopen((tmp_dir() + "/bad.tbl").c_str(), "wb");
  if (f) {
    std::fputs("T1 P1 D6\nT2 P2 Z3\n", f);
    std::fclose(f);
  }
  r = run("pocket.ngc --tools %/bad.tbl");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "bad.tbl:2:1: error: tool T2 has no diameter (D)"));
}

TEST(run_partial_cuts_up_to_the_bad_block) {
  if (skip()) return;
  // By default the cut goes up to the first bad block: the outputs show
  // that state, with the block's place marked, and the run exits 1.
  const std::string d = tmp_dir() + "/";
  Result r = run("bad_word.ngc --size 160x120 --report %/part.json --image %/part.ppm --heightmap %/part.pgm");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "bad_word.ngc:4:8: error: 'Q' is not followed by a number"));
  const std::string rep = slurp(d + "part.json");
  CHECK(has(rep, "\"status\": \"error\""));
  CHECK(has(rep, "\"stopped\": {\"reason\": \"error\", \"line\": 4}"));
  CHECK(rep.find("\"removed_mm3\": 0.000") == std::string::npos);  // line 3 cut
  // That the cut is the program's without its bad block and what follows,
  // and that a tool the table lacks stops it at its T line, is the
  // engine's (test_sim_reading.cpp). The frame marks the bad block in
  // amber; the same frame of the program without it has no amber.
  std::FILE* f = std::fopen((d + "good3.ngc").c_str(), "wb");
  if (f) {
    std::fputs("G21 G90\nG0 Z5\nG1 X10 Y10 Z-1 F300\n", f);
    std::fclose(f);
  }
  CHECK_EQ(run("bad_word.ngc -q --size 160x120 --stock -5,-5,-2,25,15,0 --image %/amber.ppm").code, 1);
  CHECK_EQ(run("%/good3.ngc -q --size 160x120 --stock -5,-5,-2,25,15,0 --image %/plain3.ppm").code, 0);
  auto amber_pixels = [](const std::string& ppm) {
    int n = 0;
    const size_t start = ppm.size() - 160 * 120 * 3;
    for (size_t k = start; k + 2 < ppm.size(); k += 3)
      if (static_cast<uint8_t>(ppm[k]) == 255 && static_cast<uint8_t>(ppm[k + 1]) == 190 && ppm[k + 2] == 0) ++n;
    return n;
  };
  CHECK(amber_pixels(slurp(d + "amber.ppm")) > 10);
  CHECK_EQ(amber_pixels(slurp(d + "plain3.ppm")), 0);
}

TEST(run_window_needs_glfw_or_a_display) {
  if (skip()) return;
  // A plain build refuses --window (exit 2); a GLFW build with no display
  // cannot open one (exit 3).
  const std::string cmd_env = "env -u DISPLAY -u WAYLAND_DISPLAY ";
  (void)cmd_env;
  const Result r = run("pocket.ngc --window --exit-when-done");
  if (r.code == 2) CHECK(has(r.err, "built without GLFW"));
  else if (r.code == 3) CHECK(has(r.err, "cannot open a window"));
  else CHECK(r.code == 2 || r.code == 3);
}

TEST(run_design_assessment_names_the_gouge_and_the_leftover) {
  if (skip()) return;
  const std::string d = tmp_dir() + "/";
  write_file(d + "pd.stl", ascii_stl(pocket_part::design()));
  // tests/run/pocket_design.stl, the README's example, is this mesh.
  CHECK(slurp(std::string(t::tests_dir()) + "/run/pocket_design.stl") == ascii_stl(pocket_part::design()));
  Result r = run("pocket.ngc -q --tool flat:6 --design %/pd.stl --report %/pd.json");
  CHECK_EQ(r.code, 0);
  // The one gouge, charged to the G81 line while cutting, warned as it is
  // found; the report names the design. The assessment's figures, the
  // binary STL's and a tolerance box's are the engine's (test_sim_design.cpp).
  CHECK(r.err == "pocket.ngc:20:1: warning: gouge 8.000 mm at X28.044 Y15.130 (design Z0.000, cut Z-8.000)\n");
  const std::string a = assessment_of(slurp(d + "pd.json"));
  CHECK(has(a, ("\"design\": {\"file\": \"" + d + "pd.stl\", \"kind\": \"stl\", \"triangles\": 10, \"columns\": 45212}").c_str()));
  CHECK(has(a, "\"max_gouge\": {\"mm\": 8.0000, \"x_mm\": 28.0435, \"y_mm\": 15.1305}"));
}

TEST(run_golden_color_error_frames_and_image) {
  if (skip()) return;
  const std::string d = tmp_dir() + "/";
  write_file(d + "pde.stl", ascii_stl(pocket_part::design()));
  const Result r = run("pocket.ngc -q --size 160x120 --design %/pde.stl --color error --no-antialias --image %/e.ppm --frames %/ef --frame-format ppm --every 4");
  CHECK_EQ(r.code, 0);
  // The error view drawn frame by frame (incremental bands) ends as the
  // final image (aliased, as the frames are); pinned (paper figure 10's view: a red G81 hole, green
  // corners and island, white elsewhere, and the legend).
  CHECK_EQ(file_hash(d + "ef/frame-000007.ppm"), file_hash(d + "e.ppm"));
  CHECK_GOLDEN_FILE("run-pocket-error-view", d + "e.ppm");
  CHECK(file_hash(d + "e.ppm") != file_hash(d + "ef/frame-000001.ppm"));
  const Result u = run("pocket.ngc -q --color error");
  CHECK_EQ(u.code, 2);
  CHECK(has(u.err, "--color error needs --design"));
  // The overlays (paper figure 9): the design translucent over the cut shows
  // the G81 hole, the cut translucent over the design the material left.
  CHECK_EQ(run("pocket.ngc -q --size 160x120 --image %/plain.ppm").code, 0);
  // Aliased (--no-antialias) as they always were; anti-aliased by default,
  // blended at twice the size (display/view/stock_view.h stock_view_blend):
  // tests/test_run_antialias.cpp checks those against the aliased ones.
  const std::string ov = "pocket.ngc -q --size 160x120 --design %/pde.stl ";
  CHECK_EQ(run(ov + "--no-antialias --overlay design --image %/od.ppm").code, 0);
  CHECK_EQ(run(ov + "--no-antialias --overlay workpiece --image %/ow.ppm").code, 0);
  CHECK_EQ(run(ov + "--overlay design --image %/oda.ppm").code, 0);
  CHECK_EQ(run(ov + "--overlay workpiece --image %/owa.ppm").code, 0);
  CHECK_GOLDEN_FILE("run-overlay-design", d + "od.ppm");
  CHECK_GOLDEN_FILE("run-overlay-workpiece", d + "ow.ppm");
  CHECK_GOLDEN_FILE("run-overlay-design-aa", d + "oda.ppm");
  CHECK_GOLDEN_FILE("run-overlay-workpiece-aa", d + "owa.ppm");
  CHECK(file_hash(d + "od.ppm") != file_hash(d + "plain.ppm"));
  const Result v = run("pocket.ngc -q --overlay design");
  CHECK_EQ(v.code, 2);
  CHECK(has(v.err, "--overlay needs --design"));
}

TEST(run_golden_gouges_are_traced_to_their_line) {
  if (skip()) return;
  const std::string d = tmp_dir() + "/";
  const char* common = "-q --design pocket_design.stl --stock 0,0,-10,33,23,0";
  // The gouge of line 7 (its figures: test_sim_design.cpp) makes the same
  // exit 4 for a CI gate: at the end, or at the gouge, which the report
  // says it stopped at.
  Result r = run(std::string("gouge_one.ngc ") + common + " --fail-on-gouge --report %/g2.json");
  CHECK_EQ(r.code, 4);
  r = run(std::string("gouge_one.ngc ") + common + " --stop-at gouge --report %/g3.json");
  CHECK_EQ(r.code, 4);
  CHECK(has(r.err, "gouge_one.ngc:7:1: warning: gouge"));
  CHECK(has(slurp(d + "g2.json"), "\"stopped\": null,"));
  CHECK(has(slurp(d + "g3.json"), "\"stopped\": {\"reason\": \"gouge\", \"line\": 7},"));
  const Result u = run("pocket.ngc -q --fail-on-gouge");
  CHECK_EQ(u.code, 2);
  CHECK(has(u.err, "--fail-on-gouge needs --design"));
  // The frames mark the gouge in red where it is found; the same frames
  // without the design have no mark.
  CHECK_EQ(run(std::string("gouge_one.ngc ") + common + " --size 160x120 --frames %/gf --frame-format ppm --every 3").code, 0);
  CHECK_EQ(run("gouge_one.ngc -q --stock 0,0,-10,33,23,0 --size 160x120 --frames %/gn --frame-format ppm --every 3").code, 0);
  CHECK(file_hash(d + "gf/frame-000002.ppm") == file_hash(d + "gn/frame-000002.ppm"));  // before line 7
  CHECK(file_hash(d + "gf/frame-000004.ppm") != file_hash(d + "gn/frame-000004.ppm"));  // after it
  CHECK_GOLDEN_FILE("run-gouge-frame-4", d + "gf/frame-000004.ppm");
}

TEST(run_golden_stock_from_an_stl_blank) {
  if (skip()) return;
  // tests/run/blank_step.stl: a closed 36 x 26 x 10 mm block whose right
  // third (X > 24) is 3 mm lower; the pocket there meets the step.
  Result r = run("pocket.ngc -q --size 160x120 --stock blank_step.stl --image %/blank.ppm --report %/blank.json");
  CHECK_EQ(r.code, 0);
  const std::string rep = slurp(tmp_dir() + "/blank.json");
  CHECK(has(rep, "\"stock\": {\"min_mm\": [-2.0000, -2.0000, -10.0000], \"max_mm\": [34.0001, 24.0396, 0.0000], \"source\": \"stl\"}"));
  // Less to remove than from the full box (the step was never there: the
  // engine's, test_sim_plan.cpp).
  CHECK(has(rep, "\"removed_mm3\": 1090.985"));
  CHECK_GOLDEN_FILE("run-blank-stock-image", tmp_dir() + "/blank.ppm");
  write_file(tmp_dir() + "/flat.stl", "solid f\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 1 1 0\n  endloop\n endfacet\nendsolid f\n");
  r = run("pocket.ngc -q --stock %/flat.stl");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "flat.stl: error: the blank is flat"));
}

TEST(run_design_from_a_height_image) {
  if (skip()) return;
  // A 2 x 1 image, white then black, stretched over the stock: the report
  // names its kind (what it assesses: test_sim_design.cpp).
  write_file(tmp_dir() + "/half.pgm", std::string("P5\n# design\n2 1\n255\n") + '\xff' + '\x00');
  const Result r = run("pocket.ngc -q --design %/half.pgm --design-z -3,0 --report %/half.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(assessment_of(slurp(tmp_dir() + "/half.json")), "\"kind\": \"pgm\", \"triangles\": 0"));
}

TEST(run_design_bad_files_exit_1_with_the_reason) {
  if (skip()) return;
  const std::string d = tmp_dir() + "/";
  std::string bin = binary_stl(pocket_part::design());
  write_file(d + "trunc.stl", bin.substr(0, bin.size() - 10));
  std::string nan_text = ascii_stl(pocket_part::design());
  nan_text.replace(nan_text.find("vertex") + 7, 2, "x1");
  write_file(d + "nan.stl", nan_text);
  std::string nan_bin = bin;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan_bin[84 + 50 * 6 + 12 + 12 + 4], &nan, 4);  // facet 7, vertex 2, y
  write_file(d + "nanb.stl", nan_bin);
  write_file(d + "empty.stl", "solid nothing\nendsolid nothing\n");
  const std::string text = ascii_stl(pocket_part::design());
  const size_t second_vertex = text.find("vertex", text.find("facet", text.find("endfacet")));
  write_file(d + "cut.stl", text.substr(0, text.find('\n', second_vertex) + 1));
  std::vector<Facet> far = pocket_part::design();
  for (Facet& f : far)
    for (auto& v : f.v) v[0] += 500;
  write_file(d + "far.stl", ascii_stl(far));
  write_file(d + "typo.stl", "solid a\n facet normal 0 0 1\n  outer loop\n   vertx 0 0 0\n");
  write_file(d + "bad.pgm", "P5\n2\n255\n");
  write_file(d + "short.pgm", "P5\n4 4\n255\nabc");
  write_file(d + "big.pgm", "P2\n2 1\n255\n255 256\n");
  struct Case {
    const char* args;
    const char* message;
  } cases[] = {
      {"--design %/trunc.stl", "trunc.stl: error: not an STL file: binary STL of 10 triangles needs 584 bytes, the file has 574 (truncated?)"},
      {"--design %/nan.stl", "nan.stl: error: triangle 1: vertex is not a number (line 4)"},
      {"--design %/nanb.stl", "nanb.stl: error: triangle 7: vertex is not a number"},
      {"--design %/empty.stl", "empty.stl: error: the mesh has no triangles"},
      {"--design %/cut.stl", "cut.stl:12: error: the file ends inside a facet (truncated?)"},
      {"--design %/far.stl", "far.stl: error: the design lies entirely outside the stock"},
      {"--design %/typo.stl", "typo.stl:4: error: expected 'vertex', found 'vertx'"},
      {"--design %/bad.pgm --design-z 0,1", "bad.pgm: error: bad PGM header"},
      {"--design %/short.pgm --design-z 0,1", "short.pgm: error: too few samples: 4x4 needs 16 bytes of data, the file has 3"},
      {"--design %/big.pgm --design-z 0,1", "big.pgm: error: sample 2 is above maxval"},
  };
  for (const Case& c : cases) {
    const Result r = run(std::string("pocket.ngc -q --report %/bad_design.json ") + c.args);
    if (r.code != 1) std::printf("  %s: exit %d\n", c.args, r.code);
    CHECK_EQ(r.code, 1);
    CHECK(has(r.err, c.message));
  }
  // Usage: the option's own checks.
  const char* usage[][2] = {
      {"--design %/x.obj", "--design needs an .stl mesh, a .pgm height image or a built-in part's name"},
      {"--design %/bad.pgm", "a PGM design needs --design-z"},
      {"--design %/pd.stl --design-z 0,1", "--design-z is for PGM designs"},
      {"--tolerance-box 0,0,1,1,0.1", "--tolerance-box needs --design"},
      {"--design %/pd.stl --tolerance -1", "--tolerance needs mm from 0 to 100"},
      {"--design %/bad.pgm --design-z 1,0", "--design-z needs ZLOW,ZHIGH"},
  };
  for (const auto& u : usage) {
    const Result r = run(std::string("pocket.ngc -q ") + u[0]);
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, u[1]));
  }
  const Result r = run("pocket.ngc -q --design %/none.stl");
  CHECK_EQ(r.code, 3);
  CHECK(has(r.err, "dexmill: error: cannot read '"));
}

TEST(run_path_overlay_draws_the_toolpath) {
  if (skip()) return;
  // The backplot over the final frame; the frames' last one (drawn a piece
  // at a time as the cut goes) equals a still drawn whole at the end,
  // anti-aliased (the path two pixels wide at twice the size) and not.
  const std::string d = tmp_dir() + "/";
  for (const char* aa : {"", "--no-antialias "}) {
    const std::string base = std::string("pocket.ngc -q --size 160x120 ") + aa;
    CHECK_EQ(run(base + "--image %/np.ppm").code, 0);
    CHECK_EQ(run(base + "--path-overlay --image %/po.ppm").code, 0);
    CHECK_EQ(run(base + "--path-overlay --frames %/pof --frame-format ppm --every 3 --image %/pof.ppm").code, 0);
    CHECK(file_hash(d + "np.ppm") != file_hash(d + "po.ppm"));
    CHECK_EQ(file_hash(d + "po.ppm"), file_hash(d + "pof.ppm"));
  }
  // Done feeds in their strong blue, done rapids in yellow (all is done),
  // in the exact colours of the aliased picture.
  const std::string img = slurp(d + "po.ppm");
  int blue = 0, yellow = 0;
  for (size_t k = img.size() - 160 * 120 * 3; k + 2 < img.size(); k += 3) {
    const uint8_t r = static_cast<uint8_t>(img[k]), g = static_cast<uint8_t>(img[k + 1]), b = static_cast<uint8_t>(img[k + 2]);
    if (r == 24 && g == 100 && b == 255) ++blue;
    if (r == 255 && g == 226 && b == 40) ++yellow;
  }
  CHECK(blue > 50);
  CHECK(yellow > 10);
  // A middle frame shows the pieces still to come, pale.
  const std::string mid = slurp(d + "pof/frame-000003.ppm");
  int pale = 0;
  for (size_t k = mid.size() - 160 * 120 * 3; k + 2 < mid.size(); k += 3)
    if (static_cast<uint8_t>(mid[k]) == 156 && static_cast<uint8_t>(mid[k + 1]) == 200 && static_cast<uint8_t>(mid[k + 2]) == 236)
      ++pale;
  CHECK(pale > 20);
}
