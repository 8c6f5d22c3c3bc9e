// The tool table of a run (--tools FILE): read once by `dexmill run`, and
// again by `dexmill optimize`'s pass over the program, which must read the
// program with the same tool lengths.
#ifndef DEXMILL_TOOLS_RUN_RUN_TOOL_TABLE_H
#define DEXMILL_TOOLS_RUN_RUN_TOOL_TABLE_H

#include <string>

#include "platform/format/tool_table.h"
#include "tools/run/read_options.h"

namespace dexmill {
namespace cli {

// Reads `path` (lengths in inch when `inch`) into *t. Returns kExitOk, or
// prints the error and returns kExitIo (unreadable) or kExitInput (bad
// table). The table's warnings are the caller's to print.
int load_tool_table(const std::string& path, bool inch, ToolTableFile* t);

// Whether the --tools table of a reading of `program` is in inch:
// --tool-units, else the program's units when it sets them before its
// first T, else --units (core/sim/tool_units.h). The program is read up to
// that T for it; standard input ("-"), which cannot be read twice, is not:
// then --units.
bool table_units_inch(const ReadOptions& o, const std::string& program);

// load_tool_table of --tools in those units (*inch gets them, when not null).
int load_read_tool_table(const ReadOptions& o, const std::string& program, ToolTableFile* t, bool* inch = nullptr);

}  // namespace cli
}  // namespace dexmill

#endif
