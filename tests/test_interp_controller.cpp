// What programs written for a real controller expect of it: G38.x probe
// moves, G7/G8, feeds and speeds above 1e6, a default feed, machine M codes
// (M25), and typos in the middle of a line; each against rs274 (LinuxCNC 2.9)
// where it has an answer, with the right warnings and no false alarms.
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "core/canon/summary.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"

using namespace dexmill;
using t::mm;

namespace {

GcodeError run(const char* program, t::Recorder* rec, GcodeDiag* d, t::Warnings* w = nullptr,
               int64_t default_feed = 0) {
  InterpOptions opt;
  opt.warnings = w;
  opt.default_feed_nm_per_min = default_feed;
  Interp in(rec, opt);
  return t::run_program(&in, program, d);
}

size_t count(const t::Warnings& w, GcodeError e) {
  size_t n = 0;
  for (const GcodeDiag& d : w.list) n += d.code == e;
  return n;
}

}  // namespace

TEST(controller_probe_moves) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // STRAIGHT_PROBE to the target at F (rs274); G38.x is modal like G1.
  CHECK_EQ(run("G21 F100\nG0 Z5\nG38.2 Z-1 F50\nX3\nG38.3 X0\nG38.4 Y2\nG38.5 Z0", &rec, &d, &w), GcodeError::kOk);
  const CanonRecord& p = rec.records[1];
  CHECK_EQ(p.kind, CanonKind::kFeed);
  CHECK(p.end == (PointNm{0, 0, mm(-1)}));
  CHECK_EQ(p.feed_nm_per_min, mm(50));
  CHECK(rec.records[2].end == (PointNm{mm(3), 0, mm(-1)}));
  CHECK_EQ(rec.count(CanonKind::kFeed), 5u);
  // One note for the program, at the first probe.
  CHECK_EQ(w.list.size(), 1u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnProbe);
  CHECK_EQ(w.list[0].line, 3u);
  // LinuxCNC's errors: no axis, no feed (G93 leaves none), no distance.
  CHECK_EQ(run("G21 F100\nG38.2 F10", &rec, &d), GcodeError::kProbeNoAxis);
  CHECK_EQ(run("G21\nG38.2 Z-5", &rec, &d), GcodeError::kFeedZero);
  CHECK_EQ(run("G21 G93\nG38.2 Z-5 F1", &rec, &d), GcodeError::kFeedZero);
  CHECK_EQ(run("G21 F10\nG38.2 X0", &rec, &d), GcodeError::kProbeTooClose);
  // LinuxCNC's convert_probe: not with cutter radius compensation on.
  CHECK_EQ(run("G21 F10\nG41.1 D2\nG0 X5\nG38.2 Z-5", &rec, &d), GcodeError::kCompForbidden);
  CHECK_EQ(d.line, 4u);
  CHECK_EQ(run("G21 F10\nG41.1 D2\nG0 X5\nG40\nG0 X8\nG38.2 Z-5", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F10\nG38.2 Z-0.00001", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F10\nG38.2 Z-5 R1", &rec, &d), GcodeError::kWordUnused);
}

TEST(controller_g7_halves_x_as_linuxcnc_does) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // rs274: in G7 every X word is a diameter, on a mill too (G0, G91, G53,
  // G10, cycles, probes); I and R are not. G8 ends it.
  CHECK_EQ(run("G21 F10\nG7 G0 X10 Y4\nG91 X2\nG90 G53 G0 X10\nG81 X4 Z-1 R1\nG80\nG8 G0 X10\nG7\nG8", &rec, &d, &w),
           GcodeError::kOk);
  CHECK_EQ(rec.records[0].end.x_nm, mm(5));
  CHECK_EQ(rec.records[1].end.x_nm, mm(6));
  CHECK_EQ(rec.records[2].end.x_nm, mm(5));
  CHECK_EQ(rec.records[4].end.x_nm, mm(2));  // [3] rises to R
  CHECK_EQ(rec.records.back().end.x_nm, mm(10));
  CHECK_EQ(w.list.size(), 1u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnDiameterMode);
  // G8 alone, and G7 G8 in one block (one modal group).
  CHECK_EQ(run("G21\nG8\nG0 X10", &rec, &d, &w), GcodeError::kOk);
  CHECK_EQ(rec.records.back().end.x_nm, mm(10));
  CHECK_EQ(run("G21\nG7 G8", &rec, &d), GcodeError::kModalGroupConflict);
}

