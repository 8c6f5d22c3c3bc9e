// The built-in demo (`dexmill run` with no FILE): the G-code of a real-
// looking job on a 100 x 70 x 20 mm block, generated deterministically
// (integer arithmetic only) and run through the same reader and cutter as
// any file. Three tools from a LinuxCNC tool table (also built in):
//   T1 flat 6 mm: helical bores at both ends, then a waterline roughing of a
//      60 x 40 mm pocket in four 2 mm stepdowns that leaves 0.3 mm on a
//      relief (a dome with ripples), each level closed by a contour pass with
//      arc corners;
//   T2 ball 6 mm: zig finishing of the relief, drop-cutter positions every
//      0.5 mm, rows 0.6 mm apart (about 6000 moves);
//   T3 spot drill (vbit:5:118): four G81 through holes in the corners.
//
// Freestanding (no heap, no stdio): `dexmill run --demo pocket`
// (tools/run/demo_program.h) and the embedding API's dm_demo_program
// write the same bytes.
#ifndef DEXMILL_CORE_CAM_DEMO_PROGRAM_H
#define DEXMILL_CORE_CAM_DEMO_PROGRAM_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

// The program text (about 7000 lines, 108 KB) into buf[0, n), NUL
// terminated (what fits: n - 1 bytes at most); its whole length in bytes
// (buf may be null with n 0, to size it).
size_t demo_program_write(char* buf, size_t n);
// The part the demo is meant to make, for its error view (paper §2.5): the
// design's top at (x, y) in um, false where it has no material (the four
// through holes): the block's top at Z0, the two 10 mm bores 8 mm deep, and
// the 60 x 40 mm pocket (3 mm corner radii) with a 6 mm floor band along
// its walls (the contour passes') and the relief inside it.
bool demo_design_top_um(int32_t x_um, int32_t y_um, int32_t* z_um);
// Its tool table, LinuxCNC format.
const char* demo_tool_table();
// The stock the demo is written for: X0,Y0,Z0,X1,Y1,Z1 in mm (the program's
// Z0 is the stock top).
const char* demo_stock();
// What the demo's block is made of (the demo is cut from a
// visibly inhomogeneous block): beech over aluminium, the paper's wood and metal
// compound; the program keeps within both materials' limits.
const char* demo_material();

}  // namespace dexmill

#endif
