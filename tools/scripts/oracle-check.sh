#!/usr/bin/env bash
# Checks `dexmill path` against LinuxCNC's interpreter, within 0.002 mm.
#
#   tools/scripts/oracle-check.sh [--rs274] [DEXMILL]
#
# 1. The stored oracles of the corpus folder CI keeps beside the clone,
#    linuxcnc-interp-oracle/*/expected (LinuxCNC's canonical trace of each
#    program): skipped with a message when that folder is absent.
# 2. With --rs274 (needs LinuxCNC's standalone interpreter `rs274`, Debian
#    package linuxcnc-uspace): every tests/gcode/paths/*.ngc and every file of
#    that corpus folder, traced by rs274 and compared the same way, both with
#    the same tool table (for G41/G42: FAMILY.tbl beside FAMILY_NAME.ngc, or
#    one the script writes).
#    Also the programs `dexmill zig` writes (they must be plain RS274/NGC
#    that LinuxCNC reads as dexmill does), from a relief the script draws
#    (lifted and zigzag, along x and y) and for the four built-in parts of run --demo.
# A program that dexmill refuses as "not supported" is reported, not failed.
# rs274 prints a spline (G5, G5.1) as NURBS_FEED without its points; for a
# trace with one, LinuxCNC's own preview of the program (lcnc_preview.py,
# the same interpreter) gives the curve (lcnc_compare.py --preview).
# Exit 1 if any comparison differs.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
shared="$root/../shared"
use_rs274=0
if [ "${1:-}" = --rs274 ]; then use_rs274=1; shift; fi
dexmill=${1:-$root/build/dexmill}
compare="python3 $root/tools/scripts/lcnc_compare.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$dexmill" ] || { echo "oracle-check: $dexmill not built (run make)" >&2; exit 2; }
failed=0; agreed=0; unsupported=0

# scale_table FACTOR TABLE: the tool table with its D and Z words times
# FACTOR (25.4: inch to mm; 1/25.4: mm to inch); what follows ';' is a
# comment, kept as it is.
scale_table() {
  awk -v f="$1" 'BEGIN { split(f, q, "/"); k = q[1] / (q[2] == "" ? 1 : q[2]) }
    { c = index($0, ";"); words = c ? substr($0, 1, c - 1) : $0; rest = c ? substr($0, c) : ""
      n = split(words, w, /[ \t]+/); out = ""
      for (i = 1; i <= n; i++) { if (w[i] == "") continue; l = toupper(substr(w[i], 1, 1))
        if ((l == "D" || l == "Z") && substr(w[i], 2) ~ /^[-+]?[0-9.]+$/) w[i] = sprintf("%s%.10g", l, substr(w[i], 2) * k)
        out = out (out == "" ? "" : " ") w[i] }
      print out rest }' "$2"
}

# check NAME PROGRAM TRACE [TOOLS]: compare dexmill's path of PROGRAM (with
# the tool table TOOLS, in mm) with TRACE.
check() {
  local name=$1 prog=$2 trace=$3 tools=${4:-}
  "$dexmill" path "$prog" ${tools:+--tools "$tools" --tool-units mm} > "$tmp/path" 2> "$tmp/err"
  local rc=$? first
  first=$(grep -m1 ': error: ' "$tmp/err" | sed 's/^.*: error: //')
  if [ $rc -ne 0 ] && grep -q 'not supported' <<<"$first"; then
    local where; where=$(grep -m1 ': error: ' "$tmp/err" | sed -E 's/^.*:([0-9]+):([0-9]+): error: .*/\1/')
    echo "$name: UNSUPPORTED (line $where: $first)"
    unsupported=$((unsupported + 1))
    return
  fi
  local preview=()
  if grep -q 'NURBS_FEED' "$trace"; then
    sed -E 's/^[[:space:]]*\$(.*)$/(grbl $\1)/' "$prog" > "$tmp/preview.ngc"
    python3 "$root/tools/scripts/lcnc_preview.py" "$tmp/preview.ngc" > "$tmp/preview" 2>/dev/null &&
      preview=(--preview "$tmp/preview")
  fi
  local res; res=$($compare "$trace" "$tmp/path" "${preview[@]}")
  local crc=$?
  if [ $crc -eq 3 ]; then  # a spline without LinuxCNC's preview to place it
    echo "$name: $res"
    unsupported=$((unsupported + 1))
    return
  fi
  # A probe (G38.2-G38.5) stops where the machine meets the work; dexmill
  # moves to the target, rs274 makes up its own contact point: a program
  # that goes on from wherever the probe stopped (G92 Z0 after it) cannot
  # agree, and is not counted as a difference.
  if [ $crc -ne 0 ] && grep -qiE '(^|[^0-9.])g *0*38\.[2-5]' "$prog"; then
    echo "$name: NOT COMPARED after a probe (the contact point is the machine's): $res"
    unsupported=$((unsupported + 1))
    return
  fi
  [ $rc -ne 0 ] && res="$res [dexmill stopped: $first]"
  echo "$name: $res"
  if [ $crc -eq 0 ]; then agreed=$((agreed + 1)); else failed=$((failed + 1)); fi
}

