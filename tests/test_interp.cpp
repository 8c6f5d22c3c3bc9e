// core/interp/interp.h: records, modal state, atomic blocks, LinuxCNC's arc
// tolerances, warnings, and the no-heap streaming guarantee.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "tests/alloc_count.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"

using namespace dexmill;
using t::mm;

namespace {

GcodeError run(const char* program, t::Recorder* rec, GcodeDiag* d, InterpOptions opt = {}) {
  Interp in(rec, opt);
  return t::run_program(&in, program, d);
}

bool same_state(const InterpState& a, const InterpState& b) {
  bool same = a.pos == b.pos && a.motion == b.motion && a.plane == b.plane && a.inch == b.inch &&
              a.incremental == b.incremental && a.arc_absolute == b.arc_absolute && a.inverse_time == b.inverse_time &&
              a.retract_to_r == b.retract_to_r && a.coord_system == b.coord_system && a.feed_nm_per_min == b.feed_nm_per_min &&
              a.spindle_rpm == b.spindle_rpm && a.spindle_dir == b.spindle_dir && a.coolant == b.coolant &&
              a.tool == b.tool && a.selected_tool == b.selected_tool && a.tlo_nm == b.tlo_nm && a.g92 == b.g92 &&
              a.cycle_level_set == b.cycle_level_set && a.ended == b.ended && a.per_rev == b.per_rev &&
              a.stray == b.stray;
  for (int i = 0; i < 9; ++i)
    same = same && a.work_offset[i] == b.work_offset[i] && a.rotation_deg_e9[i] == b.rotation_deg_e9[i];
  return same;
}

}  // namespace

TEST(interp_simple_records) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 G90\nG0 X1 Y2 Z3\nG1 X4 F600\nG2 X14 Y12 I10 J0\nG4 P1.5\nM3 S1000\nM8\nT3 M6\nM2\n", &rec, &d),
           GcodeError::kOk);
  CHECK_EQ(rec.records.size(), 8u);
  const CanonRecord& r0 = rec.records[0];
  CHECK_EQ(r0.kind, CanonKind::kTraverse);
  CHECK(r0.start == (PointNm{0, 0, 0}));
  CHECK(r0.end == (PointNm{mm(1), mm(2), mm(3)}));
  CHECK_EQ(r0.line, 2u);
  const CanonRecord& r1 = rec.records[1];
  CHECK_EQ(r1.kind, CanonKind::kFeed);
  CHECK_EQ(r1.feed_nm_per_min, mm(600));
  const CanonRecord& r2 = rec.records[2];
  CHECK_EQ(r2.kind, CanonKind::kArc);
  CHECK(r2.arc.centre == (PointNm{mm(14), mm(2), mm(3)}));
  CHECK_EQ(r2.arc.turns, -1);
  CHECK_EQ(rec.records[3].kind, CanonKind::kDwell);
  CHECK_EQ(rec.records[3].dwell_ms, 1500);
  CHECK_EQ(rec.records[4].kind, CanonKind::kSpindle);
  CHECK_EQ(rec.records[4].spindle_rpm, 1000);
  CHECK_EQ(rec.records[5].kind, CanonKind::kCoolant);
  CHECK_EQ(rec.records[5].coolant, 2);
  CHECK_EQ(rec.records[6].kind, CanonKind::kToolChange);
  CHECK_EQ(rec.records[6].tool, 3);
  CHECK_EQ(rec.records[7].kind, CanonKind::kEnd);
}

TEST(interp_bad_block_changes_nothing) {
  t::Recorder rec;
  Interp in(&rec, InterpOptions{});
  GcodeDiag d;
  CHECK_EQ(t::run_program(&in, "G21 G90 G17 F100\nG0 X10 Y0 Z1\nM3 S100", &d), GcodeError::kOk);
  const InterpState before = in.state();
  const size_t n = rec.records.size();
  // Every code of these blocks would change the state, but each has an error.
  const char* bad[] = {
      "G91 G20 G18 G55 M5 M9 T7 F50 S9 G2 X0 Y10",  // arc without centre
      "G91 G20 G93 G43.1 Z1 G1 X1",                 // two users of the axis words
      "G91 G20 G55 G98 G81 X1 Y1 Z-1",              // cycle without R
      "G91 G20 M8 G0 X1 Q1",                        // unused word
      "G92 X0 G20 G91 M7 Y1 X2",                    // duplicate word
      "G10 L20 P1 X5 Y6 G91 R30",                   // R with L20
      "G91 G0 X20000",                              // number too large
  };
  for (const char* line : bad) {
    GcodeError e = in.execute_line(line, std::strlen(line), 9, &d);
    CHECK_NE(e, GcodeError::kOk);
    CHECK(same_state(before, in.state()));
    CHECK_EQ(rec.records.size(), n);
  }
  // And the next good block runs from the unchanged state.
  CHECK_EQ(in.execute_line("X20", 3, 10, &d), GcodeError::kOk);
  CHECK(rec.records.back().end == (PointNm{mm(20), 0, mm(1)}));
}

