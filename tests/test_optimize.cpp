// `dexmill optimize` (feed optimisation) on programs the test
// writes: the output differs from the input only in F words on the lines
// expected, cuts the identical grid when the engine re-simulates it with
// the job `dexmill run` would make (tests/sim_util.h), and breaks no feed
// limit; a program within the
// limits comes back byte for byte; moves in air and in a faster material
// keep their feed; inch programs, canned cycles, G93, block delete and CRLF
// files; usage and input errors. Then the pieces in-process: the F number
// (tools/cam/feed_word.h), the per-line rule and the splice (tools/cam/feed_rewrite.h).
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/safety/material_limits.h"
#include "core/math/decimal.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"
#include "tools/cam/feed_rewrite.h"
#include "tools/cam/feed_word.h"

namespace {

using namespace run_cli;
using dexmill::cli::FeedEdit;
using dexmill::cli::FeedLine;
using dexmill::cli::FeedRewriter;

const char* kSandwich =
    "material alu plain max_feed=1200 spindle=8000..24000\n"
    "material wood wood max_feed=3000 coolant=no\n"
    "layer -20 -10 alu\n"
    "layer -10 0 wood\n";

const char* kStock = " --stock 0,0,-20,40,40,0 --pitch 0.25 --tool flat:6 -q";

int feed_warnings(const std::string& s) {
  int n = 0;
  for (size_t at = s.find("warning: feed"); at != std::string::npos; at = s.find("warning: feed", at + 1)) ++n;
  return n;
}

// The cut of a program with kStock's stock, pitch and tool and the
// material (`dexmill run` with those options), on the engine.
struct Cut {
  sim_test::Run run;
  bool ok = false;
  Cut(const std::string& program, const std::string& material, bool inch) {
    run.stock("0,0,-20,40,40,0").pitch("0.25").tool("flat:6").material(material);
    if (inch) run.inch();
    ok = run.program(program);
  }
  // The feed rule's violations (the warnings "warning: feed ...").
  size_t feed_violations() { return ok ? run.violations(dexmill::ProcessRule::kFeed).size() : SIZE_MAX; }
};

// Optimizes `name` (written with `text`) with kStock, the material and the
// units; the output is written beside it as opt-NAME. Then both are cut
// with the same job: the grids must be the same, and the output must break
// no feed limit. Returns the optimize run (its out is the program).
Result optimize_and_recut(const char* name, const char* text, const std::string& material, bool inch = false) {
  const std::string in = write_tmp(name, text);
  const Result r = run_command("optimize " + in + kStock + (inch ? " --units inch" : "") + " --material " + material);
  CHECK_EQ(r.code, 0);
  const std::string out = write_tmp((std::string("opt-") + name).c_str(), r.out.c_str());
  Cut a(in, material, inch), b(out, material, inch);
  CHECK(a.ok && b.ok);
  if (!a.ok || !b.ok) return r;
  CHECK(a.run.sim().state() == dexmill::SimState::kDone);
  CHECK(b.run.sim().state() == dexmill::SimState::kDone);
  CHECK_GT(a.run.sim().removed_lsb(), uint64_t{0});
  CHECK_EQ(a.run.grid_hash(), b.run.grid_hash());
  CHECK_EQ(b.feed_violations(), size_t{0});
  return r;
}

}  // namespace

