// The interpreter's block runner, shared by the files that implement it
// (not a public header: embedders read core/interp/interp.h). A block is
// checked against a copy of the state (BlockRunner::run and the run_*
// steps), then committed (BlockRunner::commit), so a bad block changes
// nothing (core/README.md, habit 3). The steps live by phase, after LinuxCNC's
// interp_convert: interp.cpp (order of execution, unused words, commit),
// interp_modes.cpp (modal groups, G4, G10/G28/G30/G92), interp_moves.cpp
// (G0/G1, G2/G3, G38.x), interp_cycles.cpp (canned cycles).
#ifndef DEXMILL_CORE_INTERP_BLOCK_RUNNER_H
#define DEXMILL_CORE_INTERP_BLOCK_RUNNER_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/interp/cutter_comp.h"
#include "core/interp/cycles.h"
#include "core/interp/interp.h"
#include "core/interp/polar.h"
#include "core/interp/spline.h"
#include "core/point.h"

namespace dexmill {
namespace interp_detail {


// F and S: LinuxCNC takes any value (the machine clamps to its maximum
// velocity); these bounds only keep the arithmetic in range. Above
// kFastFeedNmPerMin / kFastSpindleRpm a program gets one warning each.
constexpr int64_t kMaxFeedUnitsPerMin = 1000000000;
constexpr int64_t kMaxSpindleRpm = 1000000000;
constexpr int64_t kFastFeedNmPerMin = 1000000LL * 1000000;  // 1e6 mm/min
constexpr int64_t kFastSpindleRpm = 1000000;
constexpr int64_t kMaxDwellS = 1000000;
constexpr int64_t kMaxRepeats = 1000000;
constexpr int64_t kMaxTurns = 10000;
constexpr int64_t kMaxToolNumber = 1000000000;
constexpr int64_t kMaxCycleMoves = 10000000;

inline int64_t& axis_ref(PointNm& p, int axis) { return axis == 0 ? p.x_nm : axis == 1 ? p.y_nm : p.z_nm; }
inline int64_t axis_val(const PointNm& p, int axis) { return axis == 0 ? p.x_nm : axis == 1 ? p.y_nm : p.z_nm; }
inline bool is_cycle(int m) { return m == 730 || m == 740 || (m >= 810 && m <= 890 && m % 10 == 0); }
inline bool is_probe(int m) { return m >= 382 && m <= 385; }
// |v|, saturating: INT64_MIN (a saturated huge number) stays beyond every limit.
inline int64_t abs64(int64_t v) { return v == INT64_MIN ? INT64_MAX : (v < 0 ? -v : v); }
constexpr char kAxisLetter[3] = {'X', 'Y', 'Z'};
// Where the tool is (InterpState::stray).
inline PointNm tool_at(const InterpState& s) {
  return PointNm{s.pos.x_nm + s.stray.x_nm, s.pos.y_nm + s.stray.y_nm, s.pos.z_nm + s.stray.z_nm};
}
// Rotated coordinate systems (rotation.h): whether the system in force of s
// is turned, and a point of s's (unrotated) frame as a machine point and back.
inline bool rotated(const InterpState& s) {
  const int64_t r = s.rotation_deg_e9[s.coord_system];
  return r != 0 && r % (360LL * 1000000000) != 0;  // the common case without a division
}
inline PointNm machine_of(const InterpState& s, const PointNm& p) {
  if (!rotated(s)) return p;
  const PointNm& o = s.work_offset[s.coord_system];
  return rotate_about(xy_rotation(s.rotation_deg_e9[s.coord_system]), p, o.x_nm, o.y_nm);
}
inline PointNm frame_of_machine(const InterpState& s, const PointNm& m) {
  if (!rotated(s)) return m;
  const PointNm& o = s.work_offset[s.coord_system];
  return rotate_about(xy_rotation_inverse(xy_rotation(s.rotation_deg_e9[s.coord_system])), m, o.x_nm, o.y_nm);
}
// Whether a turned frame (in a or b) moves between a and b: another system,
// turn or origin. Then the tool's point is worked out anew (Interp::reframe_tool).
inline bool frame_moved(const InterpState& a, const InterpState& b) {
  if (!rotated(a) && !rotated(b)) return false;  // the machine frame both ways
  const PointNm& oa = a.work_offset[a.coord_system];
  const PointNm& ob = b.work_offset[b.coord_system];
  return a.coord_system != b.coord_system || a.rotation_deg_e9[a.coord_system] != b.rotation_deg_e9[b.coord_system] ||
         oa.x_nm != ob.x_nm || oa.y_nm != ob.y_nm;
}
// A feed tied to the spindle (G33/G33.1's K, G95's F): length per revolution
// times rpm. Lengths <= 1e10 nm and S <= 1e9 rpm: saturated rather than
// wrapped; the time estimate counts a feed at most at 1e6 mm/min anyway.
inline int64_t sync_feed(int64_t nm_per_rev, int64_t rpm) {
  return rpm > 0 && nm_per_rev > INT64_MAX / rpm ? INT64_MAX : nm_per_rev * rpm;
}
// Warnings a program gets once (Interp::warned_once_).
enum WarnOnce : uint16_t {
  kOnceDefaultFeed = 1 << 0,
  kOnceFastFeed = 1 << 1,
  kOnceFastSpindle = 1 << 2,
  kOnceProbe = 1 << 3,
  kOnceTapPlane = 1 << 4,
  kOnceManualRetract = 1 << 5,
  kOnceDiameter = 1 << 6,
  kOnceCompNoTable = 1 << 7,
  kOnceG49H = 1 << 8,
};
inline int plane_axis_a(Plane p) { return p == Plane::kXY ? 0 : p == Plane::kZX ? 2 : 1; }
inline int plane_axis_b(Plane p) { return p == Plane::kXY ? 1 : p == Plane::kZX ? 0 : 2; }
inline int plane_axis_c(Plane p) { return p == Plane::kXY ? 2 : p == Plane::kZX ? 1 : 0; }

// Facets of the modal state, for telling a root error from its follow-ons
// (the rule is in interp_follow_on.cpp).
enum Facet : uint16_t {
  kFacetX = 1 << 0,
  kFacetY = 1 << 1,
  kFacetZ = 1 << 2,
  kFacetPosition = kFacetX | kFacetY | kFacetZ,
  kFacetMotion = 1 << 3,       // modal motion, canned cycles' sticky R, Z, Q, P and levels
  kFacetFeed = 1 << 4,         // F and G93/G94
  kFacetPlane = 1 << 5,
  kFacetUnits = 1 << 6,
  kFacetDistance = 1 << 7,     // G90/G91
  kFacetArcDistance = 1 << 8,  // G90.1/G91.1
  kFacetOffsets = 1 << 9,      // work offsets, G92, tool length offset
  kFacetTool = 1 << 10,
  kFacetEnd = 1 << 11,         // whether the program ended (M2/M30)
  kFacetComp = 1 << 12,        // cutter radius compensation (G40, G41, G42)
  kFacetAll = (1 << 13) - 1,
};
// The facets a line would set, read leniently (it may not read at all).
uint16_t facets_written(const char* text, size_t len);
// The facets a block sets itself, from `s` (the state before it) on, given
// the facets now suspect.
uint16_t facets_set(const GcodeBlock& b, const InterpState& s, uint16_t suspect);
// Suspect facets once a block that sets `set` has run.
uint16_t suspect_after(uint16_t suspect, uint16_t set);
// What the check that raised an error read, and what the error blames.
struct ErrorFacets {
  uint16_t read;          // facets it read, after the block's own words applied
  uint16_t before_block;  // facets it read as they were before the block
  uint16_t blamed;        // facets the error says are wrong
};
ErrorFacets error_facets(GcodeError e, const GcodeBlock& b);

}  // namespace interp_detail
// Only the interpreter's own files include this header.
using namespace interp_detail;

// What cutter compensation does in a block (core/interp/interp_comp.cpp):
// done on a scratch queue while the block is checked, again when it commits.
// Only the two flags are set in a block that does not compensate.
struct CompOps {
  bool off_flush;  // G40 ended compensation: the held moves end where the tool is, and go
  bool motion;     // the block's move is compensated: the steps below replace it
  // 1. The held records go (kDequeue), after their moves end at flush_to (kMoveEnd).
  enum Flush : uint8_t { kKeep, kDequeue, kMoveEnd } flush;
  Vec2 flush_to;
  // 2. A move round the corner, made at once.
  bool corner;
  CanonKind corner_kind;
  PointNm corner_end, corner_centre;
  int32_t corner_turns;
  // 3. Where the held move starts (LinuxCNC's set_endpoint), if set.
  bool set_endpoint;
  Vec2 endpoint;
  // 4. The compensated move, held.
  CanonKind kind;
  PointNm end;
  CanonArc arc;
  int64_t dir_a, dir_b, sweep_bam;
  PointNm prog_start;  // the programmed move starts here (G93 feeds come from it)
};

// What a checked block will do when committed.
struct Plan {
  bool tool_change = false;
  bool spindle = false;
  bool coolant = false;
  bool dwell = false;
  int64_t dwell_ms = 0;
  enum Motion : uint8_t { kNone, kStraight, kArc, kCycle, kHome, kSpline, kTap, kNurbs } motion = kNone;
  CanonKind straight_kind = CanonKind::kTraverse;
  PointNm target{0, 0, 0};
  CanonArc arc{Plane::kXY, {0, 0, 0}, 1};
  bool inverse_time = false;
  Decimal inverse_f{0, 0};
  int64_t sync_feed_nm_per_min = 0;  // G33/G33.1: K times S (0: the modal feed)
  // G5.2: a control point to add (nurbs_add: 1 go on, 2 start anew from the
  // position); set whole when nurbs_add says so.
  uint8_t nurbs_add = 0;
  int32_t nurbs_order;
  bool nurbs_has_point;
  int64_t nurbs_first_weight, nurbs_x, nurbs_y, nurbs_weight;
  bool rest_skipped = false;  // M72 ran the saved modes in place of the rest of the line
  int16_t context_op = -1;  // M70 M71 M73 (tenths): what commit does to the level's context
  ModalContext context;     // M70/M73: the state saved (set whole when context_op says so)
  PointNm home_via{0, 0, 0};
  CyclePlan cycle{};
  SplinePlan spline;  // set whole by run_spline before anything reads it
  int16_t stop = -1;  // M0/M1/M2/M30/M60 in tenths
  CompOps comp;       // cutter compensation (off_flush and motion false unless it acts)
  Plan() {
    comp.off_flush = false;
    comp.motion = false;
  }
};

// A canned cycle's words, from the block or kept from the last one.
struct CycleWords {
  int64_t r_raw, z_raw;  // R and the plane axis's word as written, nm
  int64_t repeats;       // L
  int64_t q;             // G73/G83 peck, nm
  int64_t p_ms;          // dwell
  int64_t ijk[3];        // G87's I, J, K, nm
};

// Checks one block against a copy of the state; commit() applies it.
struct BlockRunner {
  Interp& in;
  const InterpState& cur;
  const GcodeBlock& b;
  GcodeDiag* d;
  InterpState nx;
  Plan plan;

