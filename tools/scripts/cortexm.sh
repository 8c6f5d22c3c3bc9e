#!/usr/bin/env bash
# cortexm.sh - proves that core/ and display/ build freestanding for Cortex-M
# (`make cortexm`): compiles every .cpp under core/ and display/ (found, not listed) with
# arm-none-eabi-g++ for each CPU with the project's integer-only flags,
# links them with the bare start-up of tools/panel/cm/startup.c (vectors,
# .data/.bss, nothing else; no heap set-up), reports flash and RAM per CPU,
# and fails if the image references
#   heap        malloc/calloc/realloc/free/_sbrk (and their _r forms), operator new/delete
#   exceptions  __cxa_* (throw, guards, atexit, pure_virtual...), _Unwind_*, personality
#               routines, std::terminate, std::__throw_*
#   RTTI        typeinfo (_ZTI*, _ZTS*), __dynamic_cast
#   float       soft-float helpers (__aeabi_f*, __aeabi_d*, __aeabi_[u][il]2[fd], __addsf3,
#               __fixdfsi, ...), libm, or any FPU instruction (v* mnemonics) in the image
#
# GC roots: every global function and object that core/ and display/ define
# (taken from the objects with nm and passed as --undefined), so each public
# entry point is kept, and new files are covered without a list to maintain;
# --gc-sections then drops only what nothing public reaches (library code,
# internal-linkage leftovers). The sizes are therefore those of the whole
# public API, an upper bound for a firmware that uses part of it.
#
# Usage: tools/scripts/cortexm.sh [options]
#   -c CPUS            comma list (default cortex-m4,cortex-m7,cortex-m0plus;
#                      also cortex-m3, cortex-m33)
#   -O LEVEL           optimisation level (default s)
#   -w DIR             work dir (default build/cortexm; kept: map files, disassembly)
#   -S N               show the N largest symbols and stack frames (default 6)
#   --allow-vfp-moves  report FPU register moves/loads/stores (vmov, vldr, vstr, vpush...,
#                      which GCC may use to move 64-bit integers on hard-float CPUs) as
#                      information instead of failing; FPU arithmetic always fails
#   --no-install       do not run `tools/scripts/install-deps.sh cross` first
# Flags from the Makefile when run by make: $DEXMILL_WARN, $DEXMILL_INTFLAGS.
# Exit: 0 clean; 1 a forbidden reference; 2 usage, compile or link error.
set -u
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
CPUS=cortex-m4,cortex-m7,cortex-m0plus; OPT=s; WORK=build/cortexm; TOPN=6; ALLOW_MOVES=0; INSTALL=1
WARN=${DEXMILL_WARN:--Wall -Wextra -Werror -Wshadow -Wvla -Wundef}
INTFLAGS=${DEXMILL_INTFLAGS:--fno-exceptions -fno-rtti -include core/integer_only.h}
usage() { sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 2; }
while [ $# -gt 0 ]; do
  case $1 in
    -c|-O|-w|-S) [ $# -ge 2 ] || usage
      case $1 in -c) CPUS=$2;; -O) OPT=$2;; -w) WORK=$2;; -S) TOPN=$2;; esac; shift 2;;
    --allow-vfp-moves) ALLOW_MOVES=1; shift;;
    --no-install) INSTALL=0; shift;;
    -h|--help) usage;;
    *) echo "cortexm: unknown argument '$1'" >&2; usage;;
  esac
done
[ $INSTALL = 1 ] && { tools/scripts/install-deps.sh cross || echo "cortexm: installing the toolchain failed" >&2; }
P=arm-none-eabi
command -v $P-g++ >/dev/null || { echo "cortexm: $P-g++ missing (tools/scripts/install-deps.sh cross)" >&2; exit 2; }
SRC=$(find core display -name "*.cpp" 2>/dev/null | LC_ALL=C sort)
[ -n "$SRC" ] || { echo "cortexm: no sources in core/ or display/" >&2; exit 2; }
mkdir -p "$WORK"; WORK=$(cd "$WORK" && pwd)