TEST(optimize_lowers_the_one_line_over_a_limit) {
  if (skip()) return;
  const std::string mat = write_tmp("opt-sandwich.txt", kSandwich);
  // Line 6 runs 2000 mm/min through both layers (over alu's 1200); line 7
  // goes on in air past the block, line 11 at 2000 in the wood alone.
  const char* prog =
      "G21 G90\nM3 S12000\nG0 Z5\nG0 X-5 Y10\nG1 Z-15 F300\nG1 X45 F2000 ; through both\nG1 Y14\nG0 Z5\n"
      "G0 X-5 Y25\nG1 Z-4 F300\nG1 X45 F2000\nG0 Z5\nM2\n";
  Cut before(write_tmp("opt-one.ngc", prog), mat, false);
  CHECK_EQ(before.feed_violations(), size_t{1});
  const std::vector<dexmill::ProcessViolation> v = before.run.violations(dexmill::ProcessRule::kFeed);
  if (v.size() == 1) {
    CHECK_EQ(v[0].line, 6u);
    CHECK(has(before.run.message(v[0]), "feed 2000 mm/min over alu's limit 1200 mm/min"));
  }
  const Result r = optimize_and_recut("opt-one.ngc", prog, mat);
  // Only F words: line 6 changed, line 7 given the programmed feed back
  // (the air move keeps its 2000), the wood-only line 11 as written.
  CHECK_EQ(r.out, std::string("G21 G90\nM3 S12000\nG0 Z5\nG0 X-5 Y10\nG1 Z-15 F300\nG1 X45 F1200 ; through both\n"
                              "G1 Y14 F2000\nG0 Z5\nG0 X-5 Y25\nG1 Z-4 F300\nG1 X45 F2000\nG0 Z5\nM2\n"));
  CHECK(has(r.err, "2 line(s) changed: 1 feed(s) lowered (1 to 1200 mm/min), 1 programmed feed(s) restored"));
  CHECK(has(r.err, "estimated time 0:"));
  CHECK(has(r.err, " after (+"));
  CHECK_EQ(feed_warnings(r.err), 0);  // the input's warnings are not repeated
  // The output again: nothing left to do, byte for byte.
  const Result again = run_command("optimize " + tmp_dir() + "/opt-opt-one.ngc" + kStock + " --material " + mat);
  CHECK(again.code == 0 && again.out == r.out);
}

TEST(optimize_keeps_a_program_within_limits_byte_for_byte) {
  if (skip()) return;
  const std::string mat = write_tmp("opt-sandwich.txt", kSandwich);
  // CRLF, a % line, N numbers, comments, odd spacing, no final line end;
  // feeds within the limits, and 9000 mm/min in the air above the block.
  const char* prog =
      "%\r\nN10 G21 G90 (metric)\r\nN20 M3 S12000\r\nN30 G0 X-5 Y10 Z5\r\nN40 G1  Z-15 F300 ;plunge\r\n"
      "N50 G1 X45 F1000\r\nN60 G1 Z10 F9000\r\nN70 G1 X-5\r\nN80 G0 Z5\r\n%";
  const Result r = optimize_and_recut("opt-calm.ngc", prog, mat);
  CHECK(r.out == prog);
  CHECK(has(r.err, "0 line(s) changed"));
  CHECK(has(r.err, "(+0.0%)"));
}

TEST(optimize_two_materials_and_crlf) {
  if (skip()) return;
  // wood-on-aluminium on a 20 mm block: beech (3000 mm/min) above Z-10,
  // 6061 (1500) below. Line 4 at 4000 in the wood alone goes to 3000; line
  // 6 at 2000 into the aluminium to 1500; line 8, at line 7's 2500 in the
  // wood, keeps it; the arc of line 12 (a half circle up into the block at
  // Z-15) goes to 1500. CRLF line ends stay.
  const char* prog =
      "G21 G90 M3 S12000\r\nG0 X-5 Y10 Z5\r\nG1 Z-5 F300\r\nG1 X45 F4000\r\nG1 Y20 Z-15 F300\r\nG1 X-5 F2000\r\n"
      "G1 Y30 Z-5 F2500\r\nG1 X45\r\nG0 Z5\r\nG0 X5 Y-5\r\nG1 Z-15 F300\r\nG2 X35 Y-5 I15 J0 F2000\r\nG0 Z5\r\n"
      "M2\r\n";
  const Result r = optimize_and_recut("opt-two.ngc", prog, "wood-on-aluminium");
  CHECK_EQ(r.out, std::string("G21 G90 M3 S12000\r\nG0 X-5 Y10 Z5\r\nG1 Z-5 F300\r\nG1 X45 F3000\r\nG1 Y20 Z-15 F300\r\n"
                              "G1 X-5 F1500\r\nG1 Y30 Z-5 F2500\r\nG1 X45\r\nG0 Z5\r\nG0 X5 Y-5\r\nG1 Z-15 F300\r\n"
                              "G2 X35 Y-5 I15 J0 F1500\r\nG0 Z5\r\nM2\r\n"));
  CHECK(has(r.err, "3 feed(s) lowered (1 to 3000 mm/min, 2 to 1500 mm/min)"));
}

