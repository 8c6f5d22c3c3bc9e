// Status codes of the core (core/README.md, habit 4): stable numbers, one message
// table, returned and never thrown. The G-code reader has its own table of
// input errors (core/gcode/error.h), since those carry a line and column.
#ifndef DEXMILL_CORE_STATUS_H
#define DEXMILL_CORE_STATUS_H

#include <stdint.h>

namespace dexmill {

enum class Status : uint8_t {
  kOk = 0,
  kBufferTooSmall = 1,   // caller-provided memory cannot hold the result
  kBadArgument = 2,      // a parameter is outside its documented domain
  kOutOfRange = 3,       // a value does not fit the fixed-point format
  kToolTooLarge = 4,     // cutter footprint exceeds the supported size
};

// Message for a status; never null.
const char* status_message(Status s);

inline bool ok(Status s) { return s == Status::kOk; }

}  // namespace dexmill

#endif
