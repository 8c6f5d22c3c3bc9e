# Sourced by panel.sh and panel_w3.sh: compiles $INT_SRC (integer-only
# sources, with $INTFLAGS and $BUILD_INC) and the given board sources for one
# kind of build into $WORK/KIND, leaving the object list in $objs.
#   build KIND CXX FLAGS BOARD_SOURCES...
build() {
  local kind=$1 cxx=$2 fl=$3 s o; shift 3; objs=()
  for s in $INT_SRC; do
    o="$WORK/$kind/$(echo "${s%.*}" | tr / _).o"
    $cxx -std=c++17 $fl $WARN -I. ${BUILD_INC:-} $INTFLAGS -c "$s" -o "$o" || return 1; objs+=("$o")
  done
  for s in "$@"; do
    o="$WORK/$kind/$(basename "${s%.*}").o"
    case $s in
      *.c) arm-none-eabi-gcc $fl -Wall -Wextra -Werror -c "$s" -o "$o" || return 1;;
      *) $cxx -std=c++17 $fl $WARN -I. -fno-exceptions -fno-rtti -c "$s" -o "$o" || return 1;;
    esac
    objs+=("$o")
  done
}
# The Cortex-M4F of qemu's mps2-an386, as the panel would be built.
CM4="-mthumb -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16 -Os -ffunction-sections -fdata-sections"

# panel_setup NAME DEFAULT_WORK "$@": the options (-w DIR, -T SEC,
# --no-install), the flags (the Makefile's $DEXMILL_WARN, $DEXMILL_INTFLAGS)
# and the toolchain; sets WORK (absolute, emptied), TMO, WARN, INTFLAGS.
panel_setup() {
  local name=$1 c; WORK=$2; shift 2; TMO=300; INSTALL=1
  while [ $# -gt 0 ]; do
    case $1 in
      -w) WORK=$2; shift 2;; -T) TMO=$2; shift 2;; --no-install) INSTALL=0; shift;;
      *) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 2;;
    esac
  done
  WARN=${DEXMILL_WARN:--Wall -Wextra -Werror -Wshadow -Wvla -Wundef}
  INTFLAGS=${DEXMILL_INTFLAGS:--fno-exceptions -fno-rtti -include core/integer_only.h}
  [ $INSTALL = 1 ] && { tools/scripts/install-deps.sh cross || echo "$name: installing the toolchain failed" >&2; }
  for c in g++ arm-none-eabi-g++ qemu-system-arm; do
    command -v $c >/dev/null || { echo "$name: $c missing (tools/scripts/install-deps.sh cross)" >&2; exit 2; }
  done
  rm -rf "$WORK"; mkdir -p "$WORK/host" "$WORK/cm4"; WORK=$(cd "$WORK" && pwd)
}
