// `dexmill run --demo NAME|list` (issue 23): the list; the instrument
// panel end to end (its zig program, the cut from aluminium, the frames,
// the final and error images, the report's assessment: no gouge, the
// leftover where the 4.5 mm ball cannot reach); `dexmill zig` of a built-in
// part gives the demo's program; --design takes a built-in part; usage
// errors. The four demos' grids and frames are pinned in the golden section
// "demo" on every xcheck target.
#include <string>
#include <sys/stat.h>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

bool exists(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

}  // namespace

TEST(demo_list_names_the_four_workpieces) {
  if (skip()) return;
  const Result r = run("--demo list");
  CHECK_EQ(r.code, 0);
  for (const char* n : {"panel ", "smiley ", "freeform ", "tsuba "}) CHECK(has(r.out, n));
  CHECK(has(r.out, "9-dexel ball"));
  CHECK(has(r.out, "two-layer"));
}

TEST(demo_panel_end_to_end) {
  if (skip()) return;
  const Result r = run("--demo panel --size 160x120", nullptr, true);
  CHECK_EQ(r.code, 0);
  const std::string dir = tmp_dir() + "/out/panel/";
  for (const char* f : {"panel.ngc", "final.png", "error.png", "report.json", "frames/frame-000001.png"}) CHECK(exists(dir + f));
  CHECK(has(r.err, "dexmill zig: grid 82 x 42 at 0.5000 mm, 42 stripes"));
  // No process warning: the feeds and speed fit aluminium.
  CHECK(!has(r.err, "warning"));
  const std::string rep = slurp(dir + "report.json");
  const std::string a = assessment_of(rep);
  CHECK(has(a, "\"kind\": \"builtin\""));
  CHECK(has(a, "\"max_gouge\": null"));
  CHECK(has(a, "\"gouges_total\": 0"));
  CHECK(!has(a, "\"max_leftover\": null"));  // the lettering and ticks are finer than the ball
  CHECK(has(rep, "\"name\": \"aluminium\""));
  // The program is what `dexmill zig panel` writes.
  const Result z = run_command("zig panel");
  CHECK_EQ(z.code, 0);
  CHECK(z.out == slurp(dir + "panel.ngc"));
  CHECK(has(z.out, "(dexmill zig: built-in part panel, tool ball:4.5,"));
  // And simulating that program by hand with --design panel assesses alike.
  const Result h = run(dir + "panel.ngc --stock 0,0,-10,39.5,19.5,0 --pitch 0.5 --tool ball:4.5 --design panel -q --report " +
                       tmp_dir() + "/hand.json");
  CHECK_EQ(h.code, 0);
  CHECK(has(assessment_of(slurp(tmp_dir() + "/hand.json")), "\"max_gouge\": null"));
}

TEST(demo_usage_errors) {
  if (skip()) return;
  struct Case {
    const char* args;
    const char* message;
  } cases[] = {
      {"--demo teapot", "--demo must be list or one of panel, smiley, freeform, tsuba, not 'teapot'"},
      {"pocket.ngc --demo panel", "--demo cuts its own program from its own design"},
      {"--demo panel --design x.stl", "--demo cuts its own program from its own design"},
      {"pocket.ngc --design teapot", "--design needs an .stl mesh, a .pgm height image or a built-in part's name"},
  };
  for (const Case& c : cases) {
    const Result r = run(c.args);
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, c.message));
  }
}
