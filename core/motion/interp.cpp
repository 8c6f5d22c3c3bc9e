// The RS274/NGC interpreter: checks a block against the modal state, then
// commits it. The order of execution within a block is LinuxCNC's
// (rs274ngc, execute_block / convert_*): feed mode, F, S, T, M6, spindle,
// coolant, dwell, plane, units, cutter compensation, tool length offset,
// coordinate system, path control, distance modes, retract mode, G10 / G28
// / G30 / G92, motion, stop.
#include "core/motion/interp.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/math/wide.h"
#include "core/motion/arc_center.h"
#include "core/motion/arc_chords.h"
#include "core/motion/cycles.h"

namespace dexmill {

namespace {

constexpr int64_t kMaxFeedUnitsPerMin = 1000000;
constexpr int64_t kMaxSpindleRpm = 1000000;
constexpr int64_t kMaxDwellS = 1000000;
constexpr int64_t kMaxRepeats = 1000000;
constexpr int64_t kMaxTurns = 10000;
constexpr int64_t kMaxToolNumber = 1000000000;
constexpr int64_t kMaxCycleMoves = 10000000;

inline int64_t& axis_ref(PointNm& p, int axis) { return axis == 0 ? p.x_nm : axis == 1 ? p.y_nm : p.z_nm; }
inline int64_t axis_val(const PointNm& p, int axis) { return axis == 0 ? p.x_nm : axis == 1 ? p.y_nm : p.z_nm; }
inline bool is_cycle(int m) { return m == 730 || m == 810 || m == 820 || m == 830 || m == 850 || m == 890; }
// |v|, saturating: INT64_MIN (a saturated huge number) stays beyond every limit.
inline int64_t abs64(int64_t v) { return v == INT64_MIN ? INT64_MAX : (v < 0 ? -v : v); }
constexpr char kAxisLetter[3] = {'X', 'Y', 'Z'};
inline int plane_axis_a(Plane p) { return p == Plane::kXY ? 0 : p == Plane::kZX ? 2 : 1; }
inline int plane_axis_b(Plane p) { return p == Plane::kXY ? 1 : p == Plane::kZX ? 0 : 2; }
inline int plane_axis_c(Plane p) { return p == Plane::kXY ? 2 : p == Plane::kZX ? 1 : 0; }

// Length of a 3D segment, nm (exact floor).
int64_t seg_length(const PointNm& a, const PointNm& b) {
  U128 s = u128_add(sum_sq_u128(b.x_nm - a.x_nm, b.y_nm - a.y_nm), sq_u128(b.z_nm - a.z_nm));
  return static_cast<int64_t>(isqrt_u128(s));
}

}  // namespace

// What a checked block will do when committed.
struct Plan {
  bool tool_change = false;
  bool spindle = false;
  bool coolant = false;
  bool dwell = false;
  int64_t dwell_ms = 0;
  enum Motion : uint8_t { kNone, kStraight, kArc, kCycle, kHome } motion = kNone;
  CanonKind straight_kind = CanonKind::kTraverse;
  PointNm target{0, 0, 0};
  CanonArc arc{Plane::kXY, {0, 0, 0}, 1};
  bool inverse_time = false;
  Decimal inverse_f{0, 0};
  PointNm home_via{0, 0, 0};
  CyclePlan cycle{};
  int16_t stop = -1;  // M0/M1/M2/M30/M60 in tenths
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
    for (; word[i] && i < 15; ++i) d->word[i] = word[i];
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

