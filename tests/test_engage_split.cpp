// Long moves split where their load changes (core/engage/engage_split.h,
// tools/cam/move_split.h): pieces from samples' feeds (the slow side covers
// the load between samples, short pieces merged, at most the rule's count,
// no split that gains too little); from the CLI, a slot entered from air
// written as an air piece at the highest feed and the slot at its chip
// limit, the output cutting the same stock within every limit and faster
// than one feed a line; lines that must stay whole (other words on the
// line, G91, inch units written at 7 decimals, CRLF kept).
#include <cstdio>
#include <string>
#include <vector>

#include "core/engage/engage_split.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kMm = 1000000;

int32_t split(const std::vector<int64_t>& s_mm10, const std::vector<int64_t>& feed, int64_t len_mm, int64_t min_mm,
              EngageSegment* out, int32_t most = kEngageMaxSegments) {
  std::vector<int64_t> s;
  for (int64_t v : s_mm10) s.push_back(v * kMm / 10);
  EngageSplitRule rule;
  rule.min_segment_nm = min_mm * kMm;
  rule.max_segments = most;
  return engage_split(s.data(), feed.data(), static_cast<int32_t>(s.size()), len_mm * kMm, rule, out);
}

}  // namespace

TEST(engage_split_pieces_at_the_load_changes) {
  EngageSegment seg[kEngageMaxSegments];
  // Air for 20 mm, then a slot: samples every 2 mm, 3000 in air, 600 in the cut.
  std::vector<int64_t> s, f;
  for (int k = 0; k <= 20; ++k) {
    s.push_back(k * 20);
    f.push_back(k < 10 ? 3000 * kMm : 600 * kMm);
  }
  int32_t n = split(s, f, 40, 5, seg);
  CHECK_EQ(n, 2);
  // The neighbours' minimum makes sample 9 slow too: the slow piece starts
  // at the last light sample, 16 mm (before the load rises at 18-20).
  CHECK_EQ(seg[0].end_nm, 16 * kMm);
  CHECK_EQ(seg[0].feed_nm_per_min, 3000 * kMm);
  CHECK_EQ(seg[1].end_nm, 40 * kMm);
  CHECK_EQ(seg[1].feed_nm_per_min, 600 * kMm);
  // Leaving the cut: the slow piece ends at the first light sample.
  std::vector<int64_t> back(f.rbegin(), f.rend());
  n = split(s, back, 40, 5, seg);
  CHECK_EQ(n, 2);
  CHECK_EQ(seg[0].end_nm, 24 * kMm);
  CHECK_EQ(seg[0].feed_nm_per_min, 600 * kMm);
  // A piece shorter than the minimum joins a neighbour at the lower feed:
  // a 4 mm light stretch in the middle of a 40 mm cut is not worth a piece.
  std::vector<int64_t> dip(21, 600 * kMm);
  for (int k = 9; k <= 12; ++k) dip[k] = 3000 * kMm;
  n = split(s, dip, 40, 5, seg);
  CHECK_EQ(n, 1);
  CHECK_EQ(seg[0].feed_nm_per_min, 600 * kMm);
  // A 16 mm light stretch is a piece of its own, 12 mm once the
  // neighbours' minimum has taken a sample off either end; with a 15 mm
  // minimum it is merged too.
  std::vector<int64_t> gap(21, 600 * kMm);
  for (int k = 6; k <= 14; ++k) gap[k] = 3000 * kMm;
  n = split(s, gap, 40, 5, seg);
  CHECK_EQ(n, 3);
  CHECK_EQ(seg[0].end_nm, 14 * kMm);
  CHECK_EQ(seg[1].end_nm, 26 * kMm);
  CHECK_EQ(seg[1].feed_nm_per_min, 3000 * kMm);
  CHECK_EQ(seg[2].feed_nm_per_min, 600 * kMm);
  CHECK_EQ(split(s, gap, 40, 15, seg), 1);
  // At most `most` pieces: the closest feeds merge first.
  std::vector<int64_t> steps;
  for (int k = 0; k <= 20; ++k) steps.push_back((k / 4 % 2 ? 3000 : 400 + 100 * (k / 8)) * kMm);
  n = split(s, steps, 40, 1, seg, 3);
  CHECK_LE(n, 3);
  CHECK_GE(n, 2);
  for (int32_t k = 0; k < n; ++k) CHECK_GE(seg[k].feed_nm_per_min, 400 * kMm);
  // A change under 15 % or a gain under 5 %: whole, at the lowest.
  std::vector<int64_t> near(21, 1000 * kMm);
  for (int k = 10; k <= 20; ++k) near[k] = 1100 * kMm;
  CHECK_EQ(split(s, near, 40, 1, seg), 1);
  CHECK_EQ(seg[0].feed_nm_per_min, 1000 * kMm);
  std::vector<int64_t> tail(21, 1000 * kMm);
  tail[20] = 3000 * kMm;  // the last 2 mm of 40 light: 0 pieces worth it (and under the minimum)
  CHECK_EQ(split(s, tail, 40, 1, seg), 1);
  // No splitting asked: whole.
  CHECK_EQ(split(s, f, 40, 5, seg, 0), 1);
  // Room for the pieces: a move that no longer fits is left whole, counted.
  EngageSplitPiece store[3];
  EngageSplits sp{store, 3, 0, 0, 0};
  EngageSegment two[2] = {{10, 1}, {20, 2}};
  CHECK(engage_splits_add(&sp, 5, two, 2));
  CHECK(!engage_splits_add(&sp, 6, two, 2));
  CHECK_EQ(sp.n, size_t{2});
  CHECK_EQ(sp.moves, uint64_t{1});
  CHECK_EQ(sp.left, uint64_t{1});
  CHECK(store[1].last && !store[0].last && store[1].line == 5);
}

