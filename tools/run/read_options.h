// How a program is read, the options `path`, `check` and `run` share:
// --units, --default-feed, --subroutine-path, --max-blocks and --tools, one
// option list that each of their tables includes (tools/cli/option_table.h),
// and the setting up of the interpreter's memory and source from them (one
// place, not one per command).
#ifndef DEXMILL_TOOLS_RUN_READ_OPTIONS_H
#define DEXMILL_TOOLS_RUN_READ_OPTIONS_H

#include <stdint.h>

#include <memory>
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "platform/input/gcode_file.h"
#include "platform/format/tool_table.h"
#include "tools/cli/option_table.h"

namespace dexmill {
namespace cli {

struct ReadOptions {
  bool inch = false;                      // --units inch: units before any G20/G21
  bool units_given = false;               // --units was given: no warning for a program that sets none
  bool feed_in_line_units = false;        // a grbl --machine: F on a G20/G21 line in its units (InterpOptions)
  // --tool-units: the tool table's units (kProgram: the rule of
  // core/sim/tool_units.h, the program's when it sets them before its first T)
  enum class ToolUnits : uint8_t { kProgram, kMm, kInch } tool_units = ToolUnits::kProgram;
  int64_t default_feed_nm_per_min = 0;    // --default-feed (0: none)
  std::vector<std::string> subroutine_path;  // --subroutine-path DIR[:DIR...]
  uint64_t max_blocks = kDefaultMaxBlocks;   // --max-blocks N (0: no limit)
  std::string tools_file;                    // --tools FILE: a LinuxCNC tool table
};

// The options, for the tables of path, check and run.
OptionList<ReadOptions> read_option_list();

// The memory of one reading of a program (parameters, o-word control
// flow) and its tool table, attached to `opt` with the options' values; the
// file gets the subroutine path.
struct ReadSetup {
  std::unique_ptr<GcodeMemory> memory = gcode_memory();
  ToolTableFile table;
  bool have_table = false;
  // Loads --tools (its warnings printed) in the units of a reading of
  // `program` (tools/run/run_tool_table.h); an exit code, 0 when fine.
  int load_tools(const ReadOptions& o, const std::string& program);
  void apply(const ReadOptions& o, InterpOptions* opt, GcodeFile* file);
};

}  // namespace cli
}  // namespace dexmill

#endif