TEST(optimize_inch_programs) {
  if (skip()) return;
  const std::string mat = write_tmp("opt-sandwich.txt", kSandwich);
  // 80 in/min (2032 mm/min) through both layers: alu's 1200 mm/min is
  // 47.2440944 in/min, written 47.244 (rounded down; 1199.9976 mm/min). A
  // compact lower-case line keeps its style; the air move after it gets 80
  // back.
  const char* prog =
      "G20 G90\nM3 S12000\nG0 X-0.2 Y0.4 Z0.2\nG1 Z-0.6 F12\ng1x1.8f80(cut)\nG1 Y0.55\nG0 Z0.2\nM2\n";
  const Result r = optimize_and_recut("opt-inch.ngc", prog, mat);
  CHECK_EQ(r.out, std::string("G20 G90\nM3 S12000\nG0 X-0.2 Y0.4 Z0.2\nG1 Z-0.6 F12\ng1x1.8f47.244(cut)\nG1 Y0.55 F80\n"
                              "G0 Z0.2\nM2\n"));
  // Programs with no G20 under --units inch: the same.
  const char* bare = "G90\nM3 S12000\nG0 X-0.2 Y0.4 Z0.2\nG1 Z-0.6 F12\nG1 X1.8 F80\nG0 Z0.2\nM2\n";
  const Result u = optimize_and_recut("opt-bare.ngc", bare, mat, true);
  CHECK(has(u.out, "G1 X1.8 F47.244\n"));
}

TEST(optimize_canned_cycles_g93_and_block_delete) {
  if (skip()) return;
  // Wood (3000) with an aluminium box (1200) under X25..40 from Z-3 down.
  const std::string mat = write_tmp("opt-insert.txt",
                                    "material wood wood max_feed=3000 coolant=no\nmaterial alu plain max_feed=1200\n"
                                    "box 25,0,-20,40,40,-3 alu\ndefault wood\n");
  // Line 4 drills three holes 10 mm apart (G91 L3): only the last reaches
  // the aluminium, and the line's one F goes to its limit; line 6's hole,
  // in the wood, keeps its feed. Line 10 (G93) runs 50 mm at F100 (5000
  // mm/min): F24 gives 1200. Line 14 (`/`) is lowered, and line 15, back
  // through both at the same limit, writes its own F (an operator may skip
  // line 14).
  const char* prog =
      "G21 G90\nM3 S12000\nG0 X5 Y20 Z5\nG91 G81 X10 Z-10 R-3 L3 F2000\nG90\nG81 X10 Y30 Z-5 R2 F2000\nG80\n"
      "G0 X-5 Y5 Z5\nG1 Z-6 F500\nG93 G1 X45 F100\nG94 G0 Z5\nG0 X-5 Y12\nG1 Z-6 F500\n/G1 X45 F2000\nG1 X-5 Y16\n"
      "G0 Z5\nM2\n";
  const Result r = optimize_and_recut("opt-cycle.ngc", prog, mat);
  CHECK_EQ(r.out, std::string("G21 G90\nM3 S12000\nG0 X5 Y20 Z5\nG91 G81 X10 Z-10 R-3 L3 F1200\nG90\n"
                              "G81 X10 Y30 Z-5 R2 F2000\nG80\nG0 X-5 Y5 Z5\nG1 Z-6 F500\nG93 G1 X45 F24\nG94 G0 Z5\n"
                              "G0 X-5 Y12\nG1 Z-6 F500\n/G1 X45 F1200\nG1 X-5 Y16 F1200\nG0 Z5\nM2\n"));
}

