// The interpreter's polar coordinates (@, ^) as LinuxCNC 2.9 reads them:
// the checks of its enhance_block, the end point of a move (find_ends, for
// G0, G1, G2, G3, G5, G5.1 and the probe moves: end_point, which also reads
// the axis words) and the holes of a canned cycle (convert_cycle_xy,
// CYCLE_MACRO). The geometry is core/interp/polar.h.
#include "core/gcode/gvalue.h"
#include "core/interp/block_runner.h"

namespace dexmill {

char BlockRunner::polar_letter() const {
  if (b.has_word('@') && b.has_word('^')) return b.col_of('@') < b.col_of('^') ? '@' : '^';
  return b.has_word('@') ? '@' : '^';
}

// LinuxCNC asks the plane before the block's own G17-G19 take effect (a
// block `G18 G1 @1 ^2` still moves in XY), then X, then Y. Polar words name
// the end of a move, so G10, G28, G30, G43.1 and G92, which take axis
// words for something else, refuse them.
GcodeError BlockRunner::check_polar(bool axis_user0) {
  if (cur.plane != Plane::kXY) return fail_letter(GcodeError::kPolarPlane, polar_letter());
  if (b.has_word('X')) return fail_letter(GcodeError::kPolarWithXY, 'X');
  if (b.has_word('Y')) return fail_letter(GcodeError::kPolarWithXY, 'Y');
  const int gm = b.g[kGMotion];
  if (axis_user0 && (gm < 0 || gm == 800)) return fail_letter(GcodeError::kPolarNotMotion, polar_letter());
  return GcodeError::kOk;
}

GcodeError BlockRunner::polar_words(PolarWords* w) {
  GcodeError e;
  w->has_radius = b.has_word('@');
  w->has_angle = b.has_word('^');
  w->radius_nm = 0;
  w->angle_deg_e9 = 0;
  if (w->has_radius && (e = length('@', &w->radius_nm)) != GcodeError::kOk) return e;
  if (w->has_angle) {
    GValue g;
    if (gvalue_from_decimal(b.val('^'), &g) != GcodeError::kOk) return fail_letter(GcodeError::kNumberTooLarge, '^');
    w->angle_deg_e9 = g.e9;
  }
  return GcodeError::kOk;
}

// The end of a move (G2, G3, G5, G5.1): the axis words, absolute or
// incremental, or @ and ^ for X and Y; the current point for the others.
GcodeError BlockRunner::end_point(PointNm* to) {
  GcodeError e;
  // From the programmed point while compensation is on (LinuxCNC's program_x).
  const PointNm base = comp_base();
  *to = base;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    axis_ref(*to, ax) = nx.incremental ? axis_val(base, ax) + v : v + offset(ax);
  }
  return b.has_polar() ? polar_target(to) : GcodeError::kOk;
}

// *to has Z (and X, Y from the current point); @ and ^ give X and Y, in the
// program frame of this block's offsets.
GcodeError BlockRunner::polar_target(PointNm* to) {
  PolarWords w;
  GcodeError e = polar_words(&w);
  if (e != GcodeError::kOk) return e;
  const int64_t x = comp_base().x_nm - offset(0), y = comp_base().y_nm - offset(1);
  int64_t px, py;
  char word = '@';
  e = nx.incremental ? polar_incremental(x, y, w, &px, &py, &word)
                     : polar_absolute(x, y, w, false, &px, &py, &word);
  if (e != GcodeError::kOk) return fail_letter(e, word);
  to->x_nm = px + offset(0);
  to->y_nm = py + offset(1);
  return GcodeError::kOk;
}

// A canned cycle's holes from @ and ^ (the cycle is planned in XY: polar
// words are LinuxCNC's only there). G90: the hole (convert_cycle_xy: a
// missing @ or ^ from the current point, the angle 0 at the origin). G91:
// the series of CYCLE_MACRO, one step per repeat; every hole is checked
// here (range, and the origin LinuxCNC stops at), the last kept.
GcodeError BlockRunner::cycle_polar(const char* w) {
  CyclePlan& c = plan.cycle;
  if (nx.plane != Plane::kXY) return fail_letter(GcodeError::kPolarPlane, polar_letter());
  PolarWords pw;
  GcodeError e = polar_words(&pw);
  if (e != GcodeError::kOk) return e;
  const int64_t ox = offset(0), oy = offset(1);
  const int64_t x = c.start_a - ox, y = c.start_b - oy;
  int64_t px, py;
  char word = '@';
  if (!nx.incremental) {
    if ((e = polar_absolute(x, y, pw, true, &px, &py, &word)) != GcodeError::kOk) return fail_letter(e, word);
    c.a = px + ox;
    c.b = py + oy;
    return GcodeError::kOk;
  }
  c.polar = true;
  c.polar_off_a = ox;
  c.polar_off_b = oy;
  c.series.init(x, y, pw.radius_nm, pw.angle_deg_e9);
  PolarSeries s = c.series;
  for (int64_t k = 0; k < c.repeats; ++k) {
    if (!s.next(&px, &py, &word)) return fail_letter(GcodeError::kPolarIncrementalOrigin, word);
    c.last_a = px + ox;
    c.last_b = py + oy;
    if ((e = check_pos(PointNm{c.last_a, c.last_b, 0}, motion_col(), w)) != GcodeError::kOk) return e;
    if (c.code == 870 &&
        (e = check_pos(PointNm{c.last_a + c.off_a, c.last_b + c.off_b, 0}, motion_col(), w)) != GcodeError::kOk)
      return e;
  }
  return GcodeError::kOk;
}

}  // namespace dexmill
