// The canonical motion seam between the G-code interpreter and everything
// downstream (core/README.md, habit 2; LinuxCNC's canon.hh is the model): the
// interpreter emits one record per canonical command, and a consumer (the
// cutter, the `dexmill path` printer, `dexmill check`) implements CanonSink.
// Records are plain values; nothing downstream calls back upstream.
#ifndef DEXMILL_CORE_CANON_CANON_H
#define DEXMILL_CORE_CANON_CANON_H

#include <stdint.h>

#include "core/point.h"

namespace dexmill {

enum class CanonKind : uint8_t {
  kTraverse = 0,    // G0 straight move at the rapid rate
  kFeed = 1,        // G1 straight move (also each straight move of a canned cycle)
  kArc = 2,         // G2/G3 arc or helix (see CanonArc)
  kDwell = 3,       // G4 (also canned-cycle dwells): dwell_ms
  kToolChange = 4,  // M6: `tool` is now in the spindle
  kSpindle = 5,     // M3/M4/M5 or S change: spindle_rpm (signed: M4 negative, 0 = stopped)
  kCoolant = 6,     // M7/M8/M9: coolant
  kPause = 7,       // M0/M1/M60: program pause (a simulation carries on)
  kEnd = 8,         // M2/M30: program end
};

// The plane of an arc: G17 (XY, axis Z), G18 (ZX, axis Y), G19 (YZ, axis X).
enum class Plane : uint8_t { kXY = 0, kZX = 1, kYZ = 2 };

struct CanonArc {
  Plane plane;
  PointNm centre;  // arc centre; its coordinate along the plane's axis equals start's
  // LinuxCNC's `rotation`: > 0 counterclockwise (G3), < 0 clockwise (G2),
  // seen looking down the plane's axis from +; |turns| - 1 extra full turns
  // (P word). start == end in the plane with |turns| = 1 is one full circle.
  int32_t turns;
};

struct CanonRecord {
  CanonKind kind;
  // The path control mode in force (G61 = 610, G61.1 = 611, G64 = 640; 0 on
  // records made outside the interpreter: taken as G64), how the move ends
  // at its junction with the next (core/canon/motion_plan.h). Here and
  // path_tolerance_nm after `tool`: in padding, so a record stays 136 bytes
  // (cutter compensation holds 32 of them in the interpreter).
  uint16_t path_mode;
  uint32_t line;         // 1-based line of the block in the source
  PointNm start, end;    // controlled point (tool tip) in machine coordinates, nm;
                         // end == start for records that do not move
  CanonArc arc;          // kArc only
  int64_t feed_nm_per_min;  // kFeed, kArc: feed in force (G93: the equivalent rate)
  int32_t tool;          // tool number in the spindle (after kToolChange: the one just loaded)
  // G64's P, the path tolerance in machine nm (0: none, LinuxCNC's "as
  // fast as possible"; at most 2^31 - 1 nm, the interpreter clamps).
  int32_t path_tolerance_nm;
  int64_t tool_length_offset_nm;  // G43/G49 offset in force (not applied to start/end)
  int64_t dwell_ms;      // kDwell
  int32_t spindle_rpm;   // kSpindle
  uint8_t coolant;       // kCoolant: bit 0 mist (M7), bit 1 flood (M8); 0 = off
};

class CanonSink {
 public:
  virtual void emit(const CanonRecord& r) = 0;

 protected:
  ~CanonSink() = default;
};

}  // namespace dexmill

#endif