TEST(optimize_usage_and_input_errors) {
  if (skip()) return;
  const std::string p = write_tmp("opt-err.ngc", "G21\nG0 X-5 Y5 Z5\nG1 Z-5 F300\nG1 X45 F2000\nM2\n");
  Result r = run_command("optimize " + p + kStock);
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "optimize needs --material"));
  CHECK_EQ(run_command("optimize" + std::string(kStock) + " --material wood").code, 2);
  CHECK_EQ(run_command("optimize " + p + kStock + " --material wood --image x.png").code, 2);
  CHECK_EQ(run_command("optimize " + p + kStock + " --material nosuch").code, 2);
  CHECK_EQ(run_command("optimize " + tmp_dir() + "/none.ngc" + kStock + " --material wood").code, 3);
  r = run_command("optimize --help");
  CHECK(r.code == 0 && has(r.out, "usage: dexmill optimize"));
  // A bad program: its error, exit 1, nothing on standard output.
  const std::string bad = write_tmp("opt-bad.ngc", "G21\nG0 X-5 Y5 Z5\nG1 Z-5 F300\nG1 X45 Q7 G999\nM2\n");
  r = run_command("optimize " + bad + kStock + " --material wood");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "opt-bad.ngc:4:"));
  CHECK(r.out.empty());
  // A bad material file: its FILE:LINE:COL error, exit 1.
  const std::string mat = write_tmp("opt-badmat.txt", "material a plain\nlayer -5 0 b\n");
  r = run_command("optimize " + p + kStock + " --material " + mat);
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "opt-badmat.txt:2:12: error:"));
  // `> FILE` onto the program itself is refused (the shell emptied it
  // already); -o FILE rewrites it in place.
  const std::string victim = write_tmp("opt-victim.ngc", "G21\nG0 X-5 Y5 Z5\nG1 Z-5 F300\nG1 X45 F2000\nM2\n");
  const int st = std::system(("'" + std::string(t::dexmill_binary()) + "' optimize " + victim + kStock +
                              " --material aluminium >" + victim + " 2>" + tmp_dir() + "/victim.err").c_str());
  CHECK(WIFEXITED(st) && WEXITSTATUS(st) == 2);
  CHECK(has(slurp(tmp_dir() + "/victim.err"), "which the shell has emptied already"));
  r = run_command("optimize " + p + kStock + " --material aluminium -o " + p);
  CHECK_EQ(r.code, 0);
  CHECK_EQ(slurp(p), std::string("G21\nG0 X-5 Y5 Z5\nG1 Z-5 F300\nG1 X45 F1500\nM2\n"));
  // Standard input.
  r = run_command("optimize -" + std::string(kStock) + " --material aluminium", bad.c_str());
  CHECK(has(r.err, "<stdin>:4:"));
}

// The F number: the fewest decimals that read back exactly, else rounded
// down at the decimals allowed; never above the feed asked for.
TEST(optimize_feed_number) {
  using dexmill::cli::feed_number;
  const int64_t mm = 1000000;
  CHECK_EQ(feed_number(1200 * mm, false, 3).text, std::string("1200"));
  CHECK_EQ(feed_number(1234567890, false, 3).text, std::string("1234.567"));
  CHECK_EQ(feed_number(1234567890, false, 6).text, std::string("1234.56789"));
  CHECK_EQ(feed_number(1200 * mm, true, 4).text, std::string("47.244"));
  CHECK_EQ(feed_number(1200 * mm, true, 4).nm_per_min, 1199997600);
  CHECK_EQ(feed_number(80 * 25400000LL, true, 6).text, std::string("80"));
  CHECK_EQ(feed_number(0, false, 3).text, std::string("0"));
  // Over a range of feeds: what the reader makes of the text is the number's
  // value, at most the feed, and within a step of the last decimal below it.
  for (int64_t f = 1; f < 30000 * mm; f = f * 7 / 5 + 12345) {
    for (bool inch : {false, true}) {
      const dexmill::cli::FeedNumber n = feed_number(f, inch, inch ? 4 : 3);
      dexmill::Decimal d;
      size_t pos = 0;
      CHECK(dexmill::decimal_parse(n.text.data(), n.text.size(), &pos, &d) == dexmill::DecimalParse::kOk);
      CHECK_EQ(dexmill::decimal_to_nm(d, inch), n.nm_per_min);
      CHECK_LE(n.nm_per_min, f);
      CHECK_GT(n.nm_per_min + (inch ? 2540 : 1000), f);
    }
  }
}

