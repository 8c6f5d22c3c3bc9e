// No silent guess about units (core/interp/units_guess.h,
// core/sim/tool_units.h): a program that sets no G20/G21 before it moves is
// warned of at that move, loudly when its numbers look like inches; the
// tool table is read in the program's units when it sets them before its
// first T. Every program here is written by the test.
#include <cstring>
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "core/sim/chunk_input.h"
#include "core/sim/tool_units.h"
#include "display/api/dexmill.h"
#include "tests/gcode_test_util.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// A small part in inches as a post writes it, without its G20: 3 x 2
// across, clearing at Z0.1, cutting 0.05 deep at F20.
const char kInchBody[] =
    "G90 G17\n"
    "G0 Z0.1\n"
    "G0 X0.5 Y0.5\n"
    "G1 Z-0.05 F10\n"
    "G1 X3.5 F20\n"
    "G1 Y2.5\n"
    "G1 X0.5\n"
    "G1 Y0.5\n"
    "G0 Z0.1\n"
    "M2\n";

// The same part in mm (76 x 51 across, clearing at 2.5, F500).
const char kMmBody[] =
    "G90 G17\n"
    "G0 Z2.5\n"
    "G0 X12.7 Y12.7\n"
    "G1 Z-1.27 F250\n"
    "G1 X88.9 F500\n"
    "G1 Y63.5\n"
    "G1 X12.7\n"
    "G1 Y12.7\n"
    "G0 Z2.5\n"
    "M2\n";

struct Read {
  t::Warnings w;
  UnitsVerdict verdict = UnitsVerdict::kSet;
  size_t count(GcodeError e) const {
    size_t n = 0;
    for (const GcodeDiag& d : w.list) n += d.code == e;
    return n;
  }
  const GcodeDiag* find(GcodeError e) const {
    for (const GcodeDiag& d : w.list)
      if (d.code == e) return &d;
    return nullptr;
  }
};

Read read(const std::string& program, bool inch = false, bool given = false, int64_t default_feed = 0) {
  Read r;
  InterpOptions opt;
  opt.inch = inch;
  opt.units_given = given;
  opt.warnings = &r.w;
  opt.default_feed_nm_per_min = default_feed;
  t::Recorder rec;
  Interp in(&rec, opt);
  GcodeDiag d;
  CHECK_EQ(interp_run_text(&in, program.data(), program.size(), &d), 0u);
  r.verdict = in.units_verdict();
  return r;
}

std::string message(const GcodeDiag& d) {
  char buf[400];
  gcode_format_message(d, buf, sizeof buf);
  return buf;
}

}  // namespace

TEST(units_inch_looking_program_without_g20_warns_loudly) {
  const Read r = read(kInchBody);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsNotSet), 1u);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsLookInch), 1u);
  CHECK_EQ(r.verdict, UnitsVerdict::kLookInch);
  // Both at the first move: line 2, the G0's column.
  const GcodeDiag* plain = r.find(GcodeError::kWarnUnitsNotSet);
  const GcodeDiag* loud = r.find(GcodeError::kWarnUnitsLookInch);
  CHECK(plain && loud);
  if (!plain || !loud) return;
  CHECK_EQ(plain->line, 2u);
  CHECK_EQ(plain->col, 1u);
  CHECK_EQ(loud->line, 2u);
  CHECK_EQ(loud->col, 1u);
  CHECK(run_cli::has(message(*plain), "no G20/G21 before the first move: the program is read in mm"));
  CHECK(run_cli::has(message(*loud), "look like inches, not mm: its moves span at most 3.5000 across and its feeds "
                                     "reach 20.0000 a minute"));
}

TEST(units_mm_program_without_g21_warns_plainly) {
  const Read r = read(kMmBody);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsNotSet), 1u);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsLookInch), 0u);
  CHECK_EQ(r.verdict, UnitsVerdict::kDefault);
}

