// The interpreter's bounds on a block's numbers (F, S, P, L, T, a canned
// cycle's moves) and the warnings past them. A part of the block runner
// (block_runner.h), for the interpreter's own files only.
#ifndef DEXMILL_CORE_INTERP_BLOCK_LIMITS_H
#define DEXMILL_CORE_INTERP_BLOCK_LIMITS_H

#include <stdint.h>

namespace dexmill {
namespace interp_detail {

// F and S: LinuxCNC takes any value (the machine clamps to its maximum
// velocity); these bounds only keep the arithmetic in range. Above
// kFastFeedNmPerMin / kFastSpindleRpm a program gets one warning each.
constexpr int64_t kMaxFeedUnitsPerMin = 1000000000;
constexpr int64_t kMaxSpindleRpm = 1000000000;
constexpr int64_t kFastFeedNmPerMin = 1000000LL * 1000000;  // 1e6 mm/min
constexpr int64_t kFastSpindleRpm = 1000000;
constexpr int64_t kMaxDwellS = 1000000;
constexpr int64_t kMaxRepeats = 1000000;
constexpr int64_t kMaxTurns = 10000;
constexpr int64_t kMaxToolNumber = 1000000000;
constexpr int64_t kMaxCycleMoves = 10000000;

}  // namespace interp_detail
}  // namespace dexmill

#endif
