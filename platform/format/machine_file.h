// Machine descriptions (`--machine FILE`): the machine a program runs on,
// into a MachineSpec (core/canon/machine.h). The kind is told by the content,
// not by the file's name: the first line that is not blank, a '#' or ';'
// comment or an `ok` decides.
//
// 1. A LinuxCNC INI file (its first such line a `[SECTION]` line, and one
//    of LinuxCNC's sections in it: [EMC], [TRAJ], [AXIS_X], ...). Lines are
//    `[SECTION]`, `KEY = VALUE`, blank, or comments starting with '#' or ';'
//    (a whole line: LinuxCNC has no comment after a value); a line ending
//    in '\' goes on on the next (errors name the first of them, columns
//    count in the joined line). Names are case-sensitive, as LinuxCNC has
//    them; of a repeated key the first counts, and of a repeated section
//    the first (LinuxCNC's inifile reads no further). Read:
//      [TRAJ] LINEAR_UNITS         mm, metric, in, inch, imperial, or a
//                                  number: 1 (mm) or 0.03937 (inch)
//      [AXIS_X] [AXIS_Y] [AXIS_Z]  MIN_LIMIT, MAX_LIMIT (the travel; both
//                                  given: the axis is limited), MAX_VELOCITY
//                                  (per second), MAX_ACCELERATION (per
//                                  second^2), all in LINEAR_UNITS
//      [EMCIO] TOOL_TABLE, [RS274NGC] PARAMETER_FILE, SUBROUTINE_PATH
//                                  (':'-separated): paths, relative ones
//                                  taken from the INI file's folder, "~/"
//                                  from $HOME
//      [RS274NGC] DISABLE_G92_PERSISTENCE  (1, yes, on, true / 0, ...)
//      [DISPLAY] MAX_FEED_OVERRIDE a ratio (1.2: 120 %)
//    Every other section and key is passed over (a real INI has hundreds),
//    but each line must still be one of the four forms.
// 2. A grbl settings dump: what `$$` prints, `$N=VALUE` lines (grbl 0.9
//    adds ` (a comment)`), and what `$#` prints: [G54:X,Y,Z] .. [G59:..]
//    (grblHAL: [G59.1:..] .. [G59.3:..]), [G28:..], [G30:..], [G92:..],
//    [TLO:Z], [PRB:X,Y,Z:OK]; `$G`'s [GC:...] gives the coordinate system
//    in force. `ok` lines, the welcome line ("Grbl 1.1h ..."), status
//    reports (<...>), other [NAME:...] messages, the commands `$$` and `$#`
//    themselves, blank and '#'/';' lines are passed over. Read: $110-$112
//    (mm/min), $120-$122 (mm/s^2), $130-$132 (mm), $13 (reports in inch),
//    $20 (soft limits: an axis is limited only with $20=1 and its travel
//    above 0), $22 (homing; grblHAL's bit 3: the machine origin set where it
//    homes), $23 (homing direction invert mask). The travel is [-$130, 0],
//    but [0, $130] for an axis of $23 when $22 has bit 3 (grbl's
//    system_check_travel_limits under HOMING_FORCE_SET_ORIGIN). Settings are
//    in mm whatever $13 says; $#'s positions are in inch when $13=1. Of a
//    repeated setting the last counts, as when the lines are sent to grbl.
// 3. LinuxCNC's parameter file (the PARAMETER_FILE, `.var`): lines
//    `NUMBER VALUE`, numbers 1..5601 in increasing order, lengths in the
//    machine's units; machine_var_parse reads it, machine_file_load for an
//    INI that names one.
//
// Lengths are within +-10 m, velocities up to 10 m/s, accelerations up to
// 1000 m/s^2, all above 0 but the lengths. Errors are "FILE:LINE:COL: error:
// MESSAGE" (the column of the part at fault); nothing of a file with an
// error is used.
#ifndef DEXMILL_PLATFORM_FORMAT_MACHINE_FILE_H
#define DEXMILL_PLATFORM_FORMAT_MACHINE_FILE_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/canon/machine.h"

namespace dexmill {

// The largest machine or parameter file read (a real INI is a few KB).
constexpr std::size_t kMachineFileMaxBytes = std::size_t{4} << 20;

struct MachineFile {
  MachineSpec spec;
  // LinuxCNC's files, resolved (see above); empty when not given.
  std::string tool_table, subroutine_path, parameter_file;
  bool disable_g92_persistence = false;  // [RS274NGC]: G92 starts cleared
  bool parameter_file_missing = false;   // machine_file_load: PARAMETER_FILE not there (yet)
  // What was read, in the file's order, for a summary: "[TRAJ]LINEAR_UNITS",
  // "[AXIS_X]MAX_LIMIT", ..., "$110", "$13", ..., "G54", "G92", "TLO", "GC".
  std::vector<std::string> keys;
};

// Parses text[0, n) named `name` (for messages); `dir` is the folder the
// INI's relative paths are taken from ("" or ".": they stay relative).
// On failure *err holds the whole error line and *out is unchanged.
bool machine_file_parse(const char* name, const char* text, std::size_t n, const std::string& dir, MachineFile* out,
                        std::string* err);

// Parses a LinuxCNC parameter file into spec's work_offset (G5x k at
// #5221 + 20k .. #5223 + 20k), g92 (#5211-#5213, in force when #5210 is not
// 0, as LinuxCNC restores it), coord_system (#5220: 1..9 -> 0..8; absent:
// G54) and have_offsets; lengths in inch when `inch` (the INI's units).
// Absent parameters are 0, as in LinuxCNC. On failure *err holds the whole
// error line and *spec is unchanged.
bool machine_var_parse(const char* name, const char* text, std::size_t n, bool inch, MachineSpec* spec,
                       std::string* err);

// Reads and parses the file at `path`, and for a LinuxCNC INI its
// PARAMETER_FILE when it names one (a missing one is not an error, since
// LinuxCNC creates it on its first run: parameter_file_missing says so;
// DISABLE_G92_PERSISTENCE clears the G92 it holds, as LinuxCNC does).
// kIoError when a file cannot be read, kInputError when one is too large
// or wrong (*err the whole message); *out is unchanged then.
enum class MachineLoad : uint8_t { kOk, kIoError, kInputError };
MachineLoad machine_file_load(const std::string& path, MachineFile* out, std::string* err);

}  // namespace dexmill

#endif
