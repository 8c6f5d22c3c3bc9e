#!/usr/bin/env bash
# check_function_length.sh - no function in tools/ is longer than 120 lines
# (from the line of its opening brace to the line of its closing one): a
# function that long does several things, which get a name each. `make
# test` runs it, and first its self-test, so that the check can be seen to
# fail on a function one line too long.
#
# Usage: tests/check_function_length.sh [FILE...]   (default tools/**/*.cpp but tools/panel/)
#        tests/check_function_length.sh --self-test
# Exit: 0 every function is short enough, 1 otherwise (each one listed).
#
# It reads C++ as this repository writes it, without a compiler: comments,
# string and character literals and preprocessor lines are blanked, then
# braces are matched. A brace opens a function body when it is outside any
# other function, follows a ')' (or a const, override, ...) and has a space
# before it; not when it follows '=' (an initializer: option tables and
# their lambdas are data) or an identifier (`member_{1}`, `Type name{...}`).
set -u
cd "$(dirname "$0")/.."
MAX=120

lengths() {
  awk -v max="$MAX" '
  function classify(stmt, before) {
    if (stmt ~ /(^|[^A-Za-z0-9_])namespace([^A-Za-z0-9_]|$)/ || stmt ~ /(^|[^A-Za-z0-9_])extern[ \t]*$/) return "n"
    if (stmt ~ /(^|[^A-Za-z0-9_])(struct|class|union|enum)([^A-Za-z0-9_]|$)/ && stmt !~ /\(/) return "c"
    if (stmt ~ /=[ \t]*$/ || stmt !~ /\)/ || before ~ /[A-Za-z0-9_]/) return "b"
    return "f"
  }
  FNR == 1 { depth = 0; in_comment = 0; stmt = ""; continued = 0 }
  {
    line = $0
    if (continued || line ~ /^[ \t]*#/) { continued = (line ~ /\\$/); next }
    code = ""
    n = length(line)
    for (i = 1; i <= n; i++) {
      c = substr(line, i, 1); c2 = substr(line, i, 2)
      if (in_comment) { if (c2 == "*/") { in_comment = 0; i++ } continue }
      if (c2 == "//") break
      if (c2 == "/*") { in_comment = 1; i++; continue }
      if (c == "\"" || c == "\047") {
        q = c
        for (i++; i <= n; i++) {
          d = substr(line, i, 1)
          if (d == "\\") { i++; continue }
          if (d == q) break
        }
        code = code " "
        continue
      }
      code = code c
    }
    m = length(code)
    for (i = 1; i <= m; i++) {
      c = substr(code, i, 1)
      if (c == "{") {
        top = depth ? kind[depth] : "n"
        k = (top == "n" || top == "c") ? classify(stmt, substr(code, i - 1, 1)) : "b"
        kind[++depth] = k
        if (k == "f") { start[depth] = FNR; name[depth] = stmt }
        stmt = ""
      } else if (c == "}") {
        if (depth && kind[depth] == "f" && FNR - start[depth] + 1 > max) {
          s = name[depth]; gsub(/[ \t]+/, " ", s); sub(/^ /, "", s)
          printf "%s:%d: %d lines (at most %d): %s\n", FILENAME, start[depth], FNR - start[depth] + 1, max, substr(s, 1, 70)
          bad = 1
        }
        if (depth) depth--
        stmt = ""
      } else if (c == ";") {
        stmt = ""
      } else {
        stmt = stmt c
      }
    }
    stmt = stmt " "
  }
  END { exit bad }' "$@"
}

# A function of MAX + 1 lines must be reported, one of MAX lines, an
# initializer of any length and a class's short members must not be.
self_test() {
  tmpdir=$(mktemp -d) || exit 1
  trap 'rm -rf "$tmpdir"' EXIT
  {
    echo 'namespace a { namespace {'
    echo 'struct S { int f() const { return 1; } };'
    echo 'const int kTable[] = {'
    for ((k = 0; k < MAX + 10; ++k)); do echo "  $k,"; done
    echo '};'
    echo 'int just_long_enough(int x) {'
    for ((k = 0; k < MAX - 2; ++k)); do echo '  x += 1;  // } not a brace'; done
    echo '}'
    echo 'int one_too_long(int x) {'
    for ((k = 0; k < MAX - 1; ++k)); do echo '  x += "}"[0];'; done
    echo '}'
    echo '}  // namespace'
    echo '}  // namespace a'
  } > "$tmpdir/t.cpp"
  local out
  out=$(lengths "$tmpdir/t.cpp")
  if [ $? -eq 1 ] && [ "$(printf '%s\n' "$out" | grep -c .)" -eq 1 ] && printf '%s' "$out" | grep -q "one_too_long"; then
    echo "ok: the function length check reports a function of $((MAX + 1)) lines, not one of $MAX"
  else
    echo "FAIL: the function length check's self-test; it reported:"
    printf '%s\n' "$out"
    exit 1
  fi
}

if [ "${1:-}" = "--self-test" ]; then
  self_test
  exit 0
fi
[ $# -gt 0 ] || set -- $(find tools -name '*.cpp' -not -path 'tools/panel/*' | LC_ALL=C sort)
if lengths "$@"; then
  echo "ok: no function in the $# files checked is longer than $MAX lines"
else
  exit 1
fi
