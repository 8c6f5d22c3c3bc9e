// The stock a program declares in a comment, as LinuxCNC's preview reads
// it (its `(WORKPIECE,...)` comments, LinuxCNC 2.10):
//   (WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=-40,XMAX=100,YMAX=100,ZMAX=0)
//   (WORKPIECE,CYLINDER,AXIS=Z,X=0,Y=0,ZMIN=-40,ZMAX=0,DIAMETER=80)
//   (WORKPIECE,TUBE,AXIS=Z,X=0,Y=0,ZMIN=-40,ZMAX=0,DIAMETER=80,INNER_DIAMETER=40)
// in the program's units and coordinate system where the comment stands; a
// second one adds to the first. dexmill's stock is a box: a cylinder or a
// tube along Z is taken as the box around it (said by `kind`); one along X
// or Y is not read (a 3-axis stock stands along Z). Keys in any case, in
// any order; a comment that is not well formed is ignored (a preview's
// comment, never an error of the program), with its reason kept.
#ifndef DEXMILL_CORE_SIM_WORKPIECE_COMMENT_H
#define DEXMILL_CORE_SIM_WORKPIECE_COMMENT_H

#include <stddef.h>
#include <stdint.h>

#include "core/point.h"

namespace dexmill {

enum class WorkpieceKind : uint8_t { kNone, kBox, kCylinder, kTube };

struct WorkpieceBox {
  WorkpieceKind kind = WorkpieceKind::kNone;
  PointNm lo{0, 0, 0}, hi{0, 0, 0};  // in the program's frame where the comment stands (nm)
};

// Reads a (WORKPIECE,...) comment in a line (`inch`: the units in force).
// True with *out when the line holds a well-formed one; false otherwise,
// with *why a static text when the line holds one that is not well formed
// (null when it holds none).
bool workpiece_comment(const char* line, size_t n, bool inch, WorkpieceBox* out, const char** why);

}  // namespace dexmill

#endif
