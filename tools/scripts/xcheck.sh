#!/usr/bin/env bash
# xcheck.sh - bit-exactness across compilers, optimisation levels and CPUs
# (`make xcheck`). Builds the golden-output program (tests/golden/golden*.cpp
# with every .cpp under core/ and display/) for every target below, runs it natively,
# under qemu-user, or on an emulated Cortex-M board with semihosting, and
# requires every stdout to be byte-identical to the others and to the pinned
# tests/golden/golden.out.
#
# Usage: tools/scripts/xcheck.sh [options]
#   -t LIST      only these targets (comma list; see -l)
#   -x LIST      all targets but these
#   -j N         targets built and run in parallel (default 2)
#   -T SEC       per-run timeout (default 180)
#   -w DIR       work dir (default build/xcheck; one folder per target, kept)
#   -l           list the targets and whether their toolchain is installed
#   --no-install do not run `tools/scripts/install-deps.sh cross` first
#   --bless      after a run where every target agrees, write the output to
#                tests/golden/golden.out (say why in the commit)
# Exit: 0 every target built, ran and matched; 1 any DIFF, BUILD-FAIL,
# RUN-FAIL, TIMEOUT or MISSING toolchain; 2 usage.
#
# Targets (Debian 12 packages come from install-deps.sh cross):
#   gcc-O0 gcc-O2 gcc-O3-native clang-O0 clang-O2 clang-O3-native   x86-64
#   ubsan        g++ -O1, AddressSanitizer + UndefinedBehaviorSanitizer; any report fails
#   ubsan-clang  the same with clang++, whose UBSan also checks pointer arithmetic
#                (pointer-overflow: a pointer formed outside its array)
#   i386-O2      g++ -m32 (g++-12-multilib; never g++-multilib, which removes the cross compilers)
#   armhf-O2 aarch64-O2                          static, under qemu-arm / qemu-aarch64
#   ppc-be-O2 s390x-be-O2 mips-be-O2             big-endian CPUs, static, under qemu-user
#   cm4-qemu   Cortex-M4F  -Os, qemu-system-arm -M mps2-an386
#   cm7-qemu   Cortex-M7   -Os, qemu-system-arm -M mps2-an500
#   cm0-qemu   Cortex-M0+  -Os (ARMv6-M, soft float), run on the Cortex-M3 of
#              mps2-an385 (qemu has no M0 board with enough RAM; the build is
#              checked to contain only ARMv6-M instructions, see check_v6m)
# Cortex-M builds are bare metal: tools/panel/cm/startup.c, newlib-nano only
# for mem*, no heap (the link fails if malloc's _sbrk is needed), output
# through semihosting (tools/panel/cm/board_semihost.cpp).
#
# Compile flags follow the Makefile: the warnings of $DEXMILL_WARN and, for
# core/, display/ and the golden sections, $DEXMILL_INTFLAGS (integer only, no
# exceptions, no RTTI); `make xcheck` passes both, the defaults below match.
set -u
cd "$(dirname "$0")/../.."
ROOT=$(pwd)

ALL_TARGETS="gcc-O0 gcc-O2 gcc-O3-native clang-O0 clang-O2 clang-O3-native ubsan ubsan-clang i386-O2 armhf-O2 aarch64-O2
ppc-be-O2 s390x-be-O2 mips-be-O2 cm4-qemu cm7-qemu cm0-qemu"
WARN=${DEXMILL_WARN:--Wall -Wextra -Werror -Wshadow -Wvla -Wundef}
INTFLAGS=${DEXMILL_INTFLAGS:--fno-exceptions -fno-rtti -include core/integer_only.h}
EXPECTED=tests/golden/golden.out
ONLY=""; EXCL=""; JOBS=2; TMO=180; WORK=build/xcheck; LIST=0; INSTALL=1; BLESS=0

usage() { sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 2; }
while [ $# -gt 0 ]; do
  case $1 in
    -t|-x|-j|-T|-w) [ $# -ge 2 ] || usage
      case $1 in -t) ONLY=$2;; -x) EXCL=$2;; -j) JOBS=$2;; -T) TMO=$2;; -w) WORK=$2;; esac; shift 2;;
    -l) LIST=1; shift;;
    --no-install) INSTALL=0; shift;;
    --bless) BLESS=1; shift;;
    -h|--help) usage;;
    *) echo "xcheck: unknown argument '$1'" >&2; usage;;
  esac
done

# ---- sources (globs: new core/ and display/ files and golden sections join by themselves)
INT_SRC=$( (find core display -name "*.cpp"; ls tests/golden/golden*.cpp tools/panel/text_out.cpp) 2>/dev/null | LC_ALL=C sort)
HOST_BOARD=tools/panel/board_host.cpp
CM_BOARD="tools/panel/cm/board_semihost.cpp"
CM_STARTUP=tools/panel/cm/startup.c
CM_LD=tools/panel/cm/mps2.ld