TEST(units_program_that_sets_them_warns_nothing) {
  for (const char* units : {"G20\n", "G21\n"}) {
    for (const char* body : {kInchBody, kMmBody}) {
      const Read r = read(std::string(units) + body);
      CHECK_EQ(r.w.list.size(), 0u);
      CHECK_EQ(r.verdict, UnitsVerdict::kSet);
    }
  }
  // In the block of the first move, before it: set in time.
  CHECK_EQ(read(std::string("G20 G0 Z0.1\n") + kInchBody).w.list.size(), 0u);
  // A post's `G53 G0` with no axis word goes nowhere: G20 after it is in time.
  CHECK_EQ(read(std::string("G53 G0\nG20\n") + kInchBody).w.list.size(), 0u);
}

TEST(units_set_after_the_first_move_warns_there_only) {
  // The first move was read in mm; the program sets inch after it: the
  // plain warning names that move, and the loud one does not come (the
  // program does say its units, late).
  const Read r = read(std::string("G0 Z0.1\nG20\n") + kInchBody);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsNotSet), 1u);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsLookInch), 0u);
  CHECK_EQ(r.find(GcodeError::kWarnUnitsNotSet)->line, 1u);
  CHECK_EQ(r.verdict, UnitsVerdict::kDefault);
}

TEST(units_given_by_the_caller_warn_nothing) {
  CHECK_EQ(read(kInchBody, true, true).w.list.size(), 0u);
  CHECK_EQ(read(kInchBody, false, true).w.list.size(), 0u);
  CHECK_EQ(read(kInchBody, false, true).verdict, UnitsVerdict::kGiven);
  // A default of inch that nobody chose: plain only (the numbers fit it).
  const Read r = read(kInchBody, true, false);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsNotSet), 1u);
  CHECK_EQ(r.count(GcodeError::kWarnUnitsLookInch), 0u);
  CHECK(run_cli::has(message(r.w.list[0]), "read in inch"));
}

TEST(units_rule_thresholds) {
  // Each condition of the rule, just inside and just outside.
  const auto loud = [](const std::string& p, int64_t default_feed = 0) {
    return read(p, false, false, default_feed).count(GcodeError::kWarnUnitsLookInch);
  };
  // Across: 19.999 is small, 20 is not.
  CHECK_EQ(loud("G0 Z1\nG1 Z-0.1 F20\nG1 X19.999\nM2\n"), 1u);
  CHECK_EQ(loud("G0 Z1\nG1 Z-0.1 F20\nG1 X20\nM2\n"), 0u);
  CHECK_EQ(loud("G0 Z1\nG1 Z-0.1 F20\nG1 Y-20\nM2\n"), 0u);
  // The top: below 2.5 with fast feeds still looks like inches; at 2.5 the
  // feeds must be slow.
  CHECK_EQ(loud("G0 Z2.499\nG1 Z-0.1 F300\nG1 X5\nM2\n"), 1u);
  CHECK_EQ(loud("G0 Z2.5\nG1 Z-0.1 F300\nG1 X5\nM2\n"), 0u);
  CHECK_EQ(loud("G0 Z2.5\nG1 Z-0.1 F49.999\nG1 X5\nM2\n"), 1u);
  CHECK_EQ(loud("G0 Z2.5\nG1 Z-0.1 F50\nG1 X5\nM2\n"), 0u);
  // Feeds of 2000 a minute are no inch program's.
  CHECK_EQ(loud("G0 Z1\nG1 Z-0.1 F1999\nG1 X5\nM2\n"), 1u);
  CHECK_EQ(loud("G0 Z1\nG1 Z-0.1 F2000\nG1 X5\nM2\n"), 0u);
  // No feed of its own (the controller's default stands in): not judged.
  CHECK_EQ(loud("G0 Z1\nG1 Z-0.1\nG1 X5\nM2\n", 10000000), 0u);
  CHECK_EQ(loud("G0 Z1\nG0 X5\nM2\n"), 0u);
}

