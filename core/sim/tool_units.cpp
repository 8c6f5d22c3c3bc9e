// The tool table's units; see tool_units.h.
#include "core/sim/tool_units.h"

#include "core/sim/gcode_runner.h"

namespace dexmill {

namespace {

struct Quiet final : GcodeMessages {
  void error(const GcodeDiag&) override {}
  void warning(const GcodeDiag&) override {}
};

}  // namespace

bool tool_table_inch(LineInput* in, InterpOptions opt) {
  opt.warnings = nullptr;
  opt.messages = nullptr;
  Interp interp(nullptr, opt);
  Quiet quiet;
  GcodeRunner runner(in, &interp, &quiet, false);
  while (!interp.tool_named() && runner.step()) {
  }
  return interp.tool_named() && interp.units_set_at_tool() ? interp.inch_at_tool() : opt.inch;
}

}  // namespace dexmill
