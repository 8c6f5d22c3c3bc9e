#!/usr/bin/env bash
# embed_check.sh - the example embedder (tools/examples/embed.c: the C API,
# 4 KB pieces, a few moves a step, incremental redraws) writes the PPM that
# `dexmill run --image` writes for the same program, stock, tool, grid and
# size, byte for byte (the CLI's axis triad and scale bar left out: embed.c
# leaves the API's decorations off; and aliased, as the API's views are:
# --no-antialias). `make test` runs it.
#
# Usage: tests/embed_check.sh DEXMILL EMBED   (from the repository root)
# Exit: 0 every case identical, 1 otherwise.
set -u
cd "$(dirname "$0")/run"
BIN=$1; EMBED=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
bad=0; n=0
# program, stock, tool, grid, size
while read -r prog stock tool grid size; do
  n=$((n + 1))
  "$BIN" run "$prog" -q --no-decorations --no-antialias --stock "$stock" --tool "$tool" --grid "$grid" --size "$size" --image "$tmp/cli$n.ppm" ||
    { echo "embed_check: dexmill run $prog failed"; bad=1; continue; }
  "$EMBED" "$prog" "$tmp/embed$n.ppm" "$stock" "$tool" "$grid" "$size" > "$tmp/embed$n.out" ||
    { echo "embed_check: embed $prog failed"; bad=1; continue; }
  # A picture, not an empty file: the header and every pixel.
  w=${size%x*}; h=${size#*x}
  [ "$(wc -c < "$tmp/embed$n.ppm")" -gt $((w * h * 3)) ] || { echo "embed_check: $prog: short PPM"; bad=1; }
  if cmp -s "$tmp/cli$n.ppm" "$tmp/embed$n.ppm"; then echo "ok: embed $prog ($tool, $grid, $size): $(cat "$tmp/embed$n.out")"
  else echo "embed_check: $prog: embed's PPM differs from dexmill run's"; bad=1; fi
done <<'CASES'
pocket.ngc 0,0,-10,33,23,0 flat:6 330x230 320x240
pocket.ngc -2,-2,-10,35,25,0.5 ball:4 96x64 640x480
arcs_inch.ngc 0,0,-5,45,35,0 vbit:3:90 200x160 200x150
thin_floor.ngc 0,0,-6,70,40,0 flat:3 700x400 300x200
CASES
[ $n -eq 4 ] || { echo "embed_check: $n cases ran, not 4"; bad=1; }
exit $bad
