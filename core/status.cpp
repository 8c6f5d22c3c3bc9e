#include "core/status.h"

namespace dexmill {

const char* status_message(Status s) {
  switch (s) {
    case Status::kOk: return "ok";
    case Status::kBufferTooSmall: return "buffer too small";
    case Status::kBadArgument: return "bad argument";
    case Status::kOutOfRange: return "value out of range";
    case Status::kToolTooLarge: return "tool too large for the grid pitch";
  }
  return "unknown status";
}

}  // namespace dexmill