  BlockRunner(Interp& interp, const GcodeBlock& block, GcodeDiag* diag)
      : in(interp), cur(interp.state_), b(block), d(diag), nx(interp.state_) {}

  GcodeError fail(GcodeError e, uint16_t col, const char* word) {
    d->code = e;
    d->col = col ? col : 1;
    int i = 0;
    for (; i < 15 && word[i]; ++i) d->word[i] = word[i];
    d->word[i] = 0;
    return e;
  }
  GcodeError fail_letter(GcodeError e, char letter) {
    const char w[2] = {letter, 0};
    return fail(e, b.col_of(letter), w);
  }
  GcodeError fail_code(GcodeError e, char letter, int16_t tenths, uint16_t col) {
    char w[16];
    gcode_code_text(letter, tenths, w);
    return fail(e, col, w);
  }

  // A length word in the block's units, range-checked against `limit`
  // (an X word halved in G7, as LinuxCNC reads it).
  GcodeError length(char letter, int64_t* nm, int64_t limit = kGcodeMaxCoordNm) {
    const Decimal& v = b.val(letter);
    *nm = decimal_to_nm(v, nx.inch);
    if (letter == 'X' && nx.diameter_x) *nm = div_round(*nm, 2);  // G7: a diameter
    if (abs64(*nm) > limit) return fail_letter(GcodeError::kNumberTooLarge, letter);
    return GcodeError::kOk;
  }
  GcodeError integer(char letter, int64_t lo, int64_t hi, int64_t* out) {
    if (!decimal_to_int(b.val(letter), out)) return fail_letter(GcodeError::kNotInteger, letter);
    if (*out < lo) return fail_letter(lo >= 0 ? GcodeError::kNegativeValue : GcodeError::kNumberTooLarge, letter);
    if (*out > hi) return fail_letter(GcodeError::kNumberTooLarge, letter);
    return GcodeError::kOk;
  }
  GcodeError check_pos(const PointNm& p, uint16_t col, const char* word) {
    for (int ax = 0; ax < 3; ++ax) {
      int64_t v = axis_val(p, ax);
      if (abs64(v) > kGcodeMaxCoordNm) {
        d->a_nm = v;
        return fail(GcodeError::kPositionOutOfRange, col, word);
      }
    }
    return GcodeError::kOk;
  }
  // Offsets from program to path frame after this block's modal changes.
  int64_t offset(int axis) const {
    return axis_val(nx.work_offset[nx.coord_system], axis) + axis_val(nx.g92, axis);
  }
  uint16_t motion_col() const { return b.g[kGMotion] >= 0 ? b.g_col[kGMotion] : b.first_col; }
  // A warning the program gets once (WarnOnce), quoting `word` and a length.
  void warn_once(uint16_t bit, GcodeError e, uint16_t col, const char* word, int64_t a_nm = 0);
  // Whether the block sets the units, names the first T, or makes the first
  // move before any G20/G21 (interp.cpp; at commit, the tool at `start`).
  void note_units(const PointNm& start);

