// G5.2/G5.3 (LinuxCNC 2.9's convert_nurbs, its checks in its order): G5.2
// is a modal motion whose blocks each add a control point (X and Y, weight
// P); the first point is where G5.2 began, weight 1 (or the P of a G5.2
// block without X and Y); L above 3 sets the order (3 otherwise, and an L
// of 3 or less is ignored, as LinuxCNC ignores it). The position does not
// move while the points are read, so G91 points all count from where G5.2
// began, and a Z word is read and ignored, as in LinuxCNC; a block of
// another motion drops the points read. G5.3 makes the curve (nurbs.h)
// and leaves no motion mode in force.
#include "core/interp/block_runner.h"

namespace dexmill {

GcodeError BlockRunner::run_nurbs(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  const NurbsCurve& c = in.nurbs_;
  if (motion == 53) {
    if (cur.motion != 52) return fail(GcodeError::kNurbsNoStart, col, w);
    if (c.count < c.order) {
      d->a_nm = c.order;
      return fail(GcodeError::kNurbsTooFew, col, w);
    }
    if (!nurbs_weights_ok(c)) return fail(GcodeError::kNurbsTooMany, col, w);
    plan.motion = Plan::kNurbs;
    nx.pos.x_nm = c.x_nm[c.count - 1];
    nx.pos.y_nm = c.y_nm[c.count - 1];
    nx.motion = 800;  // LinuxCNC: no motion mode after G5.3
    return GcodeError::kOk;
  }
  const bool has_xy = b.has_word('X') && b.has_word('Y');
  if (b.has_word('X') != b.has_word('Y')) return fail(GcodeError::kNurbsXY, col, w);
  const bool fresh = cur.motion != 52;  // LinuxCNC drops the points of an earlier G5.2
  const int32_t count = fresh ? 0 : c.count;
  int64_t p_e9 = -1;
  if (b.has_word('P')) p_e9 = decimal_scale(b.val('P'), 1000000000);
  if (!has_xy && p_e9 > 0 && count > 0) return fail_letter(GcodeError::kNurbsPOnlyFirst, 'P');
  if (p_e9 <= 0 && count > 0) return fail(GcodeError::kNurbsWeight, col, w);
  if (nx.inverse_time) return fail(GcodeError::kNurbsTooMany, col, w);
  if ((e = need_feed(col, w)) != GcodeError::kOk) return e;
  plan.nurbs_add = count == 0 ? 2 : 1;
  plan.nurbs_first_weight = !has_xy && p_e9 > 0 ? p_e9 : 1000000000;
  plan.nurbs_order = count == 0 ? 3 : c.order;
  if (b.has_word('L')) {
    int64_t l;
    if ((e = integer('L', 0, 1000000, &l)) != GcodeError::kOk) return e;
    if (l > kNurbsMaxOrder) return fail_letter(GcodeError::kNurbsTooMany, 'L');
    if (l > 3) plan.nurbs_order = static_cast<int32_t>(l);
  }
  plan.nurbs_has_point = has_xy;
  if (has_xy) {
    if ((count == 0 ? 1 : count) + 1 > kNurbsMaxPoints) return fail(GcodeError::kNurbsTooMany, col, w);
    if (p_e9 <= 0) return fail(GcodeError::kNurbsWeight, col, w);
    PointNm to;
    if ((e = end_point(&to)) != GcodeError::kOk) return e;
    if ((e = check_pos(to, col, w)) != GcodeError::kOk) return e;
    plan.nurbs_x = to.x_nm;
    plan.nurbs_y = to.y_nm;
    plan.nurbs_weight = p_e9;
  }
  nx.pos = cur.pos;  // the position stays until G5.3 (end_point left it alone)
  return GcodeError::kOk;
}

void BlockRunner::commit_nurbs(CanonRecord* r) {
  NurbsCurve& c = in.nurbs_;
  nurbs_prepare(&c);
  r->kind = CanonKind::kFeed;
  for (int32_t s = 0; s < nurbs_spans(c); ++s) {
    const uint32_t m = nurbs_pieces(c, s, in.options_.spline_sagitta_nm);
    for (uint32_t i = 1; i <= m; ++i) {
      nurbs_point(c, s, i, m, &r->end.x_nm, &r->end.y_nm);
      in.emit(r);
      r->start = r->end;
    }
  }
  c.count = 0;
}

}  // namespace dexmill
