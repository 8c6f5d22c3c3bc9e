#!/bin/sh
# make bless: rewrites every golden of the tree at ROOT from what this build
# makes, and nothing else (tests/golden/README.md lists them):
#   tests/golden/golden.out        the golden-output program's output
#   tests/golden/hashes.txt        the hashes the unit tests pin by name
#   tests/golden/frames/NAME.png   the pictures of the frame goldens
#   tests/gcode/paths/NAME.path    `dexmill path` of each NAME.ngc there
#   tests/run/pocket.report.golden the report of tests/run/pocket.ngc
# The last four are written by the unit tests' golden cases (those whose
# name holds "golden", tests/golden_check.h) under DEXMILL_BLESS=1; a file is
# written only when its content changes, so blessing a passing tree leaves
# it as it was (tests/bless_check.sh checks that). A hash or picture no case
# checks any more fails the bless, named.
#
# Usage: tests/bless.sh ROOT GOLDEN_BIN TEST_BIN DEXMILL_BIN [JOBS]
# (binaries as absolute paths: this runs in ROOT).
set -eu
[ $# -ge 4 ] || { sed -n '2,/^set -eu/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
root=$1 golden=$2 tests=$3 bin=$4 jobs=${5:-2}
cd "$root"
# golden.out first: tests/test_stamp.cpp reads its grid hashes from it.
new=$(mktemp) log=$(mktemp)
trap 'rm -f "$new" "$log"' EXIT
"$golden" > "$new"
if cmp -s "$new" tests/golden/golden.out; then echo "bless: tests/golden/golden.out unchanged"
else cp "$new" tests/golden/golden.out; echo "bless: wrote tests/golden/golden.out"; fi
if ! DEXMILL_BLESS=1 DEXMILL_BLESS_LOG="$log" DEXMILL="$bin" "$tests" --jobs "$jobs" golden > "$new"; then
  cat "$new"; echo "bless: a golden case failed (above): what it blessed may be incomplete" >&2; exit 1
fi
tail -n 1 "$new" | sed 's/^/bless: golden cases: /'
# A hash or picture that no case checks any more is not removed (a name
# misspelt in a test would take its golden with it); it is named, and fails.
LC_ALL=C sort -u "$log" > "$new"
unused=$( { grep -v '^#' tests/golden/hashes.txt | awk 'NF { print "hash " $1 }'
            for f in tests/golden/frames/*.png; do [ -e "$f" ] && basename "$f" .png | sed 's/^/frame /'; done
          } | LC_ALL=C sort | LC_ALL=C comm -23 - "$new")
if [ -n "$unused" ]; then
  echo "$unused" | sed 's/^/bless: checked by no test (remove it, and say why in the commit): /' >&2; exit 1
fi
