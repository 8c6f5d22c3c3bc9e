// LinuxCNC's rotated coordinate systems (G10 L2 R): the XY plane of a work
// coordinate system turned by R degrees, counterclockwise, about its origin.
//
// The interpreter works unrotated, as LinuxCNC's does: its points are the
// program's plus the G92 and work offsets. Records go out rotated, as
// LinuxCNC's canon turns them (rotate_and_offset: machine = rot(program +
// G92) + work offset), i.e. a point p turns about the work offset o:
// machine = rot(p - o) + o. When the frame in force changes under a
// standing tool (a G54-G59.3 switch, G10 on the system in force, M72), the
// interpreter's point is worked out again from the machine point, as
// LinuxCNC's interpreter does, so that the tool does not move.
//
// Integer only: the angle (degrees e9) to a binary angle (bam_of_degrees,
// 0.5 bam = 7.3e-10 rad), CORDIC sine and cosine (2 q30 LSB each), each
// product floored at q29 and the sum rounded. Error bound for a point at
// distance d from the origin it turns about (tests/test_rotation.cpp checks
// it against a double oracle): |error| <= 4.5e-9 d + 1.5 nm (10 m: 46 nm),
// twice that for a point turned back and forth.
#ifndef DEXMILL_CORE_INTERP_ROTATION_H
#define DEXMILL_CORE_INTERP_ROTATION_H

#include <stdint.h>

#include "core/point.h"

namespace dexmill {

struct XyRotation {
  bool on;  // false: a whole number of turns, no arithmetic at all
  int32_t cos_q30, sin_q30;
};

// The rotation by deg_e9 degrees (any value: whole turns are off).
XyRotation xy_rotation(int64_t deg_e9);
// The same rotation the other way.
XyRotation xy_rotation_inverse(const XyRotation& r);
// p turned by r about (ox, oy); z unchanged. Coordinates within +-2^40 nm.
PointNm rotate_about(const XyRotation& r, const PointNm& p, int64_t ox_nm, int64_t oy_nm);

}  // namespace dexmill

#endif
