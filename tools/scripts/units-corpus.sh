#!/usr/bin/env bash
# The check the "looks like inches" rule (core/interp/units_guess.h) was
# chosen by: every corpus program that says G20 (index.tsv's units column)
# is copied with its G20/G21 words taken out and must get the loud warning
# from `dexmill check`; every one that says G21, copied the same way, must
# not. One line per program (its verdict and what the warning quotes);
# exit 1 when the rule misses an inch program or flags a mm one.
#
#   tools/scripts/units-corpus.sh CORPUS_DIR [DEXMILL]
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus=${1:?usage: units-corpus.sh CORPUS_DIR [DEXMILL]}
dexmill=${2:-$root/build/dexmill}
[ -f "$corpus/index.tsv" ] || { echo "units-corpus: no $corpus/index.tsv, skipped"; exit 0; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
missed=0 false_alarms=0 inch=0 mm=0
while IFS=$'\t' read -r path _ _ _ _ _ _ _ units _; do
  case $units in G20) want=inch;; G21) want=mm;; *) continue;; esac
  copy="$tmp/$(echo "$path" | tr / _)"
  sed -E 's/[Gg][[:space:]]*0*2[[:space:]]*[01]([^0-9.]|$)/\1/g' "$corpus/$path" > "$copy"
  loud=$("$dexmill" check "$copy" 2>&1 | grep -m1 'look like inches' | sed -E 's/.*span at most ([0-9.]+) across.*reach ([0-9.]+) a minute.*/across \1, feeds up to \2/')
  if [ "$want" = inch ]; then inch=$((inch + 1)); else mm=$((mm + 1)); fi
  if [ -n "$loud" ]; then verdict="looks like inch ($loud)"; else verdict="not flagged"; fi
  if [ "$want" = inch ] && [ -z "$loud" ]; then missed=$((missed + 1)); verdict="$verdict  MISSED"; fi
  if [ "$want" = mm ] && [ -n "$loud" ]; then false_alarms=$((false_alarms + 1)); verdict="$verdict  FALSE ALARM"; fi
  printf '%-4s %-58s %s\n' "$units" "$path" "$verdict"
done < <(tail -n +2 "$corpus/index.tsv")
echo "units-corpus: $inch inch programs ($missed missed), $mm mm programs ($false_alarms flagged)"
[ $missed -eq 0 ] && [ $false_alarms -eq 0 ]