TEST(interp_bad_block_under_a_turned_frame_changes_nothing) {
  // A G54-G59.3 switch works the tool's point out in the new frame before
  // the block runs (rotation.h); a block that then fails gives it back.
  t::Recorder rec;
  Interp in(&rec, InterpOptions{});
  GcodeDiag d;
  CHECK_EQ(t::run_program(&in, "G21 G90 F100\nG10 L2 P1 X10 R30\nG10 L2 P2 R-90\nG0 X10 Y0 Z1", &d), GcodeError::kOk);
  const InterpState before = in.state();
  const char* bad[] = {"G55 G2 X0 Y10", "G56 G1 X1 Q1", "G55 G0 X20000"};
  for (const char* line : bad) {
    CHECK_NE(in.execute_line(line, std::strlen(line), 9, &d), GcodeError::kOk);
    CHECK(same_state(before, in.state()));
  }
  // The switch with a move: from where the tool stands (machine X 18.66,
  // Y 5; G55's Y 18.66 when turned -90 about the machine origin) to G55's
  // X1 on the same Y: machine X 18.66, Y -1.
  CHECK_EQ(in.execute_line("G55 G1 X1", 9, 10, &d), GcodeError::kOk);
  const CanonRecord& r = rec.records.back();
  CHECK(std::llabs(r.start.x_nm - 18660254) <= 2 && std::llabs(r.start.y_nm - 5000000) <= 2);
  CHECK(std::llabs(r.end.x_nm - 18660254) <= 2 && std::llabs(r.end.y_nm + 1000000) <= 2);
}

