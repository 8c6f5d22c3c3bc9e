// The part's own frame, seen from the machine: where a setup
// (core/stock/stock_transform.h) has put the part it turned over, turned
// about Z or moved. A part point is 2 p_part = turn * 2 p_machine + offset:
// turn row-major with entries -1, 0, 1 (a rotation or reflection), offset
// in half nanometres, because a box's centre, which setups turn about, may
// fall on half a nanometre. What is given in the part's frame (the stock's
// materials, a design part) is met through it in every setup.
#ifndef DEXMILL_CORE_MATH_PART_FRAME_H
#define DEXMILL_CORE_MATH_PART_FRAME_H

#include <stdint.h>

#include "core/point.h"

namespace dexmill {

struct PartFrame {
  int8_t turn[9];
  int64_t offset_half_nm[3];
};

PartFrame part_frame_identity();
bool part_frame_is_identity(const PartFrame& f);
// The turn keeps Z an axis of its own (Z to +Z or -Z, X and Y among
// themselves): what every setup makes, and what a vertical column needs to
// stay one in the part.
bool part_frame_keeps_z(const PartFrame& f);

// The part point of a machine point, and the machine point of a part
// point; each coordinate rounded down where it falls on half a nanometre
// (error at most 0.5 nm). Coordinates within kCoordLimitNm
// (core/math/fixed.h) keep every product within int64.
PointNm part_frame_to_part(const PartFrame& f, const PointNm& machine);
PointNm part_frame_to_machine(const PartFrame& f, const PointNm& part);

}  // namespace dexmill

#endif
