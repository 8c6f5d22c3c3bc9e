// `dexmill run --demo NAME|list` (the paper's loop, §3): the list; the instrument
// panel end to end (its zig program, the cut from aluminium, the frames,
// the final and error images, the report's assessment: no gouge, the
// leftover where the 4.5 mm ball cannot reach); `dexmill zig` of a built-in
// part gives the demo's program, which cut on the engine against the part
// (tests/sim_util.h) assesses alike; usage errors. The free-form part's zig
// program, cut on the engine, leaves the scallop its stepover predicts.
// The four demos' grids and frames are pinned in the golden section "demo"
// on every xcheck target.
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

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
  CHECK(lacks(r.err, "warning"));
  const std::string rep = slurp(dir + "report.json");
  const std::string a = assessment_of(rep);
  CHECK(has(a, "\"kind\": \"builtin\""));
  CHECK(has(a, "\"max_gouge\": null"));
  CHECK(has(a, "\"gouges_total\": 0"));
  CHECK(lacks(a, "\"max_leftover\": null"));  // the lettering and ticks are finer than the ball
  CHECK(has(rep, "\"name\": \"aluminium\""));
  // The program is what `dexmill zig panel` writes.
  const Result z = run_command("zig panel");
  CHECK_EQ(z.code, 0);
  CHECK(z.out == slurp(dir + "panel.ngc"));
  CHECK(has(z.out, "(dexmill zig: built-in part panel, tool ball:4.5,"));
  // And cutting that program by hand with the panel as the design (as
  // `dexmill run ... --design panel` would) assesses alike.
  sim_test::Run h;
  CHECK(h.stock("0,0,-10,39.5,19.5,0").pitch("0.5").tool("ball:4.5").design("panel").program(dir + "panel.ngc"));
  CHECK(h.sim().state() == dexmill::SimState::kDone);
  CHECK(has(h.assessment(), "\"max_gouge\": null"));
}

TEST(demo_usage_errors) {
  if (skip()) return;
  struct Case {
    const char* args;
    const char* message;
  } cases[] = {
      {"--demo teapot", "--demo must be list or one of pocket, panel, smiley, freeform, tsuba, not 'teapot'"},
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

TEST(zig_leftover_matches_the_scallop_the_stepover_predicts) {
  if (skip()) return;
  // The free-form part with stripes two dexels apart (1 mm): the rows
  // between stripes keep the cusp a 3 mm ball leaves one pitch (0.5 mm)
  // off its pass, R - sqrt(R^2 - p^2) = 0.0858 mm on a flat, more on a
  // slope (at most h / cos^2 of the steepest slope, tan 0.63: 0.120 mm).
  // The dexel model sees it at those rows: most of the columns between
  // stripes (half of all) keep more than 0.02 mm, none more than the bound,
  // none is gouged.
  const double R = 1.5, p = 0.5, flat = R - std::sqrt(R * R - p * p), bound = flat * (1 + 0.63 * 0.63);
  const Result r = run_command("zig freeform --stepover 1 -o " + tmp_dir() + "/ff.ngc");
  CHECK_EQ(r.code, 0);
  // Cut on the engine as `dexmill run ff.ngc --stock 0,0,-30,127.5,127.5,0
  // --pitch 0.5 --tool ball:3 --design freeform` would.
  sim_test::Run cut;
  CHECK(cut.stock("0,0,-30,127.5,127.5,0").pitch("0.5").tool("ball:3").design("freeform").program(tmp_dir() + "/ff.ngc"));
  CHECK(cut.sim().state() == dexmill::SimState::kDone);
  const std::string a = cut.assessment();
  CHECK(has(a, "\"max_gouge\": null"));
  // The histogram: columns per band, edges -1 -0.5 -0.2 -0.1 -0.05 -0.02
  // -0.01 0.01 0.02 0.05 0.1 0.2 0.5 1 (mm): bin k lies under edge k.
  const size_t at = a.find("\"columns\": [");
  CHECK(at != std::string::npos);
  if (at == std::string::npos) return;
  std::vector<long> bins;
  for (const char* q = a.c_str() + at + 12; *q && *q != ']';) {
    bins.push_back(std::strtol(q, const_cast<char**>(&q), 10));
    while (*q == ',' || *q == ' ') ++q;
  }
  CHECK_EQ(bins.size(), size_t(15));
  if (bins.size() != 15) return;
  long total = 0, over_002 = 0;
  for (size_t k = 0; k < bins.size(); ++k) total += bins[k];
  for (size_t k = 9; k < bins.size(); ++k) over_002 += bins[k];
  CHECK_GT(over_002, total / 2 * 7 / 10);
  CHECK_EQ(bins[12] + bins[13] + bins[14], 0);  // nothing over 0.2 mm
  const size_t m = a.find("\"max_leftover\": {\"mm\": ");
  CHECK(m != std::string::npos);
  if (m == std::string::npos) return;
  const double worst = std::atof(a.c_str() + m + 23);
  CHECK_GT(worst, flat);
  CHECK_LE(worst, bound);
  std::printf("scallop: predicted %.4f mm on a flat (%.4f bound on the slopes), largest left %.4f mm, %ld of %ld columns over 0.02 mm\n",
              flat, bound, worst, over_002, total);
}
