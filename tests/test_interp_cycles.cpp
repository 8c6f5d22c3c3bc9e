// The canned cycles LinuxCNC has beyond the drilling ones (G74, G84, G86,
// G87, G88), what they do to the spindle, where they leave the tool, and the
// retract level when the offsets change in a series: each against what
// LinuxCNC 2.9's rs274 prints for the same program (the moves are also in
// tests/gcode/paths/, checked by tools/scripts/oracle-check.sh --rs274).
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"

using namespace dexmill;
using t::mm;

namespace {

GcodeError run(const char* program, t::Recorder* rec, GcodeDiag* d, t::Warnings* w = nullptr) {
  InterpOptions opt;
  opt.warnings = w;
  Interp in(rec, opt);
  return t::run_program(&in, program, d);
}

// The records from line `line` on, as text: "T x y z" (traverse), "F x y z"
// (feed), "D ms", "S rpm", "P" (pause), in mm.
std::string trace(const t::Recorder& rec, uint32_t line) {
  std::string s;
  char buf[96];
  for (const CanonRecord& r : rec.records) {
    if (r.line < line) continue;
    switch (r.kind) {
      case CanonKind::kTraverse:
      case CanonKind::kFeed:
        std::snprintf(buf, sizeof buf, "%c %g %g %g|", r.kind == CanonKind::kFeed ? 'F' : 'T', r.end.x_nm / 1e6,
                      r.end.y_nm / 1e6, r.end.z_nm / 1e6);
        break;
      case CanonKind::kDwell: std::snprintf(buf, sizeof buf, "D %d|", static_cast<int>(r.dwell_ms)); break;
      case CanonKind::kSpindle: std::snprintf(buf, sizeof buf, "S %d|", r.spindle_rpm); break;
      case CanonKind::kPause: std::snprintf(buf, sizeof buf, "P|"); break;
      default: buf[0] = 0; break;
    }
    s += buf;
  }
  return s;
}

}  // namespace

TEST(cycles_g84_taps_and_restores_the_spindle) {
  t::Recorder rec;
  GcodeDiag d;
  // rs274: feed down, STOP, START_CCW, DWELL(0.7), feed out to the G98
  // level, STOP, START_CW; the next block reuses P.
  CHECK_EQ(run("G21 F100 S500 M3\nG0 Z10\nG98 G84 X1 Y1 Z-2 R1 P0.7\nX2", &rec, &d), GcodeError::kOk);
  CHECK_EQ(trace(rec, 3),
           std::string("T 1 1 10|T 1 1 1|F 1 1 -2|S 0|S -500|D 700|F 1 1 10|S 0|S 500|"
                       "T 2 1 10|T 2 1 1|F 2 1 -2|S 0|S -500|D 700|F 2 1 10|S 0|S 500|"));
  // The feeds are made with the spindle reversed.
  for (const CanonRecord& r : rec.records)
    if (r.kind == CanonKind::kFeed && r.end.z_nm == mm(10)) CHECK_EQ(r.spindle_rpm, -500);
  // G74 is the mirror image with M4; P is 0 until one is given.
  t::Recorder rec74;
  CHECK_EQ(run("G21 F100 S500 M4\nG0 Z10\nG99 G74 X1 Y1 Z-2 R1", &rec74, &d), GcodeError::kOk);
  CHECK_EQ(trace(rec74, 3), std::string("T 1 1 10|T 1 1 1|F 1 1 -2|S 0|S 500|D 0|F 1 1 1|S 0|S -500|"));
}

