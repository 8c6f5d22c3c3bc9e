#!/usr/bin/env bash
# panel_w3.sh - a 256 x 256 job on the Cortex-M4 panel (`make panel-w3`):
# paper-w3's path (written as a header by tools/panel/w3_path_dump.cpp from
# tools/bench/workloads.cpp) cut by exact sweeps and redrawn incrementally by
# tools/panel/panel_w3_main.cpp, built like panel.sh's demo for the host
# and for qemu's MPS2 AN386 (-icount shift=0: SysTick counts instructions).
# Every output line not starting with "info" must be equal; the board's
# info lines are the instruction counts (at 1 instruction a cycle, n / 168
# is microseconds on a 168 MHz part).
#
# Usage: tools/scripts/panel_w3.sh [--no-install] [-w DIR (default build/panel_w3)] [-T SEC (default 300)]
# Exit: 0 equal; 1 different output or a run failed; 2 a build failed or usage.
set -u
cd "$(dirname "$0")/../.."
. "$(dirname "$0")/panel_build.sh"  # panel_setup, build(), CM4
panel_setup panel_w3 build/panel_w3 "$@"

# The path, from the bench's own workload code (host, floating point).
g++ -std=c++17 -O2 $WARN -I. tools/panel/w3_path_dump.cpp tools/bench/workloads.cpp core/grid/grid.cpp core/math/fixed.cpp \
  -o "$WORK/w3_path_dump" && "$WORK/w3_path_dump" > "$WORK/w3_path.h" || { echo "panel_w3: path generation failed"; exit 2; }

INT_SRC="$(find core display -name "*.cpp" 2>/dev/null | LC_ALL=C sort) tools/panel/panel_w3_main.cpp tools/panel/text_out.cpp"
BUILD_INC="-I$WORK"  # the generated path header
build host g++ "-O2" tools/panel/board_host.cpp && g++ "${objs[@]}" -o "$WORK/host/panel_w3" ||
  { echo "panel_w3: host build failed"; exit 2; }
build cm4 arm-none-eabi-g++ "$CM4" tools/panel/cm/board_semihost.cpp tools/panel/cm/startup.c &&
  arm-none-eabi-g++ $CM4 "${objs[@]}" -nostartfiles --specs=nano.specs -T tools/panel/cm/mps2.ld \
    -Wl,--gc-sections -Wl,--no-warn-rwx-segments -o "$WORK/cm4/panel_w3.elf" ||
  { echo "panel_w3: Cortex-M4 build failed"; exit 2; }

panel_compare panel_w3
