#!/usr/bin/env bash
# The time estimate against its bounds on real programs: for each program,
# `dexmill run --machine MACHINE` and the report's time_model figures,
# no acceleration (a lower bound), blended (the estimate: each axis within
# its velocity and acceleration, corners blended within G64 P, LinuxCNC's
# way; core/canon/motion_plan.h) and stop (every move from rest to rest at
# the slowest axis's acceleration, an upper bound), as a Markdown table.
# With LCNC=1 a last column is LinuxCNC's own time for the program from a
# real trajectory-planner run (tools/scripts/linuxcnc-time.sh; slow: the
# sim runs in real time), where it can be had.
#
#   tools/scripts/time-compare.sh [--machine INI] [PROGRAM...]
# Default: tools/examples/mill.ini and eight programs of the shared corpus
# beside the checkout (the folder CI clones next to it).
set -eu
cd "$(dirname "$0")/../.."
machine=tools/examples/mill.ini
if [ "${1:-}" = --machine ]; then machine=$2; shift 2; fi
corpus=../shared/corpus
if [ $# -eq 0 ]; then
  set -- $corpus/linuxcnc/inside-corners_test.ngc $corpus/linuxcnc/flowsnake.ngc $corpus/linuxcnc/arcspiral.ngc \
    $corpus/linuxcnc/blur_torus.ngc $corpus/CAMotics/heart.ngc $corpus/CAMotics/vcarve.ngc \
    $corpus/grbl/HSM_test.nc $corpus/CAMotics/bear.nc
fi
bin=${DEXMILL:-build/dexmill}
[ -x "$bin" ] || { echo "time-compare: build $bin first (make)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
key() { sed -n "s/.*\"$1\": \([0-9.]*\).*/\1/p" "$tmp/r.json" | head -1; }
head="| program | lines | no acceleration | blended | stop at every move | blended / no accel |"
rule="|---|---:|---:|---:|---:|---:|"
[ "${LCNC:-0}" = 1 ] && head="$head LinuxCNC | blended / LinuxCNC |" rule="$rule---:|---:|"
echo "$head"
echo "$rule"
for p in "$@"; do
  # A coarse grid: the estimate is the first pass's, the cut only has to run.
  if ! "$bin" run "$p" -q --grid 64x64 --machine "$machine" --report "$tmp/r.json" 2>"$tmp/err"; then
    echo "| $(basename "$p") | run failed: $(head -1 "$tmp/err") |"
    continue
  fi
  lines=$(wc -l <"$p")
  na=$(key no_accel_s) bl=$(key blended_s) st=$(key stop_s)
  row="| $(basename "$p") | $lines | $na s | $bl s | $st s | $(awk -v a="$bl" -v b="$na" 'BEGIN{printf "%.3f", a / b}') |"
  if [ "${LCNC:-0}" = 1 ]; then
    lc=$(tools/scripts/linuxcnc-time.sh "$machine" "$p" 2>"$tmp/lerr" | sed -n 's/^linuxcnc_s //p')
    if [ -n "$lc" ]; then row="$row $lc s | $(awk -v a="$bl" -v b="$lc" 'BEGIN{printf "%.3f", a / b}') |"
    else row="$row n/a | $(head -c 60 "$tmp/lerr" | tr '\n' ' ') |"; fi
  fi
  echo "$row"
done