TEST(optimize_feed_rule) {
  const int64_t mm = 1000000;
  auto feeding = [&](int64_t prog, int64_t limit, bool has_f) {
    FeedLine l;
    l.feeds = true;
    l.programmed_nm_per_min = prog * mm;
    l.limit_nm_per_min = limit < 0 ? dexmill::kNoFeedLimit : limit * mm;
    l.has_f = has_f;
    l.sets_feed = has_f;
    l.feed_after_nm_per_min = prog * mm;
    return l;
  };
  FeedRewriter w;
  CHECK(w.line(feeding(2000, -1, true)).kind == FeedEdit::Kind::kNone);
  FeedEdit e = w.line(feeding(2000, 1200, false));  // lowered: F added
  CHECK(e.kind == FeedEdit::Kind::kInsert && e.number == "1200" && e.lowered);
  CHECK(w.line(feeding(2000, 1200, false)).kind == FeedEdit::Kind::kNone);  // carried
  CHECK(w.line(feeding(2000, 1500, false)).number == "1500");              // a higher limit: raised to it
  // An F on a line with no motion sets the feed: the next line needs nothing.
  FeedLine f;
  f.sets_feed = f.has_f = true;
  f.feed_after_nm_per_min = 2000 * mm;
  CHECK(w.line(f).kind == FeedEdit::Kind::kNone);
  CHECK(w.line(feeding(2000, 3000, false)).kind == FeedEdit::Kind::kNone);
  // A feed within its limit on a line with F: kept; the programmed feed
  // below the limit is never raised.
  CHECK(w.line(feeding(800, 1200, true)).kind == FeedEdit::Kind::kNone);
  CHECK(w.line(feeding(800, 1200, false)).kind == FeedEdit::Kind::kNone);
  // G93: F x limit / rate.
  FeedLine g = feeding(5000, 1200, true);
  g.inverse_time = true;
  g.inverse_f = dexmill::Decimal{1000, 1};  // F100.0
  e = w.line(g);
  CHECK(e.kind == FeedEdit::Kind::kChange && e.number == "24");
  CHECK_EQ(e.feed_nm_per_min, 1200 * mm);
}

TEST(optimize_feed_splice) {
  using dexmill::cli::feed_splice;
  auto apply = [](const char* line, FeedEdit::Kind k, const char* number) {
    FeedEdit e;
    e.kind = k;
    e.number = number;
    std::string s = line;
    const dexmill::cli::FeedSplice sp = feed_splice(s.data(), s.size(), e);
    return s.replace(sp.at, sp.erase, sp.text);
  };
  const auto ins = FeedEdit::Kind::kInsert, chg = FeedEdit::Kind::kChange;
  CHECK_EQ(apply("G1 X10 Y5", ins, "1200"), std::string("G1 X10 Y5 F1200"));
  CHECK_EQ(apply("G1X10Y5", ins, "1200"), std::string("G1X10Y5F1200"));
  CHECK_EQ(apply("g1x10y5 (cut) ; more", ins, "1200"), std::string("g1x10y5f1200 (cut) ; more"));
  CHECK_EQ(apply("N20 G1 X10;cut", ins, "1200"), std::string("N20 G1 X10 F1200;cut"));
  CHECK_EQ(apply("/ G1 X10   ", ins, "5"), std::string("/ G1 X10 F5   "));
  CHECK_EQ(apply("X10", ins, "5"), std::string("X10 F5"));
  CHECK_EQ(apply("G1 X10 F2000 Y5", chg, "1200"), std::string("G1 X10 F1200 Y5"));
  CHECK_EQ(apply("G1X10f 2 000.0Y5", chg, "1200"), std::string("G1X10f1200Y5"));
}

TEST(optimize_leaves_feeds_per_revolution_as_written) {
  if (skip()) return;
  const std::string mat = write_tmp("opt-sandwich.txt", kSandwich);
  const std::string opts = std::string(kStock) + " --material " + mat;
  // G95 F0.2 at 12000 rpm is 2400 mm/min through alu (limit 1200) and a
  // rigid tap at K1.5: no F word per minute can say either, so both stay
  // as written with a warning each, and the G94 line after is still lowered.
  const char* prog =
      "G21 G90\nM3 S12000\nG0 X-5 Y10 Z5\nG95 F0.2\nG1 Z-15\nG1 X45\nG0 Z5\nG94\nG0 X20 Y20\n"
      "G33.1 Z-12 K1.5\nG0 Y30\nG1 Z-15 F300\nG1 X-5 F2000\nG0 Z5\nM2\n";
  const Result r = run_command("optimize " + write_tmp("opt-rev.ngc", prog) + opts);
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "opt-rev.ngc:6:1: warning: feed per spindle revolution (G95, G33, G33.1) left as written: 2400 mm/min"));
  CHECK(has(r.err, "opt-rev.ngc:10:1: warning: feed per spindle revolution"));
  CHECK(has(r.out, "G95 F0.2\nG1 Z-15\nG1 X45\n"));
  CHECK(has(r.out, "G33.1 Z-12 K1.5\n"));
  CHECK(has(r.out, "G1 X-5 F1200\n"));
}
