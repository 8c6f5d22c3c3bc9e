#!/usr/bin/env bash
# panel.sh - the Cortex-M panel demo (`make panel`): builds
# tools/panel/panel_main.cpp with every .cpp under core/ and display/ (found, not listed) for
# the host and, freestanding, for a Cortex-M4F on qemu's MPS2 AN386 board
# (semihosting for output only), runs both, and requires every output line
# that does not start with "info" (instruction counts exist only on the
# board) to be identical. The board run uses -icount shift=0, so SysTick
# counts retired instructions (see tools/panel/cm/board_semihost.cpp).
#
# Usage: tools/scripts/panel.sh [--no-install] [-w DIR (default build/panel)] [-T SEC (default 300)]
# Flags from the Makefile when run by make: $DEXMILL_WARN, $DEXMILL_INTFLAGS.
# Exit: 0 equal; 1 different output or a run failed; 2 a build failed or usage.
set -u
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
. "$(dirname "$0")/panel_build.sh"  # panel_setup, build(), CM4
panel_setup panel build/panel "$@"
INT_SRC="$(find core display -name "*.cpp" 2>/dev/null | LC_ALL=C sort) tools/panel/panel_main.cpp tools/panel/text_out.cpp"

build host g++ "-O2" tools/panel/board_host.cpp && g++ "${objs[@]}" -o "$WORK/host/panel" ||
  { echo "panel: host build failed"; exit 2; }
build cm4 arm-none-eabi-g++ "$CM4" tools/panel/cm/board_semihost.cpp tools/panel/cm/startup.c &&
  arm-none-eabi-g++ $CM4 "${objs[@]}" -nostartfiles --specs=nano.specs -T tools/panel/cm/mps2.ld \
    -Wl,--gc-sections -Wl,--no-warn-rwx-segments -Wl,-Map="$WORK/cm4/panel.map" -o "$WORK/cm4/panel.elf" ||
  { echo "panel: Cortex-M4 build failed"; exit 2; }

read -r tx dt bs _ < <(arm-none-eabi-size "$WORK/cm4/panel.elf" | tail -1)
echo "panel: Cortex-M4 image: FLASH $((tx + dt)) B (text+rodata $tx, data $dt), RAM $((dt + bs)) B static (grid, cutters, stack not included)"
addr=$(arm-none-eabi-nm -C "$WORK/cm4/panel.elf" | awk '$NF == "kDemo" || $NF ~ /::kDemo$/ { print $1; exit }')
if [ -n "$addr" ]; then
  [ $((16#$addr)) -lt $((16#20000000)) ] && where=flash || where=RAM
  echo "panel: demo program kDemo at 0x$addr ($where)"
fi

panel_compare panel
