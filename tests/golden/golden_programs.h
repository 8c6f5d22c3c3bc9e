// The fixed cutting programs behind the golden grid hashes, as constant data
// (they live in flash on a microcontroller). Header-only so that unit tests
// can run the same programs (tests/*.cpp may include it).
//
// "stamp-test" is exactly the program of tests/test_stamp.cpp
// (golden_program), which checks its grids against this output's stamp-test
// lines in golden.out: they are pinned there only.
// The others add what a real job does: ramp entries, a zig-zag pocket, a
// polygonal helix, drilling plunges with every cutter shape, a through hole
// and slot, a tool too short for its depth (cases c and d of figure 2),
// moves below the stock and half outside the grid, coordinates that are not
// multiples of the pitch, and a grid origin off zero.
#ifndef DEXMILL_TESTS_GOLDEN_GOLDEN_PROGRAMS_H
#define DEXMILL_TESTS_GOLDEN_GOLDEN_PROGRAMS_H

#include <stdint.h>

#include "core/math/fixed.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace golden {

constexpr int64_t mm(int64_t v) { return v * dexmill::kNmPerMm; }
constexpr int64_t um(int64_t v) { return v * dexmill::kNmPerUm; }

struct ProgramTool {
  dexmill::ToolKind kind;
  int64_t diameter_nm;
  int64_t corner_nm;     // bull nose
  int32_t tip_mdeg;      // V-bit
  int64_t flute_nm;
  int64_t length_nm;
};

struct ProgramMove {
  uint8_t tool;               // index into the program's tools
  dexmill::PointNm from, to;  // tool tip, machine nm
};

struct Program {
  const char* name;
  int32_t nx, ny;
  int64_t x0_nm, y0_nm, z0_nm, pitch_nm;
  int64_t stock_top_nm;  // block of stock from z0 up to here
  int64_t range_nm;      // material range the height LSB must cover (lsb_for_range)
  const ProgramTool* tools;
  int ntools;
  const ProgramMove* moves;
  int nmoves;
};

