// The machine's soft limits as findings (`dexmill run --machine FILE`,
// `--check travel`): every move, in machine coordinates (the tool tip plus
// the tool length offset in force along Z: core/canon/machine.h), stays inside
// the travel of each axis that has one, or is a finding at its line with
// the axis, the side and how far past it goes: what the controller would
// fault on, found before the machine does. Rapids are checked as the
// straight moves the interpreter emits (LinuxCNC's G0 is a straight line
// in machine space; a controller that moves one axis after another, a
// dog-leg, stays inside the box of the same two points, so it is inside
// the limits whenever the straight move is).
//
// A straight move is inside when its end is (the travel is a box, and its
// start is where the move before it ended, checked there). A move that
// starts past a limit (the one before it left) is a finding only where it
// goes farther past: the move that left the travel is the one named. The
// position the program starts at is the machine's, not the program's (a
// simulation starts at its origin): an axis counts from the first move
// that moves it (an arc moves its plane's two axes).
// An arc or helix is checked at its chords' points (core/canon/arc_chords.h,
// sagitta 1 um), each within 2 nm + 6e-9 r of the arc, and a point counts
// only past a limit by more than kTravelSlackNm: no false alarm from
// rounding, and an arc bulging past a limit by less than 1 um between two
// chord points may go unseen. Integer only, no heap: the panel's too.
#ifndef DEXMILL_CORE_SAFETY_TRAVEL_WATCH_H
#define DEXMILL_CORE_SAFETY_TRAVEL_WATCH_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/canon/machine.h"

namespace dexmill {

constexpr int64_t kTravelSlackNm = 10;
constexpr int32_t kTravelKept = 100;

struct TravelFinding {
  uint32_t line = 0;
  uint8_t axis = 0;        // 0 X, 1 Y, 2 Z
  bool above = false;      // past the maximum (else below the minimum)
  int64_t excess_nm = 0;   // how far past it the move goes, at its farthest
  int64_t at_nm = 0;       // that farthest machine coordinate
  int64_t limit_nm = 0;
};

struct TravelWatch {
  MachineKind kind = MachineKind::kNone;  // whose limits (the messages name them)
  MachineAxis axis[3];
  // Where the program starts is the machine's own (after homing, a
  // previous job): an axis is checked from the first move that moves it.
  bool known[3] = {false, false, false};
  uint64_t total = 0;      // moves past a limit (one a move and axis side)
  int32_t nkept = 0;
  TravelFinding kept[kTravelKept];
};

void travel_watch_init(TravelWatch* w, const MachineSpec& m);
// Checks the move r (straight or arc; other records pass); true when it
// went past a limit.
bool travel_watch_check(TravelWatch* w, const CanonRecord& r);

}  // namespace dexmill

#endif
