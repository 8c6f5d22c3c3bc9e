// core/engage/engage_load.h against Kienzle's law in doubles (force,
// power, torque for a slot and a light pass), core/engage/load_watch.h's
// limits (findings where a move is over them, none where it is not), and
// `dexmill run --check load`, --spindle-power, --fail-on-load, the
// material file's kc1.1, mc and max_chip.
#include <cmath>
#include <cstdio>
#include <string>

#include "core/engage/engage_load.h"
#include "core/engage/load_watch.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// A move engaged from entry to exit degrees, a_p deep, the section A mm^2,
// at F mm/min and S rpm with z flutes, its chip from engage_chip.
EngageMove slot_move(const EngageTool& t, double entry_deg, double ap_mm, double area_mm2, double f, int32_t rpm) {
  EngageMove m;
  m.feed = true;
  m.worst.engaged = true;
  m.worst.entry_bam = static_cast<uint32_t>(entry_deg / 2) * kEngageStepBam;
  m.worst.exit_bam = static_cast<uint32_t>(kEngageSteps) * kEngageStepBam;
  m.worst.ap_nm = static_cast<int64_t>(ap_mm * 1e6);
  m.worst.area_um2 = static_cast<int64_t>(area_mm2 * 1e6);
  m.section = m.worst;
  m.feed_nm_per_min = static_cast<int64_t>(f * 1e6);
  m.spindle_rpm = rpm;
  m.fz_nm = m.feed_nm_per_min / (static_cast<int64_t>(rpm) * t.flutes);
  m.chip = engage_chip(t, m.worst, m.fz_nm);
  m.mrr_um3_per_min = m.section.area_um2 * (m.feed_nm_per_min / 1000);
  return m;
}

}  // namespace

TEST(engage_load_is_kienzle) {
  Tool tl{};
  tl.kind = ToolKind::kFlat;
  tl.diameter_nm = 6000000;
  tl.length_nm = 40000000;
  EngageTool t;
  engage_tool_init(tl, 60000, &t);
  const CuttingCoefficients c{650, 250000};
  double worst = 0;
  for (double entry : {0.0, 90.0, 142.0}) {  // steps of 2 degrees
    const double R = 3, width = R * (1 + std::cos(entry * M_PI / 180));  // from the entry to the far side
    EngageMove m = slot_move(t, entry, 2, 2 * width, 1200, 10000);
    engage_load(t, c, &m);
    CHECK(m.has_load);
    const double fz = m.fz_nm * 1e-6, a = entry * M_PI / 180, b = M_PI;
    const double hmax = fz * (a > M_PI / 2 ? std::sin(a) : 1.0), hm = fz * (std::cos(a) - std::cos(b)) / (b - a);
    const double force = 650 * 2 * std::pow(hmax, 0.75);
    const double power = 650 * std::pow(hm, -0.25) * (2 * width) * 1200 / 60 / 1000;
    const double torque = power * 60 / (2 * M_PI * 10000);
    // Kienzle on the chip engage_chip gave (its own error is tested in test_engage.cpp).
    const double f_rel = std::fabs(m.force_mn * 1e-3 - 650 * 2 * std::pow(m.chip.max_nm * 1e-6, 0.75)) / force;
    const double p_rel = std::fabs(m.power_mw * 1e-3 - power) / power;
    const double t_rel = std::fabs(m.torque_mn_m * 1e-3 - torque) / torque;
    worst = std::fmax(worst, std::fmax(f_rel, p_rel));
    CHECK(f_rel <= 1e-4);
    CHECK(p_rel <= 2e-3);  // the mean chip from 2-degree steps
    CHECK(t_rel <= 2e-3 + 1e-3 / torque);  // and one unit, a mN m
  }
  std::printf("  engage_load: force and power within %.4f %% of Kienzle's\n", 100 * worst);
  // No coefficients, no spindle speed: no load.
  EngageMove m = slot_move(t, 0, 2, 12, 1200, 10000);
  engage_load(t, CuttingCoefficients{}, &m);
  CHECK(!m.has_load);
  m.spindle_rpm = 0;
  engage_load(t, c, &m);
  CHECK(!m.has_load);
  // The specific force rises on thin chips: kc(0.01 mm) = kc1.1 x 100^0.25.
  CHECK(std::fabs(kienzle_kc_kpa(c, 10000) * 1e-3 - 650 * std::pow(100.0, 0.25)) <= 0.01);
  CHECK_EQ(kienzle_kc_kpa(c, 0), kienzle_kc_kpa(c, kKienzleMinChipNm));
}

