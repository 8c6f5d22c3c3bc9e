// The units a tool table is read in. LinuxCNC reads its table in the
// machine's units (the INI's LINEAR_UNITS), whatever G20/G21 the program
// says; dexmill has no machine, only --units, which a user rarely gives,
// so that rule would read an inch shop's table of D0.25 tools as
// quarter-millimetre ones. The rule here: the program's units when it sets
// G20/G21 before its first T word (a shop's table is in the units its
// programs are written in), else the default (--units); an option
// (--tool-units) says otherwise for a table kept in the other units.
#ifndef DEXMILL_CORE_SIM_TOOL_UNITS_H
#define DEXMILL_CORE_SIM_TOOL_UNITS_H

#include "core/gcode/line_reader.h"
#include "core/interp/interp.h"

namespace dexmill {

// Reads the program from `in` with `opt` (its warnings and messages
// dropped; its errors ignored: the real reading reports them) up to the
// block with its first T word, or its end. True when the table is in inch
// by the rule above (opt.inch when the program sets no units by then).
bool tool_table_inch(LineInput* in, InterpOptions opt);

}  // namespace dexmill

#endif
