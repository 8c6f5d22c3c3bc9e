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

# panel_compare NAME: runs $WORK/host/NAME and $WORK/cm4/NAME.elf under qemu
# (mps2-an386, instruction counter on), prints the board's output and exits 0
# when its lines other than `info` equal the host's, 1 otherwise.
panel_compare() {
  local name=$1 fail=0 t0 t1 t2
  t0=$(date +%s.%N)
  "$WORK/host/$name" > "$WORK/host/stdout" 2> "$WORK/host/stderr" || { echo "$name: host run failed (rc $?)"; fail=1; }
  t1=$(date +%s.%N)
  timeout -k 5 "$TMO" qemu-system-arm -M mps2-an386 -icount shift=0 -nographic -monitor none -serial none \
    -chardev stdio,id=semi0 -semihosting-config enable=on,target=native,chardev=semi0 \
    -kernel "$WORK/cm4/$name.elf" < /dev/null > "$WORK/cm4/stdout" 2> "$WORK/cm4/stderr" || { echo "$name: qemu run failed (rc $?)"; fail=1; }
  t2=$(date +%s.%N)
  echo "$name: host run $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }') s, qemu run $(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.2f", b - a }') s"
  echo "--- Cortex-M4 (qemu mps2-an386) output"
  cat "$WORK/cm4/stdout"
  if [ $fail = 0 ] && diff <(grep -v '^info' "$WORK/host/stdout") <(grep -v '^info' "$WORK/cm4/stdout") > "$WORK/diff.txt"; then
    echo "RESULT: PASS (Cortex-M4 output equals the host build's, $(grep -vc '^info' "$WORK/host/stdout") lines)"
    exit 0
  fi
  echo "--- host vs Cortex-M4 (non-info lines)"; head -20 "$WORK/diff.txt"
  echo "RESULT: FAIL"
  exit 1
}