namespace programs {

using dexmill::PointNm;
using dexmill::ToolKind;

// ---- "stamp-test": tests/test_stamp.cpp golden_program --------------------
constexpr ProgramTool kStampTestTools[] = {
    {ToolKind::kBall, mm(6), 0, 0, mm(20), mm(40)},
    {ToolKind::kFlat, mm(4), 0, 0, mm(20), mm(40)},
    {ToolKind::kBullNose, mm(8), mm(1), 0, mm(20), mm(40)},
    {ToolKind::kVBit, mm(6), 0, 90000, mm(20), mm(40)},
};
constexpr ProgramMove kStampTestMoves[] = {
    {0, {mm(5), mm(5), mm(15)}, {mm(35), mm(25), mm(12)}},
    {1, {mm(5), mm(25), mm(18)}, {mm(35), mm(5), mm(17)}},
    {2, {mm(20), mm(2), mm(10)}, {mm(20), mm(28), mm(16)}},
    {3, {mm(2), mm(15), mm(19)}, {mm(38), mm(15), mm(17)}},
    {1, {mm(30), mm(10), mm(25)}, {mm(30), mm(10), -mm(2)}},        // plunge through
    {0, {mm(10), mm(20), mm(14)}, {mm(10), mm(20), mm(14)}},        // zero length
    {0, {-mm(500), mm(10), mm(10)}, {-mm(100), mm(10), mm(10)}},    // outside
    {0, {-mm(100), -mm(100), mm(13)}, {mm(100), mm(100), mm(13)}},  // across
};

// ---- "pocket": a small job with every cutter -------------------------------
constexpr ProgramTool kPocketTools[] = {
    {ToolKind::kFlat, mm(4), 0, 0, mm(15), mm(40)},
    {ToolKind::kBall, mm(6), 0, 0, mm(15), mm(40)},
    {ToolKind::kBullNose, mm(6), um(1500), 0, mm(15), mm(40)},
    {ToolKind::kVBit, mm(6), 0, 60000, mm(10), mm(30)},
    {ToolKind::kBall, mm(3), 0, 0, mm(3), mm(3)},  // short: shaft top 3 mm above the tip
};
constexpr int64_t kPz = um(17500);  // pocket floor
constexpr ProgramMove kPocketMoves[] = {
    // flat: ramp entry, then a zig-zag pocket
    {0, {mm(4), mm(4), mm(21)}, {mm(14), mm(4), kPz}},
    {0, {mm(14), mm(4), kPz}, {mm(28), mm(4), kPz}},
    {0, {mm(28), mm(4), kPz}, {mm(28), mm(6), kPz}},
    {0, {mm(28), mm(6), kPz}, {mm(4), mm(6), kPz}},
    {0, {mm(4), mm(6), kPz}, {mm(4), mm(8), kPz}},
    {0, {mm(4), mm(8), kPz}, {mm(28), mm(8), kPz}},
    {0, {mm(28), mm(8), kPz}, {mm(28), mm(10), kPz}},
    {0, {mm(28), mm(10), kPz}, {mm(4), mm(10), kPz}},
    // ball: a diagonal ramp at coordinates off the pitch
    {1, {um(2123), um(20654), um(19500)}, {um(29877), um(12346), um(15250)}},
    // ball: a helix as an octagon around (16, 16), radius 5 mm, 19 -> 15 mm
    {1, {mm(21), mm(16), mm(19)}, {um(19536), um(19536), um(18500)}},
    {1, {um(19536), um(19536), um(18500)}, {mm(16), mm(21), mm(18)}},
    {1, {mm(16), mm(21), mm(18)}, {um(12464), um(19536), um(17500)}},
    {1, {um(12464), um(19536), um(17500)}, {mm(11), mm(16), mm(17)}},
    {1, {mm(11), mm(16), mm(17)}, {um(12464), um(12464), um(16500)}},
    {1, {um(12464), um(12464), um(16500)}, {mm(16), mm(11), mm(16)}},
    {1, {mm(16), mm(11), mm(16)}, {um(19536), um(12464), um(15500)}},
    {1, {um(19536), um(12464), um(15500)}, {mm(21), mm(16), mm(15)}},
    // bull nose: a drilling plunge, then a ramp along y
    {2, {mm(8), mm(18), mm(25)}, {mm(8), mm(18), mm(12)}},
    {2, {mm(24), mm(2), mm(18)}, {mm(24), mm(22), mm(14)}},
    // V-bit: an engraved line and a plunge
    {3, {mm(3), mm(21), mm(19)}, {mm(29), mm(3), um(18600)}},
    {3, {mm(26), mm(20), mm(25)}, {mm(26), mm(20), mm(16)}},
    // flat: a plunge through the stock, then a slot through it (holes)
    {0, {mm(12), mm(12), mm(25)}, {mm(12), mm(12), -mm(1)}},
    {0, {mm(12), mm(12), -mm(1)}, {mm(16), mm(13), -mm(1)}},
    // short ball (shaft top 3 mm above its tip) in untouched stock: buried
    // with its shaft inside the material (case d, ignored), then below the
    // floor (case c: dexel bottoms rise to the shaft top), then a pass 1.5 mm
    // deep across the through slot (case b; holes stay holes)
    {4, {mm(4), um(14500), mm(25)}, {mm(4), um(14500), mm(10)}},
    {4, {mm(4), um(14500), mm(10)}, {mm(4), um(14500), -mm(1)}},
    {4, {mm(10), mm(12), um(18500)}, {mm(20), um(12500), um(18500)}},
    // ball: entirely below the stock, and half outside the grid
    {1, {0, 0, -mm(30)}, {mm(32), mm(24), -mm(30)}},
    {1, {-mm(5), mm(10), mm(16)}, {mm(8), -mm(4), mm(16)}},
};

// ---- "fine": a small engraving at a pitch that is no power of ten, with the
// grid's origin off zero (negative coordinates, rounding of dexel indices) --
constexpr ProgramTool kFineTools[] = {
    {ToolKind::kVBit, mm(2), 0, 90000, mm(5), mm(20)},
    {ToolKind::kBall, mm(1), 0, 0, mm(5), mm(20)},
    {ToolKind::kBullNose, mm(2), um(250), 0, mm(5), mm(20)},
    {ToolKind::kFlat, um(500), 0, 0, mm(5), mm(20)},
};
constexpr ProgramMove kFineMoves[] = {
    {0, {-mm(1), -um(500), um(1800)}, {mm(10), mm(7), um(1650)}},
    {0, {mm(10), mm(7), um(1650)}, {mm(11), -mm(1), um(1900)}},
    {1, {um(333), um(4444), um(1700)}, {um(9876), um(4321), um(1700)}},
    {1, {um(9876), um(4321), um(1700)}, {um(9876), um(4321), um(1200)}},
    {2, {mm(2), mm(1), um(1500)}, {mm(2), mm(7), um(1500)}},
    {3, {mm(7), mm(1), mm(5)}, {mm(7), mm(1), -mm(3)}},  // drilled through the floor
    {3, {mm(7), mm(1), -mm(3)}, {mm(8), mm(2), -mm(3)}},
};

constexpr Program kAll[] = {
    {"stamp-test", 82, 62, 0, 0, 0, um(500), mm(20), mm(25), kStampTestTools, 4, kStampTestMoves, 8},
    {"pocket", 64, 48, 0, 0, 0, um(500), mm(20), mm(25), kPocketTools, 5, kPocketMoves,
     static_cast<int>(sizeof kPocketMoves / sizeof kPocketMoves[0])},
    {"fine", 80, 60, -um(75), -mm(1), -mm(2), um(150), mm(2), mm(5), kFineTools, 4, kFineMoves,
     static_cast<int>(sizeof kFineMoves / sizeof kFineMoves[0])},
};
constexpr int kCount = static_cast<int>(sizeof kAll / sizeof kAll[0]);

}  // namespace programs
}  // namespace golden

#endif
