#!/bin/sh
# make check-bless: make bless (tests/bless.sh) on a copy of tests/ in which
# one golden of every kind is spoilt must give back tests/ byte for byte.
# So bless writes each kind of golden, writes it as the tests check it, and
# changes nothing else: on a tree whose goldens pass it changes nothing.
#
# Usage: tests/bless_check.sh GOLDEN_BIN TEST_BIN DEXMILL_BIN [JOBS]
set -eu
[ $# -ge 3 ] || { sed -n '2,/^set -eu/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
cd "$(dirname "$0")/.."
scratch=$(mktemp -d /tmp/dexmill-bless-check-XXXXXX)
trap 'rm -rf "$scratch"' EXIT
# Against a copy too, made first: tests/ itself may gain files while other
# checks of make test run beside this one.
cp -R tests "$scratch/pristine"
mkdir "$scratch/tree"
cp -R "$scratch/pristine" "$scratch/tree/tests"
p=$scratch/pristine t=$scratch/tree/tests
# One of each kind: a line of golden.out, a hash, a picture changed and one
# removed, a path trace, the report.
sed -i 's/^\(stamp stamp-test m=16 .*grid=\)[0-9a-f]*/\10000000000000000/' "$t/golden/golden.out"
sed -i 's/^golden-block-iso .*/golden-block-iso 0123456789abcdef/' "$t/golden/hashes.txt"
cp "$t/golden/frames/golden-tool-ball.png" "$t/golden/frames/golden-pocket-top.png"
rm "$t/golden/frames/run-pocket-image.png"
echo "spoilt" >> "$t/gcode/paths/polar.path"
sed -i '1s/.*/{ "spoilt": 1,/' "$t/run/pocket.report.golden"
if cmp -s "$p/golden/hashes.txt" "$t/golden/hashes.txt" || cmp -s "$p/golden/golden.out" "$t/golden/golden.out" ||
   cmp -s "$p/run/pocket.report.golden" "$t/run/pocket.report.golden"; then
  echo "FAIL: tests/bless_check.sh did not spoil its copy"; exit 1
fi
out=$(tests/bless.sh "$scratch/tree" "$@" 2>&1) || { echo "$out"; echo "FAIL: make bless failed on a copy of tests/"; exit 1; }
if ! d=$(diff -r "$p" "$t" 2>&1); then
  echo "$d" | head -20
  echo "FAIL: make bless on a spoilt copy of tests/ did not give tests/ back (above: tests/ against the copy)"
  exit 1
fi
echo "ok: make bless rewrites golden.out, hashes, pictures, path traces and the report, and nothing else"