TEST(controller_fast_feeds_and_speeds) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // rs274 takes F2000000 and S3000000; dexmill too, with one warning each.
  CHECK_EQ(run("G21\nF2000000 S3000000 M3\nG1 X20\nF3000000\nG1 X40 S4000000\nF100\nG1 X41", &rec, &d, &w),
           GcodeError::kOk);
  CHECK_EQ(count(w, GcodeError::kWarnFastFeed), 1u);
  CHECK_EQ(count(w, GcodeError::kWarnFastSpindle), 1u);
  CHECK_EQ(w.list.size(), 2u);
  // No warning at 1e6 itself, nor in inch up to 1e6 mm/min.
  t::Warnings w2;
  CHECK_EQ(run("G21 F1000000 S1000000 M3\nG1 X1\nG20\nF39000\nG1 X1", &rec, &d, &w2), GcodeError::kOk);
  CHECK_EQ(w2.list.size(), 0u);
  // The time estimate counts a feed at most at 1e6 mm/min: 20 mm at 2e6
  // take as long as at 1e6, 1.2 ms.
  MotionSummary s;
  Interp in(&s, InterpOptions{});
  CHECK_EQ(t::run_program(&in, "G21 F2000000\nG1 X20", &d), GcodeError::kOk);
  CHECK_EQ(s.feed_time_us(), 1200);
}

TEST(controller_default_feed) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // Without it, LinuxCNC's error; with it, the move at the default, one
  // warning at the first such move, the feed then modal until F or G94.
  CHECK_EQ(run("G21\nG0 X1\nG1 X2", &rec, &d), GcodeError::kFeedZero);
  CHECK_EQ(run("G21\nG0 X1\nG1 X2\nG2 X4 I1\nF300\nG1 X5\nG94\nG1 X6\nG81 X7 Z-1 R1", &rec, &d, &w, mm(1200)),
           GcodeError::kOk);
  CHECK_EQ(w.list.size(), 1u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnDefaultFeed);
  CHECK_EQ(w.list[0].line, 3u);
  CHECK_EQ(w.list[0].a_nm, mm(1200));
  std::vector<int64_t> feeds;
  for (const CanonRecord& r : rec.records)
    if (r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc) feeds.push_back(r.feed_nm_per_min);
  CHECK_EQ(feeds.size(), 5u);
  CHECK_EQ(feeds[0], mm(1200));
  CHECK_EQ(feeds[1], mm(1200));
  CHECK_EQ(feeds[2], mm(300));
  CHECK_EQ(feeds[3], mm(1200));  // G94 cleared F (as in LinuxCNC): the default again
  // A program that sets F before cutting never hears of it.
  t::Warnings w2;
  CHECK_EQ(run("G21 F500\nG1 X2", &rec, &d, &w2, mm(1200)), GcodeError::kOk);
  CHECK_EQ(w2.list.size(), 0u);
  CHECK_EQ(rec.records.back().feed_nm_per_min, mm(500));
  // G93 still needs F on every move.
  CHECK_EQ(run("G21 G93\nG1 X2", &rec, &d, nullptr, mm(1200)), GcodeError::kInverseTimeNoF);
}

TEST(controller_machine_m_codes) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // Centroid's M25 and other M codes LinuxCNC leaves to a remap: skipped
  // with a warning; M100-M199 keep theirs; M200 and up are errors as in
  // LinuxCNC ("M-code greater than 199"); M98/M99 are no accessories.
  CHECK_EQ(run("G21\nM25\nM10 G0 X1\nM101 P1\nM2", &rec, &d, &w), GcodeError::kOk);
  CHECK_EQ(w.list.size(), 3u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnMcodeMachine);
  CHECK_EQ(std::string(w.list[0].word), std::string("M25"));
  CHECK_EQ(w.list[2].code, GcodeError::kWarnMcodeIgnored);
  CHECK_EQ(rec.count(CanonKind::kTraverse), 1u);
  CHECK_EQ(run("G21\nM250", &rec, &d), GcodeError::kUnknownMcode);
  CHECK_EQ(run("G21\nM98", &rec, &d), GcodeError::kUnknownMcode);
  CHECK_EQ(run("G21\nM25 M26", &rec, &d), GcodeError::kModalGroupConflict);
}

TEST(controller_stray_letters_are_typos) {
  t::Recorder rec;
  GcodeDiag d;
  // A stray O inside a line is a typo (rs274: "Bad character 'o' used"), not
  // an o-word; at the start of a line it is one.
  for (const char* p : {"G21\nG1 X1 Y1O F100", "G21\nG0 X1 Y1O0 Z2", "G21\nG0 X1 Y1 Z2 O100"}) {
    CHECK_EQ(run(p, &rec, &d), GcodeError::kMisplacedOword);
  }
  CHECK_EQ(run("G21\nO100 sub", &rec, &d), GcodeError::kUnsupportedOword);
  CHECK_EQ(run("G21\nG1 X1 YO1", &rec, &d), GcodeError::kMissingNumber);
}