# ---- target table: sets CXX FLAGS LDFLAGS RUN KIND NEED (commands that must exist)
QEMU_SEMI="qemu-system-arm -nographic -monitor none -serial none -chardev stdio,id=semi0 -semihosting-config enable=on,target=native,chardev=semi0"
define() {
  CXX=""; FLAGS=""; LDFLAGS=""; RUN=""; KIND=host; NEED=""
  case $1 in
    gcc-O0) CXX=g++; FLAGS="-O0";;
    gcc-O2) CXX=g++; FLAGS="-O2";;
    gcc-O3-native) CXX=g++; FLAGS="-O3 -march=native";;
    clang-O0) CXX=clang++; FLAGS="-O0";;
    clang-O2) CXX=clang++; FLAGS="-O2";;
    clang-O3-native) CXX=clang++; FLAGS="-O3 -march=native";;
    ubsan) CXX=g++; FLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
      LDFLAGS="-fsanitize=address,undefined"; RUN="env ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1";;
    ubsan-clang) CXX=clang++; FLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
      LDFLAGS="-fsanitize=address,undefined"; RUN="env ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1";;
    i386-O2) CXX=g++; FLAGS="-m32 -O2"; LDFLAGS="-m32"; NEED="test -d /usr/lib/gcc/x86_64-linux-gnu/12/32";;
    armhf-O2) CXX=arm-linux-gnueabihf-g++; FLAGS="-O2"; LDFLAGS="-static"; RUN=qemu-arm;;
    aarch64-O2) CXX=aarch64-linux-gnu-g++; FLAGS="-O2"; LDFLAGS="-static"; RUN=qemu-aarch64;;
    ppc-be-O2) CXX=powerpc-linux-gnu-g++; FLAGS="-O2"; LDFLAGS="-static"; RUN=qemu-ppc;;
    s390x-be-O2) CXX=s390x-linux-gnu-g++; FLAGS="-O2"; LDFLAGS="-static"; RUN=qemu-s390x;;
    mips-be-O2) CXX=mips-linux-gnu-g++; FLAGS="-O2"; LDFLAGS="-static"; RUN=qemu-mips;;
    cm4-qemu) KIND=cm; CXX=arm-none-eabi-g++; FLAGS="-mthumb -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16 -Os"
      RUN="$QEMU_SEMI -M mps2-an386 -kernel";;
    cm7-qemu) KIND=cm; CXX=arm-none-eabi-g++; FLAGS="-mthumb -mcpu=cortex-m7 -mfloat-abi=hard -mfpu=fpv5-d16 -Os"
      RUN="$QEMU_SEMI -M mps2-an500 -kernel";;
    cm0-qemu) KIND=cm; CXX=arm-none-eabi-g++; FLAGS="-mthumb -mcpu=cortex-m0plus -mfloat-abi=soft -Os"
      RUN="$QEMU_SEMI -M mps2-an385 -kernel";;
    *) return 1;;
  esac
  NEED="command -v $CXX${NEED:+ && $NEED}"
  case $RUN in qemu-*) NEED="$NEED && command -v ${RUN%% *}";; esac
  [ $KIND = cm ] && NEED="$NEED && command -v qemu-system-arm && test -f \"\$($CXX $FLAGS --specs=nano.specs -print-file-name=libc_nano.a)\""
  return 0
}
available() { define "$1" && bash -c "$NEED" >/dev/null 2>&1; }

sel=()
for t in ${ONLY:-$ALL_TARGETS}; do
  for u in ${t//,/ }; do
    define "$u" || { echo "xcheck: unknown target '$u' (see -l)" >&2; exit 2; }
    case ",$EXCL," in *",$u,"*) continue;; esac
    sel+=("$u")
  done
