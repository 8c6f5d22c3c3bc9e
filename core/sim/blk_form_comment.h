// Heidenhain's blank form, the de-facto standard a TNC control's programs
// declare their stock with, as G-code carries it in comments:
//   (BLK FORM 0.1 Z X+0 Y+0 Z-40)    the MIN point, after the spindle axis
//   (BLK FORM 0.2 X+100 Y+100 Z+0)   the MAX point, or an increment from
//   (BLK FORM 0.2 IX+100 IY+100 IZ+40)  MIN (I before the letter)
// in the program's units and coordinate system where the 0.2 stands. Only a
// spindle along Z (a 3-axis stock); every axis given. A comment that is not
// well formed is ignored with its reason, as a WORKPIECE comment is
// (core/sim/workpiece_comment.h); its other forms (a cylinder) too.
#ifndef DEXMILL_CORE_SIM_BLK_FORM_COMMENT_H
#define DEXMILL_CORE_SIM_BLK_FORM_COMMENT_H

#include <stddef.h>

#include "core/sim/workpiece_comment.h"

namespace dexmill {

// The 0.1 line remembered until its 0.2.
struct BlkForm {
  bool have_min = false;
  PointNm min{0, 0, 0};
};

// Reads a line: true with *out (kind kBox) when a 0.2 completes the box;
// false otherwise, with *why a static text when the line holds a BLK FORM
// comment that is not well formed (null when it holds none, or a 0.1).
bool blk_form_comment(const char* line, size_t n, bool inch, BlkForm* st, WorkpieceBox* out, const char** why);

}  // namespace dexmill

#endif
