// The machine a program runs on (`--machine FILE`: a LinuxCNC INI file or
// a grbl settings dump, read by platform/format/machine_file.h): its soft
// limits, velocities and accelerations per axis, the units it reports in,
// and the work offsets its controller holds. Plain data: the travel check
// (core/safety/travel_watch.h) and the time model read it, on the panel too.
//
// Machine coordinates are the controlled point's (LinuxCNC's joint
// positions, grbl's MPos): the tool tip plus the tool length offset in
// force along Z. LinuxCNC's travel is [MIN_LIMIT, MAX_LIMIT]; grbl's
// after homing is [-$130, 0] (its limits_soft_check), [0, $130] for an
// axis $23 homes the other way on a build that sets the origin where it
// homes (grblHAL's $22 bit 3).
#ifndef DEXMILL_CORE_CANON_MACHINE_H
#define DEXMILL_CORE_CANON_MACHINE_H

#include <stdint.h>

#include "core/point.h"

namespace dexmill {

enum class MachineKind : uint8_t { kNone = 0, kLinuxcnc = 1, kGrbl = 2 };

struct MachineAxis {
  bool limited = false;               // soft limits known (grbl: $20=1 and $130.. > 0)
  int64_t min_nm = 0, max_nm = 0;     // the travel, machine coordinates
  int64_t max_velocity_nm_per_min = 0;  // 0: not given
  int64_t max_accel_nm_per_s2 = 0;      // 0: not given
};

constexpr int32_t kMachineCoordSystems = 9;  // G54 .. G59.3

struct MachineSpec {
  MachineKind kind = MachineKind::kNone;
  MachineAxis axis[3];
  bool inch = false;  // the units it is set up in (LinuxCNC LINEAR_UNITS, grbl $13)
  // The work offsets it holds (LinuxCNC's PARAMETER_FILE, grbl's $#), in
  // machine nm: the program starts with them.
  bool have_offsets = false;
  PointNm work_offset[kMachineCoordSystems] = {};
  PointNm g92{0, 0, 0};
  int64_t tlo_nm = 0;         // grbl's [TLO:] (G43.1 in force)
  uint8_t coord_system = 0;   // 0 = G54 (LinuxCNC #5220 - 1)
  int32_t max_feed_override_ppm = 0;  // LinuxCNC [DISPLAY] MAX_FEED_OVERRIDE (0: not given)
};

}  // namespace dexmill

#endif
