// `--color engagement` (core/engage/engage_band.h, display/colour/engage_colours.h):
// the bands against their edges on both sides (angle and limit scales, a
// plunge unmeasured, air none); in the engine, a full slot and a light
// pass beside it in the bands their engagement angles give (180 and 78
// degrees), the plunge's hole apart, the same classes whether frames flush
// the cut after every step or never; with a material's chip limit the
// scale turns to the limit's share; from the CLI, a top view with the
// slot in the hot colour and the light pass in a cool one, and the legend
// named by the scale.
#include <cstdio>
#include <string>
#include <vector>

#include "core/engage/engage_band.h"
#include "core/math/trig.h"
#include "display/colour/engage_colours.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;

namespace {

EngageMove engaged(double deg) {
  EngageMove m;
  m.feed = true;
  m.samples = 4;
  m.removed_lsb = 100;
  m.worst.engaged = true;
  m.worst.entry_bam = 0;
  m.worst.exit_bam = static_cast<uint32_t>(deg / 360.0 * 4294967296.0);
  return m;
}

// A full slot along Y=10 at 2 mm deep, then a pass 2.4 mm over on its climb
// side (78 degrees), 10000 rpm; the plunge at X-5 stands in air, and a
// second plunge at X15 Y3 drills into the stock.
const char* kSlotAndPass =
    "G21 G90 G94\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F1200\nG1 Y12.4\nG1 X-5\nG0 Z5\n"
    "G0 X15 Y3\nG1 Z-3 F200\nG0 Z5\nM30\n";

// The class at (x, y) mm of a run's engagement colours.
uint8_t cls_at(sim_test::Run& r, double x, double y) {
  const DexelGrid<height_t>& g = r.sim().grid();
  const int32_t i = static_cast<int32_t>((x * 1e6 - g.x0_nm) / g.pitch_nm + 0.5);
  const int32_t j = static_cast<int32_t>((y * 1e6 - g.y0_nm) / g.pitch_nm + 0.5);
  return r.sim().engage_classes()[g.index(i, j)];
}

void engagement_run(sim_test::Run* r, const char* material, bool sync_each_step) {
  r->stock("0,0,-10,30,20,0").pitch("0.12").tool("flat:6,flutes=2");
  if (material) r->material(material);
  r->o.view.color = cli::ViewOptions::Color::kEngagement;
  r->text("engage_colours.ngc", kSlotAndPass, SimBudget(), sync_each_step);
}

}  // namespace

TEST(engage_band_edges_on_both_sides) {
  // By angle: sixths of a half turn.
  CHECK_EQ(engage_band(engaged(29.9), false, 0, 0), 1);
  CHECK_EQ(engage_band(engaged(30.1), false, 0, 0), 2);
  CHECK_EQ(engage_band(engaged(89.9), false, 0, 0), 3);
  CHECK_EQ(engage_band(engaged(90.1), false, 0, 0), 4);
  CHECK_EQ(engage_band(engaged(149.9), false, 0, 0), 5);
  CHECK_EQ(engage_band(engaged(179.99), false, 0, 0), 6);
  // Removed material within an LSB of the surface: the lightest band.
  EngageMove skim = engaged(0);
  skim.worst.engaged = false;
  CHECK_EQ(engage_band(skim, false, 0, 0), 1);
  // By the limits: fifths, the limit itself in the fifth, over it the sixth.
  EngageMove m = engaged(180);
  m.chip.max_nm = 19999;
  CHECK_EQ(engage_band(m, true, 0, 100000), 1);
  m.chip.max_nm = 20001;
  CHECK_EQ(engage_band(m, true, 0, 100000), 2);
  m.chip.max_nm = 100000;
  CHECK_EQ(engage_band(m, true, 0, 100000), 5);
  m.chip.max_nm = 100001;
  CHECK_EQ(engage_band(m, true, 0, 100000), 6);
  // The power's share when it is the larger; without a load, the chip's.
  m.chip.max_nm = 10000;
  m.power_mw = 700000;
  CHECK_EQ(engage_band(m, true, 1000000, 100000), 1);  // has_load false: power not known
  m.has_load = true;
  CHECK_EQ(engage_band(m, true, 1000000, 100000), 4);
  m.power_mw = 5000000000LL;  // far over: saturated, still the last band
  CHECK_EQ(engage_band(m, true, 1000000, 100000), 6);
  // A plunge (no samples) is unmeasured; air, and a rapid, none.
  EngageMove plunge = engaged(0);
  plunge.samples = 0;
  CHECK_EQ(engage_band(plunge, false, 0, 0), kEngageBandUnmeasured);
  EngageMove air = engaged(90);
  air.removed_lsb = 0;
  CHECK_EQ(engage_band(air, false, 0, 0), 0);
  EngageMove rapid = engaged(90);
  rapid.feed = false;
  CHECK_EQ(engage_band(rapid, true, 1000000, 100000), 0);
}

