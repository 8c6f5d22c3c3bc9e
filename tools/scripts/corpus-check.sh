#!/usr/bin/env bash
# Runs `dexmill path` and `dexmill check` over every file of a corpus folder
# (CORPUS; by default the one CI keeps beside the clone)
# and prints one line per file: OK (path produced, N moves), or the first
# error. A file fails the script only when dexmill crashes, path and check
# disagree (one finds an error the other does not), or an error comes
# without a FILE:LINE:COL message.
#
# A file refused only because it feeds before any F ("feed move with zero
# feed rate": grbl and Fusion 360 programs count on the controller's
# default feed) is run again with --default-feed 1000 and, if that reads,
# counted OK with a note.
#
# When LinuxCNC's stand-alone interpreter rs274 is installed, every refusal
# is also put to it: one it makes at the same line (its error comes with
# the text of the line it stopped at) is the file's fault, not dexmill's,
# and the summary counts those apart.
#
#   tools/scripts/corpus-check.sh [DEXMILL]
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
# CORPUS: a folder of real programs (CI keeps one beside the clone).
corpus="${CORPUS:-$root/../shared/corpus}"
dexmill=${1:-$root/build/dexmill}
default_feed=1000
if [ ! -d "$corpus" ]; then
  echo "corpus-check: no corpus at $corpus (set CORPUS=DIR); skipping"
  exit 0
fi
[ -x "$dexmill" ] || { echo "corpus-check: $dexmill not built (run make)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
have_rs274=0
if command -v rs274 >/dev/null; then
  have_rs274=1
  # Every tool exists, of length 0 (as oracle-check.sh): unknown tools are
  # no refusal of the file's.
  for t in $(seq 0 999); do echo "T$t P$t Z0 D0"; done > "$tmp/tools.tbl"
fi

# lcnc_verdict FILE LINE: what rs274 says of FILE, against dexmill's refusal
# at LINE: lcnc_same=1 when it stops there too; its message in lcnc_msg.
lcnc_verdict() {
  local f=$1 line=$2
  # grbl `$` lines: dexmill skips them with a warning; rs274 gets them as
  # comments (as in oracle-check.sh), so that it reads what dexmill reads.
  sed -E 's/^[[:space:]]*\$(.*)$/(grbl $\1)/' "$f" > "$tmp/prog.ngc"
  # rs274 keeps its tool data in $HOME/.tool.mmap, shared by every rs274
  # running at the time: a HOME of its own keeps others' tables out.
  ( cd "$tmp" && HOME="$tmp" timeout 120 rs274 -t "$tmp/tools.tbl" -g "$tmp/prog.ngc" > "$tmp/trace" 2>&1 < /dev/null )
  # After its canonical calls, rs274 prints the error and the line's text.
  local rest; rest=$(grep -v -E '^\s*[0-9]+ N\S* |^executing$' "$tmp/trace")
  lcnc_msg=$(sed -n 1p <<<"$rest")
  local text; text=$(sed -n 2p <<<"$rest" | sed -E 's/[[:space:]]+$//')
  local ours; ours=$(sed -n "${line}p" "$tmp/prog.ngc" | tr -d '\r' | sed -E 's/[[:space:]]+$//')
  lcnc_same=0
  if [ -z "$lcnc_msg" ]; then
    lcnc_msg="no error"
  elif [ -n "$text" ] && [ "$text" = "$ours" ]; then
    lcnc_same=1
  else
    lcnc_msg="$lcnc_msg, at: $text"
  fi
}

ok=0; ok_feed=0; refused=0; refused_lcnc=0; bad=0
for rel in $(cut -f1 "$corpus/index.tsv" | tail -n +2); do
  f="$corpus/$rel"
  opts=()
  note=""
  "$dexmill" path "$f" > "$tmp/path" 2> "$tmp/perr"; prc=$?
  "$dexmill" check --max-errors 0 "$f" > /dev/null 2> "$tmp/cerr"; crc=$?
  if [ $prc -eq 1 ] && grep -m1 ': error: ' "$tmp/perr" | grep -q 'feed move with zero feed rate'; then
    # The controller's default feed, as --default-feed gives it.
    opts=(--default-feed "$default_feed")
    note=" (with --default-feed $default_feed: it feeds before any F)"
    "$dexmill" path "${opts[@]}" "$f" > "$tmp/path" 2> "$tmp/perr"; prc=$?
    "$dexmill" check "${opts[@]}" --max-errors 0 "$f" > /dev/null 2> "$tmp/cerr"; crc=$?
  fi
  moves=$(grep -c -E '^(rapid|feed) ' "$tmp/path")
  nerr=$(grep -c ': error: ' "$tmp/cerr")
  nwarn=$(grep -c ': warning: ' "$tmp/cerr")
  first=$(grep -m1 ': error: ' "$tmp/perr" | sed "s|^$corpus/||")
  warn=""
  [ "$nwarn" -gt 0 ] && warn=", $nwarn warning(s): $(grep -m1 ': warning: ' "$tmp/cerr" | sed -E 's/^.*: warning: //')"
  if [ $prc -eq 0 ] && [ $crc -eq 0 ]; then
    echo "OK       $rel: $moves path lines$warn$note"
    ok=$((ok + 1))
    [ -n "$note" ] && ok_feed=$((ok_feed + 1))
  elif [ $prc -eq 1 ] && [ $crc -eq 1 ] && [ -n "$first" ]; then
    lcnc=""
    if [ $have_rs274 = 1 ]; then
      eline=$(sed -E 's/^[^:]*:([0-9]+):[0-9]+: error: .*/\1/' <<<"$first")
      lcnc_verdict "$f" "$eline"
      if [ $lcnc_same = 1 ]; then
        lcnc=" [LinuxCNC's rs274 refuses it at the same line: $lcnc_msg]"
        refused_lcnc=$((refused_lcnc + 1))
      else
        lcnc=" [rs274: $lcnc_msg]"
      fi
    fi
    echo "REFUSED  $first ($nerr error(s) in all; $moves path lines before it$warn)$note$lcnc"
    refused=$((refused + 1))
  else
    echo "BAD      $rel: path exit $prc, check exit $crc: $(head -c 300 "$tmp/perr")"
    bad=$((bad + 1))
  fi
done
lcnc_part=""
[ $have_rs274 = 1 ] && lcnc_part=" ($refused_lcnc of them by LinuxCNC's rs274 too, at the same line)"
echo "corpus-check: $ok OK ($ok_feed with --default-feed), $refused refused with an error$lcnc_part, $bad bad"
# pcb2gcode's auto-levelling program probes 102 points of the board before
# it mills: on a stock under all of them (the board, X-290..-115 Y-95..-20
# mm) every probe must touch its top (a 0.2 mm tip between the grid's axes
# included) and the program run to its end.
al="$corpus/pcb2gcode/example_board_al_custom_tiled_back.ngc"
if [ -f "$al" ]; then
  if "$dexmill" run "$al" --tool flat:0.2 --stock -290,-95,-1.6,-115,-20,0 -q --report "$tmp/al.json" 2>"$tmp/al.err" &&
     grep -q '"errors": \[\]' "$tmp/al.json"; then
    echo "OK       pcb2gcode auto-levelling: 102 probes touch the board, the program runs to its end"
  else
    echo "BAD      pcb2gcode auto-levelling: $(head -c 300 "$tmp/al.err")"
    bad=$((bad + 1))
  fi
fi
[ $bad -eq 0 ]
