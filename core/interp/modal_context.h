// M70-M73 (LinuxCNC 2.9): the modal state a program or a subroutine saves
// and gets back. M70 saves, M73 saves and gives it back when the subroutine
// returns, M71 forgets, M72 restores; one context per call level (a
// subroutine's M72 cannot see its caller's M70). What is kept is what
// LinuxCNC keeps (checked against rs274): units, plane, cutter compensation
// (on or off), distance and arc distance modes, feed mode, F, S, spindle
// direction, coolant, the coordinate system (which one, not its offsets),
// the tool length offset, the canned-cycle retract mode, lathe diameter mode
// and path control. Not the motion mode.
#ifndef DEXMILL_CORE_INTERP_MODAL_CONTEXT_H
#define DEXMILL_CORE_INTERP_MODAL_CONTEXT_H

#include <stdint.h>

#include "core/canon/canon.h"

namespace dexmill {

struct InterpState;

struct ModalContext {
  bool valid;
  bool auto_restore;  // M73: given back when the level's subroutine returns
  bool inch, incremental, arc_absolute, inverse_time, per_rev, retract_to_r, diameter_x;
  Plane plane;
  int8_t comp_side;  // 0 off, else G41/G42's side
  uint8_t coord_system;
  uint8_t coolant;
  int8_t spindle_dir;
  int16_t path_mode;
  int32_t path_tolerance_nm;
  int32_t spindle_rpm;
  int64_t feed_nm_per_min;
  int64_t tlo_nm;
};

inline bool operator==(const ModalContext& a, const ModalContext& b) {
  return a.valid == b.valid && a.auto_restore == b.auto_restore && a.inch == b.inch &&
         a.incremental == b.incremental && a.arc_absolute == b.arc_absolute && a.inverse_time == b.inverse_time &&
         a.per_rev == b.per_rev && a.retract_to_r == b.retract_to_r && a.diameter_x == b.diameter_x &&
         a.plane == b.plane && a.comp_side == b.comp_side && a.coord_system == b.coord_system &&
         a.coolant == b.coolant && a.spindle_dir == b.spindle_dir && a.path_mode == b.path_mode && a.path_tolerance_nm == b.path_tolerance_nm &&
         a.spindle_rpm == b.spindle_rpm && a.feed_nm_per_min == b.feed_nm_per_min && a.tlo_nm == b.tlo_nm;
}

// The context of s (valid; auto_restore as given).
ModalContext modal_context_save(const InterpState& s, bool auto_restore);
// Puts c's modes into *s. The caller moves the controlled point for a
// changed tool length offset and emits what changed (spindle, coolant).
void modal_context_apply(const ModalContext& c, InterpState* s);

}  // namespace dexmill

#endif
