// The sweep's entry points with the column loops in the word width the
// program does not use (core/config.h, kSweepWordBits: 32 bits on a 64-bit
// CPU, 64 on a 32-bit one), for the tests that hold both widths to the same
// bits (tests/test_sweep_widths.cpp) and to the oracle. Nothing else calls
// them: a board's linker (--gc-sections) drops them.
#include "core/config.h"
#include "core/cut/sweep_internal.h"
#include "core/cut/sweep_piece.h"

namespace dexmill {

DEXMILL_SWEEP_LINE_W_INSTANTIATE_ALL(96 - kSweepWordBits)

}  // namespace dexmill