TEST(load_watch_finds_what_is_over_and_only_that) {
  LoadWatch w;
  w.spindle_power_mw = 500000;
  EngageMove m;
  m.feed = true;
  m.line = 7;
  m.chip.max_nm = 60000;
  m.has_load = true;
  m.power_mw = 400000;
  CHECK(!load_watch_check(&w, m, 60000));  // at the limits: no finding
  CHECK_EQ(w.total, 0u);
  m.chip.max_nm = 60001;
  CHECK(load_watch_check(&w, m, 60000));
  m.power_mw = 500001;
  m.line = 8;
  CHECK(load_watch_check(&w, m, 0));  // no chip limit: the power's alone
  CHECK_EQ(w.total, 2u);
  CHECK_EQ(w.kept[0].line, 7u);
  CHECK(w.kept[0].rule == LoadRule::kChip);
  CHECK(w.kept[1].rule == LoadRule::kPower);
  CHECK_EQ(w.kept[1].value, 500001);
}

TEST(run_check_load) {
  using namespace run_cli;
  if (skip()) return;
  // A full slot 2 mm deep at 1200 mm/min, 10000 rpm (0.06 mm a tooth),
  // then a 0.6 mm pass beside it at the same feed (a thinner chip).
  write_tmp("load.ngc", "G21 G90 G94\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F1200\nG1 Y13.6\nG1 X-5\nG0 Z5\nM30\n");
  write_tmp("alu.mat", "material alu plain kc1.1=650 mc=0.25 max_chip=0.05\n");
  const std::string base = "%/load.ngc -q --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --material %/alu.mat ";
  // Power in a 2 x 6 mm slot at 1200 mm/min: kc(hm = 0.0382) = 650 x 0.0382^-0.25 = 1463 N/mm^2,
  // x 12 mm^2 x 20 mm/s = 351 W.
  Result r = run(base + "--check load --spindle-power 300 --report %/load.json --engagement-csv %/load.csv");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "load.ngc:5:1: warning: chip over alu's max_chip of 0.0500 mm a tooth"));
  CHECK(has(r.err, "load.ngc:5:1: warning: power over the spindle's 300 W"));
  CHECK(lacks(r.err, "load.ngc:7:1: warning: power"));  // the light pass is within it
  const std::string rep = slurp(tmp_dir() + "/load.json");
  CHECK(has(rep, "\"load\": {\"spindle_power_w\": 300.000, \"total\": "));
  CHECK(has(rep, "{\"rule\": \"power\", \"line\": 5, \"message\": \"power 3"));
  CHECK(has(rep, "\"max_power\": {\"w\": 3"));
  CHECK(has(rep, "\"line\": 5, \"at\": \""));
  CHECK(has(rep, "\"tools\": [\n      {\"tool\": "));
  const std::string csv = slurp(tmp_dir() + "/load.csv");
  CHECK(has(csv, "\n5,3.547,2.0000,6.0000,180.00,14398.5,0.06000,0.03820,157.6,352.8,1200.0,0.337,0,"));  // 351 W analytic
  // The load plot: spindle power with the limit, the worst line marked.
  CHECK_EQ(run(base + "--spindle-power 300 --load-plot %/load.svg").code, 0);
  const std::string svg = slurp(tmp_dir() + "/load.svg");
  CHECK(has(svg, "spindle power") && has(svg, "limit 300 W") && has(svg, "L5 max power"));
  CHECK_EQ(run(base + "--load-plot %/load.pdf").code, 2);
  // Exit 4 with --fail-on-load; limits it stays within: no finding, exit 0.
  CHECK_EQ(run(base + "--spindle-power 300 --fail-on-load").code, 4);
  write_tmp("alu2.mat", "material alu plain kc1.1=650 mc=0.25 max_chip=0.07\n");
  r = run("%/load.ngc -q --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --material %/alu2.mat "
          "--spindle-power 400 --fail-on-load --report %/ok.json");
  CHECK_EQ(r.code, 0);
  CHECK(lacks(r.err, "warning: chip") && lacks(r.err, "warning: power"));
  CHECK(has(slurp(tmp_dir() + "/ok.json"), "\"load\": {\"spindle_power_w\": 400.000, \"total\": 0, \"findings\": []}"));
  // --check load needs a material; a bad coefficient is its file's line and column.
  CHECK_EQ(run("%/load.ngc -q --check load").code, 2);
  write_tmp("bad.mat", "material alu plain\nmaterial b plain kc1.1=abc\n");
  r = run("%/load.ngc -q --material %/bad.mat");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "bad.mat:2:18: error: kc1.1 is a force in N/mm2"));
  write_tmp("bad2.mat", "material alu plain mc=1.5\n");
  CHECK(has(run("%/load.ngc -q --material %/bad2.mat").err, "bad2.mat:1:20: error: mc is Kienzle's exponent"));
}

