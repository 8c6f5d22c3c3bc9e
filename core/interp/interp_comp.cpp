// The interpreter's cutter radius compensation, as LinuxCNC 2.9 does it
// (rs274ngc interp_convert.cc: convert_cutter_compensation_on/off,
// convert_straight_comp1/comp2, convert_arc_comp1/comp2, and the checks
// that refuse other codes while it is on; interp_find.cc find_ends). The
// geometry helpers and the queue are core/interp/cutter_comp.{h,cpp}.
//
// While compensation is on, InterpState::pos is LinuxCNC's current point:
// where the compensated tool is; comp.prog is the programmed point, from
// which incremental and unwritten axes count. G40 makes the programmed
// point current and leaves the tool where it is (InterpState::stray), so the
// exit move starts from the tool.
#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/interp/arc_center.h"
#include "core/canon/arc_chords.h"
#include "core/interp/block_runner.h"

namespace dexmill {

namespace {

constexpr uint32_t kQuarter = kBamQuarterTurn;
constexpr uint32_t kHalf = kBamHalfTurn;
constexpr int64_t kSmall = kCompCornerTolBam;
// LinuxCNC refuses the first arc of compensation when |cos A| < 1e-4
// (TOLERANCE_EQUAL), A the angle at the new end: 1e-4 in q30.
constexpr int32_t kCosTolQ30 = 107374;

Vec2 sub(Vec2 p, Vec2 q) { return Vec2{p.a - q.a, p.b - q.b}; }
// Points 2^16 times finer than a nanometre, and back (|v| <= 100 m fits).
constexpr int kFineBits = 16;
Vec2 fine(Vec2 v) { return Vec2{v.a * (int64_t{1} << kFineBits), v.b * (int64_t{1} << kFineBits)}; }
int64_t fine(int64_t v) { return v * (int64_t{1} << kFineBits); }
Vec2 unfine(Vec2 v) {
  return Vec2{div_round(v.a, int64_t{1} << kFineBits), div_round(v.b, int64_t{1} << kFineBits)};
}
bool same(Vec2 p, Vec2 q) { return p.a == q.a && p.b == q.b; }
// An angle difference as LinuxCNC normalises beta: [-pi/2, 3pi/2).
int64_t beta_of(uint32_t d) { return static_cast<int64_t>(static_cast<uint32_t>(d + kQuarter)) - kQuarter; }
// The direction of travel of an arc at point p on it (turn > 0: counterclockwise).
Vec2 arc_tangent(Vec2 centre, Vec2 p, int32_t turn) {
  const Vec2 r = sub(p, centre);
  return turn > 0 ? Vec2{-r.b, r.a} : Vec2{r.b, -r.a};
}

}  // namespace

void BlockRunner::emit_now(void* interp, CanonRecord* r) { static_cast<Interp*>(interp)->emit_now(r); }

// G40 / G41 / G42 / G41.1 / G42.1 (convert_cutter_compensation_on/off), in
// LinuxCNC's order: after the plane and units, before the tool length.
GcodeError BlockRunner::comp_mode() {
  const int g = b.g[kGCutterComp];
  if (g < 0) return GcodeError::kOk;
  const uint16_t col = b.g_col[kGCutterComp];
  const int16_t code = static_cast<int16_t>(g);
  if (g == 400) {
    if (nx.comp.side && nx.comp.radius_nm > 0 && !nx.comp.first_move) {
      // The held moves end where the tool is and go; the programmed point
      // becomes the current one, the tool stays (the exit move starts there).
      plan.comp.off_flush = true;
      const PointNm tool = tool_at(nx);
      nx.pos = nx.comp.prog;
      nx.stray = PointNm{tool.x_nm - nx.pos.x_nm, tool.y_nm - nx.pos.y_nm, tool.z_nm - nx.pos.z_nm};
      nx.comp.arc_not_allowed = true;
    }
    nx.comp.side = 0;
    nx.comp.first_move = true;
    return GcodeError::kOk;
  }
  if (nx.plane == Plane::kYZ) return fail_code(GcodeError::kCompPlane, 'G', code, col);
  if (nx.comp.side) return fail_code(GcodeError::kCompOnWhenOn, 'G', code, col);
  int side = g == 410 || g == 411 ? 1 : -1;
  int64_t radius = 0;
  GcodeError e;
  if (g == 411 || g == 421) {  // the D word is the diameter
    if (!b.has_word('D')) return fail_code(GcodeError::kCompNoD, 'G', code, col);
    if (b.has_word('L')) return fail_code(GcodeError::kUnsupportedCompOrientation, 'G', code, col);
    int64_t dia;
    if ((e = length('D', &dia)) != GcodeError::kOk) return e;
    radius = div_round(dia, 2);
  } else {
    // D names the tool (LinuxCNC takes a number within 1e-4 of a whole
    // one); D0 or none: the tool in the spindle.
    int64_t tool = 0;
    if (b.has_word('D')) {
      const int64_t micro = decimal_scale(b.val('D'), 1000000);
      tool = div_round(micro, 1000000);
      if (abs64(micro - tool * 1000000) >= 100) return fail_letter(GcodeError::kNotInteger, 'D');
      if (tool < 0) return fail_letter(GcodeError::kNegativeValue, 'D');
      if (tool > kMaxToolNumber) return fail_letter(GcodeError::kNumberTooLarge, 'D');
    }
    if (tool == 0) tool = nx.tool;
    const ToolTable* t = in.options_.tools;
    if (!t) {
      char w[16];
      gcode_code_text('G', code, w);
      warn_once(kOnceCompNoTable, GcodeError::kWarnCompNoTable, col, w);
    } else if (tool != 0 && !t->tool_radius_nm(static_cast<int32_t>(tool), &radius)) {
      return b.has_word('D') ? fail_letter(GcodeError::kToolUnknown, 'D')
                             : fail_code(GcodeError::kToolUnknown, 'G', code, col);
    }
    if (abs64(radius) > kGcodeMaxCoordNm) return fail_code(GcodeError::kNumberTooLarge, 'G', code, col);
  }
  // A negative radius (a tool smaller than the nominal one the path was made
  // for) swaps the side.
  if (radius < 0) {
    radius = -radius;
    side = -side;
  }
  nx.comp.side = static_cast<int8_t>(side);
  nx.comp.radius_nm = radius;
  return GcodeError::kOk;
}

// M codes LinuxCNC refuses while compensation is on (convert_m runs before
// G40 is read, so the state before the block counts): M6, the override
// switches M48/M49 and M50-M53 (unless P0), the I/O codes M62-M68.
GcodeError BlockRunner::comp_forbid_m() {
  if (!cur.comp.side) return GcodeError::kOk;
  if (b.m[kMToolChange] == 60) return fail_code(GcodeError::kCompForbidden, 'M', 60, b.m_col[kMToolChange]);
  const int io = b.m[kMIo];
  if (io >= 620 && io <= 680) return fail_code(GcodeError::kCompForbidden, 'M', static_cast<int16_t>(io), b.m_col[kMIo]);
  const int ov = b.m[kMOverride];
  const bool p0 = b.has_word('P') && decimal_is_zero(b.val('P'));
  if (ov == 480 || ov == 490 || (ov >= 500 && ov <= 530 && !p0))
    return fail_code(GcodeError::kCompForbidden, 'M', static_cast<int16_t>(ov), b.m_col[kMOverride]);
  return GcodeError::kOk;
}

// Modal codes LinuxCNC refuses while compensation is on, in its order of
// execution (tool length, coordinate system, path control, retract mode),
// with the compensation this block leaves.
GcodeError BlockRunner::comp_forbid_modes() {
  if (!nx.comp.side) return GcodeError::kOk;
  const int groups[4] = {kGToolLength, kGCoordSystem, kGPathControl, kGRetract};
  for (int gr : groups)
    if (b.g[gr] >= 0) return fail_code(GcodeError::kCompForbidden, 'G', b.g[gr], b.g_col[gr]);
  return GcodeError::kOk;
}

// Group 0: G10 L2/L20 on the coordinate system in use, G28/G30, G28.1/G30.1,
// G92 and its kin.
GcodeError BlockRunner::comp_forbid_group0(int g0) {
  if (!nx.comp.side) return GcodeError::kOk;
  bool refused = g0 == 280 || g0 == 300 || g0 == 281 || g0 == 301 || (g0 >= 920 && g0 <= 923);
  if (g0 == 100 && b.has_word('P')) {
    int64_t l = 0, p = -1;
    if (b.has_word('L') && decimal_to_int(b.val('L'), &l) && (l == 2 || l == 20) && decimal_to_int(b.val('P'), &p))
      refused = p == 0 || p - 1 == nx.coord_system;
  }
  if (refused) return fail_code(GcodeError::kCompForbidden, 'G', static_cast<int16_t>(g0), b.g_col[kGNonModal]);
  return GcodeError::kOk;
}

// The block's move is compensated: CompOps from nothing done yet.
CompOps& BlockRunner::comp_ops(CanonKind kind) {
  CompOps& o = plan.comp;
  o.motion = true;
  o.flush = CompOps::kKeep;
  o.corner = false;
  o.set_endpoint = false;
  o.kind = kind;
  o.dir_a = o.dir_b = o.sweep_bam = 0;
  o.prog_start = comp_base();
  return o;
}

// G0/G1 with compensation (convert_straight_comp1, convert_straight_comp2).
// `to` is the programmed end; plan and nx.pos are for the uncompensated move.
GcodeError BlockRunner::comp_straight(int motion, bool g53, const PointNm& to) {
  if (nx.comp.radius_nm == 0) return GcodeError::kOk;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  if (g53) return fail_code(GcodeError::kCompForbidden, 'G', 530, b.g_col[kGNonModal]);
  const Plane pl = nx.plane;
  const int side = nx.comp.side;
  const int64_t r = nx.comp.radius_nm;
  const Vec2 p = comp_plane_xy(pl, to), c = comp_plane_xy(pl, cur.pos);
  const int64_t cz = plane_c(pl, cur.pos), pz = plane_c(pl, to);
  CompOps& o = comp_ops(motion == 0 ? CanonKind::kTraverse : CanonKind::kFeed);
  Vec2 end = c;
  if (nx.comp.first_move) {
    // The entry move: to the programmed end, offset square to the move.
    const Vec2 dv = sub(p, c);
    const int64_t dist = comp_length(dv);
    if (dist <= r) {
      d->a_nm = dist;
      d->b_nm = r;
      return fail(GcodeError::kCompEntryTooShort, motion_col(), w);
    }
    end = comp_polar(p, r, comp_normal_bam(comp_dir_bam(dv), side));
    o.set_endpoint = true;
    o.endpoint = c;
    // LinuxCNC records the normal as this move's direction.
    o.dir_a = side > 0 ? -dv.b : dv.b;
    o.dir_b = side > 0 ? dv.a : -dv.a;
    nx.comp.first_move = false;
    nx.comp.tan_a = dv.a;
    nx.comp.tan_b = dv.b;
  } else {
    const Vec2 op = comp_plane_xy(pl, cur.comp.prog);
    // No motion in the plane: held (direction 0) behind the last move, which
    // it follows wherever that move's end goes. Otherwise a corner.
    if (!same(p, op)) {
      const Vec2 dir = sub(p, op);
      const uint32_t theta = comp_normal_bam(comp_dir_bam(Vec2{cur.comp.tan_a, cur.comp.tan_b}), side);
      const uint32_t alpha = comp_dir_bam(dir);
      const int64_t beta = beta_of(side > 0 ? theta - alpha - kQuarter : alpha - theta - kQuarter);
      const uint32_t n = comp_normal_bam(alpha, side);
      end = comp_polar(p, r, n);
      const Vec2 mid = comp_polar(op, r, n);
      const CompQueue& q = in.comp_q_;
      const bool front_arc = q.n > 0 && q.e[0].rec.kind == CanonKind::kArc;
      const int32_t front_turn = front_arc ? q.e[0].rec.arc.turns : 0;
      // The "h" shape: the tool on the right going over an arc's top and
      // down beside a line (or the mirror case): LinuxCNC keeps it above.
      const bool concave = beta < -kSmall || beta > kHalf + kSmall ||
                           (beta > kHalf - kSmall && front_arc && ((side < 0 && front_turn > 0) || (side > 0 && front_turn < 0)));
      if (!concave && beta > kSmall) {
        // Convex: round the programmed corner; a rapid cannot, it goes
        // straight to the offset start of the new line.
        o.flush = CompOps::kMoveEnd;
        o.flush_to = c;
        o.corner = true;
        o.corner_kind = motion == 0 ? CanonKind::kTraverse : CanonKind::kArc;
        o.corner_end = comp_plane_point(pl, mid, cz);
        o.corner_centre = comp_plane_point(pl, op, cz);
        o.corner_turns = side > 0 ? -1 : 1;
        o.set_endpoint = true;
        o.endpoint = mid;
      } else if (concave) {
        Vec2 meet;
        if (!front_arc) {
          // Line after line: back the last move up by r / tan(half the
          // corner's outside angle).
          const uint32_t half_corner = static_cast<uint32_t>((beta + kHalf) / 2);
          const SinCosQ30 sc = sincos_bam(half_corner);
          const int64_t retreat = muldiv_round(r, sc.cos_q30, sc.sin_q30);
          meet = comp_polar(c, retreat, comp_dir_bam(Vec2{cur.comp.tan_a, cur.comp.tan_b}) + kHalf);
        } else {
          // Arc, then line: where the held (compensated) arc meets the new
          // offset line.
          const CanonRecord& prev = q.e[0].rec;
          const Vec2 pc = comp_plane_xy(pl, prev.arc.centre);
          const int64_t oldrad = comp_length(sub(comp_plane_xy(pl, prev.end), pc));
          const uint32_t th = prev.arc.turns > 0 ? alpha + kQuarter : alpha - kQuarter;
          const uint32_t phi = comp_dir_bam(sub(pc, op));
          const bool inside = comp_inside_arc(side, prev.arc.turns);
          const int64_t uncomp = inside ? oldrad + r : oldrad - r;
          const int64_t dd = muldiv_round(uncomp, sincos_bam(th - phi).cos_q30, int64_t{1} << 30);
          const int64_t d2 = inside ? dd - r : dd + r;
          if (abs64(d2) > oldrad) return fail(GcodeError::kCompArcLineGouge, motion_col(), w);
          const uint32_t ac = comp_acos_bam(d2, oldrad);
          const bool plus = inside ? prev.arc.turns < 0 : prev.arc.turns > 0;
          meet = comp_polar(pc, oldrad, plus ? th + kHalf + ac : th + kHalf - ac);
        }
        o.flush = CompOps::kMoveEnd;
        o.flush_to = meet;
      } else {
        // Straight on (or tangent after an arc).
        o.flush = CompOps::kDequeue;
        o.set_endpoint = true;
        o.endpoint = c;
      }
      o.dir_a = dir.a;
      o.dir_b = dir.b;
      nx.comp.tan_a = dir.a;
      nx.comp.tan_b = dir.b;
    }
  }
  o.end = comp_plane_point(pl, end, pz);
  nx.comp.prog = to;
  nx.pos = o.end;
  if ((check_pos(o.end, motion_col(), w)) != GcodeError::kOk) return d->code;
  return GcodeError::kOk;
}

// The checks of the first arc of compensation that LinuxCNC makes before
// it finds the centre (convert_arc_comp1, arc_data_comp_r).
GcodeError BlockRunner::comp_arc_entry(int motion, const PointNm& to, bool has_r, int64_t r_abs) {
  if (!nx.comp.side || nx.comp.radius_nm == 0 || !nx.comp.first_move) return GcodeError::kOk;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const Plane pl = nx.plane;
  const int64_t r = nx.comp.radius_nm;
  const int64_t dist = comp_length(sub(comp_plane_xy(pl, to), comp_plane_xy(pl, cur.pos)));
  if (dist <= r) {
    d->a_nm = dist;
    d->b_nm = r;
    return fail(GcodeError::kCompEntryArcTooShort, motion_col(), w);
  }
  const int32_t turn = motion == 30 ? 1 : -1;
  if (has_r && r_abs <= r && comp_inside_arc(nx.comp.side, turn)) {
    d->a_nm = r_abs;
    d->b_nm = r;
    return fail(GcodeError::kCompArcTooSmall, motion_col(), w);
  }
  return GcodeError::kOk;
}

// G2/G3 with compensation (convert_arc_comp1, convert_arc_comp2). The arc
// is checked and planned (plan.arc, plan.target) as programmed, from
// comp_base(); (ca, cb) is its centre.
GcodeError BlockRunner::comp_arc(int motion, const PointNm& to, int64_t ca, int64_t cb) {
  if (!nx.comp.side || nx.comp.radius_nm == 0) return GcodeError::kOk;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const Plane pl = nx.plane;
  const int side = nx.comp.side;
  const int64_t r = nx.comp.radius_nm;
  const int32_t turn = plan.arc.turns;
  const bool inside = comp_inside_arc(side, turn);
  const Vec2 e = comp_plane_xy(pl, to), c = comp_plane_xy(pl, cur.pos), centre{ca, cb};
  const int64_t cz = plane_c(pl, cur.pos), ez = plane_c(pl, to);
  CompOps& o = comp_ops(CanonKind::kArc);
  const uint32_t gamma = inside ? comp_dir_bam(sub(centre, e)) : comp_dir_bam(sub(e, centre));
  const Vec2 end = comp_polar(e, r, gamma);
  Vec2 new_centre = centre;
  if (nx.comp.first_move) {
    const int64_t radius_nm = comp_length(sub(c, centre));
    if (inside && radius_nm <= r) {
      d->a_nm = radius_nm;
      d->b_nm = r;
      return fail(GcodeError::kCompArcTooSmall, motion_col(), w);
    }
    // The compensated arc runs from the tool to the offset end, its centre
    // on the line from that end through the programmed centre, as far from
    // both: c_len = |C - end| / (2 cos A). Worked 2^16 times finer than a
    // nanometre: A is ill-conditioned when the new centre lies far away.
    const Vec2 ef = comp_polar(fine(e), fine(r), gamma);
    const Vec2 ce = sub(fine(c), ef);
    const uint32_t ab = comp_dir_bam(sub(fine(centre), ef));
    const int32_t cos_a = sincos_bam(comp_dir_bam(ce) - ab).cos_q30;
    if (cos_a > -kCosTolQ30 && cos_a < kCosTolQ30) {
      d->a_nm = comp_length(sub(e, centre));
      d->b_nm = r;
      return fail(GcodeError::kCompArcTooSmall, motion_col(), w);
    }
    const int64_t c_len = muldiv_round(comp_length(ce), int64_t{1} << 29, cos_a);
    new_centre = unfine(comp_polar(ef, c_len, ab));
    const int64_t r1 = comp_length(sub(new_centre, end)), r2 = comp_length(sub(new_centre, c));
    if (abs64(r1 - r2) > (nx.inch ? kArcSpiralTolInchNm : kArcSpiralTolMmNm))
      return fail(GcodeError::kCompInternal, motion_col(), w);
    o.sweep_bam = comp_find_turn(c, new_centre, turn, end);
    nx.comp.first_move = false;
  } else {
    const Vec2 op = comp_plane_xy(pl, cur.comp.prog);
    const int64_t arc_radius = comp_length(sub(centre, e));
    const uint32_t theta = comp_dir_bam(Vec2{cur.comp.tan_a, cur.comp.tan_b});
    uint32_t delta = comp_dir_bam(sub(centre, op));
    const uint32_t alpha = turn > 0 ? delta - kQuarter : delta + kQuarter;
    const int64_t beta = beta_of(side > 0 ? theta - alpha : alpha - theta);
    if (inside && arc_radius <= r) {
      d->a_nm = arc_radius;
      d->b_nm = r;
      return fail(GcodeError::kCompArcTooSmall, motion_col(), w);
    }
    if (!inside) delta += kHalf;
    const CompQueue& q = in.comp_q_;
    const bool front_arc = q.n > 0 && q.e[0].rec.kind == CanonKind::kArc;
    const int64_t off_half = beta - kHalf;
    // Convex where the tool goes round over the top of an arc tangent to
    // the path before it ("m" and "h" shapes) counts as concave.
    const bool concave = beta < -kSmall || beta > kHalf + kSmall || (off_half > -kSmall && off_half < kSmall && !inside);
    if (concave) {
      Vec2 meet;
      if (!front_arc) {
        // Line, then arc: where the offset line meets the offset arc.
        const int64_t cy = muldiv_round(arc_radius, sincos_bam(static_cast<uint32_t>(beta) - kQuarter).sin_q30,
                                        int64_t{1} << 30);
        const int64_t dist = inside ? arc_radius - r : arc_radius + r;
        const int64_t toward = inside ? cy + r : cy - r;
        if (abs64(toward) > dist) return fail(GcodeError::kCompLineArcGouge, motion_col(), w);
        const uint32_t as = comp_asin_bam(toward, dist);
        const uint32_t ang = inside ? (turn > 0 ? theta + as : theta - as) : (turn > 0 ? theta + kHalf - as : theta + kHalf + as);
        meet = comp_polar(centre, dist, ang);
      } else {
        // Arc, then arc: where the two offset circles cross.
        const CanonRecord& prev = q.e[0].rec;
        const Vec2 pc = comp_plane_xy(pl, prev.arc.centre);
        const int64_t oldrad = comp_length(sub(comp_plane_xy(pl, prev.end), pc));
        const int64_t newrad = inside ? arc_radius - r : arc_radius + r;
        const Vec2 cc = sub(centre, pc);
        const int64_t arc_cc = comp_length(cc);
        if (oldrad == 0 || arc_cc == 0) return fail(GcodeError::kCompArcSameCentre, motion_col(), w);
        // The crossing's distance along the line of centres from the old
        // centre (law of cosines), then the angle it makes there.
        const int64_t x = muldiv_round(oldrad - newrad, oldrad + newrad, 2 * arc_cc) + div_round(arc_cc, 2);
        if (abs64(x) > oldrad) return fail(GcodeError::kCompArcArcGouge, motion_col(), w);
        const uint32_t pullback = comp_acos_bam(x, oldrad);
        const uint32_t cc_dir = comp_dir_bam(cc);
        const bool plus = comp_inside_arc(side, prev.arc.turns) ? turn > 0 : turn < 0;
        meet = comp_polar(pc, oldrad, plus ? cc_dir + pullback : cc_dir - pullback);
      }
      o.flush = CompOps::kMoveEnd;
      o.flush_to = meet;
    } else if (beta > kSmall) {
      // Convex: an arc round the programmed corner first.
      const Vec2 mid = comp_polar(op, r, delta);
      o.flush = CompOps::kDequeue;
      o.corner = true;
      o.corner_kind = CanonKind::kArc;
      o.corner_end = comp_plane_point(pl, mid, cz);
      o.corner_centre = comp_plane_point(pl, op, cz);
      o.corner_turns = side > 0 ? -1 : 1;
      o.set_endpoint = true;
      o.endpoint = mid;
    } else {
      o.flush = CompOps::kDequeue;
      o.set_endpoint = true;
      o.endpoint = c;
    }
    o.sweep_bam = comp_find_turn(op, centre, turn, e);
  }
  const Vec2 tan = arc_tangent(centre, e, turn);
  nx.comp.tan_a = tan.a;
  nx.comp.tan_b = tan.b;
  o.end = comp_plane_point(pl, end, ez);
  o.arc = CanonArc{pl, comp_plane_point(pl, new_centre, cz), turn};
  nx.comp.prog = to;
  nx.pos = o.end;
  if ((check_pos(o.end, motion_col(), w)) != GcodeError::kOk) return d->code;
  return GcodeError::kOk;
}

// Steps 1-4 of CompOps on queue q (held records start at `at` when none is
// held); out null: only the errors (the block is being checked).
GcodeError BlockRunner::comp_apply(CompQueue* q, const CanonRecord& r, PointNm at, const CompEmit* out) const {
  const CompOps& o = plan.comp;
  const Plane pl = nx.plane;
  if (o.flush == CompOps::kDequeue) at = q->dequeue(out, at);
  if (o.flush == CompOps::kMoveEnd) {
    const GcodeError e = q->move_end_and_flush(pl, o.flush_to, nx.inch, out, &at);
    if (e != GcodeError::kOk) return e;
  }
  if (o.corner) {
    CanonRecord k = r;
    k.kind = o.corner_kind;
    k.start = at;
    k.end = o.corner_end;
    k.arc = CanonArc{pl, o.corner_centre, o.corner_turns};
    if (out) out->fn(out->ctx, &k);
    q->endpoint_valid = false;  // LinuxCNC held it and let it go at once
    at = o.corner_end;
  }
  if (o.set_endpoint) q->set_endpoint(o.endpoint);
  CanonRecord m = r;
  m.kind = o.kind;
  m.end = o.end;
  if (o.kind == CanonKind::kArc) m.arc = o.arc;
  return q->push(m, at, o.dir_a, o.dir_b, o.sweep_bam) ? GcodeError::kOk : GcodeError::kCompQueueFull;
}

// The block against a scratch copy of the held records: what G40, the move
// and a program stop do to them, and whether they fit.
GcodeError BlockRunner::comp_check_queue() {
  CompQueue& q = in.comp_scratch_;
  q.copy_from(in.comp_q_);
  const PointNm at = tool_at(cur);
  CanonRecord held{};
  held.kind = CanonKind::kDwell;
  // What the block makes before its move waits behind a held move.
  const int before = (plan.tool_change ? 1 : 0) + (plan.spindle ? 1 : 0) + (plan.coolant ? 1 : 0) + (plan.dwell ? 1 : 0);
  for (int i = 0; i < before && q.n > 0; ++i)
    if (!q.push(held, at, 0, 0, 0)) return fail(GcodeError::kCompQueueFull, b.first_col, "");
  GcodeError e;
  PointNm p = at;
  if (plan.comp.off_flush) {
    if ((e = q.move_end_and_flush(nx.plane, comp_plane_xy(nx.plane, cur.pos), nx.inch, nullptr, &p)) != GcodeError::kOk)
      return fail_code(e, 'G', 400, b.g_col[kGCutterComp]);
    q.dequeue(nullptr, p);
  }
  if (plan.comp.motion) {
    if ((e = comp_apply(&q, held, at, nullptr)) != GcodeError::kOk) {
      char w[16];
      gcode_code_text('G', nx.motion, w);
      return fail(e, motion_col(), w);
    }
  }
  if (plan.stop >= 0 && q.n > 0) {
    if ((e = q.move_end_and_flush(nx.plane, comp_plane_xy(nx.plane, nx.pos), nx.inch, nullptr, &p)) != GcodeError::kOk)
      return fail_code(e, 'M', plan.stop, b.m_col[kMStop]);
  }
  return GcodeError::kOk;
}

// The compensated move of a checked block, for real: `r` carries the
// block's feed, tool and the rest; `start` is where the tool is.
void BlockRunner::comp_commit_motion(CanonRecord* r, const PointNm& start) {
  const CompEmit out{&BlockRunner::emit_now, &in};
  (void)comp_apply(&in.comp_q_, *r, start, &out);  // checked with the block
}

// G40 that ended compensation (before the block's move), or a program stop
// (after it): the held moves end where the tool is, and go.
void BlockRunner::comp_commit_flush(const PointNm& tool) {
  const CompEmit out{&BlockRunner::emit_now, &in};
  PointNm at = tool;
  (void)in.comp_q_.move_end_and_flush(nx.plane, comp_plane_xy(nx.plane, tool), nx.inch, &out, &at);
  in.comp_q_.dequeue(&out, at);
}

}  // namespace dexmill
