// The golden and panel programs' only contact with the machine under them:
// write output bytes, and count instructions where the board can.
//
// Two implementations, one per kind of target (tools/scripts/xcheck.sh and
// panel.sh pick one):
//   tools/panel/board_host.cpp        hosted Linux (native or qemu-user): stdout
//   tools/panel/cm/board_semihost.cpp bare-metal Cortex-M on an emulated MPS2
//                                      board: Arm semihosting, SysTick
// Everything else of the golden program (tests/golden/) and of the panel
// here is integer-only, heap-free and I/O-free, like core/, so the same
// bytes come out everywhere (w3_path_dump.cpp, a host program, excepted).
#ifndef DEXMILL_TOOLS_PANEL_BOARD_H
#define DEXMILL_TOOLS_PANEL_BOARD_H

#include <stddef.h>
#include <stdint.h>

namespace golden {

// Writes n bytes to the program's standard output.
void board_write(const char* s, size_t n);

// Retired instructions since an arbitrary start, or 0 when the board cannot
// count them (the host). On the emulated Cortex-M this is exact only under
// `qemu-system-arm -icount shift=0` (see cm/board_semihost.cpp).
uint64_t board_instructions();

// What board_instructions() measures, for the report: never null.
const char* board_clock_name();

}  // namespace golden

#endif
