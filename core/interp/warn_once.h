// The warnings a program gets once, one bit each. A part of the block
// runner (block_runner.h), for the interpreter's own files only.
#ifndef DEXMILL_CORE_INTERP_WARN_ONCE_H
#define DEXMILL_CORE_INTERP_WARN_ONCE_H

#include <stdint.h>

namespace dexmill {
namespace interp_detail {

// Interp::warned_once_ holds them.
enum WarnOnce : uint16_t {
  kOnceDefaultFeed = 1 << 0,
  kOnceFastFeed = 1 << 1,
  kOnceFastSpindle = 1 << 2,
  kOnceProbe = 1 << 3,
  kOnceTapPlane = 1 << 4,
  kOnceManualRetract = 1 << 5,
  kOnceDiameter = 1 << 6,
  kOnceCompNoTable = 1 << 7,
  kOnceG49H = 1 << 8,
  kOnceFeedBeforeUnits = 1 << 9,
};

}  // namespace interp_detail
}  // namespace dexmill

#endif
