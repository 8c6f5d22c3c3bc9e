// The tool table of a run (--tools FILE): read once by `dexmill run`, and
// again by `dexmill optimize`'s pass over the program, which must read the
// program with the same tool lengths.
#ifndef DEXMILL_TOOLS_RUN_TOOL_TABLE_H
#define DEXMILL_TOOLS_RUN_TOOL_TABLE_H

#include <string>

#include "platform/tool_table.h"

namespace dexmill {
namespace cli {

// Reads `path` (lengths in inch when `inch`) into *t. Returns kExitOk, or
// prints the error and returns kExitIo (unreadable) or kExitInput (bad
// table). The table's warnings are the caller's to print.
int load_tool_table(const std::string& path, bool inch, ToolTableFile* t);

}  // namespace cli
}  // namespace dexmill

#endif