TEST(cycles_spindle_errors) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 F100 S500\nG84 X1 Z-2 R1", &rec, &d), GcodeError::kCycleSpindleStopped);
  CHECK_EQ(run("G21 F100 S500 M4\nG84 X1 Z-2 R1", &rec, &d), GcodeError::kCycleSpindleWrongWay);
  CHECK_EQ(run("G21 F100 S500 M3\nG74 X1 Z-2 R1", &rec, &d), GcodeError::kCycleSpindleWrongWay);
  CHECK_EQ(std::string(d.word), std::string("G74"));
  for (const char* c : {"G86 X1 Z-2 R1 P1", "G87 X1 Z-2 R1 I1 J1 K-1", "G88 X1 Z-2 R1 P1"}) {
    CHECK_EQ(run((std::string("G21 F100 S500 M5\n") + c).c_str(), &rec, &d), GcodeError::kCycleSpindleStopped);
    // Either way round is fine for boring.
    CHECK_EQ(run((std::string("G21 F100 S500 M4\n") + c).c_str(), &rec, &d), GcodeError::kOk);
  }
  // A failed cycle changes nothing: the spindle and position stay.
  Interp in(&rec, InterpOptions{});
  CHECK_EQ(t::run_program(&in, "G21 F100 S500 M4\nG0 Z5", &d), GcodeError::kOk);
  const InterpState before = in.state();
  CHECK_EQ(in.execute_line("G84 X1 Z-2 R1", 13, 3, &d), GcodeError::kCycleSpindleWrongWay);
  CHECK(in.state().pos == before.pos);
  CHECK_EQ(in.state().motion, before.motion);
  CHECK_EQ(in.state().spindle_dir, -1);
}

TEST(cycles_p_words) {
  t::Recorder rec;
  GcodeDiag d;
  // G86 and G88 need P when they start (LinuxCNC: "Dwell time p word missing").
  CHECK_EQ(run("G21 F100 S500 M3\nG86 X1 Z-2 R1", &rec, &d), GcodeError::kCycleNoP);
  CHECK_EQ(run("G21 F100 S500 M3\nG86 X1 Z-2 R1 P0.5\nG88 X2 Z-2 R1", &rec, &d), GcodeError::kCycleNoP);
  // G84 takes the last P of any cycle (rs274: G82 P1.5 then G84 dwells 1.5 s).
  t::Recorder r2;
  CHECK_EQ(run("G21 F100 S500 M3\nG82 X1 Z-2 R1 P1.5\nG80\nG84 X2 Z-2 R1", &r2, &d), GcodeError::kOk);
  CHECK_EQ(r2.records.back().kind, CanonKind::kSpindle);
  bool dwell = false;
  for (const CanonRecord& r : r2.records)
    if (r.line == 4 && r.kind == CanonKind::kDwell) dwell = r.dwell_ms == 1500;
  CHECK(dwell);
  // A P with a cycle that dwells not is still an unused word.
  CHECK_EQ(run("G21 F100\nG81 X1 Z-2 R1 P1", &rec, &d), GcodeError::kWordUnused);
}

TEST(cycles_g86_stops_the_spindle_for_the_rapid_out) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 F100 S500 M3\nG0 Z10\nG98 G86 X15 Y5 Z-2 R2 P0.5", &rec, &d), GcodeError::kOk);
  CHECK_EQ(trace(rec, 3), std::string("T 15 5 10|T 15 5 2|F 15 5 -2|D 500|S 0|T 15 5 10|S 500|"));
}

TEST(cycles_g87_back_bores) {
  t::Recorder rec;
  GcodeDiag d;
  // rs274, G17: over to the offset at R, spindle stopped, down under the
  // part, over to the axis, start, feed up to K and back, out the same way.
  CHECK_EQ(run("G21 F100 S500 M3\nG0 Z10\nG98 G87 X20 Y5 Z-5 R2 I1 J0.5 K-3\nX22", &rec, &d), GcodeError::kOk);
  const std::string hole20 = "T 20 5 10|T 20 5 2|T 21 5.5 2|S 0|T 21 5.5 -5|T 20 5 -5|S 500|F 20 5 -3|F 20 5 -5|S 0|"
                             "T 21 5.5 -5|T 21 5.5 10|T 20 5 10|S 500|";
  CHECK_EQ(trace(rec, 3).substr(0, hole20.size()), hole20);
  // I, J, K are sticky: the second hole has the same offset.
  CHECK_EQ(trace(rec, 4).substr(0, 27), std::string("T 22 5 10|T 22 5 2|T 23 5.5"));
  // G18: I and K offset in X and Z, J is the top (rs274).
  t::Recorder r18;
  CHECK_EQ(run("G21 F100 S500 M4\nG18 G0 Y10\nG98 G87 X1 Z2 Y-3 R1 I0.5 J-2 K0.3", &r18, &d), GcodeError::kOk);
  CHECK_EQ(trace(r18, 3).substr(0, 65), std::string("T 1 10 2|T 1 1 2|T 1.5 1 2.3|S 0|T 1.5 -3 2.3|T 1 -3 2|S -500|F 1"));
  // G91: K counts from the bottom.
  t::Recorder r91;
  CHECK_EQ(run("G21 F100 S500 M3\nG0 Z10\nG91 G87 X20 Y5 Z-7 R-8 I1 J0 K2", &r91, &d), GcodeError::kOk);
  CHECK_EQ(trace(r91, 3).substr(0, 67), std::string("T 20 5 10|T 20 5 2|T 21 5 2|S 0|T 21 5 -5|T 20 5 -5|S 500|F 20 5 -3"));
  CHECK_EQ(run("G21 F100 S500 M3\nG87 X20 Y5 Z-5 R2 I1 J0.5", &rec, &d), GcodeError::kCycleNoIjk);
  CHECK_EQ(run("G21 F100 S500 M3\nG81 X20 Z-5 R2 I1", &rec, &d), GcodeError::kWordUnused);
}