TEST(optimize_splits_a_move_that_enters_the_stock) {
  using namespace run_cli;
  if (skip()) return;
  // A slot along Y10 entered from 25 mm out (22 mm of air before the
  // edge meets the stock at X0), then a pass 4 mm over it whose first half
  // runs over the slot (2 of its 6 mm in material) and second half over
  // stock the slot left (a full slot where the first slot stopped at X15).
  write_tmp("split.ngc",
            "G21 G90 G94\nS10000 M3\nG0 X-25 Y10 Z5\nG1 Z-2 F300\nG1 X15 F600\nG0 Z5\n"
            "G0 X-25 Y14\nG1 Z-2 F300\nG1 X35 F600\nG0 Z5\nM30\n");
  const std::string cut = " --tool flat:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.12 --material aluminium";
  Result r = run_command("optimize %/split.ngc" + cut + " --target chip-load -o %/split-opt.ngc");
  CHECK_EQ(r.code, 0);
  const std::string out = slurp(tmp_dir() + "/split-opt.ngc");
  std::printf("%s", out.c_str());
  // The slot: air at aluminium's max_feed (1500) to 2.5 mm before the
  // edge, then the slot at the chip limit (0.06 mm: 1200).
  CHECK(has(out, "G1 Z-2 F1500\nG91 G1 X19.5 F1500\nG90\nG1 X15 F1200\n"));
  CHECK(has(r.err, "long move(s) split where their load changes"));
  // The same stock, no load finding, and faster than one feed a line.
  CHECK_EQ(run("%/split-opt.ngc -q" + cut + " --fail-on-load --heightmap %/split-after.pgm").code, 0);
  CHECK_EQ(run("%/split.ngc -q" + cut + " --heightmap %/split-before.pgm").code, 0);
  CHECK_EQ(file_hash(tmp_dir() + "/split-after.pgm"), file_hash(tmp_dir() + "/split-before.pgm"));
  Result whole = run_command("optimize %/split.ngc" + cut + " --target chip-load --split-lines 0 -o %/split-whole.ngc");
  CHECK(lacks(slurp(tmp_dir() + "/split-whole.ngc"), "G91"));
  auto after_s = [](const std::string& err) {
    const size_t at = err.find(" before, ");
    return at == std::string::npos ? std::string() : err.substr(at + 9, err.find(" after", at) - at - 9);
  };
  std::printf("  after, split %s, whole %s\n", after_s(r.err).c_str(), after_s(whole.err).c_str());
  CHECK(after_s(r.err) < after_s(whole.err));  // "0:05.1" < "0:07.9": same width
  // A power target (250 W): the slot, 353 W at 1200, slowed to 757 until
  // its end leaves the stock, where the load falls and the chip limit
  // (1200) sets the last piece; still the same stock, no finding.
  write_tmp("split-pow.ngc", "G21 G90 G94\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F1200\nG1 Y13.6\nG1 X-5\nG0 Z5\nM30\n");
  r = run_command("optimize %/split-pow.ngc" + cut + " --target power 250 --max-feed 3000 -o %/split-pow-opt.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/split-pow-opt.ngc"), "G91 G1 X34.5 F757\nG90\nG1 X35 F1200\n"));
  CHECK_EQ(run("%/split-pow-opt.ngc -q" + cut + " --spindle-power 250 --fail-on-load --heightmap %/split-pow-after.pgm").code, 0);
  CHECK_EQ(run("%/split-pow.ngc -q" + cut + " --heightmap %/split-pow-before.pgm").code, 0);
  CHECK_EQ(file_hash(tmp_dir() + "/split-pow-after.pgm"), file_hash(tmp_dir() + "/split-pow-before.pgm"));
  // Ramps with a ball: the pieces lie on each move exactly, but the sweep
  // rounds a piece within its own 1-LSB bound, and here some dexels come
  // out one LSB apart from the whole move's. The output's check cut finds
  // them and undoes those splits: the stock is the input's, byte for byte.
  write_tmp("split-ball.ngc", "G21 G90 G94\nS10000 M3\nG0 X-15 Y2.134 Z5\nG1 Z-2.195 F300\nG1 X37.638 Y0.665 Z-2.690 F600\nG0 Z5\nG0 X-15 Y5.149 Z5\nG1 Z-1.803 F300\nG1 X37.887 Y2.713 Z-1.832 F600\nG0 Z5\nG0 X-15 Y8.236 Z5\nG1 Z-1.366 F300\nG1 X37.623 Y5.248 Z-1.811 F600\nG0 Z5\nG0 X-15 Y10.822 Z5\nG1 Z-0.958 F300\nG1 X39.453 Y13.230 Z-0.988 F600\nG0 Z5\nG0 X-15 Y12.825 Z5\nG1 Z-1.583 F300\nG1 X39.391 Y12.113 Z-1.799 F600\nG0 Z5\nG0 X-15 Y15.922 Z5\nG1 Z-0.558 F300\nG1 X32.217 Y15.549 Z-1.054 F600\nG0 Z5\nM30\n");
  const std::string ball = " --tool ball:6,flutes=2 --stock 0,0,-10,30,20,0 --pitch 0.1 --material aluminium";
  r = run_command("optimize %/split-ball.ngc" + ball + " --target chip-load -o %/split-ball-opt.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "split(s) undone where the pieces' sweep rounded a dexel apart"));
  CHECK_EQ(run("%/split-ball-opt.ngc -q" + ball + " --fail-on-load --heightmap %/split-ball-after.pgm").code, 0);
  CHECK_EQ(run("%/split-ball.ngc -q" + ball + " --heightmap %/split-ball-before.pgm").code, 0);
  CHECK_EQ(file_hash(tmp_dir() + "/split-ball-after.pgm"), file_hash(tmp_dir() + "/split-ball-before.pgm"));
  // The slot's split (above) was not undone: no false alarm.
  CHECK(lacks(run_command("optimize %/split.ngc" + cut + " --target chip-load -o %/split-opt2.ngc").err, "undone"));
  // A line with more than the move stays whole; so does a G91 program.
  write_tmp("split-m.ngc", "G21 G90 G94\nS10000 M3\nG0 X-25 Y10 Z5\nG1 Z-2 F300\nG1 X15 F600 M8\nG0 Z5\nM30\n");
  r = run_command("optimize %/split-m.ngc" + cut + " --target chip-load -o %/split-m-opt.ngc");
  CHECK_EQ(r.code, 0);
  CHECK(lacks(slurp(tmp_dir() + "/split-m-opt.ngc"), "G91"));
  CHECK(has(r.err, "1 left whole"));
  write_tmp("split-inc.ngc", "G21 G90 G94\nS10000 M3\nG0 X-25 Y10 Z5\nG1 Z-2 F300\nG91 G1 X40 F600\nG90 G0 Z5\nM30\n");
  r = run_command("optimize %/split-inc.ngc" + cut + " --target chip-load -o %/split-inc-opt.ngc");
  CHECK(lacks(slurp(tmp_dir() + "/split-inc-opt.ngc"), "G91 G1 X19"));
  // Inch, CRLF: the pieces in inches at 7 decimals, the line ends kept.
  write_tmp("split-in.ngc", "G20 G90 G94\r\nS10000 M3\r\nG0 X-1 Y0.4 Z0.2\r\nG1 Z-0.08 F12\r\nG1 X0.6 F24\r\nG0 Z0.2\r\nM30\r\n");
  r = run_command("optimize %/split-in.ngc" + cut + " --target chip-load -o %/split-in-opt.ngc");
  CHECK_EQ(r.code, 0);
  const std::string in = slurp(tmp_dir() + "/split-in-opt.ngc");
  std::printf("%s", in.c_str());
  CHECK(has(in, "\r\nG91 G1 X"));
  CHECK(has(in, "\r\nG90\r\nG1 X0.6 F"));
  CHECK_EQ(run("%/split-in-opt.ngc -q" + cut + " --heightmap %/split-in-after.pgm").code, 0);
  CHECK_EQ(run("%/split-in.ngc -q" + cut + " --heightmap %/split-in-before.pgm").code, 0);
  CHECK_EQ(file_hash(tmp_dir() + "/split-in-after.pgm"), file_hash(tmp_dir() + "/split-in-before.pgm"));
  // The options are --target's, and checked.
  CHECK_EQ(run_command("optimize %/split.ngc" + cut + " --split-min 2").code, 2);
  CHECK_EQ(run_command("optimize %/split.ngc" + cut + " --target chip-load --split-min 0").code, 2);
  CHECK_EQ(run_command("optimize %/split.ngc" + cut + " --target chip-load --split-lines -1").code, 2);
  CHECK_EQ(run_command("optimize %/split.ngc" + cut + " --target chip-load --fail-on-load").code, 2);  // run's
}