TEST(units_evidence_rule_direct) {
  UnitsEvidence e;
  CHECK(!units_look_like_inch(e));
  CanonRecord r{};
  r.kind = CanonKind::kFeed;
  r.end = PointNm{3000000, 2000000, -100000};
  r.feed_nm_per_min = 20000000;
  units_evidence_add(&e, r, true);
  CHECK(units_look_like_inch(e));
  CHECK_EQ(e.extent_nm(), 3000000);
  CanonRecord far = r;
  far.kind = CanonKind::kTraverse;
  far.end = PointNm{0, 25000000, 5000000};
  units_evidence_add(&e, far, true);
  CHECK(!units_look_like_inch(e));
  CHECK_EQ(e.extent_nm(), 25000000);
  // Records that do not move are no evidence.
  UnitsEvidence s;
  CanonRecord spindle = far;
  spindle.kind = CanonKind::kSpindle;
  units_evidence_add(&s, spindle, true);
  CHECK(!s.moved);
}

namespace {

bool table_inch(const char* program, bool default_inch) {
  static char buf[1 << 16];
  ChunkInput in(buf, sizeof buf);
  in.feed(program, std::strlen(program));
  in.close();
  InterpOptions opt;
  opt.inch = default_inch;
  return tool_table_inch(&in, opt);
}

}  // namespace

TEST(units_tool_table_follows_units_set_before_the_first_t) {
  CHECK(table_inch("G20\nT1 M6\nG0 X1\n", false));
  CHECK(!table_inch("G21\nT1 M6\nG0 X1\n", true));
  CHECK(table_inch("G20 T1 M6\n", false));  // in the T's block: before it
  // None before the T: the default, whatever comes after.
  CHECK(!table_inch("T1 M6\nG20\nG0 X1\n", false));
  CHECK(table_inch("T1 M6\nG21\nG0 X1\n", true));
  CHECK(!table_inch("G0 X1\nM2\n", false));
  CHECK(table_inch("G0 X1\nM2\n", true));
}

namespace {

// Runs a program through the embedding API (display/api/dexmill.h): its
// progress at the end.
dm_progress api_run(const std::string& program) {
  dm_job j;
  dm_progress p{};
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  j.stock.lo_nm[2] = -5000000;
  j.stock.hi_nm[0] = 100000000;
  j.stock.hi_nm[1] = 70000000;
  j.pitch_nm = 500000;
  j.tool.spec = "flat:3";
  size_t n = 0;
  CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
  std::vector<uint64_t> mem(n / 8 + 1);
  dm_sim* sim = nullptr;
  CHECK_EQ(dm_create(&j, mem.data(), n, &sim), DM_OK);
  if (!sim) return p;
  int32_t state = DM_READY;
  bool fed = false;
  for (int guard = 0; guard < 100000 && (state == DM_READY || state == DM_NEED_INPUT); ++guard) {
    CHECK_EQ(dm_step(sim, nullptr, &state), DM_OK);
    if (state != DM_NEED_INPUT) continue;
    if (!fed) CHECK_EQ(dm_feed(sim, program.data(), program.size()), DM_OK);
    else CHECK_EQ(dm_end_input(sim), DM_OK);
    fed = true;
  }
  CHECK_EQ(state, DM_DONE);
  CHECK_EQ(dm_get_progress(sim, &p), DM_OK);
  dm_destroy(sim);
  return p;
}

}  // namespace

TEST(units_verdict_in_the_c_api) {
  const dm_progress inch = api_run(kInchBody);
  CHECK_EQ(inch.units_verdict, static_cast<uint32_t>(DM_UNITS_VERDICT_LOOK_INCH));
  CHECK_EQ(inch.warnings, 2u);
  const dm_progress mm = api_run(kMmBody);
  CHECK_EQ(mm.units_verdict, static_cast<uint32_t>(DM_UNITS_VERDICT_DEFAULT));
  CHECK_EQ(mm.warnings, 1u);
  const dm_progress set = api_run(std::string("G21\n") + kMmBody);
  CHECK_EQ(set.units_verdict, static_cast<uint32_t>(DM_UNITS_VERDICT_SET));
  CHECK_EQ(set.warnings, 0u);
}