TEST(cycles_g88_leaves_the_tool_at_the_bottom) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // rs274: feed, DWELL, STOP, PROGRAM_STOP, START; the next hole's rapid
  // goes from the bottom straight to the clearance level over it.
  CHECK_EQ(run("G21 F100 S500 M3\nG0 Z10\nG98 G88 X25 Y5 Z-2 R2 P0.5\nX27\nG80 G0 Z20", &rec, &d, &w), GcodeError::kOk);
  CHECK_EQ(trace(rec, 3), std::string("T 25 5 10|T 25 5 2|F 25 5 -2|D 500|S 0|P|S 500|"
                                      "T 27 5 10|T 27 5 2|F 27 5 -2|D 500|S 0|P|S 500|T 27 5 20|"));
  for (const CanonRecord& r : rec.records) {
    if (r.line == 4 && r.kind == CanonKind::kTraverse && r.end.x_nm == mm(27) && r.end.z_nm == mm(10))
      CHECK(r.start == (PointNm{mm(25), mm(5), mm(-2)}));
    if (r.line == 5 && r.kind == CanonKind::kTraverse) CHECK(r.start == (PointNm{mm(27), mm(5), mm(-2)}));
  }
  // The interpreter reckons the tool at the clearance level, as LinuxCNC does.
  size_t n = 0;
  for (const GcodeDiag& x : w.list) n += x.code == GcodeError::kWarnManualRetract;
  CHECK_EQ(n, 1u);
}

TEST(cycles_g84_in_g18_g19_moves_as_linuxcnc) {
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  // rs274 (LinuxCNC 2.9): the tap feeds go to points with the plane's axes
  // swapped: G18 (1, -2, 2) becomes (-2, 2, 1), G19 (-2, 1, 2) becomes (2, -2, 1).
  CHECK_EQ(run("G21 F100 S500 M3\nG18 G0 Y10\nG98 G84 X1 Z2 Y-2 R1 P0.2\nG19 G0 X10\nG98 G84 Y1 Z2 X-2 R1 P0.2",
               &rec, &d, &w),
           GcodeError::kOk);
  CHECK_EQ(trace(rec, 3), std::string("T 1 10 2|T 1 1 2|F -2 2 1|S 0|S -500|D 200|F 10 2 1|S 0|S 500|"
                                      "T 10 10 2|T 10 1 2|T 1 1 2|F 2 -2 1|S 0|S -500|D 200|F 2 10 1|S 0|S 500|"));
  // The G0 after it starts where the tap left the tool.
  for (const CanonRecord& r : rec.records)
    if (r.line == 4 && r.kind == CanonKind::kTraverse) CHECK(r.start == (PointNm{mm(10), mm(2), mm(1)}));
  CHECK_EQ(w.list.size(), 1u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnTapPlane);
}