TEST(optimize_target_sets_feeds_by_the_load) {
  using namespace run_cli;
  if (skip()) return;
  // The slot of run_check_load in aluminium (max_chip 0.06 mm, max_feed
  // 1500 mm/min): the plunge and the step over are in air.
  write_tmp("tgt.ngc", "G21 G90 G94\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F1200\nG1 Y13.6\nG1 X-5\nG0 Z5\nM30\n");
  const std::string cut = " --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --material aluminium";
  // One feed a line here (--split-lines 0; the pieces of a move whose load
  // changes along it: test_engage_split.cpp).
  const std::string whole = " --split-lines 0";
  // A 0.03 mm chip: the slot and the pass (both with a full 0.06 mm chip
  // at 1200) halved, the air moves at the highest feed.
  Result r = run_command("optimize %/tgt.ngc" + cut + whole + " --target chip-load=0.03 -o %/tgt-chip.ngc");
  CHECK_EQ(r.code, 0);
  const std::string chip = slurp(tmp_dir() + "/tgt-chip.ngc");
  CHECK(has(chip, "G1 Z-2 F1500\nG1 X35 F600\nG1 Y13.6 F1500\nG1 X-5 F600\n"));
  CHECK(has(r.err, "target chip-load 0.03 mm: 2 line(s) raised, 2 lowered"));
  // 250 W: the slot (353 W at 1200) lowered to 1200 (250/353)^(4/3) = 757;
  // the pass (207 W) would go to 1543, but the chip limit holds it at 1200.
  r = run_command("optimize %/tgt.ngc" + cut + whole + " --target power 250 --max-feed 3000 -o %/tgt-pow.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/tgt-pow.ngc"), "G1 X35 F757\nG1 Y13.6 F1500\nG1 X-5 F1200\n"));
  // Re-simulated: the same stock, no move over the power or the chip.
  CHECK_EQ(run("%/tgt-pow.ngc -q" + cut + " --spindle-power 250 --fail-on-load --heightmap %/after.pgm").code, 0);
  CHECK_EQ(run("%/tgt.ngc -q" + cut + " --heightmap %/before.pgm").code, 0);
  CHECK_EQ(file_hash(tmp_dir() + "/after.pgm"), file_hash(tmp_dir() + "/before.pgm"));
  CHECK_EQ(run("%/tgt.ngc -q" + cut + " --spindle-power 250 --fail-on-load").code, 4);  // before, it was over
  // A removal rate: 7200 mm^3/min, half the slot's 14398 (the pass, 8573 at 1200, goes to 1007).
  r = run_command("optimize %/tgt.ngc" + cut + whole + " --target mrr=7200 -o %/tgt-mrr.ngc");
  CHECK(has(slurp(tmp_dir() + "/tgt-mrr.ngc"), "G1 X35 F600\n"));
  // Bad forms are usage errors; --min-feed without --target too.
  CHECK_EQ(run_command("optimize %/tgt.ngc" + cut + " --target power").code, 2);
  CHECK_EQ(run_command("optimize %/tgt.ngc" + cut + " --target torque=3").code, 2);
  CHECK_EQ(run_command("optimize %/tgt.ngc" + cut + " --min-feed 100").code, 2);
}

