// Axes, planes and rotated frames as the block runner reads them: an axis
// of a point by number, the axes of an arc's plane, where the tool is, a
// point of a turned coordinate system (rotation.h) in machine terms and
// back, a motion code's kind, a spindle-synchronised feed. A part of the
// block runner (block_runner.h), for the interpreter's own files only.
#ifndef DEXMILL_CORE_INTERP_BLOCK_AXES_H
#define DEXMILL_CORE_INTERP_BLOCK_AXES_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/interp/interp.h"
#include "core/interp/rotation.h"
#include "core/point.h"

namespace dexmill {
namespace interp_detail {

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
inline int plane_axis_a(Plane p) { return p == Plane::kXY ? 0 : p == Plane::kZX ? 2 : 1; }
inline int plane_axis_b(Plane p) { return p == Plane::kXY ? 1 : p == Plane::kZX ? 0 : 2; }
inline int plane_axis_c(Plane p) { return p == Plane::kXY ? 2 : p == Plane::kZX ? 1 : 0; }

}  // namespace interp_detail
}  // namespace dexmill

#endif
