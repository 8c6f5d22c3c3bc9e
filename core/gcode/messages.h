// Where a runner's diagnostics go (core/sim/gcode_runner.h): errors, the
// interpreter's warnings (GcodeDiagSink), the file they are of; counted.
// The host prints them (platform/input/gcode_file.h GcodeStderrMessages); an
// embedder keeps them (core/sim/simulation.h).
#ifndef DEXMILL_CORE_GCODE_MESSAGES_H
#define DEXMILL_CORE_GCODE_MESSAGES_H

#include <stdint.h>

#include "core/gcode/error.h"

namespace dexmill {

class GcodeMessages : public GcodeDiagSink {
 public:
  virtual void error(const GcodeDiag& d) = 0;
  // Diagnostics from now on are of this file (a subroutine file's lines).
  virtual void set_file(const char* name) { (void)name; }
  uint32_t errors() const { return errors_; }
  uint32_t warnings() const { return warnings_; }

 protected:
  ~GcodeMessages() = default;
  uint32_t errors_ = 0;
  uint32_t warnings_ = 0;
};

}  // namespace dexmill

#endif