TEST(default_spindle_speed_for_programs_without_one) {
  using namespace run_cli;
  if (skip()) return;
  // The slot with no S word and no M3 (a router's spindle switched by
  // hand), and its first feed move with no F in force.
  write_tmp("nos.ngc", "G21 G90 G94\nG0 X-5 Y10 Z5\nG1 Z-2\nG1 X35 F1200\nG0 Z5\nM30\n");
  const std::string cut = " --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --default-feed 300";
  // Without a speed: measured but no chip, counted and said.
  Result r = run("%/nos.ngc" + cut + " --engagement-csv %/nos.csv --report %/nos.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "warning: 1 cutting moves ran with no spindle speed (no S word, or no M3)"));
  CHECK(has(slurp(tmp_dir() + "/nos.json"), "\"engaged\": 1, \"no_spindle_speed\": 1,"));
  CHECK(has(slurp(tmp_dir() + "/nos.csv"), ",0.00000,0.00000,,,1200.0,"));
  // --default-spindle 10000: the chip of the S10000 slot, 0.06 mm a tooth, and no warning.
  r = run("%/nos.ngc" + cut + " --default-spindle 10000 --engagement-csv %/nos2.csv --report %/nos2.json");
  CHECK_EQ(r.code, 0);
  CHECK(lacks(r.err, "no spindle speed"));
  CHECK(has(slurp(tmp_dir() + "/nos2.json"), "\"engaged\": 1, \"no_spindle_speed\": 0,"));
  CHECK(has(slurp(tmp_dir() + "/nos2.csv"), ",0.06000,0.03820,,,1200.0,"));
  // optimize reads the program as the cut did (--default-feed's F for the
  // plunge) and halves the slot's feed for a 0.03 mm chip; without a
  // speed it cannot say, and keeps it.
  r = run_command("optimize %/nos.ngc" + cut + " --default-spindle 10000 --material aluminium --target chip-load=0.03 "
                  "-o %/nos-opt.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/nos-opt.ngc"), "G1 X35 F600\n"));
  r = run_command("optimize %/nos.ngc" + cut + " --material aluminium --target chip-load=0.03 -o %/nos-kept.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/nos-kept.ngc"), "G1 X35 F1200\n"));
  CHECK_EQ(run("%/nos.ngc" + cut + " --default-spindle 0").code, 2);
  CHECK_EQ(run("%/nos.ngc" + cut + " --default-spindle fast").code, 2);
}

TEST(optimize_leaves_an_f_it_cannot_change) {
  using namespace run_cli;
  if (skip()) return;
  // The slot's F from a parameter: its line stays as written, said, and
  // the rest is rewritten (the air move after it raised).
  write_tmp("fpar.ngc", "G21 G90 G94\n#1=600\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F#1\nG1 Y13.6\nG0 Z5\nM30\n");
  const std::string cut = " --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --material aluminium";
  Result r = run_command("optimize %/fpar.ngc" + cut + " --target chip-load -o %/fpar-opt.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "fpar.ngc:6:1: warning: F here is not a number this rewrite can change: left as written (600 mm/min"));
  const std::string out = slurp(tmp_dir() + "/fpar-opt.ngc");
  CHECK(has(out, "\nG1 X35 F#1\n"));
  CHECK(has(out, "\nG1 Z-2 F1500\n"));
  // Lowered for a limit (F#1 = 3000 is over aluminium's max_feed): counted as left over.
  write_tmp("fpar2.ngc", "G21 G90 G94\n#1=3000\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F#1\nG0 Z5\nM30\n");
  r = run_command("optimize %/fpar2.ngc" + cut + " -o %/fpar2-opt.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "mm/min was wanted, a limit)"));
  CHECK(has(r.err, "1 line(s) left over a limit"));
}