TEST(engage_colours_give_each_cut_its_moves_band) {
  sim_test::Run r;
  engagement_run(&r, nullptr, false);
  CHECK(r.sim().engage_classes() != nullptr);
  CHECK(!r.sim().engage_by_limits());
  CHECK_EQ(cls_at(r, 20, 9), 6);     // the slot: 180 degrees
  CHECK_EQ(cls_at(r, 20, 14.5), 3);  // the pass beside it: 78 degrees
  CHECK_EQ(cls_at(r, 15, 3), kEngageBandUnmeasured);  // the plunge
  CHECK_EQ(cls_at(r, 20, 18), 0);    // uncut
  CHECK_EQ(cls_at(r, 5, 2), 0);
  // Frames flushing the cut after every step change no class.
  sim_test::Run synced;
  engagement_run(&synced, nullptr, true);
  const DexelGrid<height_t>& g = r.sim().grid();
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  size_t differ = 0, coloured = 0;
  for (size_t k = 0; k < n; ++k) {
    differ += r.sim().engage_classes()[k] != synced.sim().engage_classes()[k];
    coloured += r.sim().engage_classes()[k] != 0;
  }
  CHECK_EQ(differ, size_t{0});
  CHECK_GT(coloured, size_t{10000});
  CHECK_EQ(r.sim().engagement()->engaged, synced.sim().engagement()->engaged);
  CHECK_EQ(r.sim().engagement()->rate.mrr_um3_per_min, synced.sim().engagement()->rate.mrr_um3_per_min);
  // Off, none are kept.
  sim_test::Run off;
  off.stock("0,0,-10,30,20,0").pitch("0.12").tool("flat:6");
  off.o.out.engagement_csv = run_cli::tmp_dir() + "/engage_colours_off.csv";
  off.text("engage_colours_off.ngc", kSlotAndPass);
  CHECK(off.sim().engage_classes() == nullptr);
}

TEST(engage_colours_by_the_chip_limit_with_a_material) {
  // Aluminium's max_chip is 0.06 mm; the slot's chip is 0.06 mm a tooth
  // (1200 / (10000 x 2)): the limit itself, the fifth band; the pass at
  // 78 degrees thins it to 0.06 sin 78 = 0.0587: also the fifth.
  sim_test::Run r;
  engagement_run(&r, "aluminium", false);
  CHECK(r.sim().engage_by_limits());
  CHECK_EQ(cls_at(r, 20, 9), 5);
  CHECK_EQ(cls_at(r, 20, 14.5), 5);
}

TEST(run_color_engagement_top_view) {
  using namespace run_cli;
  if (skip()) return;
  const std::string prog = write_tmp("engage_colours.ngc", kSlotAndPass);
  const std::string base = prog + " --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --view top --size 320x240 "
                                  "-q --no-decorations --color engagement ";
  Result r = run(base + "--image " + tmp_dir() + "/engage.ppm");
  CHECK_EQ(r.code, 0);
  const std::vector<unsigned char> px = ppm_rgb(slurp(tmp_dir() + "/engage.ppm"), 24);
  CHECK(!px.empty());
  // Shades of the slot's crimson (red over green, blue over green) and
  // the pass's green (green over red and blue).
  int hot = 0, cool = 0;
  for (size_t k = 0; k + 2 < px.size(); k += 3) {
    const int r0 = px[k], g0 = px[k + 1], b0 = px[k + 2];
    hot += r0 > g0 + 90 && b0 > g0 + 20;
    cool += g0 > r0 + 40 && g0 > b0 + 30;
  }
  std::printf("  slot crimson pixels %d, pass green %d\n", hot, cool);
  CHECK_GT(hot, 1500);  // a 6 mm slot 30 mm long, about 40 x 200 pixels, less the pass over its edge
  CHECK_GT(cool, 800);
  CHECK(has(run("--help").out, "engagement (each cut by its move's load"));
  CHECK(has(run("--color heat").err, "plain, error, material, tool, slope, thin or engagement"));
}
