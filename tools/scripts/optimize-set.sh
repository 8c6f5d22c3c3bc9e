#!/usr/bin/env bash
# The benchmark set of `dexmill optimize --target` (the README's figures):
# pocketing and adaptive programs from the corpus and the demo's pocket,
# each optimized for a chip-load target (its material's max_chip), then
# both programs simulated with --check load. One line a program: the
# estimated cycle time before and after, the thickest chip and largest
# power before and after, the load findings after (none may remain), the
# highest feed written, the long moves split in pieces, and whether the
# two heightmaps are byte-identical (they must be: the pieces lie on the
# moves, within 1.3 nm).
# Then the median time change. Exit 1 when a program's output breaks a
# limit or cuts a different stock.
#
#   tools/scripts/optimize-set.sh CORPUS_DIR [DEXMILL] [-- EXTRA OPTIONS, e.g. --accel 500]
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus=${1:?usage: optimize-set.sh CORPUS_DIR [DEXMILL] [-- OPTIONS]}
shift
dexmill=$root/build/dexmill
if [ $# -gt 0 ] && [ "$1" != -- ]; then dexmill=$1; shift; fi
[ $# -gt 0 ] && [ "$1" = -- ] && shift
extra=("$@")
[ -f "$corpus/index.tsv" ] || { echo "optimize-set: no $corpus/index.tsv, skipped"; exit 0; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# The demo's pocket, with the demo's own tool table, stock and material.
(cd "$tmp" && "$dexmill" run --demo pocket -q >/dev/null 2>&1)
printf 'T1 P1 D6 ;flat:6\nT2 P2 D6 ;ball:6\nT3 P3 D5 ;vbit:5:118\n' > "$tmp/demo.tbl"

# name | program | its options (materials: the routers' programs in the
# wood preset, beech; the spindle speed where the program gives none)
set_list() {
  cat <<EOF
demo pocket|$tmp/out/demo.ngc|--stock 0,0,-20,100,70,0 --tools $tmp/demo.tbl --material wood-on-aluminium
SheepTile-v2 (Fusion 360 pocket)|$corpus/gsender/SheepTile-v2.nc|--material wood --default-feed 1000
1110_wall (Fusion 360 2D pocket)|$corpus/led_floor/1110_wall_265bit.nc|--material wood
botomata_bottom (CAMotics pockets)|$corpus/CAMotics/botomata_bottom.nc|--material wood
tball-pocket (jscut pocket)|$corpus/cncjs/tball-pocket.gcode|--material wood --tool flat:3.175 --default-spindle 18000
HSM_test (grbl adaptive pocketing)|$corpus/grbl/HSM_test.nc|--material wood --tool flat:6 --default-spindle 18000
EOF
}

# "key": {"unit": VALUE ... from a report's engagement, or "-".
max_of() { grep -o "\"$2\": {\"$3\": [0-9.]*" "$1" | head -1 | sed 's/.*: //' || true; }
seconds() { echo "$1" | awk -F: '{ s = 0; for (k = 1; k <= NF; ++k) s = s * 60 + $k; print s }'; }

bad=0 n=0
changes=()
printf '%-36s %9s %9s %7s  %-17s %-13s %4s %-9s %5s %s\n' program before after change "chip mm (before>after)" "power W" finds "max feed" split stock
while IFS='|' read -r name prog opts; do
  [ -f "$prog" ] || { echo "optimize-set: $prog missing, skipped"; continue; }
  w="$tmp/$n"; mkdir -p "$w"
  # shellcheck disable=SC2086
  "$dexmill" optimize "$prog" $opts --pitch 0.2 "${extra[@]}" --target chip-load -o "$w/opt.nc" 2> "$w/opt.err" ||
    { echo "optimize-set: $name: optimize failed: $(tail -1 "$w/opt.err")"; bad=1; n=$((n + 1)); continue; }
  line=$(grep -m1 'estimated time' "$w/opt.err")
  t0=$(echo "$line" | sed -E 's/.*estimated time ([0-9:.]+) before.*/\1/')
  t1=$(echo "$line" | sed -E 's/.* before, ([0-9:.]+) after.*/\1/')
  pct=$(echo "$line" | sed -E 's/.*after \(([-+0-9.]+)%\).*/\1/')
  split=$(grep -m1 -oE '[0-9]+ long move\(s\) split' "$w/opt.err" | cut -d' ' -f1)
  for which in before after; do
    p=$prog; [ $which = after ] && p=$w/opt.nc
    # shellcheck disable=SC2086
    "$dexmill" run "$p" $opts --pitch 0.2 "${extra[@]}" --check load -q --report "$w/$which.json" \
      --heightmap "$w/$which.pgm" --image "$w/$which.ppm" 2>/dev/null
  done
  c0=$(max_of "$w/before.json" max_chip mm); c1=$(max_of "$w/after.json" max_chip mm)
  p0=$(max_of "$w/before.json" max_power w); p1=$(max_of "$w/after.json" max_power w)
  finds=$(grep -o '"load": {"spindle_power_w": [^,]*, "total": [0-9]*' "$w/after.json" | sed 's/.*: //')
  feed=$(grep -oE '[Ff] *[0-9.]+' "$w/opt.nc" | tr -d 'Ff ' | sort -g | tail -1)
  same=identical
  cmp -s "$w/before.pgm" "$w/after.pgm" || { same="DIFFERENT($(cmp -l "$w/before.pgm" "$w/after.pgm" | wc -l)B)"; bad=1; }
  [ "${finds:-0}" = 0 ] || bad=1
  printf '%-36s %9s %9s %6s%%  %-8s> %-8s %5s> %-6s %4s %-9s %5s %s\n' "$name" "$t0" "$t1" "$pct" "${c0:--}" "${c1:--}" \
    "${p0:--}" "${p1:--}" "${finds:-?}" "F$feed" "${split:-0}" "$same"
  changes+=("$pct")
  n=$((n + 1))
done < <(set_list)
median=$(printf '%s\n' "${changes[@]}" | sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
echo "optimize-set: $n programs, median cycle-time change $median%"
exit $bad