  GcodeError run();
  GcodeError run_modes();
  GcodeError run_context(int m);
  bool context_rest_follows() const;
  GcodeError run_group0(int g0);
  GcodeError run_motion(int motion);
  GcodeError run_straight(int motion, bool g53);
  GcodeError run_sync(int motion);
  GcodeError run_nurbs(int motion);
  void commit_nurbs(CanonRecord* r);
  GcodeError run_arc(int motion);
  GcodeError run_cycle(int motion);
  GcodeError cycle_words(int motion, const char* w, CycleWords* out);
  GcodeError cycle_spindle(int motion, const char* w);
  GcodeError cycle_check_range(const char* w);
  void cycle_warnings(int motion, const char* w);
  GcodeError run_probe(int motion);
  // Polar coordinates (@, ^; interp_polar.cpp): LinuxCNC's checks of the
  // block, the words, a move's end point, a canned cycle's holes.
  GcodeError check_polar(bool axis_user0);
  char polar_letter() const;
  GcodeError polar_words(PolarWords* w);
  GcodeError polar_target(PointNm* to);
  GcodeError end_point(PointNm* to);
  GcodeError cycle_polar(const char* w);
  // G5, G5.1 (interp_spline.cpp).
  GcodeError run_spline(int motion);
  void commit_spline(CanonRecord* r);
  // A feed move needs a feed rate: F in force, else --default-feed (one
  // warning, at the first such move), else kFeedZero.
  GcodeError need_feed(uint16_t col, const char* word);
  GcodeError run_home(int g0);
  GcodeError check_unused(int g0, int motion);
  // Cutter radius compensation (interp_comp.cpp).
  GcodeError comp_mode();                         // G40, G41, G42, G41.1, G42.1
  GcodeError comp_forbid_m();                     // M codes LinuxCNC refuses while it is on
  GcodeError comp_forbid_modes();                 // G43/G49, G54.., G61/G64, G98/G99
  GcodeError comp_forbid_group0(int g0);          // G10 L2/L20, G28/G30, G28.1/G30.1, G92..
  // LinuxCNC's find_ends: while compensation is on and past its entry
  // move, incremental and unwritten axes count from the programmed point,
  // not from the compensated one (which is where the tool is).
  const PointNm& comp_base() const { return cur.comp.side && !cur.comp.first_move ? cur.comp.prog : cur.pos; }
  CompOps& comp_ops(CanonKind kind);
  GcodeError comp_straight(int motion, bool g53, const PointNm& to);
  GcodeError comp_arc_entry(int motion, const PointNm& to, bool has_r, int64_t r_abs);
  GcodeError comp_arc(int motion, const PointNm& to, int64_t ca, int64_t cb);
  GcodeError comp_check_queue();                  // the held records, this block applied
  bool comp_acts() const { return cur.comp.side || plan.comp.motion || in.comp_q_.n; }
  GcodeError comp_apply(CompQueue* q, const CanonRecord& r, PointNm at, const CompEmit* out) const;
  void comp_commit_motion(CanonRecord* r, const PointNm& start);
  void comp_commit_flush(const PointNm& tool);
  static void emit_now(void* interp, CanonRecord* r);  // CompEmit to the sink
  void commit();
};

}  // namespace dexmill

#endif