  // A length word in the block's units, range-checked against `limit`.
  GcodeError length(char letter, int64_t* nm, int64_t limit = kGcodeMaxCoordNm) {
    const Decimal& v = b.val(letter);
    *nm = decimal_to_nm(v, nx.inch);
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

  GcodeError run();
  GcodeError run_modes();
  GcodeError run_group0(int g0);
  GcodeError run_motion(int motion);
  GcodeError run_straight(int motion, bool g53);
  GcodeError run_arc(int motion);
  GcodeError run_cycle(int motion);
  GcodeError run_home(int g0);
  GcodeError check_unused(int g0, int motion);
  void commit();
};

GcodeError BlockRunner::run() {
  const int g0 = b.g[kGNonModal];
  const int gm = b.g[kGMotion];
  const bool tlo_axes = b.g[kGToolLength] == 431;
  const bool axis_user0 = g0 == 100 || g0 == 280 || g0 == 300 || g0 == 920 || tlo_axes;
  if (gm >= 0 && gm != 800 && axis_user0) {
    return fail_code(GcodeError::kTwoAxisUsers, 'G', static_cast<int16_t>(tlo_axes ? 431 : g0),
                     tlo_axes ? b.g_col[kGToolLength] : b.g_col[kGNonModal]);
  }
  int motion = -1;  // the motion this block makes, in tenths
  if (gm >= 0) {
    motion = gm;
  } else if (b.has_axis() && !axis_user0) {
    motion = cur.motion;
  }
  if (b.has_axis() && !axis_user0 && motion == 800) {
    if (gm == 800) return fail_code(GcodeError::kAxisWordsWithG80, 'G', 800, b.g_col[kGMotion]);
    const char ax = b.has_word('X') ? 'X' : b.has_word('Y') ? 'Y' : 'Z';
    return fail_letter(GcodeError::kAxisWordsUnused, ax);
  }
  GcodeError e = check_unused(g0, motion);
  if (e != GcodeError::kOk) return e;
  e = run_modes();
  if (e != GcodeError::kOk) return e;
  if (g0 >= 0 && g0 != 530 && g0 != 40) {
    e = run_group0(g0);
    if (e != GcodeError::kOk) return e;
  }
  if (g0 == 530 && motion != 0 && motion != 10) return fail_code(GcodeError::kG53BadMotion, 'G', 530, b.g_col[kGNonModal]);
  if (motion >= 0) {
    e = run_motion(motion);
    if (e != GcodeError::kOk) return e;
  }
  if (b.m[kMStop] >= 0) {
    plan.stop = b.m[kMStop];
    if (plan.stop == 20 || plan.stop == 300) nx.ended = true;
  }
  return GcodeError::kOk;
}

// Words that no code of the block uses are errors, as in LinuxCNC.
GcodeError BlockRunner::check_unused(int g0, int motion) {
  const bool arc = motion == 20 || motion == 30;
  const bool cycle = is_cycle(motion);
  const bool user_m = b.m[kMUser] >= 0 || b.m[kMIo] >= 0;
  const int path = b.g[kGPathControl];
  if (!arc) {
    const char ijk[3] = {'I', 'J', 'K'};
    for (char c : ijk)
      if (b.has_word(c)) return fail_letter(GcodeError::kWordUnused, c);
  }
  if (b.has_word('R') && !arc && !cycle && g0 != 100) return fail_letter(GcodeError::kWordUnused, 'R');
  if (b.has_word('P') && !(g0 == 40 || g0 == 100 || path == 640 || arc || motion == 820 || motion == 890 || user_m))
    return fail_letter(GcodeError::kWordUnused, 'P');
  if (b.has_word('Q') && !(motion == 730 || motion == 830 || path == 640 || b.m[kMToolChange] == 610 || user_m))
    return fail_letter(GcodeError::kWordUnused, 'Q');
  if (b.has_word('L') && !(g0 == 100 || cycle)) return fail_letter(GcodeError::kWordUnused, 'L');
  if (b.has_word('H') && b.g[kGToolLength] != 430) return fail_letter(GcodeError::kWordUnused, 'H');
  if (b.has_word('D')) return fail_letter(GcodeError::kWordUnused, 'D');
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_modes() {
  GcodeError e;
  // Units first: every length of the block is in the units the block sets.
  if (b.g[kGUnits] >= 0) nx.inch = b.g[kGUnits] == 200;
  if (b.g[kGFeedMode] >= 0) {
    // LinuxCNC sets F to 0 on every G93 or G94 (the block's own F comes after).
    nx.inverse_time = b.g[kGFeedMode] == 930;
    nx.feed_nm_per_min = 0;
  }
  if (b.has_word('F')) {
    const Decimal& f = b.val('F');
    if (decimal_is_negative(f)) return fail_letter(GcodeError::kNegativeValue, 'F');
    if (decimal_scale(f, 1) > kMaxFeedUnitsPerMin) return fail_letter(GcodeError::kNumberTooLarge, 'F');
    if (nx.inverse_time) {
      plan.inverse_f = f;
    } else {
      nx.feed_nm_per_min = decimal_to_nm(f, nx.inch);
    }
  }
  if (b.has_word('S')) {
    const Decimal& s = b.val('S');
    if (decimal_is_negative(s)) return fail_letter(GcodeError::kNegativeValue, 'S');
    int64_t rpm = decimal_scale(s, 1);
    if (rpm > kMaxSpindleRpm) return fail_letter(GcodeError::kNumberTooLarge, 'S');
    nx.spindle_rpm = static_cast<int32_t>(rpm);
  }
  if (b.has_word('T')) {
    int64_t t;
    if ((e = integer('T', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
    nx.selected_tool = static_cast<int32_t>(t);
  }
  if (b.m[kMToolChange] == 60) {
    nx.tool = nx.selected_tool;
    plan.tool_change = true;
  } else if (b.m[kMToolChange] == 610) {  // M61 Q: set the tool number without a change
    if (!b.has_word('Q')) return fail_code(GcodeError::kWordUnused, 'M', 610, b.m_col[kMToolChange]);
    int64_t t;
    if ((e = integer('Q', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
    nx.tool = nx.selected_tool = static_cast<int32_t>(t);
    plan.tool_change = true;
  }
  if (b.m[kMSpindle] >= 0 && b.m[kMSpindle] != 190)
    nx.spindle_dir = static_cast<int8_t>(b.m[kMSpindle] == 30 ? 1 : b.m[kMSpindle] == 40 ? -1 : 0);
  const int32_t old_rpm = cur.spindle_dir * cur.spindle_rpm, new_rpm = nx.spindle_dir * nx.spindle_rpm;
  plan.spindle = old_rpm != new_rpm;
  if (b.coolant_bits) {
    nx.coolant = (b.coolant_bits & 4) ? 0 : static_cast<uint8_t>(nx.coolant | (b.coolant_bits & 3));
    plan.coolant = true;
  }
  if (b.g[kGNonModal] == 40) {
    if (!b.has_word('P')) return fail_code(GcodeError::kDwellNoP, 'G', 40, b.g_col[kGNonModal]);
    const Decimal& p = b.val('P');
    if (decimal_is_negative(p)) return fail_letter(GcodeError::kNegativeValue, 'P');
    int64_t ms = decimal_scale(p, 1000);
    if (ms > kMaxDwellS * 1000) return fail_letter(GcodeError::kNumberTooLarge, 'P');
    plan.dwell = true;
    plan.dwell_ms = ms;
  }
  if (b.g[kGPlane] >= 0) nx.plane = b.g[kGPlane] == 170 ? Plane::kXY : b.g[kGPlane] == 180 ? Plane::kZX : Plane::kYZ;
  if (b.g[kGToolLength] == 490) {
    nx.tlo_nm = 0;
  } else if (b.g[kGToolLength] == 430) {
    int64_t t = nx.tool;
    if (b.has_word('H')) {
      if ((e = integer('H', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
    }
    int64_t len = 0;
    if (in.options_.tools && t != 0 && !in.options_.tools->tool_length_nm(static_cast<int32_t>(t), &len))
      return b.has_word('H') ? fail_letter(GcodeError::kToolUnknown, 'H')
                             : fail_code(GcodeError::kToolUnknown, 'G', 430, b.g_col[kGToolLength]);
    if (abs64(len) > kGcodeMaxCoordNm) return fail_code(GcodeError::kNumberTooLarge, 'G', 430, b.g_col[kGToolLength]);
    nx.tlo_nm = len;
  } else if (b.g[kGToolLength] == 431) {
    // G43.1: the axis words are the offset; only Z is kept (X/Y offsets are
    // for lathes and are not carried by the canonical record).
    int64_t z = 0;
    if (b.has_word('X')) return fail_letter(GcodeError::kUnsupportedAxis, 'X');
    if (b.has_word('Y')) return fail_letter(GcodeError::kUnsupportedAxis, 'Y');
    if (b.has_word('Z') && (e = length('Z', &z)) != GcodeError::kOk) return e;
    nx.tlo_nm = z;
  }
  if (nx.tlo_nm != cur.tlo_nm) {
    // The spindle stays where it is, so the controlled point (the tool tip,
    // machine position minus the offset) moves by the change, as in LinuxCNC.
    nx.pos.z_nm = cur.pos.z_nm - (nx.tlo_nm - cur.tlo_nm);
    char w[16];
    gcode_code_text('G', b.g[kGToolLength], w);
    if ((e = check_pos(nx.pos, b.g_col[kGToolLength], w)) != GcodeError::kOk) return e;
  }
  if (b.g[kGCoordSystem] >= 0) {
    const int g = b.g[kGCoordSystem];
    nx.coord_system = static_cast<uint8_t>(g <= 590 ? (g - 540) / 10 : 6 + (g - 591));
  }
  if (b.g[kGPathControl] >= 0) nx.path_mode = b.g[kGPathControl];
  if (b.g[kGDistance] >= 0) nx.incremental = b.g[kGDistance] == 910;
  if (b.g[kGArcDistance] >= 0) nx.arc_absolute = b.g[kGArcDistance] == 901;
  if (b.g[kGRetract] >= 0) nx.retract_to_r = b.g[kGRetract] == 990;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_group0(int g0) {
  GcodeError e;
  const uint16_t col = b.g_col[kGNonModal];
  switch (g0) {
    case 100: {  // G10 L2 / L20: set a work offset
      if (!b.has_word('L')) return fail_code(GcodeError::kG10NoL, 'G', 100, col);
      int64_t l;
      if ((e = integer('L', 0, 100, &l)) != GcodeError::kOk) return e;
      if (l == 1 || l == 10 || l == 11) {
        char w[16];
        gcode_code_text('G', 100, w);
        in.warn(GcodeError::kWarnG10ToolTable, b.line, col, w);
        return GcodeError::kOk;
      }
      if (l != 2 && l != 20) return fail_letter(GcodeError::kG10BadL, 'L');
      if (!b.has_word('P')) return fail_code(GcodeError::kG10PNeeded, 'G', 100, col);
      int64_t p;
      if (!decimal_to_int(b.val('P'), &p) || p < 0 || p > 9) return fail_letter(GcodeError::kG10BadP, 'P');
      if (b.has_word('R') && !decimal_is_zero(b.val('R')))
        return fail_letter(GcodeError::kUnsupportedRotation, 'R');
      const int sys = p == 0 ? nx.coord_system : static_cast<int>(p - 1);
      for (int ax = 0; ax < 3; ++ax) {
        const char c = kAxisLetter[ax];
        if (!b.has_word(c)) continue;
        int64_t v;
        if ((e = length(c, &v)) != GcodeError::kOk) return e;
        // L2: the offset itself; L20: the offset that makes the current
        // position read v in that system.
        int64_t off = l == 2 ? v : axis_val(cur.pos, ax) - axis_val(nx.g92, ax) - v;
        if (abs64(off) > kGcodeMaxCoordNm) {
          d->a_nm = off;
          return fail_letter(GcodeError::kPositionOutOfRange, c);
        }
        axis_ref(nx.work_offset[sys], ax) = off;
      }
      return GcodeError::kOk;
    }
    case 280:
    case 300:
      return run_home(g0);
    case 281:
      nx.g28_home = PointNm{cur.pos.x_nm, cur.pos.y_nm, cur.pos.z_nm + nx.tlo_nm};
      return GcodeError::kOk;
    case 301:
      nx.g30_home = PointNm{cur.pos.x_nm, cur.pos.y_nm, cur.pos.z_nm + nx.tlo_nm};
      return GcodeError::kOk;
    case 920: {  // G92: the current point reads the given values
      if (!b.has_axis()) return fail_code(GcodeError::kG92NoAxis, 'G', 920, col);
      for (int ax = 0; ax < 3; ++ax) {
        const char c = kAxisLetter[ax];
        if (!b.has_word(c)) continue;
        int64_t v;
        if ((e = length(c, &v)) != GcodeError::kOk) return e;
        int64_t off = axis_val(cur.pos, ax) - axis_val(nx.work_offset[nx.coord_system], ax) - v;
        if (abs64(off) > kGcodeMaxCoordNm) {
          d->a_nm = off;
          return fail_letter(GcodeError::kPositionOutOfRange, c);
        }
        axis_ref(nx.g92, ax) = off;
      }
      nx.g92_saved = nx.g92;
      return GcodeError::kOk;
    }
    case 921:
      nx.g92 = nx.g92_saved = PointNm{0, 0, 0};
      return GcodeError::kOk;
    case 922:
      nx.g92 = PointNm{0, 0, 0};
      return GcodeError::kOk;
    case 923:
      nx.g92 = nx.g92_saved;
      return GcodeError::kOk;
    default:
      return GcodeError::kOk;
  }
}

// G28/G30: rapid to the given point (if any axis is given), then rapid the
// given axes (all when none is given) to the stored machine position.
GcodeError BlockRunner::run_home(int g0) {
  GcodeError e;
  const PointNm home = g0 == 280 ? nx.g28_home : nx.g30_home;
  PointNm via = cur.pos, to = cur.pos;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    const int64_t home_path = axis_val(home, ax) - (ax == 2 ? nx.tlo_nm : 0);
    if (!b.has_axis()) {
      axis_ref(to, ax) = home_path;
      continue;
    }
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    axis_ref(via, ax) = nx.incremental ? axis_val(cur.pos, ax) + v : v + offset(ax);
    axis_ref(to, ax) = home_path;
  }
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(g0), w);
  if ((e = check_pos(via, b.g_col[kGNonModal], w)) != GcodeError::kOk) return e;
  if ((e = check_pos(to, b.g_col[kGNonModal], w)) != GcodeError::kOk) return e;
  plan.motion = Plan::kHome;
  plan.home_via = via;
  plan.target = to;
  nx.pos = to;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_motion(int motion) {
  if (motion != cur.motion) {
    nx.motion = static_cast<int16_t>(motion);
    if (!is_cycle(motion)) nx.cycle_level_set = false;
  }
  if (motion == 800) return GcodeError::kOk;
  // G0/G1 written with no axis word make a move of length zero (LinuxCNC
  // emits it, and checks the feed of G1); a modal one on a line of other
  // words (F100 alone) makes none.
  if (!b.has_axis() && (motion == 0 || motion == 10) && b.g[kGMotion] < 0) return GcodeError::kOk;
  if (motion == 0 || motion == 10) return run_straight(motion, b.g[kGNonModal] == 530);
  if (motion == 20 || motion == 30) return run_arc(motion);
  if (!b.has_axis() && b.g[kGMotion] < 0) return GcodeError::kOk;
  return run_cycle(motion);
}

GcodeError BlockRunner::run_straight(int motion, bool g53) {
  GcodeError e;
  if (g53 && nx.incremental) return fail_code(GcodeError::kG53Incremental, 'G', 530, b.g_col[kGNonModal]);
  PointNm to = cur.pos;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    if (g53) axis_ref(to, ax) = v - (ax == 2 ? nx.tlo_nm : 0);
    else axis_ref(to, ax) = nx.incremental ? axis_val(cur.pos, ax) + v : v + offset(ax);
  }
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  if ((e = check_pos(to, motion_col(), w)) != GcodeError::kOk) return e;
  if (motion == 10) {
    if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, motion_col(), w);
    if (!nx.inverse_time && nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, motion_col(), w);
    if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  }
  plan.motion = Plan::kStraight;
  plan.straight_kind = motion == 0 ? CanonKind::kTraverse : CanonKind::kFeed;
  plan.target = to;
  plan.inverse_time = nx.inverse_time && motion == 10;
  nx.pos = to;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_arc(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  const Plane pl = nx.plane;
  const int ia = plane_axis_a(pl), ib = plane_axis_b(pl);
  // I, J, K belong to X, Y, Z; the one along the plane's axis is an error.
  const char off_letter[3] = {'I', 'J', 'K'};
  const char not_here = off_letter[plane_axis_c(pl)];
  if (b.has_word(not_here)) return fail_letter(GcodeError::kArcWordWrongPlane, not_here);
  const bool has_r = b.has_word('R');
  const bool has_ijk = b.has_word(off_letter[ia]) || b.has_word(off_letter[ib]);
  if (!has_r && !has_ijk) return fail(GcodeError::kArcNoCentre, col, w);
  if (has_r && has_ijk) return fail_letter(GcodeError::kArcRAndIjk, 'R');
  PointNm to = cur.pos;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    axis_ref(to, ax) = nx.incremental ? axis_val(cur.pos, ax) + v : v + offset(ax);
  }
  if ((e = check_pos(to, col, w)) != GcodeError::kOk) return e;
  int64_t turns = 1;
  if (b.has_word('P')) {
    if (!decimal_to_int(b.val('P'), &turns) || turns < 1) return fail_letter(GcodeError::kTurnsNotPositive, 'P');
    if (turns > kMaxTurns) return fail_letter(GcodeError::kNumberTooLarge, 'P');
  }
  if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, col, w);
  if (!nx.inverse_time && nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, col, w);
  if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  const ArcPlanar p{axis_val(cur.pos, ia), axis_val(cur.pos, ib), axis_val(to, ia), axis_val(to, ib)};
  int64_t ca, cb;
  if (has_r) {
    int64_t r;
    if ((e = length('R', &r, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    e = arc_centre_from_radius(p, r, motion == 20, &ca, &cb, &d->a_nm, &d->b_nm);
    if (e != GcodeError::kOk) return fail(e, b.g[kGMotion] >= 0 ? col : b.col_of('R'), w);
  } else {
    int64_t oa = 0, ob = 0;
    if (b.has_word(off_letter[ia]) && (e = length(off_letter[ia], &oa, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    if (b.has_word(off_letter[ib]) && (e = length(off_letter[ib], &ob, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    ca = nx.arc_absolute ? oa + offset(ia) : p.sa + oa;
    cb = nx.arc_absolute ? ob + offset(ib) : p.sb + ob;
    if (abs64(ca) > kGcodeMaxArcNm || abs64(cb) > kGcodeMaxArcNm) {
      d->a_nm = abs64(ca) > abs64(cb) ? ca : cb;
      return fail(GcodeError::kPositionOutOfRange, col, w);
    }
    e = arc_check_centre(p, ca, cb, nx.inch, &d->a_nm, &d->b_nm);
    if (e != GcodeError::kOk) {
      const uint16_t c = b.g[kGMotion] >= 0 ? col : b.col_of(b.has_word(off_letter[ia]) ? off_letter[ia] : off_letter[ib]);
      if (e == GcodeError::kArcZeroRadius) d->a_nm = d->a_nm < d->b_nm ? d->a_nm : d->b_nm;
      return fail(e, c, w);
    }
  }
  const int64_t sc = axis_val(cur.pos, plane_axis_c(pl));
  plan.motion = Plan::kArc;
  plan.target = to;
  plan.arc.plane = pl;
  plan.arc.centre = plane_point(pl, ca, cb, sc);
  plan.arc.turns = static_cast<int32_t>(motion == 20 ? -turns : turns);
  plan.inverse_time = nx.inverse_time;
  nx.pos = to;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_cycle(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  if (nx.inverse_time) return fail(GcodeError::kCycleInverseTime, col, w);
  if (nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, col, w);
  const bool same = cur.motion == motion;
  const Plane pl = nx.plane;
  const int ia = plane_axis_a(pl), ib = plane_axis_b(pl), ic = plane_axis_c(pl);
  const char lc = kAxisLetter[ic];
  int64_t r_raw = cur.cycle_r_nm, z_raw = cur.cycle_z_nm;
  if (b.has_word('R')) {
    if ((e = length('R', &r_raw)) != GcodeError::kOk) return e;
  } else if (!same) {
    return fail(GcodeError::kCycleNoR, col, w);
  }
  if (b.has_word(lc)) {
    if ((e = length(lc, &z_raw)) != GcodeError::kOk) return e;
  } else if (!same) {
    return fail(GcodeError::kCycleNoZ, col, w);
  }
  int64_t repeats = 1;
  if (b.has_word('L')) {
    if ((e = integer('L', 0, kMaxRepeats, &repeats)) != GcodeError::kOk) return e;
    if (repeats == 0) return fail_letter(GcodeError::kCycleZeroRepeats, 'L');
  }
  int64_t q = cur.cycle_q_nm, p_ms = cur.cycle_p_ms;
  if (motion == 730 || motion == 830) {
    if (b.has_word('Q')) {
      if ((e = length('Q', &q)) != GcodeError::kOk) return e;
    } else if (!same) {
      return fail(GcodeError::kCycleNoQ, col, w);
    }
    if (q <= 0) return b.has_word('Q') ? fail_letter(GcodeError::kCycleQNotPositive, 'Q')
                                       : fail(GcodeError::kCycleQNotPositive, col, w);
  }
  if (motion == 820 || motion == 890) {
    if (b.has_word('P')) {
      const Decimal& pv = b.val('P');
      if (decimal_is_negative(pv)) return fail_letter(GcodeError::kNegativeValue, 'P');
      p_ms = decimal_scale(pv, 1000);
      if (p_ms > kMaxDwellS * 1000) return fail_letter(GcodeError::kNumberTooLarge, 'P');
    } else if (!same) {
      return fail(GcodeError::kCycleNoP, col, w);
    }
  }
  CyclePlan& c = plan.cycle;
  c.code = static_cast<int16_t>(motion);
  c.plane = pl;
  c.repeats = repeats;
  c.q_nm = q;
  c.dwell_ms = p_ms;
  c.start_a = axis_val(cur.pos, ia);
  c.start_b = axis_val(cur.pos, ib);
  const int64_t cur_c = axis_val(cur.pos, ic);
  int64_t old_c = cur.cycle_level_set ? cur.cycle_level_nm : cur_c;
  nx.cycle_level_set = true;
  nx.cycle_level_nm = old_c;
  int64_t va = 0, vb = 0;
  const char la = kAxisLetter[ia], lb = kAxisLetter[ib];
  if (b.has_word(la) && (e = length(la, &va)) != GcodeError::kOk) return e;
  if (b.has_word(lb) && (e = length(lb, &vb)) != GcodeError::kOk) return e;
  if (nx.incremental) {
    // RS274/NGC: X, Y and R are increments from the current point and the
    // initial level, Z an increment from R.
    c.inc_a = va;
    c.inc_b = vb;
    c.a = c.start_a;
    c.b = c.start_b;
    c.r_c = r_raw + old_c;
    c.bottom_c = c.r_c + z_raw;
  } else {
    c.inc_a = c.inc_b = 0;
    c.a = b.has_word(la) ? va + offset(ia) : c.start_a;
    c.b = b.has_word(lb) ? vb + offset(ib) : c.start_b;
    c.r_c = r_raw + offset(ic);
    c.bottom_c = z_raw + offset(ic);
  }
  if (c.r_c < c.bottom_c) {
    d->a_nm = c.r_c;
    d->b_nm = c.bottom_c;
    return fail(GcodeError::kCycleRBelowZ, col, w);
  }
  c.current_c = cur_c;
  c.raise_first = old_c < c.r_c;
  if (c.raise_first) {
    old_c = c.r_c;
    c.current_c = c.r_c;
  }
  c.clear_c = nx.retract_to_r ? c.r_c : old_c;
  // Range: the holes lie on a line, so its ends bound it; levels likewise.
  const int64_t last_a = c.a + c.inc_a * repeats, last_b = c.b + c.inc_b * repeats;
  const int64_t levels[4] = {c.r_c, c.bottom_c, c.clear_c, c.current_c};
  for (int64_t lv : levels) {
    if ((e = check_pos(plane_point(pl, last_a, last_b, lv), col, w)) != GcodeError::kOk) return e;
    if ((e = check_pos(plane_point(pl, c.a + c.inc_a, c.b + c.inc_b, lv), col, w)) != GcodeError::kOk) return e;
  }
  if (motion == 730 || motion == 830) {
    const int64_t pecks = cycle_peck_count(c.r_c, c.bottom_c, q);
    if (pecks > kMaxCycleMoves / repeats) return b.has_word('Q') ? fail_letter(GcodeError::kNumberTooLarge, 'Q')
                                                                 : fail(GcodeError::kNumberTooLarge, col, w);
  }
  nx.cycle_r_nm = r_raw;
  nx.cycle_z_nm = z_raw;
  nx.cycle_q_nm = q;
  nx.cycle_p_ms = p_ms;
  plan.motion = Plan::kCycle;
  nx.pos = plane_point(pl, last_a, last_b, c.clear_c);
  return GcodeError::kOk;
}

namespace {

// Feeds a cycle's moves to the sink as records.
struct CycleRecords final : CycleOut {
  Interp* in;
  CanonRecord* base;
  PointNm at;
  void (*emit)(Interp*, CanonRecord*);
  void move(CanonKind kind, const PointNm& to) override {
    base->kind = kind;
    base->start = at;
    base->end = to;
    at = to;
    emit(in, base);
  }
  void dwell(int64_t ms) override {
    base->kind = CanonKind::kDwell;
    base->start = base->end = at;
    base->dwell_ms = ms;
    emit(in, base);
    base->dwell_ms = 0;
  }
};

// Length of an arc or helix record, nm (for G93 feed rates).
int64_t arc_length(const CanonRecord& r) {
  ArcChords ch;
  ch.init(r, 1000000);
  const Plane p = r.arc.plane;
  const int64_t ra = hypot_floor(plane_a(p, r.start) - plane_a(p, r.arc.centre), plane_b(p, r.start) - plane_b(p, r.arc.centre));
  int64_t sweep = ch.sweep_bam();
  if (sweep < 0) sweep = -sweep;
  // r * sweep * 2 pi / 2^32, with 2 pi = 6283185307 / 1e9.
  const int64_t planar = muldiv_round(muldiv_round(ra, sweep, static_cast<int64_t>(1) << 32), 6283185307, 1000000000);
  const int64_t dc = plane_c(p, r.end) - plane_c(p, r.start);
  return static_cast<int64_t>(isqrt_u128(sum_sq_u128(planar, dc)));
}

}  // namespace

void BlockRunner::commit() {
  Interp& I = in;
  const PointNm start = cur.pos;
  I.state_ = nx;
  CanonRecord r{};
  r.line = b.line;
  r.start = r.end = start;
  r.arc = CanonArc{Plane::kXY, start, 1};
  r.feed_nm_per_min = nx.feed_nm_per_min;
  r.tool = nx.tool;
  r.tool_length_offset_nm = nx.tlo_nm;
  if (plan.tool_change) {
    r.kind = CanonKind::kToolChange;
    I.emit(&r);
  }
  if (plan.spindle) {
    r.kind = CanonKind::kSpindle;
    r.spindle_rpm = nx.spindle_dir * nx.spindle_rpm;
    I.emit(&r);
  }
  r.spindle_rpm = nx.spindle_dir * nx.spindle_rpm;
  if (plan.coolant) {
    r.kind = CanonKind::kCoolant;
    r.coolant = nx.coolant;
    I.emit(&r);
  }
  r.coolant = nx.coolant;
  if (plan.dwell) {
    r.kind = CanonKind::kDwell;
    r.dwell_ms = plan.dwell_ms;
    I.emit(&r);
    r.dwell_ms = 0;
  }
  switch (plan.motion) {
    case Plan::kNone:
      break;
    case Plan::kStraight:
      r.kind = plan.straight_kind;
      r.end = plan.target;
      if (plan.inverse_time) r.feed_nm_per_min = decimal_scale(plan.inverse_f, seg_length(start, plan.target));
      I.emit(&r);
      break;
    case Plan::kArc:
      r.kind = CanonKind::kArc;
      r.end = plan.target;
      r.arc = plan.arc;
      if (plan.inverse_time) r.feed_nm_per_min = decimal_scale(plan.inverse_f, arc_length(r));
      I.emit(&r);
      break;
    case Plan::kHome:
      r.kind = CanonKind::kTraverse;
      r.end = plan.home_via;
      I.emit(&r);
      r.start = plan.home_via;
      r.end = plan.target;
      I.emit(&r);
      break;
    case Plan::kCycle: {
      CycleRecords out;
      out.in = &I;
      out.base = &r;
      out.at = start;
      out.emit = [](Interp* interp, CanonRecord* rec) { interp->emit(rec); };
      cycle_emit(plan.cycle, &out);
      break;
    }
  }
  if (plan.stop >= 0) {
    r.start = r.end = nx.pos;
    r.kind = (plan.stop == 20 || plan.stop == 300) ? CanonKind::kEnd : CanonKind::kPause;
    I.emit(&r);
  }
}

Interp::Interp(CanonSink* sink, const InterpOptions& options) : sink_(sink), options_(options) { reset(); }

void Interp::reset() {
  state_ = InterpState{};
  state_.motion = 800;
  state_.plane = Plane::kXY;
  state_.inch = options_.inch;
  state_.path_mode = 640;
  records_ = 0;
  warned_after_end_ = false;
}

void Interp::emit(CanonRecord* r) {
  ++records_;
  if (sink_) sink_->emit(*r);
}

void Interp::warn(GcodeError code, uint32_t line, uint16_t col, const char* word) {
  if (!options_.warnings) return;
  GcodeDiag d{};
  d.code = code;
  d.line = line;
  d.col = col ? col : 1;
  int i = 0;
  for (; word && word[i] && i < 15; ++i) d.word[i] = word[i];
  d.word[i] = 0;
  options_.warnings->warning(d);
}

GcodeError Interp::execute_line(const char* text, size_t len, uint32_t line, GcodeDiag* diag) {
  GcodeBlock block;
  GcodeLineKind kind;
  GcodeError e = gcode_read_block(text, len, line, &block, &kind, diag);
  if (state_.ended) {
    // RS274/NGC: nothing after the end is read. Say so once if it looks like code.
    if (!warned_after_end_ && (e != GcodeError::kOk || (kind == GcodeLineKind::kBlock && block.has) ||
                               kind == GcodeLineKind::kGrblCommand)) {
      warned_after_end_ = true;
      warn(GcodeError::kWarnAfterEnd, line, 1, "");
    }
    return GcodeError::kOk;
  }
  if (e != GcodeError::kOk) return e;
  switch (kind) {
    case GcodeLineKind::kPercent:
      // The first % opens the program; a second one ends it.
      if (state_.percent_open) state_.ended = true;
      state_.percent_open = true;
      return GcodeError::kOk;
    case GcodeLineKind::kProgramNumber:
      return GcodeError::kOk;
    case GcodeLineKind::kGrblCommand:
      warn(GcodeError::kWarnGrblCommand, line, diag->col, diag->word);
      return GcodeError::kOk;
    case GcodeLineKind::kBlock:
      break;
  }
  // Ignored M codes: warn, then run the rest of the block.
  const int ignored_groups[3] = {kMOverride, kMIo, kMUser};
  for (int g : ignored_groups) {
    if (block.m[g] >= 0) {
      char w[16];
      gcode_code_text('M', block.m[g], w);
      warn(GcodeError::kWarnMcodeIgnored, line, block.m_col[g], w);
    }
  }
  if (block.m[kMSpindle] == 190) warn(GcodeError::kWarnMcodeIgnored, line, block.m_col[kMSpindle], "M19");
  BlockRunner run(*this, block, diag);
  e = run.run();
  if (e != GcodeError::kOk) {
    diag->line = line;
    return e;
  }
  run.commit();
  return GcodeError::kOk;
}

uint32_t interp_run_text(Interp* in, const char* text, size_t len, GcodeDiag* first) {
  uint32_t errors = 0, line = 1;
  size_t start = 0;
  for (size_t i = 0; i <= len; ++i) {
    if (i < len && text[i] != '\n') continue;
    if (i == len && start == len) break;  // no empty line after a final '\n'
    GcodeDiag d;
    if (in->execute_line(text + start, i - start, line, &d) != GcodeError::kOk) {
      if (errors++ == 0 && first) *first = d;
    }
    ++line;
    start = i + 1;
  }
  return errors;
}

}  // namespace dexmill
