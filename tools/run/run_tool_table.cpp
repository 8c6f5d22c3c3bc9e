#include "tools/run/run_tool_table.h"

#include <cstdio>
#include <memory>

#include "core/sim/tool_units.h"
#include "platform/input/gcode_file.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {

int load_tool_table(const std::string& path, bool inch, ToolTableFile* t) {
  const ToolTableFile::Load l = t->load(path.c_str(), inch);
  if (l == ToolTableFile::Load::kIoError) return fail(kExitIo, "%s", t->message().c_str());
  if (l == ToolTableFile::Load::kInputError) {
    std::fprintf(stderr, "%s\n", t->message().c_str());
    return kExitInput;
  }
  return kExitOk;
}

bool table_units_inch(const ReadOptions& o, const std::string& program) {
  if (o.tool_units != ReadOptions::ToolUnits::kProgram) return o.tool_units == ReadOptions::ToolUnits::kInch;
  GcodeFile in;
  if (program.empty() || program == "-" || !in.open(program.c_str())) return o.inch;  // the reading reports it
  in.set_subroutine_path(o.subroutine_path);
  const std::unique_ptr<GcodeMemory> memory = gcode_memory();
  InterpOptions opt;
  opt.inch = o.inch;
  opt.default_feed_nm_per_min = o.default_feed_nm_per_min;
  opt.max_blocks = o.max_blocks;
  memory->attach(&opt);
  return tool_table_inch(&in, opt);
}

int load_read_tool_table(const ReadOptions& o, const std::string& program, ToolTableFile* t, bool* inch) {
  const bool in_inch = table_units_inch(o, program);
  if (inch) *inch = in_inch;
  return load_tool_table(o.tools_file, in_inch, t);
}

}  // namespace cli
}  // namespace dexmill