if [ -d "$shared/corpus/linuxcnc-interp-oracle" ]; then
  echo "== stored LinuxCNC oracles (../shared/corpus/linuxcnc-interp-oracle)"
  for d in "$shared"/corpus/linuxcnc-interp-oracle/*/; do
    prog=$(ls "$d"*.ngc | head -1)
    # A trace made with a tool table: LinuxCNC's standalone interpreter read
    # it in inch (its GET_EXTERNAL_LENGTH_UNITS); dexmill gets it in mm.
    table=""
    if ls "$d"*.tbl >/dev/null 2>&1; then
      table="$tmp/stored_$(basename "$d").tbl"
      scale_table 25.4 "$(ls "$d"*.tbl | head -1)" > "$table"
    fi
    check "$(basename "$d")" "$prog" "$d/expected" "$table"
  done
else
  echo "oracle-check: ../shared is absent; skipping the stored LinuxCNC oracles"
fi

if [ $use_rs274 = 1 ]; then
  if ! command -v rs274 >/dev/null; then
    echo "oracle-check: rs274 not installed (apt-get install linuxcnc-uspace); skipping --rs274"
  else
    echo "== rs274 (LinuxCNC $(dpkg-query -W -f='${Version}' linuxcnc-uspace 2>/dev/null)) on the project's programs and the corpus"
    files=$(ls "$root"/tests/gcode/paths/*.ngc 2>/dev/null)
    if [ -d "$shared/corpus" ]; then
      files="$files $(cut -f1 "$shared/corpus/index.tsv" | tail -n +2 | sed "s|^|$shared/corpus/|")"
    fi
    # A tool table with tools 0..999, all of length 0 (dexmill's path does not
    # apply tool lengths; without a table rs274 refuses unknown tools), for
    # cutter compensation 1/8 in across (the corpus's cam.ngc cuts with a
    # 3.1 mm end mill, T1), T4 1 in (comp-g1.ngc says so). dexmill reads it in
    # mm; the standalone rs274 reads its tool table in inch (its
    # GET_EXTERNAL_LENGTH_UNITS), so it gets the same table in inch.
    for t in $(seq 0 999); do
      if [ $t = 4 ]; then echo "T$t P$t Z0 D25.4"; else echo "T$t P$t Z0 D3.175"; fi
    done > "$tmp/tools.tbl"
    # mm_to_inch TABLE: the same table with D and Z in inch (exact for the
    # diameters the project's tables use, multiples of 0.0254 mm).
    mm_to_inch() { scale_table "1/25.4" "$1"; }
    # dexmill zig's programs, from a relief drawn here.
    python3 - "$tmp/relief.pgm" <<'PY'
import math, sys
w, h = 48, 32
px = bytes(int(255 * (0.5 + 0.25 * math.sin(6 * i / w) * math.cos(5 * j / h) + (0.3 if 14 < i < 24 and 9 < j < 19 else 0)) / 1.3)
           for j in range(h) for i in range(w))
open(sys.argv[1], "wb").write(b"P5\n%d %d\n255\n" % (w, h) + px)
PY
    zig_files=
    for v in "lifted-x:" "zigzag-x:--zigzag" "lifted-y:--direction y" "zigzag-y:--zigzag --direction y --step 0.75"; do
      out="$tmp/zig-${v%%:*}.ngc"
      if "$dexmill" zig "$tmp/relief.pgm" --stock 0,0,-20,48,32,0 --design-z -14,-2 --tool ball:4 --pitch 0.5 ${v#*:} -o "$out" 2>/dev/null; then
        zig_files="$zig_files $out"
      else
        echo "zig ${v%%:*}: dexmill zig failed"; failed=$((failed + 1))
      fi
    done
    for n in panel smiley freeform tsuba; do  # the --demo parts' programs
      if "$dexmill" zig "$n" -o "$tmp/zig-$n.ngc" 2>/dev/null; then zig_files="$zig_files $tmp/zig-$n.ngc"
      else echo "zig $n: dexmill zig failed"; failed=$((failed + 1)); fi
    done
    files="$files$zig_files"
    for f in $files; do
      # dexmill skips grbl `$` lines with a warning; LinuxCNC would stop
      # there, so it gets them as comments.
      sed -E 's/^[[:space:]]*\$(.*)$/(grbl $\1)/' "$f" > "$tmp/prog.ngc"
      # The project's FAMILY_NAME.ngc runs with FAMILY.tbl when there is one
      # (as in tests/test_gcode_files.cpp), everything else with the table above.
      table="$(dirname "$f")/$(basename "$f" | sed 's/_.*//; s/\.[^.]*$//').tbl"
      [ "${f#"$root"/tests/gcode/paths/}" != "$f" ] && [ -f "$table" ] || table="$tmp/tools.tbl"
      mm_to_inch "$table" > "$tmp/tools_inch.tbl"
      # rs274 keeps its tool data in $HOME/.tool.mmap, shared by every rs274
      # running at the time: a HOME of its own keeps others' tables out.
      ( cd "$tmp" && HOME="$tmp" timeout 300 rs274 -t "$tmp/tools_inch.tbl" -g "$tmp/prog.ngc" > "$tmp/trace" 2>&1 < /dev/null )
      name=${f#"$root"/}; name=${name#"$shared"/}; name=${name#"$tmp"/}
      check "$name" "$f" "$tmp/trace" "$table"
    done
  fi
fi
echo "oracle-check: $agreed agree, $failed differ, $unsupported not supported by dexmill or not comparable"
[ $failed -eq 0 ]