TEST(interp_linuxcnc_arc_tolerance) {
  t::Recorder rec;
  GcodeDiag d;
  // Centre format, mm: |r2 - r1| <= 0.028284 mm, or <= 2.83 mm while within 0.1 %.
  CHECK_EQ(run("G21 F1\nG0 X10\nG3 X0 Y10.02 I-10", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F1\nG0 X10\nG3 X0 Y10.03 I-10", &rec, &d), GcodeError::kArcRadiusMismatch);
  CHECK_EQ(d.line, 3u);
  CHECK_EQ(d.a_nm, mm(10));
  CHECK_EQ(d.b_nm, mm(10.03));
  CHECK_EQ(run("G21 F1\nG0 X1000\nG3 X0 Y1000.9 I-1000", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F1\nG0 X1000\nG3 X0 Y1001.1 I-1000", &rec, &d), GcodeError::kArcRadiusMismatch);
  // Inch: 0.0028284 in.
  CHECK_EQ(run("G20 F1\nG0 X1\nG3 X0 Y1.002 I-1", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G20 F1\nG0 X1\nG3 X0 Y1.003 I-1", &rec, &d), GcodeError::kArcRadiusMismatch);
  // Radius format: half the chord may exceed |R| by 0.00127 mm at most.
  CHECK_EQ(run("G21 F1\nG2 X10 R4.999", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F1\nG2 X10 R4.998", &rec, &d), GcodeError::kArcRTooSmall);
  CHECK_EQ(run("G21 F1\nG0 X1\nG2 X1 R4", &rec, &d), GcodeError::kArcRSameEnds);
  CHECK_EQ(run("G21 F1\nG2 X10 Y0.0005 I0.0002", &rec, &d), GcodeError::kArcZeroRadius);
}

TEST(interp_r_arc_centres) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 F1\nG2 X10 R5\nG3 X20 R5\nG2 X10 Y10 R10\nG2 X0 Y0 R-10\nG18 G2 Z5 X5 R5", &rec, &d),
           GcodeError::kOk);
  CHECK(rec.records[0].arc.centre == (PointNm{mm(5), 0, 0}));
  CHECK(rec.records[1].arc.centre == (PointNm{mm(15), 0, 0}));
  // G2 with R > 0: centre right of the chord, the short way (90 degrees).
  CHECK(rec.records[2].arc.centre == (PointNm{mm(20), mm(10), 0}));
  // R < 0: left of the chord, the long way round (270 degrees).
  CHECK(rec.records[3].arc.centre == (PointNm{mm(10), 0, 0}));
  CHECK_EQ(rec.records[4].arc.plane, Plane::kZX);
}

// F on the line that changes the units: RS274/NGC sets F (its step 3)
// before the units (step 12), so LinuxCNC reads it in the units before the
// line (rs274 on "G20 F6": SET_FEED_RATE(6.0000), then
// USE_LENGTH_UNITS(CANON_UNITS_INCHES); its sim moves at 6 mm/min), warned
// of; grbl (feed_in_line_units) reads the line's units. No warning where the
// line sets no new units, sets the ones in force, or F is per revolution.
TEST(interp_feed_on_a_units_line) {
  struct Case {
    const char* program;
    bool line_units;
    int64_t feed_nm_per_min;
    uint32_t warn_line;  // 0: no warning
    uint16_t warn_col;
  };
  const Case cases[] = {
      {"G20 F6\nG1 X1", false, mm(6), 1, 5},        // the CAMotics vcarve.ngc opening
      {"G20 F6\nG1 X1", true, 6 * 25400000, 0, 0},  // grbl's reading
      {"G20\nF6\nG1 X1", false, 6 * 25400000, 0, 0},  // F after the units line: inch
      {"G21 F100 G1 X1", false, mm(100), 0, 0},      // mm already: no change
      {"G20\nG20 F6 G1 X1", false, 6 * 25400000, 0, 0},
      {"G20\nG1 G21 X1 F100", false, INT64_C(100) * 25400000, 2, 11},  // the other way: 100 in/min
      {"G20 F6\nG21\nG1 X1", false, mm(6), 1, 5},  // a later units change keeps the feed
      {"G21 S1000 M3\nG20 G95 F0.002\nG1 X1", false, 50800 * 1000, 0, 0},
  };
  for (const Case& c : cases) {
    t::Recorder rec;
    t::Warnings w;
    InterpOptions opt;
    opt.warnings = &w;
    opt.feed_in_line_units = c.line_units;
    GcodeDiag d;
    CHECK_EQ(run(c.program, &rec, &d, opt), GcodeError::kOk);
    CHECK_EQ(rec.records.back().feed_nm_per_min, c.feed_nm_per_min);
    std::vector<GcodeDiag> seen;
    for (const GcodeDiag& g : w.list)
      if (g.code == GcodeError::kWarnFeedBeforeUnits) seen.push_back(g);
    CHECK_EQ(seen.size(), c.warn_line ? 1u : 0u);
    if (!seen.empty()) {
      CHECK_EQ(seen[0].line, c.warn_line);
      CHECK_EQ(seen[0].col, c.warn_col);
    }
  }
}

TEST(interp_inverse_time_and_units) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 G93\nG1 X10 F2\nG20 G94 G1 X1 F10", &rec, &d), GcodeError::kOk);
  CHECK_EQ(rec.records[0].feed_nm_per_min, mm(20));  // 10 mm in 1/2 minute
  // F10 on the line that says G20 is read in mm, the units before it
  // (RS274/NGC sets F before the units; LinuxCNC's rs274 prints
  // SET_FEED_RATE(10) before USE_LENGTH_UNITS(INCHES) and moves at 10 mm/min).
  CHECK_EQ(rec.records[1].feed_nm_per_min, mm(10));
  CHECK(rec.records[1].end == (PointNm{25400000, 0, 0}));
  CHECK_EQ(run("G21 G93\nG1 X10 F2\nG1 X20", &rec, &d), GcodeError::kInverseTimeNoF);
  InterpOptions inch;
  inch.inch = true;
  rec.records.clear();
  CHECK_EQ(run("G0 X1", &rec, &d, inch), GcodeError::kOk);
  CHECK_EQ(rec.records[0].end.x_nm, 25400000);
}

TEST(interp_offsets_and_home) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21\nG10 L2 P2 X10 Y20 Z30\nG55 G0 X1 Y1 Z1\nG92 X0 Y0 Z0\nG0 X1\nG53 G0 Z-5\nG28.1\nG0 X0 Y0 Z0\nG28",
               &rec, &d),
           GcodeError::kOk);
  CHECK(rec.records[0].end == (PointNm{mm(11), mm(21), mm(31)}));
  CHECK(rec.records[1].end == (PointNm{mm(12), mm(21), mm(31)}));
  CHECK(rec.records[2].end == (PointNm{mm(12), mm(21), mm(-5)}));
  CHECK(rec.records[3].end == (PointNm{mm(11), mm(21), mm(31)}));
  // G28 with no axis: a zero-length traverse (LinuxCNC does the same), then home.
  CHECK(rec.records[4].end == rec.records[3].end);
  CHECK(rec.records[5].end == (PointNm{mm(12), mm(21), mm(-5)}));
}

TEST(interp_tool_length_from_table) {
  struct Table final : ToolTable {
    bool tool_length_nm(int32_t tool, int64_t* z) const override {
      if (tool != 4) return false;
      *z = mm(50);
      return true;
    }
    bool tool_radius_nm(int32_t, int64_t*) const override { return false; }
  } table;
  InterpOptions opt;
  opt.tools = &table;
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21\nT4 M6\nG43 H4\nG0 X1 Z10\nG53 G0 Z0\nG49\nG0 X2", &rec, &d, opt), GcodeError::kOk);
  CHECK_EQ(rec.records[1].tool_length_offset_nm, mm(50));
  CHECK(rec.records[1].end == (PointNm{mm(1), 0, mm(10)}));
  CHECK(rec.records[2].end == (PointNm{mm(1), 0, mm(-50)}));  // spindle at machine Z0: tip 50 mm below
  CHECK(rec.records[3].end == (PointNm{mm(2), 0, 0}));        // G49: the tip reads the spindle again
  CHECK_EQ(run("G21\nG43 H5", &rec, &d, opt), GcodeError::kToolUnknown);
}

TEST(interp_warnings_and_end) {
  t::Recorder rec;
  t::Warnings w;
  InterpOptions opt;
  opt.warnings = &w;
  GcodeDiag d;
  CHECK_EQ(run("$H\nG21 M48\nG0 X1\nM30\nG0 X2\nG0 X3", &rec, &d, opt), GcodeError::kOk);
  CHECK_EQ(w.list.size(), 3u);
  CHECK_EQ(w.list[0].code, GcodeError::kWarnGrblCommand);
  CHECK_EQ(w.list[1].code, GcodeError::kWarnMcodeIgnored);
  CHECK_EQ(w.list[2].code, GcodeError::kWarnAfterEnd);
  CHECK_EQ(w.list[2].line, 5u);
  CHECK_EQ(rec.count(CanonKind::kTraverse), 1u);
  CHECK_EQ(rec.count(CanonKind::kEnd), 1u);
}

TEST(interp_warnings_at_end_of_input) {
  struct Case {
    const char* program;
    std::vector<GcodeError> warnings;
    uint32_t line;  // of the last warning
  };
  const Case cases[] = {
      {"G21\nG0 X1\nM2\n", {}, 0},
      {"", {GcodeError::kWarnEmptyProgram}, 1},
      {"(comment)\n;another\n\n%\n%\n", {GcodeError::kWarnEmptyProgram}, 1},
      {"G21\nG0 X1\nG1 X2 F10", {GcodeError::kWarnNoProgramEnd}, 3},
      {"%\nG21\nG0 X1\n", {GcodeError::kWarnNoClosingPercent}, 3},
      {"%\nG21\nG0 X1\n%\n", {}, 0},
      {"G21\nG0 X0 Y0\nG4 P1\nM2\n", {GcodeError::kWarnNoMotion}, 1},  // a move to where it is goes nowhere
      {"G21\nG0 X0\n", {GcodeError::kWarnNoProgramEnd, GcodeError::kWarnNoMotion}, 1},
      {"G21\nG1 X1\nM2\n", {}, 0},  // moves of a failed block are unknown: no verdict
      {"G21\nG0 X1\nG1 X2 M2\n", {}, 0},  // and it may have been the end
      {"G21\nG0 X1\nG1 X2\n", {GcodeError::kWarnNoProgramEnd}, 3},
      {"G21 F100\nG2 X0 I1\nM30\n", {}, 0},  // a full circle moves
  };
  for (const Case& c : cases) {
    t::Warnings w;
    InterpOptions opt;
    opt.warnings = &w;
    Interp in(nullptr, opt);
    (void)interp_run_text(&in, c.program, std::strlen(c.program), nullptr);
    if (!CHECK_EQ(w.list.size(), c.warnings.size())) {
      std::printf("  program: %s\n", c.program);
      continue;
    }
    for (size_t i = 0; i < w.list.size(); ++i) CHECK_EQ(w.list[i].code, c.warnings[i]);
    if (!w.list.empty()) CHECK_EQ(w.list.back().line, c.line);
  }
}

namespace {

// Runs a program to its end as `dexmill check` does (a bad block is skipped)
// and lists its errors as "LINE:CODE" for a root error, "LINE:CODE~" for a
// follow-on.
std::string errors_of(const char* program) {
  Interp in(nullptr, InterpOptions{});
  std::string out;
  uint32_t line = 0;
  for (const char* p = program; *p;) {
    const char* e = std::strchr(p, '\n');
    const size_t n = e ? static_cast<size_t>(e - p) : std::strlen(p);
    GcodeDiag d;
    const GcodeError err = in.execute_line(p, n, ++line, &d);
    if (err != GcodeError::kOk)
      out += std::to_string(line) + ":" + std::to_string(gcode_error_number(err)) + (d.follow_on ? "~ " : " ");
    if (!e) break;
    p = e + 1;
  }
  return out;
}

}  // namespace

// One cause, one error. After a block fails, what it would have set
// is suspect, and so is what an error blames; an error that reads a suspect
// facet is a follow-on (core/interp/interp_follow_on.cpp).
TEST(interp_follow_on_errors) {
  const int feed0 = gcode_error_number(GcodeError::kFeedZero);
  const std::string f0 = std::to_string(feed0);
  // No F: the first G1 says so, the next ones follow; F mends it, G94 breaks it anew.
  CHECK_EQ(errors_of("G21\nG0 X1\nG1 X2\nG1 X3\nF100\nG1 X4\nG94\nG1 X5\nG1 X6"),
           "3:" + f0 + " 4:" + f0 + "~ 8:" + f0 + " 9:" + f0 + "~ ");
  // The F was on a line that did not read: the G1 after it follows from that line.
  CHECK_EQ(errors_of("G21\nG1 Z#1 F#2\nG1 X1\nG1 X2 F10\nG1 X3"), "2:101 3:" + f0 + "~ ");
  // The motion mode was on it: the axis words after it have none.
  CHECK_EQ(errors_of("G21 F100\nG1 X#1 Y2\nX3 Y4\nG0 X5\nX6\nG80\nX7\nX8"), "2:101 3:50~ 7:50 8:50~ ");
  // The arc starts where a failed move should have ended: unknown, until an
  // absolute move puts the tool back on known ground.
  CHECK_EQ(errors_of("G21 F100\nG0 X0 Y0\nG1 X#1 Y10\nG2 X30 Y0 R10\nG0 X0 Y0\nG2 X30 Y0 R10"), "3:101 4:46~ 6:46 ");
  CHECK_EQ(errors_of("G21 F100\nG91\nG1 X#1\nG2 X30 R10\nG90 G0 X0\nG91 G2 X30 R10"), "3:101 4:46~ 6:46 ");
  // Units a bad line may have changed make every absolute position unknown.
  CHECK_EQ(errors_of("G21 F100\nG20 G0 X#1\nG0 X0 Y0\nG2 X30 Y0 R10\nG21 G0 X0 Y0\nG2 X30 Y0 R10"),
           "2:101 4:46~ 6:46 ");
  // A line's own mistakes are always news.
  CHECK_EQ(errors_of("G21\nG1 X1\nG1 X2 A1\nG1 X3 Q"), "2:" + f0 + " 3:103 4:4 ");
  // A modal arc on lines meant for lines: once.
  CHECK_EQ(errors_of("G21 F100\nG2 X1 Y1 I1\nX2 Y2\nX3 Y3\nG1 X4\nG2 X5 Y5"), "3:42 4:42~ 6:42 ");
  // A cycle whose sticky R was on a bad line.
  CHECK_EQ(errors_of("G21 F100\nG81 X1 Y1 Z-1 R#1\nG81 X2 Y2\nG80\nG81 X3 Y3"), "2:101 3:53~ 5:53 ");
  // An o-word line may have done anything; a stray O names nothing.
  CHECK_EQ(errors_of("G21\nG0 X1\no100 call\nG1 X2"), "3:100 4:" + f0 + "~ ");
  CHECK_EQ(errors_of("G21\nG0 X1\nG0 X1O\nG1 X2"), "3:21 4:" + f0 + " ");
  // The first error is never a follow-on.
  CHECK_EQ(errors_of("G1 X1"), "1:" + f0 + " ");
}

TEST(interp_large_numbers_are_errors) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21\nG0 X10000", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21\nG0 X10000.000001", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G20\nG0 X394", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21 G91\nG0 X6000\nG0 X6000", &rec, &d), GcodeError::kPositionOutOfRange);
  CHECK_EQ(d.a_nm, mm(12000));
  CHECK_EQ(run("G21 F1\nG0 X1\nG2 X1 I99999", &rec, &d), GcodeError::kOk);  // 100 km radius? no: 99.999 m
  CHECK_EQ(run("G21 F1\nG2 X1 I100001", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21 F1\nG81 X1 Z-1 R1 L1000001", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21 F1\nG83 X1 Z-9000 R1 Q0.000001", &rec, &d), GcodeError::kCyclePeckCount);
  // F and S: LinuxCNC takes any; dexmill up to 1e9 (a warning above 1e6).
  CHECK_EQ(run("G21\nS1000000000 M3", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21\nS1000000001 M3", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G20\nG1 X1 F1000000000", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21\nG1 X1 F1000000001", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21\nT2147483648", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21\nG4 P1000001", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21 F1\nG0 X1\nG2 X1 I-1 P10001", &rec, &d), GcodeError::kNumberTooLarge);
}

