#!/usr/bin/env bash
# check_comments.sh - comments point inside the repository: no issue number
# (say what the rule is, or name the file of this repository that explains
# it), no document of the folder that sits beside a clone in CI, and none of
# the design, style, CLI or paper notes that used to live there (their
# content is core/README.md and tools/CLI.md now). `make test` runs it, and
# first its self-test, which plants bad lines and good ones.
#
# Usage: tests/check_comments.sh [PATH...]   (default: core display platform
#                                            tools tests Makefile README.md)
#        tests/check_comments.sh --self-test
# Exit: 0 nothing points outside, 1 otherwise (each FILE:LINE listed).
#
# What is looked for:
# - anywhere in a line (a comment, a test's name or message): an issue
#   number ("issue N", "Issue #N", "issues N"), "(issue" ending a line
#   (the number on the next), "the issue's", /work/shared, and the names
#   DESIGN.md, STYLE.md, PAPER-NOTES and CLI.md other than tools/CLI.md;
# - in comments only: a path into the shared folder beside the clone. A
#   script may still read a corpus from there at run time (the corpus
#   scripts' CORPUS default); its comments name the folder by its role.
# Comments are what follows // or lies in /* */ in C and C++ files, what
# follows a # in scripts and the Makefile; in other files (Markdown, the man
# page, G-code) every line counts.
set -u
cd "$(dirname "$0")/.."
self="tests/check_comments.sh"

scan() {
  awk '
  function kind(f,   base) {
    base = f; sub(/.*\//, "", base)
    if (base ~ /\.(c|cc|cpp|h|hpp)$/) return "c"
    if (base ~ /\.(sh|py|dict|mk|pc|in|tbl|cfg|ini|toml|ya?ml)$/ || base == "Makefile") return "sh"
    return "text"
  }
  FNR == 1 { k = kind(FILENAME); in_block = 0 }
  {
    line = $0
    everywhere = "[Ii]ssues? #?[0-9]|\\([Ii]ssue[ \t]*$|[Ii]ssue\047s|/work/shared|DESIGN\\.md|STYLE\\.md|PAPER-NOTES|(^|[^/A-Za-z0-9_-])CLI\\.md"
    outside = "(^|[^A-Za-z0-9_.-])(\\.\\./)?shared/|\\.\\./shared([^A-Za-z0-9_]|$)"
    comment = ""
    if (k == "text") comment = line
    else if (k == "sh") {
      if (match(line, /(^|[ \t])#/)) comment = substr(line, RSTART)
    } else {
      rest = line
      if (in_block) {
        if ((e = index(rest, "*/")) > 0) { comment = substr(rest, 1, e + 1); rest = substr(rest, e + 2); in_block = 0 }
        else { comment = rest; rest = "" }
      }
      while (rest != "") {
        s = index(rest, "//"); b = index(rest, "/*")
        if (s > 0 && (b == 0 || s < b)) { comment = comment " " substr(rest, s); break }
        if (b == 0) break
        rest = substr(rest, b)
        if ((e = index(substr(rest, 3), "*/")) > 0) { comment = comment " " substr(rest, 1, e + 3); rest = substr(rest, e + 4) }
        else { comment = comment " " rest; in_block = 1; rest = "" }
      }
    }
    if (line ~ everywhere || comment ~ outside) {
      printf "%s:%d: %s\n", FILENAME, FNR, substr(line, 1, 120)
      bad = 1
    }
  }
  END { exit bad }' "$@"
}

# The text files under the paths, this script and build output left out.
files_of() {
  find "$@" -path '*/build' -prune -o -type f -print 2>/dev/null | LC_ALL=C sort |
    while IFS= read -r f; do
      [ "$f" = "$self" ] && continue
      grep -Iq . "$f" 2>/dev/null && printf '%s\n' "$f"
    done
}

# Each planted bad line must be reported, and no good one.
self_test() {
  tmpdir=$(mktemp -d) || exit 1
  trap 'rm -rf "$tmpdir"' EXIT
  local sh="../sh""ared" iss="iss""ue"
  {
    echo "// The pocket's cut ($iss 23, paper §3): bad 1"
    echo "int x;  // rules in $sh/DESIGN.md: bad 2"
    echo "/* a block comment that cites"
    echo "   $sh/corpus: bad 3 */"
    echo "// the $iss's program: bad 4"
    echo "// exit codes (CLI.md: bad 5"
    echo "// with the number on the next line ($iss"
    echo "// 35): the line before is bad 6"
    echo "const char* kCorpus = \"$sh/corpus\";  // good: code, not a comment"
    echo "// good: tools/CLI.md, core/README.md habit 4, #5420, reissued"
    echo "TEST(reads_g38) { run(\"G38.2 Z-1\"); }  // good"
  } > "$tmpdir/t.cpp"
  {
    echo "# reads every file of $sh/corpus: bad 7"
    echo "corpus=\"\${CORPUS:-\$root/$sh/corpus}\"  # good: the default path is code"
    echo "echo \"skipping: $sh is absent\""
  } > "$tmpdir/t.sh"
  local out want got
  out=$(cd "$tmpdir" && scan t.cpp t.sh)
  got=$(printf '%s\n' "$out" | cut -d: -f1,2 | paste -sd' ')
  want="t.cpp:1 t.cpp:2 t.cpp:4 t.cpp:5 t.cpp:6 t.cpp:7 t.sh:1"
  if [ "$got" = "$want" ]; then
    echo "ok: the comment check reports the 7 planted lines that point outside, not the good ones"
  else
    echo "FAIL: the comment check's self-test; it reported:"
    printf '%s\n' "$out"
    exit 1
  fi
}

if [ "${1:-}" = "--self-test" ]; then
  self_test
  exit 0
fi
[ $# -gt 0 ] || set -- core display platform tools tests Makefile README.md
mapfile -t list < <(files_of "$@")
if scan "${list[@]}"; then
  echo "ok: no comment in the ${#list[@]} files checked points outside the repository"
else
  echo "check_comments: the lines above point outside the repository (tests/check_comments.sh says what to write instead)"
  exit 1
fi