TEST(cycles_retract_level_follows_offsets) {
  // LinuxCNC keeps the initial level in program coordinates (cycle_il): the
  // program below retracts to Z15 after G92 Z5 (rs274), with a warning.
  t::Recorder rec;
  t::Warnings w;
  GcodeDiag d;
  CHECK_EQ(run("G21 F100\nG0 Z10\nG98 G81 X1 Y1 Z-2 R1\nG92 Z5\nX2 Y2\nX3", &rec, &d, &w), GcodeError::kOk);
  CHECK_EQ(trace(rec, 5), std::string("T 2 2 10|T 2 2 6|F 2 2 3|T 2 2 15|T 3 2 15|T 3 2 6|F 3 2 3|T 3 2 15|"));
  CHECK_EQ(w.list.size(), 1u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnCycleLevelMoved);
  CHECK_EQ(w.list[0].line, 5u);
  CHECK_EQ(w.list[0].a_nm, mm(15));
  CHECK_EQ(w.list[0].b_nm, mm(10));
  // G10 L2 on the coordinate system in force does the same.
  t::Recorder r2;
  t::Warnings w2;
  CHECK_EQ(run("G21 F100\nG0 Z10\nG98 G81 X1 Y1 Z-2 R1\nG10 L2 P1 Z-3\nX2", &r2, &d, &w2), GcodeError::kOk);
  CHECK_EQ(trace(r2, 5), std::string("T 2 1 10|T 2 1 -2|F 2 1 -5|T 2 1 7|"));
  CHECK_EQ(w2.list.size(), 1u);
  // No false alarm: offsets that do not move (G92 on X only) or G99 (R is
  // re-offset like every word, nothing surprising) say nothing.
  for (const char* p : {"G21 F100\nG0 Z10\nG98 G81 X1 Y1 Z-2 R1\nG92 X0\nX2",
                        "G21 F100\nG0 Z10\nG99 G81 X1 Y1 Z-2 R1\nG92 Z5\nX2", "G21 F100\nG0 Z10\nG98 G81 X1 Y1 Z-2 R1\nX2\nX3"}) {
    t::Warnings w3;
    CHECK_EQ(run(p, &rec, &d, &w3), GcodeError::kOk);
    CHECK_EQ(w3.list.size(), 0u);
  }
}

TEST(cycles_peck_count_is_bounded) {
  t::Recorder rec;
  GcodeDiag d;
  // 100 mm in 0.001 mm pecks: 99 999 pecks, legal and made.
  CHECK_EQ(run("G21 F100\nG0 Z1\nG83 X1 Z-99 R1 Q0.001", &rec, &d), GcodeError::kOk);
  CHECK_EQ(rec.count(CanonKind::kFeed), 100000u);
  // 5 000 000 pecks: over kMaxCyclePecks, an error naming the
  // count, at the Q word.
  CHECK_EQ(run("G21 F100\nG83 X1 Z-4 R1 Q0.000001", &rec, &d), GcodeError::kCyclePeckCount);
  CHECK_EQ(d.a_nm, 4999999);
  CHECK_EQ(d.col, 15);
  char msg[200];
  gcode_format_message(d, msg, sizeof msg);
  CHECK_EQ(std::string(msg), std::string("G83: Q makes 4999999 pecks down 5.0000 mm, more than the 1000000 a block may "
                                         "make (is Q in the right units?)"));
  // Repeats count: 20 000 pecks a hole is fine, not 100 times over.
  CHECK_EQ(run("G21 F100\nG91 G83 X1 Z-20 R0 Q0.001 L50", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F100\nG91 G73 X1 Z-20 R0 Q0.001 L51", &rec, &d), GcodeError::kCyclePeckCount);
  CHECK_EQ(d.a_nm, 19999 * 51);
}

TEST(cycles_words_linuxcnc_refuses) {
  t::Recorder rec;
  GcodeDiag d;
  // rs274: "L word with no G10, cutter compensation, canned cycle ..." for
  // G74 alone of the cycles; Q with the tapping and boring cycles.
  CHECK_EQ(run("G21 F100 S100 M4\nG74 X1 Z-2 R1 L2", &rec, &d), GcodeError::kWordUnused);
  CHECK_EQ(std::string(d.word), std::string("L"));
  CHECK_EQ(run("G21 F100 S100 M3\nG84 X1 Z-2 R1 L2", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F100 S100 M3\nG84 X1 Z-2 R1 Q1", &rec, &d), GcodeError::kWordUnused);
  CHECK_EQ(run("G21 F100 S100 M3\nG87 X1 Z-2 R1 I1 J1 K-1 P1", &rec, &d), GcodeError::kWordUnused);
  CHECK_EQ(run("G21 F100 S100 M3\nG88 X1 Z-2 R1 P1 L2", &rec, &d), GcodeError::kOk);
}