done
[ ${#sel[@]} -gt 0 ] || { echo "xcheck: no targets selected" >&2; exit 2; }

if [ $INSTALL = 1 ] && [ $LIST = 0 ]; then
  tools/scripts/install-deps.sh cross || echo "xcheck: installing the cross toolchains failed; missing targets will fail" >&2
fi
if [ $LIST = 1 ]; then
  for t in "${sel[@]}"; do
    define "$t"; available "$t" && a=yes || a=MISSING
    printf "%-16s %-8s %s %s%s\n" "$t" "$a" "$CXX" "$FLAGS" "${RUN:+  | run: ${RUN/$QEMU_SEMI/qemu-system-arm (semihosting)}}"
  done
  exit 0
fi
mkdir -p "$WORK"; WORK=$(cd "$WORK" && pwd)

now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

# ARMv6-M (Cortex-M0/M0+) has only six 32-bit instructions; anything else in
# the cm0 image would run on qemu's Cortex-M3 but fault on a real M0+.
check_v6m() {
  arm-none-eabi-objdump -d "$1" | grep -P '^ +[0-9a-f]+:\t[0-9a-f]{4} [0-9a-f]{4} +\t' |
    grep -vP '\t(bl|dmb|dsb|isb|mrs|msr)\t' > "$1.not-v6m"
  [ ! -s "$1.not-v6m" ]
}

# Builds and runs one target; leaves status, times, stdout, stderr, rc in $WORK/$t.
run_target() {
  local t=$1 d="$WORK/$1" t0 t1 t2 rc objs=() src o fl
  rm -rf "$d"; mkdir -p "$d/obj"; define "$t"
  if ! available "$t"; then echo MISSING > "$d/status"; echo "- -" > "$d/times"; return; fi
  t0=$(now)
  : > "$d/build.log"
  build() {
    for src in $INT_SRC; do
      o="$d/obj/$(echo "${src%.*}" | tr / _).o"
      fl="-std=c++17 $FLAGS $WARN -I. $INTFLAGS"
      [ $KIND = cm ] && fl="$fl -ffunction-sections -fdata-sections"
      echo "$CXX $fl -c $src -o $o" >> "$d/build.log"
      $CXX $fl -c "$src" -o "$o" >> "$d/build.log" 2>&1 || return 1
      objs+=("$o")
    done
    if [ $KIND = cm ]; then
      fl="-std=c++17 $FLAGS $WARN -I. -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections"
      for src in $CM_BOARD; do
        o="$d/obj/$(basename "${src%.*}").o"; objs+=("$o")
        echo "$CXX $fl -c $src -o $o" >> "$d/build.log"; $CXX $fl -c "$src" -o "$o" >> "$d/build.log" 2>&1 || return 1
      done
      fl="${FLAGS} -Wall -Wextra -Werror -ffunction-sections"
      echo "arm-none-eabi-gcc $fl -c $CM_STARTUP" >> "$d/build.log"
      arm-none-eabi-gcc $fl -c "$CM_STARTUP" -o "$d/obj/startup.o" >> "$d/build.log" 2>&1 || return 1
      fl="$FLAGS ${objs[*]} $d/obj/startup.o -nostartfiles --specs=nano.specs -T $CM_LD -Wl,--gc-sections -Wl,--no-warn-rwx-segments -Wl,-Map=$d/golden.map -o $d/golden.elf"
      echo "$CXX $fl" >> "$d/build.log"; $CXX $fl >> "$d/build.log" 2>&1 || return 1
      if [ "$t" = cm0-qemu ] && ! check_v6m "$d/golden.elf"; then
        echo "not ARMv6-M: 32-bit instructions other than bl/dmb/dsb/isb/mrs/msr:" >> "$d/build.log"
        head -5 "$d/golden.elf.not-v6m" >> "$d/build.log"; return 1
      fi
    else
      fl="-std=c++17 $FLAGS $WARN -I. -fno-exceptions -fno-rtti"
      o="$d/obj/board_host.o"; objs+=("$o")
      echo "$CXX $fl -c $HOST_BOARD -o $o" >> "$d/build.log"; $CXX $fl -c "$HOST_BOARD" -o "$o" >> "$d/build.log" 2>&1 || return 1
      echo "$CXX $FLAGS ${objs[*]} $LDFLAGS -o $d/golden" >> "$d/build.log"
      if ! $CXX $FLAGS "${objs[@]}" $LDFLAGS -o "$d/golden" >> "$d/build.log" 2>&1; then
        [ "$LDFLAGS" = -static ] || return 1
        # No static C library for this cross target: link dynamically, run with its sysroot.
        RUN="$RUN -L /usr/${CXX%-g++}"
        echo "$CXX $FLAGS ${objs[*]} -o $d/golden  (static failed; dynamic + $RUN)" >> "$d/build.log"
        $CXX $FLAGS "${objs[@]}" -o "$d/golden" >> "$d/build.log" 2>&1 || return 1
      fi
    fi
  }
  if ! build; then echo BUILD-FAIL > "$d/status"; echo "$(secs "$t0" "$(now)") -" > "$d/times"; return; fi
  t1=$(now)
  local bin="$d/golden"; [ $KIND = cm ] && bin="$d/golden.elf"
  echo "$RUN $bin" > "$d/run.cmd"
  (cd "$d" && timeout -k 5 "$TMO" $RUN "$bin" < /dev/null > "$d/stdout" 2> "$d/stderr"); rc=$?
  t2=$(now)
  echo "$(secs "$t0" "$t1") $(secs "$t1" "$t2")" > "$d/times"; echo "$rc" > "$d/rc"
  if [ $rc = 124 ] || [ $rc = 137 ]; then echo TIMEOUT > "$d/status"
  elif [ $rc != 0 ]; then echo RUN-FAIL > "$d/status"
  elif [ "${t#ubsan}" != "$t" ] && [ -s "$d/stderr" ]; then echo RUN-FAIL > "$d/status"   # a sanitizer report
  else echo RAN > "$d/status"; fi
}

tstart=$(now)
echo "xcheck: ${#sel[@]} targets, $JOBS at a time, work dir ${WORK#$ROOT/}"
echo "xcheck: sources: $(for f in $INT_SRC; do dirname "$f"; done | uniq -c | awk '{print $2 "/ " $1}' | paste -sd, | sed 's/,/, /g')"
for t in "${sel[@]}"; do
  run_target "$t" &
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n; done
done
wait

# ---- compare: reference = the first target that ran; everything against it and golden.out
ref=""
for t in gcc-O2 "${sel[@]}"; do [ "$(cat "$WORK/$t/status" 2>/dev/null)" = RAN ] && { ref=$t; break; }; done
fail=0
printf "\n%-16s %-10s %7s %7s %4s  %-16s %s\n" TARGET RESULT BUILD_s RUN_s RC STDOUT_SHA256 NOTE
for t in "${sel[@]}"; do
  d="$WORK/$t"; st=$(cat "$d/status"); read -r tb tr < "$d/times"; rc=$(cat "$d/rc" 2>/dev/null || echo -)
  sha=-; note=""
  [ -f "$d/stdout" ] && sha=$(sha256sum < "$d/stdout" | cut -c1-16)
  case $st in
    RAN)
      if cmp -s "$WORK/$ref/stdout" "$d/stdout"; then st=SAME; [ "$t" = "$ref" ] && note="(reference)"
      else st=DIFF; fail=1; note="differs from $ref"; fi
      [ -s "$d/stderr" ] && note="$note stderr: $(head -c 60 "$d/stderr" | tr '\n' ' ')";;
    MISSING) fail=1; define "$t"; note="toolchain or emulator not installed ($CXX${RUN:+, ${RUN%% *}})";;
    *) fail=1
      if [ "$st" = BUILD-FAIL ]; then note=$(grep -m1 -E 'error|Error|undefined|not ARMv6-M' "$d/build.log")
      else note=$(cat "$d/stderr" "$d/stdout" 2>/dev/null | grep -m1 -E 'runtime error|ERROR|fault|FAIL|Abort' || tail -n1 "$d/stderr"); fi
      note=$(echo "$note" | tr '\n' ' ' | cut -c1-100);;
  esac
  printf "%-16s %-10s %7s %7s %4s  %-16s %s\n" "$t" "$st" "$tb" "$tr" "$rc" "$sha" "$note"
