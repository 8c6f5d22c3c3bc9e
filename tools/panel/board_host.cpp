// Board of the hosted targets (x86-64, i386, and the Linux CPUs under
// qemu-user): output to stdout. No instruction counter.
#include <stdio.h>

#include "tools/panel/board.h"

namespace golden {

void board_write(const char* s, size_t n) {
  fwrite(s, 1, n, stdout);
}

uint64_t board_instructions() { return 0; }

const char* board_clock_name() { return "none (host)"; }

}  // namespace golden
