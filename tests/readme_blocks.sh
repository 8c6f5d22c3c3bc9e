#!/usr/bin/env bash
# readme_blocks.sh - every command a README marks runnable runs as written.
#
# A fenced block whose info string is `sh runnable` (```sh runnable, maybe
# indented in a list) is a command a user is told to type; a block marked
# ```text output after it is what that command prints on standard output,
# and must be exactly that. Each README's
# runnable blocks run in order, with bash -e, from the root of a scratch
# copy of the repository (the files git tracks, or every file but build/
# and out/ outside a checkout), so that they see what a clean clone holds
# and write nowhere in this tree. The copy's build/ is this tree's build
# folder (the binary `make test` built), and build/ is on PATH, so
# `dexmill` stands for the installed binary.
# Blocks are written from the repository's root, in any README.
#
# Usage: tests/readme_blocks.sh BUILD_DIR [README...]  (default: every README.md)
#        tests/readme_blocks.sh --self-test BUILD_DIR
# Exit: 0 every block ran with status 0, 1 otherwise (the block's file, line
# and output are printed).
set -u
cd "$(dirname "$0")/.."
TIMEOUT_S=120

# Prints "LINE<TAB>FILE<TAB>KIND" for each runnable block (KIND run) and
# each output block (```text output: KIND out) of README $1, writing block
# K's text to $2/block-K.
extract() {
  awk -v out="$2" '
    /^[ \t]*```/ {
      if (inside) { inside = 0; close(file); next }
      kind = $0 ~ /^[ \t]*```sh[ \t]+runnable[ \t]*$/ ? "run" : $0 ~ /^[ \t]*```text[ \t]+output[ \t]*$/ ? "out" : ""
      if (kind != "") {
        inside = 1; n++; file = out "/block-" n; printf "" > file
        indent = match($0, /[^ \t]/) - 1  # a block in a list item is indented as its fence
        print FNR "\t" file "\t" kind
      }
      next
    }
    inside { if (substr($0, 1, indent) ~ /^[ \t]*$/) $0 = substr($0, indent + 1); print > file }
  ' "$1"
}

# Runs the runnable blocks of README $1 in a fresh copy, and checks each
# output block against the standard output of the runnable block before
# it; prints failures.
run_readme() {
  local readme=$1 build=$2 copy blocks status=0 line file kind n=0 last=
  grep -q '^[[:space:]]*```sh[[:space:]]\+runnable[[:space:]]*$' "$readme" || return 0
  copy=$(mktemp -d) || return 1
  if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git ls-files -z | tar -cf - --null -T - 2>/dev/null | tar -xf - -C "$copy"
  else
    tar -cf - --exclude=./build --exclude=./out . | tar -xf - -C "$copy"
  fi
  # Outside a checkout (the self-test's README is not tracked) it is copied too.
  [ -f "$copy/$readme" ] || { mkdir -p "$copy/$(dirname "$readme")"; cp "$readme" "$copy/$readme"; }
  rm -rf "$copy/build" && ln -s "$build" "$copy/build"
  blocks=$(mktemp -d)
  while IFS=$'\t' read -r line file kind; do
    [ -n "$line" ] || continue
    if [ "$kind" = out ]; then
      if [ -z "$last" ] || ! cmp -s "$file" "$last"; then
        echo "FAIL: $readme:$line: this output block is not what the runnable block before it printed:"
        if [ -n "$last" ]; then diff "$file" "$last" | sed 's/^/    /'; else echo "    (no runnable block before it)"; fi
        status=1
      fi
      continue
    fi
    n=$((n + 1))
    last=$file.stdout
    if ! (cd "$copy" && PATH="$copy/build:$PATH" timeout "$TIMEOUT_S" bash -e "$file") > "$last" 2> "$file.stderr"; then
      echo "FAIL: $readme:$line: this runnable block failed:"
      sed 's/^/    /' "$file"
      echo "  its output:"
      cat "$last" "$file.stderr" | tail -n 30 | sed 's/^/    /'
      status=1
    fi
  done < <(extract "$readme" "$blocks")
  rm -rf "$copy" "$blocks"
  RAN=$((RAN + n))
  return $status
}

self_test() {
  local build=$1 tmp status
  tmp=$(mktemp -d)
  mkdir -p "$tmp/t"
  printf '# t\n```sh runnable\ntrue\n```\n```\nfalse   # not runnable: never run\n```\n```sh runnable\nexit 3\n```\n' > "$tmp/t/README.md"
  # An output block that is what its command printed, and one that is not.
  printf '```sh runnable\necho one\n```\n```text output\none\n```\n```sh runnable\necho two\n```\n```text output\nthree\n```\n' >> "$tmp/t/README.md"
  RAN=0
  if (cd "$tmp" && run_readme t/README.md "$build") > "$tmp/log" 2>&1; then
    echo "FAIL: readme_blocks.sh --self-test: a failing block passed"; cat "$tmp/log"; status=1
  elif ! grep -q 't/README.md:8: this runnable block failed' "$tmp/log" || grep -q 'README.md:2:' "$tmp/log" ||
       ! grep -q 't/README.md:20: this output block is not' "$tmp/log" || grep -q 'README.md:14:' "$tmp/log"; then
    echo "FAIL: readme_blocks.sh --self-test: wrong block reported:"; cat "$tmp/log"; status=1
  else
    status=0
  fi
  rm -rf "$tmp"
  return $status
}

if [ "${1:-}" = "--self-test" ]; then
  self_test "$(cd "${2:?BUILD_DIR}" && pwd)"
  exit $?
fi
build=$(cd "${1:?usage: tests/readme_blocks.sh BUILD_DIR [README...]}" && pwd) || exit 1
shift
if [ $# -eq 0 ]; then
  set -- $(find . -name README.md -not -path './build/*' -not -path './out/*' | sed 's|^\./||' | sort)
fi
RAN=0
failed=0
for readme in "$@"; do
  run_readme "$readme" "$build" || failed=1
done
# The README's walkthrough is runnable: a check with nothing to run is no check.
if [ "$RAN" -eq 0 ]; then echo "FAIL: no runnable block in $*"; exit 1; fi
[ $failed -eq 0 ] && echo "ok: $RAN runnable README blocks ran as written"
exit $failed