done

for t in "${sel[@]}"; do
  d="$WORK/$t"; st=$(cat "$d/status")
  if [ "$st" = RAN ] && ! cmp -s "$WORK/$ref/stdout" "$d/stdout"; then
    echo; echo "--- $t differs from $ref (first 20 lines of diff; full output in ${d#$ROOT/}/stdout)"
    diff "$WORK/$ref/stdout" "$d/stdout" | head -20
  elif [ "$st" = BUILD-FAIL ] || [ "$st" = RUN-FAIL ] || [ "$st" = TIMEOUT ]; then
    echo; echo "--- $t: $st (logs in ${d#$ROOT/})"
    { [ "$st" = BUILD-FAIL ] && grep -v '^[a-z0-9_+-]*g++ \|^arm-none-eabi-gcc ' "$d/build.log" | head -12; } || tail -n 12 "$d/stderr" "$d/stdout" 2>/dev/null
  fi
done

echo
if [ -z "$ref" ]; then
  echo "xcheck: no target ran"; fail=1
elif [ $fail = 0 ] && [ $BLESS = 1 ]; then
  cp "$WORK/$ref/stdout" "$EXPECTED"; echo "xcheck: blessed: wrote $EXPECTED from $ref ($(wc -l < "$EXPECTED") lines)"
elif [ ! -f "$EXPECTED" ]; then
  echo "xcheck: $EXPECTED is missing (run with --bless to pin the output)"; fail=1
elif cmp -s "$EXPECTED" "$WORK/$ref/stdout"; then
  echo "xcheck: output equals the pinned $EXPECTED ($(wc -l < "$EXPECTED") lines)"
else
  echo "xcheck: output of $ref DIFFERS from the pinned $EXPECTED (re-pin with --bless only if the change is intended):"
  diff "$EXPECTED" "$WORK/$ref/stdout" | head -20; fail=1
fi
echo "xcheck: $(secs "$tstart" "$(now)") s"
if [ $fail = 0 ]; then echo "RESULT: PASS (${#sel[@]} targets identical)"; else echo "RESULT: FAIL"; fi
exit $fail
