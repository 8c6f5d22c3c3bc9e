#!/usr/bin/env bash
# install_check.sh - `make install` into a temporary DESTDIR installs what
# the Makefile says; an embedder (tools/examples/embed.c) built from the
# installed header and libraries with `pkg-config --cflags --libs dexmill`
# runs and draws what the in-tree one draws; the installed Python wrapper
# finds the installed library; `make uninstall` leaves no file behind.
# `make test` runs it.
#
# Usage: tests/install_check.sh MAKE CC EMBED   (from the repository root)
# Exit: 0 all of that held, 1 otherwise.
set -u
cd "$(dirname "$0")/.."
MAKE_CMD=$1; CC=$2; EMBED=$3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
dest=$tmp/dest; prefix=/usr/local; root=$dest$prefix
fail() { echo "install_check: $*"; exit 1; }

$MAKE_CMD --no-print-directory -s install DESTDIR="$dest" PREFIX=$prefix > "$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log"; fail "make install failed"; }
for f in bin/dexmill lib/libdexmill.a lib/libdexmill.so lib/libdexmill_io.a include/dexmill.h include/dexmill_io.h \
         lib/pkgconfig/dexmill.pc share/man/man1/dexmill.1 share/dexmill/python/dexmill.py share/doc/dexmill/LICENSE; do
  [ -s "$root/$f" ] || fail "$prefix/$f was not installed"
done
"$root/bin/dexmill" --version > /dev/null || fail "the installed dexmill does not run"
grep -q '^\.SH EMBEDDING' "$root/share/man/man1/dexmill.1" || fail "the man page has no EMBEDDING section"
! grep -q '^\.\\" @OPTIONS@$' "$root/share/man/man1/dexmill.1" || fail "the man page kept its marker line"

# The .pc gives paths under its prefix; here the prefix is DESTDIR's.
export PKG_CONFIG_PATH=$root/lib/pkgconfig
flags=$(pkg-config --define-variable=prefix="$root" --cflags --libs dexmill) || fail "pkg-config dexmill failed"
case $flags in *"-I$root/include"*"-L$root/lib"*) ;; *) fail "pkg-config gives '$flags', not paths under the prefix";; esac
$CC -std=c99 -Wall -Wextra -Werror -pedantic tools/examples/embed.c $flags -o "$tmp/embed" || fail "embed.c did not build"
args="tests/run/pocket.ngc 0,0,-10,33,23,0 ball:6 200x140 240x180"
set -- $args
LD_LIBRARY_PATH=$root/lib "$tmp/embed" "$1" "$tmp/installed.ppm" "$2" "$3" "$4" "$5" > /dev/null ||
  fail "the installed embedder failed"
"$EMBED" "$1" "$tmp/tree.ppm" "$2" "$3" "$4" "$5" > /dev/null || fail "the in-tree embedder failed"
cmp -s "$tmp/installed.ppm" "$tmp/tree.ppm" || fail "the installed embedder draws other pixels"
PYTHONPATH=$root/share/dexmill/python python3 -c "
import dexmill, os
assert dexmill._find_library() == os.path.join('$root', 'lib', 'libdexmill.so'), dexmill._find_library()
" || fail "the installed Python wrapper does not find the installed library"

$MAKE_CMD --no-print-directory -s uninstall DESTDIR="$dest" PREFIX=$prefix > "$tmp/uninstall.log" 2>&1 ||
  { cat "$tmp/uninstall.log"; fail "make uninstall failed"; }
left=$(find "$dest" ! -type d)
[ -z "$left" ] || fail "make uninstall left: $left"
echo "ok: make install (10 files), an embedder built with pkg-config from them, make uninstall (none left)"