namespace {
struct CountingSink final : CanonSink {
  uint64_t moves = 0;
  int64_t checksum = 0;
  void emit(const CanonRecord& r) override {
    ++moves;
    checksum += r.end.x_nm ^ r.end.y_nm ^ r.end.z_nm;
  }
};
}  // namespace

TEST(interp_150k_lines_no_heap) {
  // The interpreter keeps no per-line memory: 150 000 lines of mixed moves,
  // arcs and cycles make no heap allocation and leave its size unchanged.
  CountingSink sink;
  Interp in(&sink, InterpOptions{});
  GcodeDiag d;
  char line[128];
  const uint64_t before = t::heap_allocations();
  const char* head = "G21 G90 G17 F1200 S10000 M3";
  CHECK_EQ(in.execute_line(head, std::strlen(head), 1, &d), GcodeError::kOk);
  uint32_t n = 1;
  for (int i = 0; i < 150000; ++i) {
    int len;
    switch (i % 5) {
      case 0: len = std::snprintf(line, sizeof line, "N%d G1 X%d.%03d Y%d Z-1.5", i, i % 300, i % 1000, (i / 300) % 200); break;
      case 1: len = std::snprintf(line, sizeof line, "G0 X%d Y%d Z2 (rapid)", i % 300, (i / 300) % 200); break;
      case 2: len = std::snprintf(line, sizeof line, "G2 I5 J0 (full circle)"); break;
      case 3: len = std::snprintf(line, sizeof line, "G98 G81 X%d Y3 Z-2 R1 ; drill", i % 300); break;
      default: len = std::snprintf(line, sizeof line, "G80 g0 z 5"); break;
    }
    GcodeError e = in.execute_line(line, static_cast<size_t>(len), ++n, &d);
    if (e != GcodeError::kOk && !CHECK_EQ(e, GcodeError::kOk)) break;
  }
  CHECK_EQ(t::heap_allocations() - before, 0u);
  CHECK_GT(sink.moves, 150000u);
  // Most of it is cutter compensation's queue of held records and the
  // scratch copy a block is checked against (2 x kCompQueueMax records).
  static_assert(sizeof(Interp) < 8192, "the interpreter's whole state is small and fixed");
}
