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
