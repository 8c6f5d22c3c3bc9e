#!/usr/bin/env bash
# Runs `dexmill path` and `dexmill check` over every file of ../shared/corpus
# and prints one line per file: OK (path produced, N moves), or the first
# error. A file fails the script only when dexmill crashes, path and check
# disagree (one finds an error the other does not), or an error comes
# without a FILE:LINE:COL message.
#
#   tools/scripts/corpus-check.sh [DEXMILL]
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus="$root/../shared/corpus"
dexmill=${1:-$root/build/dexmill}
if [ ! -d "$corpus" ]; then
  echo "corpus-check: ../shared/corpus is absent; skipping"
  exit 0
fi
[ -x "$dexmill" ] || { echo "corpus-check: $dexmill not built (run make)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ok=0; refused=0; bad=0
for rel in $(cut -f1 "$corpus/index.tsv" | tail -n +2); do
  f="$corpus/$rel"
  "$dexmill" path "$f" > "$tmp/path" 2> "$tmp/perr"; prc=$?
  "$dexmill" check --max-errors 0 "$f" > /dev/null 2> "$tmp/cerr"; crc=$?
  moves=$(grep -c -E '^(rapid|feed) ' "$tmp/path")
  nerr=$(grep -c ': error: ' "$tmp/cerr")
  nwarn=$(grep -c ': warning: ' "$tmp/cerr")
  first=$(grep -m1 ': error: ' "$tmp/perr" | sed "s|^$corpus/||")
  warn=""
  [ "$nwarn" -gt 0 ] && warn=", $nwarn warning(s): $(grep -m1 ': warning: ' "$tmp/cerr" | sed -E 's/^.*: warning: //')"
  if [ $prc -eq 0 ] && [ $crc -eq 0 ]; then
    echo "OK       $rel: $moves path lines$warn"
    ok=$((ok + 1))
  elif [ $prc -eq 1 ] && [ $crc -eq 1 ] && [ -n "$first" ]; then
    echo "REFUSED  $first ($nerr error(s) in all; $moves path lines before it$warn)"
    refused=$((refused + 1))
  else
    echo "BAD      $rel: path exit $prc, check exit $crc: $(head -c 300 "$tmp/perr")"
    bad=$((bad + 1))
  fi
done
echo "corpus-check: $ok OK, $refused refused with an error, $bad bad"
[ $bad -eq 0 ]