cpuflags() {
  case $1 in
    cortex-m0|cortex-m0plus|cortex-m3) echo "-mthumb -mcpu=$1 -mfloat-abi=soft";;
    cortex-m4) echo "-mthumb -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16";;
    cortex-m7) echo "-mthumb -mcpu=cortex-m7 -mfloat-abi=hard -mfpu=fpv5-d16";;
    cortex-m33) echo "-mthumb -mcpu=cortex-m33 -mfloat-abi=hard -mfpu=fpv5-sp-d16";;
    *) return 1;;
  esac
}

# The start-up calls main and the board's exit/fault hooks; here nothing runs.
cat > "$WORK/stub.c" <<'EOF'
/* cortexm.sh: stands in for the firmware around core/ (link-only check). */
int main(int argc, char** argv) { (void)argc; (void)argv; return 0; }
void board_exit(int code) { (void)code; for (;;) {} }
void board_fault(void) { for (;;) {} }
EOF

HEAP='^(malloc|calloc|realloc|free|_malloc_r|_calloc_r|_realloc_r|_free_r|_sbrk|_sbrk_r|memalign|_memalign_r|aligned_alloc|posix_memalign|_Zn[wa].*|_Zd[la].*)$'
EXC='^(__cxa_.*|_Unwind_.*|__gxx_personality_.*|__aeabi_unwind_cpp_pr[0-9]|_ZSt9terminatev|_ZSt[0-9]+__throw_.*|_ZN10__cxxabiv1.*)$'
RTTI='^(_ZTI.*|_ZTS.*|__dynamic_cast)$'
SOFTFP='^(__aeabi_[fd].*|__aeabi_u?[il]2[fd]|__[a-z]+(sf|df|tf)[a-z0-9]*|(sqrt|sin|cos|tan|atan2?|exp|log|pow|floor|ceil|fabs|fmod|round|lround|trunc)[fl]?)$'
HELPERS='^(__aeabi_(idiv|uidiv|idivmod|uidivmod|ldivmod|uldivmod|lmul|llsl|llsr|lasr|lcmp|ulcmp)|__(u?(div|mod)di3|udivmoddi4|muldi3|ashldi3|lshrdi3|ashrdi3|clzdi2|ctzdi2|popcount[sd]i2))$'
VFP_ARITH='^v(add|sub|mul|nmul|div|sqrt|fma|fms|fnma|fnms|neg|abs|cmp|cmpe|cvt|cvtr|cvtb|cvtt|rint[a-z]?|sel[a-z]*|maxnm|minnm|mla|mls|nmla|nmls)$'