TEST(controller_g49_with_h_is_centroid_style) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // Centroid's posts end with `G49 H0`: LinuxCNC refuses the H; its meaning
  // is plain (G49 cancels the offset whatever H says), so it is a warning,
  // once, and the tool length offset is off after it.
  CHECK_EQ(run("G21\nT1 M6\nG43 H1\nG0 Z5\nG49 H0\nG0 Z6\nG49 H3\nM2", &rec, &d, &w), GcodeError::kOk);
  CHECK_EQ(count(w, GcodeError::kWarnG49H), 1u);
  CHECK_EQ(w.list.size(), 1u);
  CHECK_EQ(w.list[0].line, 5u);
  CHECK_EQ(w.list[0].col, 5);
  CHECK_EQ(rec.records.back().tool_length_offset_nm, 0);
  // No false pass: H with no G43 nor G49 is still LinuxCNC's error.
  CHECK_EQ(run("G21\nG0 X1 H0", &rec, &d), GcodeError::kWordUnused);
  CHECK_EQ(run("G21\nH2", &rec, &d), GcodeError::kWordUnused);
}

TEST(controller_g33_feeds_at_pitch_times_speed) {
  t::Recorder rec;
  GcodeDiag d;
  // G33.1: in and out at K * S (1.25 mm * 400 rpm = 500 mm/min), ending where
  // it began; G33 one feed at K * S; the modal F (100) untouched by either.
  CHECK_EQ(run("G21 F100 S400 M3\nG0 X1 Y2 Z5\nG33.1 Z-3 K1.25\nG1 X2\nG33 X3 K0.5\nG1 X4\nM2", &rec, &d),
           GcodeError::kOk);
  std::vector<CanonRecord> feeds;
  for (const CanonRecord& r : rec.records)
    if (r.kind == CanonKind::kFeed) feeds.push_back(r);
  CHECK_EQ(feeds.size(), 5u);
  CHECK_EQ(feeds[0].feed_nm_per_min, mm(500));
  CHECK_EQ(feeds[0].end.z_nm, mm(-3));
  CHECK_EQ(feeds[1].feed_nm_per_min, mm(500));
  CHECK_EQ(feeds[1].start.z_nm, mm(-3));
  CHECK_EQ(feeds[1].end.z_nm, mm(5));
  CHECK_EQ(feeds[2].feed_nm_per_min, mm(100));
  CHECK_EQ(feeds[2].start.x_nm, mm(1));
  CHECK_EQ(feeds[3].feed_nm_per_min, mm(200));
  CHECK_EQ(feeds[4].feed_nm_per_min, mm(100));
  // A pitch and speed whose product passes int64 saturates (no wrap) and
  // warns as a fast feed does.
  t::Warnings w;
  CHECK_EQ(run("G21 S1000000000 M3\nG33.1 Z-3 K9000\nM2", &rec, &d, &w), GcodeError::kOk);
  CHECK_EQ(count(w, GcodeError::kWarnFastFeed), 1u);
  CHECK(rec.records.size() > 2 && rec.records[rec.records.size() - 2].feed_nm_per_min > 0);
}

TEST(controller_g95_feeds_per_revolution) {
  t::Recorder rec;
  GcodeDiag d;
  // F per revolution times the speed in force at each move; G94 and G95
  // clear F as LinuxCNC does; inch per revolution under G20.
  CHECK_EQ(run("G21 S1000 M3\nG95 F0.1\nG1 X10\nS500\nG2 X20 R5\nG94 F100\nG1 X30\nG20 G95 F0.002\nG1 X1.5\nM2",
               &rec, &d),
           GcodeError::kOk);
  std::vector<int64_t> rates;
  for (const CanonRecord& r : rec.records)
    if (r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc) rates.push_back(r.feed_nm_per_min);
  CHECK_EQ(rates.size(), 4u);
  CHECK_EQ(rates[0], mm(100));
  CHECK_EQ(rates[1], mm(50));
  CHECK_EQ(rates[2], mm(100));
  CHECK_EQ(rates[3], 50800 * 500);  // 0.002 in = 50 800 nm a revolution, at 500 rpm
  // LinuxCNC's errors: no F after G95 (it clears F), S0, and no stand-in
  // default feed for a feed per revolution.
  CHECK_EQ(run("G21 S1000 M3 F100\nG95\nG1 X10", &rec, &d), GcodeError::kFeedZero);
  CHECK_EQ(run("G21 M3\nG95 F0.1\nG1 X10", &rec, &d), GcodeError::kFeedPerRevNoSpeed);
  CHECK_EQ(d.line, 3u);
  CHECK_EQ(run("G21 S1000 M3\nG95\nG1 X10", &rec, &d, nullptr, mm(1000)), GcodeError::kFeedZero);
  // No false alarm: G95 with S and F reads, without the default feed.
  CHECK_EQ(run("G21 S1 M3\nG95 F1\nG1 X10\nM2", &rec, &d), GcodeError::kOk);
}