worst=0; summary=()
echo "cortexm: $(echo $SRC | wc -w) sources: $(echo $SRC)"
for cpu in ${CPUS//,/ }; do
  CF=$(cpuflags "$cpu") || { echo "cortexm: unknown cpu '$cpu'" >&2; exit 2; }
  D="$WORK/$cpu"; rm -rf "$D"; mkdir -p "$D/obj"
  FLAGS="$CF -O$OPT -std=c++17 $WARN -I. $INTFLAGS -ffunction-sections -fdata-sections -fstack-usage"
  echo
  echo "== $cpu: $P-g++ $FLAGS"
  objs=()
  for s in $SRC; do
    o="$D/obj/$(echo "${s%.*}" | tr / _).o"
    $P-g++ $FLAGS -c "$s" -o "$o" 2> "$D/compile.log" || { cat "$D/compile.log"; echo "cortexm: COMPILE FAILED ($cpu): $s"; exit 2; }
    objs+=("$o")
  done
  $P-gcc $CF -O$OPT -ffunction-sections -c tools/panel/cm/startup.c -o "$D/startup.o" &&
    $P-gcc $CF -O$OPT -ffunction-sections -c "$WORK/stub.c" -o "$D/stub.o" || exit 2

  # GC roots: the global symbols core/ and display/ define.
  $P-nm --defined-only --extern-only "${objs[@]}" | awk 'NF == 3 && $2 ~ /^[TWDRBVu]$/ { print $3 }' | sort -u > "$D/roots.txt"
  roots=(); while read -r r; do roots+=("-Wl,--undefined=$r"); done < "$D/roots.txt"
  # nosys.specs supplies _sbrk & co. (and `end` the heap start it wants), so
  # a heap user links and is named below instead of failing the link.
  LINK="-nostartfiles --specs=nano.specs --specs=nosys.specs -Wl,--defsym=end=_ebss -T tools/panel/cm/mps2.ld -Wl,--gc-sections -Wl,--no-warn-rwx-segments"
  if ! $P-g++ $CF -O$OPT "${objs[@]}" "$D/startup.o" "$D/stub.o" $LINK -Wl,--cref,--no-demangle -Wl,-Map="$D/image.map" \
       "${roots[@]}" -o "$D/image.elf" > "$D/link.log" 2>&1; then
    grep -v 'is not implemented and will always fail' "$D/link.log" | head -20; echo "cortexm: LINK FAILED ($cpu)"; exit 2
  fi
  $P-g++ $CF -O$OPT "$D/startup.o" "$D/stub.o" $LINK -o "$D/baseline.elf" > /dev/null 2>&1 || { echo "cortexm: baseline link failed"; exit 2; }

  echo "-- objects (before gc; text includes constants)"
  $P-size "${objs[@]}" | awk 'NR == 1 { printf "   %8s %6s %6s  %s\n", "text", "data", "bss", "object"; next }
    { n = split($6, a, "/"); printf "   %8d %6d %6d  %s\n", $1, $2, $3, a[n] }'
  read -r tx dt bs _ < <($P-size "$D/image.elf" | tail -1)
  read -r btx bdt bbs _ < <($P-size "$D/baseline.elf" | tail -1)
  flash=$((tx + dt)); ram=$((dt + bs)); cflash=$((tx + dt - btx - bdt)); cram=$((dt + bs - bdt - bbs))
  echo "-- image ($(wc -l < "$D/roots.txt") roots = every global symbol of core/ and display/)"
  printf "   FLASH %d B (text %d + data %d), RAM %d B static (data %d + bss %d), stack not included\n" $flash "$tx" "$dt" $ram "$dt" "$bs"
  printf "   of which core/display and the library code they pull in: FLASH %d B, RAM %d B\n" $cflash $cram
  printf "   (baseline = start-up + empty main: FLASH %d B, RAM %d B)\n" $((btx + bdt)) $((bdt + bbs))

  $P-nm "$D/image.elf" | awk 'NF >= 2 { print $NF }' | sort -u > "$D/image_syms.txt"
  $P-objdump -d "$D/image.elf" > "$D/image.dis"
  whoref() {  # objects that reference symbol $1, from the linker's cross-reference table
    awk -v s="$1" '/^Cross Reference Table/ { x = 1; next }
      x && $1 == s { f = 1; if (NF >= 2) { print $2 }; next } x && f && /^[ \t]/ { print $1; next } x && f { exit }' "$D/image.map" |
      sed 's|.*/||' | tail -n +2 | head -3 | tr '\n' ' '; }
  bad=0
  check() {  # label regex: FOUND fails
    local hits; hits=$(grep -E "$2" "$D/image_syms.txt")
    if [ -z "$hits" ]; then printf "   %-44s none\n" "$1"; return; fi
    printf "   %-44s FOUND\n" "$1"; bad=1
    for h in $hits; do printf "       %-40s referenced by: %s\n" "$($P-c++filt "$h" | cut -c1-40)" "$(whoref "$h")"; done
  }
  echo "-- forbidden references (linked image)"
  check "heap (malloc/free/_sbrk, new/delete)" "$HEAP"
  check "exceptions (__cxa_*, _Unwind_*, terminate)" "$EXC"
  check "RTTI (typeinfo, dynamic_cast)" "$RTTI"
  check "soft-float helpers / libm" "$SOFTFP"
  # FPU instructions: every M-profile mnemonic starting with v is FP (or MVE).
  awk -F'\t' 'NF >= 3 && $3 ~ /^v[a-z0-9]/ { m = $3; sub(/\..*/, "", m); print m }' "$D/image.dis" | sort | uniq -c > "$D/vfp.txt"
  n_arith=$(awk -v re="$VFP_ARITH" '$2 ~ re { n += $1 } END { print n + 0 }' "$D/vfp.txt")
  n_moves=$(awk -v re="$VFP_ARITH" '$2 !~ re { n += $1 } END { print n + 0 }' "$D/vfp.txt")
  if [ "$n_arith" -gt 0 ]; then printf "   %-44s FOUND %d\n" "FPU arithmetic/conversion instructions" "$n_arith"; bad=1
  else printf "   %-44s none\n" "FPU arithmetic/conversion instructions"; fi
  if [ "$n_moves" -gt 0 ]; then
    printf "   %-44s %s %d\n" "FPU register moves/loads/stores" "$([ $ALLOW_MOVES = 1 ] && echo "present (allowed)" || echo FOUND)" "$n_moves"
    [ $ALLOW_MOVES = 1 ] || bad=1
  else printf "   %-44s none\n" "FPU register moves/loads/stores"; fi
  if [ -s "$D/vfp.txt" ]; then
    awk '/^[0-9a-f]+ <.*>:$/ { fn = $2 } $0 ~ /\tv[a-z0-9]+/ { print fn }' "$D/image.dis" | sort | uniq -c | head -5 |
      while read -r c f; do printf "       %4d in %s\n" "$c" "$(echo "$f" | tr -d '<>:' | $P-c++filt | cut -c1-70)"; done
  fi

  echo "-- integer helper calls (allowed; 64-bit multiply/divide are library calls on ARMv6-M)"
  helpers=$(grep -E "$HELPERS" "$D/image_syms.txt" | tr '\n' ' ')
  printf "   in image: %s\n" "${helpers:-none}"
  # Which functions call them: the stamping loop must not (paper §2.3 inner loop).
  awk '/^[0-9a-f]+ <.*>:$/ { fn = $2 } /\tbl\t/ && match($0, /<__(aeabi_[a-z0-9]+|[a-z0-9]+di[0-9])>/) {
         print fn, substr($0, RSTART + 1, RLENGTH - 2) }' "$D/image.dis" | sort | uniq -c |
    awk '{ print $2, $3 "x" $1 }' | awk '{ a[$1] = a[$1] " " $2 } END { for (f in a) print f, a[f] }' | sort > "$D/helper_calls.txt"
  while read -r f calls; do
    printf "   %-58s %s\n" "$(echo "$f" | tr -d '<>:' | $P-c++filt | sed 's/dexmill:://g; s/unsigned /u/g' | cut -c1-58)" "$calls"
  done < "$D/helper_calls.txt"
  hot=$(grep -E '^<_ZN7dexmill14stamp_instance' "$D/helper_calls.txt" | cut -c1-200)
  if [ -n "$hot" ]; then echo "   NOTE: stamp_instance calls helpers (inner cutting loop?): $hot"
  else echo "   stamp_instance<uint8/16/32>: no helper calls (the per-dexel loop is plain 32-bit code)"; fi

  echo "-- largest symbols"
  $P-nm -S --size-sort -C --radix=d "$D/image.elf" | tail -n "$TOPN" | tac |
    awk '{ printf "   %7d %s %s\n", $2, $3, substr($0, index($0, $4)) }' | sed 's/dexmill:://g' | cut -c1-100
  echo "-- largest stack frames (-fstack-usage)"
  cat "$D"/obj/*.su 2>/dev/null | awk -F'\t' '{ f = $1; sub(/^[^:]*:[0-9]+:[0-9]+:/, "", f); printf "   %6d %-8s %s\n", $2, $3, f }' |
    sort -rn | head -n "$TOPN" | sed 's/dexmill:://g' | cut -c1-100
  if [ $bad = 1 ]; then verdict=FORBIDDEN; worst=1; else verdict=OK; fi
  echo "RESULT $cpu: $verdict"
  summary+=("$(printf "%-14s %9d %8d %13d %9d  %s" "$cpu" $flash $ram $cflash $cram "$verdict")")
done

echo
printf "%-14s %9s %8s %13s %9s  %s\n" CPU FLASH_B RAM_B CORE_FLASH_B CORE_RAM_B CHECK
for l in "${summary[@]}"; do echo "$l"; done
echo "(FLASH = text + data of the whole image; CORE_ = minus start-up + empty main; RAM static, no stack)"
echo "work dir: ${WORK#$ROOT/}"
exit $worst
