#!/usr/bin/env bash
# The live window of `dexmill run --window`, checked as a person would see
# it: a GLFW build runs tests/run/pocket.ngc in a window under Xvfb, the
# window is captured with xwd once the program is done, and its picture
# (above the status line) must equal, pixel for pixel, the PPM of the same
# final frame that the run wrote with --image: once aliased (--no-antialias,
# the live view's default and the still's with that flag) and once
# anti-aliased (--antialias: the live view as the still is by default).
# Then clicks, as a person would click (xdotool): seen from the top, a click
# on the pocket's floor must print `dexmill measure --at`'s line for it on
# standard output (its floor's Z-3, the line that cut it, the design there:
# --design tests/run/pocket_design.stl), one line a click
# on the part and none for a click beside it, each the very line measure
# --at prints for the stock the run saves, and mark the place (the marker's
# cyan in the window).
#
#   tools/scripts/window-test.sh            builds build/glfw/dexmill if needed
# Skips (exit 0, with a message) when Xvfb, xwd or GLFW is not installed,
# and the clicks alone when xdotool is not: tools/scripts/install-deps.sh
# window installs them.
set -u
cd "$(dirname "$0")/../.."
skip() { echo "window-test: skipped: $*"; exit 0; }
command -v Xvfb >/dev/null || skip "Xvfb is not installed (tools/scripts/install-deps.sh window)"
command -v xwd >/dev/null || skip "xwd is not installed (x11-apps)"
pkg-config --exists glfw3 2>/dev/null || skip "GLFW is not installed (libglfw3-dev)"
make -s -j2 GLFW=1 BUILD=build/glfw build/glfw/dexmill || { echo "window-test: FAIL: the GLFW build failed"; exit 1; }

tmp=$(mktemp -d)
xpid=; dpid=
cleanup() {
  [ -n "$dpid" ] && kill "$dpid" 2>/dev/null
  [ -n "$xpid" ] && kill "$xpid" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
disp=:$((90 + RANDOM % 100))
Xvfb "$disp" -screen 0 800x600x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 &
xpid=$!
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X${disp#:}" ] && break; sleep 0.1; done
[ -e "/tmp/.X11-unix/X${disp#:}" ] || { echo "window-test: FAIL: Xvfb did not start"; cat "$tmp/xvfb.log"; exit 1; }

# One run in a window with flag $1; its capture is compared with its --image.
check_window() {
  # --hold keeps the last frame up while xwd takes it; the window then closes itself.
  rm -f "$tmp/final.ppm" "$tmp/window.xwd"
  DISPLAY=$disp build/glfw/dexmill run tests/run/pocket.ngc --window --exit-when-done --hold 3 --speed 50 \
    --size 320x240 "$1" --image "$tmp/final.ppm" -q 2>"$tmp/run.err" &
  dpid=$!
  for _ in $(seq 300); do [ -s "$tmp/final.ppm" ] && break; kill -0 "$dpid" 2>/dev/null || break; sleep 0.1; done
  [ -s "$tmp/final.ppm" ] || { echo "window-test: FAIL ($1): no final image"; cat "$tmp/run.err"; exit 1; }
  sleep 0.5
  xwd -display "$disp" -name dexmill -silent -out "$tmp/window.xwd" || { echo "window-test: FAIL ($1): xwd could not capture the window"; exit 1; }
  wait "$dpid"; rc=$?; dpid=
  [ "$rc" = 0 ] || { echo "window-test: FAIL ($1): dexmill exited $rc"; cat "$tmp/run.err"; exit 1; }
  compare "$1" || exit 1
}

compare() {
python3 - "$tmp/window.xwd" "$tmp/final.ppm" "$1" <<'PY'
import struct, sys

def read_xwd(path):
    d = open(path, "rb").read()
    h = struct.unpack(">25I", d[:100])
    header_size, width, height = h[0], h[4], h[5]
    byte_order, bpp, bpl, ncolors = h[7], h[11], h[12], h[19]
    rmask, gmask, bmask = h[14], h[15], h[16]
    if bpp != 32:
        sys.exit("window-test: FAIL (" + sys.argv[3] + "): xwd gave %d bits per pixel, this check reads 32" % bpp)
    pos = header_size + 12 * ncolors
    fmt = "<I" if byte_order == 0 else ">I"
    def shift(m):
        s = 0
        while m and not (m >> s) & 1: s += 1
        return s
    rs, gs, bs = shift(rmask), shift(gmask), shift(bmask)
    px = []
    for y in range(height):
        row = d[pos + y * bpl: pos + y * bpl + 4 * width]
        px.append([((v & rmask) >> rs, (v & gmask) >> gs, (v & bmask) >> bs)
                   for (v,) in struct.iter_unpack(fmt, row)])
    return width, height, px

def read_ppm(path):
    d = open(path, "rb").read()
    parts, pos = [], 0
    while len(parts) < 4:
        while d[pos:pos+1].isspace(): pos += 1
        end = pos
        while not d[end:end+1].isspace(): end += 1
        parts.append(d[pos:end]); pos = end
    pos += 1
    w, h = int(parts[1]), int(parts[2])
    return w, h, [[tuple(d[pos + 3 * (y * w + x): pos + 3 * (y * w + x) + 3]) for x in range(w)] for y in range(h)]

ww, wh, win = read_xwd(sys.argv[1])
pw, ph, pic = read_ppm(sys.argv[2])
if ww != pw or wh <= ph:
    sys.exit("window-test: FAIL (" + sys.argv[3] + "): window %dx%d, image %dx%d (the window should be the image plus a status line)" % (ww, wh, pw, ph))
for y in range(ph):
    for x in range(pw):
        if win[y][x] != pic[y][x]:
            sys.exit("window-test: FAIL (" + sys.argv[3] + "): first differing pixel (%d, %d): window %s, image %s" % (x, y, win[y][x], pic[y][x]))
band = set(p for row in win[ph:] for p in row)
if len(band) < 2:
    sys.exit("window-test: FAIL (" + sys.argv[3] + "): the status line under the picture is blank")
print("window-test: ok (" + sys.argv[3] + "): the %dx%d window shows the final frame pixel for pixel, with a status line below" % (ww, wh))
PY
}

check_window --no-antialias
check_window --antialias

# Clicks on the finished part, seen from the top (the pocket's left side
# lies left of the picture's centre), and one on the background; each part
# click's line must be measure --at's.
check_clicks() {
  if ! command -v xdotool >/dev/null; then
    echo "window-test: skipped: the clicks: xdotool is not installed (tools/scripts/install-deps.sh window)"
    return 0
  fi
  rm -f "$tmp/final.ppm" "$tmp/window.xwd"
  DISPLAY=$disp build/glfw/dexmill run tests/run/pocket.ngc --window --exit-when-done --hold 6 --speed 50 \
    --size 320x240 --view top --no-antialias --image "$tmp/final.ppm" --save-stock "$tmp/click.dxstock" \
    --design tests/run/pocket_design.stl -q >"$tmp/click.out" 2>"$tmp/run.err" &
  dpid=$!
  for _ in $(seq 300); do [ -s "$tmp/final.ppm" ] && break; kill -0 "$dpid" 2>/dev/null || break; sleep 0.1; done
  [ -s "$tmp/final.ppm" ] || { echo "window-test: FAIL (clicks): no final image"; cat "$tmp/run.err"; exit 1; }
  sleep 0.5
  wid=$(DISPLAY=$disp xdotool search --name '^dexmill$' | head -1)
  [ -n "$wid" ] || { echo "window-test: FAIL (clicks): xdotool found no dexmill window"; exit 1; }
  # The pocket's floor, the picture's centre, the background's corner.
  for p in "80 120" "160 120" "4 4"; do
    set -- $p
    DISPLAY=$disp xdotool mousemove --window "$wid" "$1" "$2" click 1
    sleep 0.4
  done
  xwd -display "$disp" -name dexmill -silent -out "$tmp/window.xwd" || { echo "window-test: FAIL (clicks): xwd could not capture the window"; exit 1; }
  wait "$dpid"; rc=$?; dpid=
  [ "$rc" = 0 ] || { echo "window-test: FAIL (clicks): dexmill exited $rc"; cat "$tmp/run.err"; exit 1; }
  python3 - "$tmp/click.out" "$tmp/window.xwd" <<'PY' || exit 1
import re, struct, sys
out = open(sys.argv[1]).read().splitlines()
if len(out) != 2:
    sys.exit("window-test: FAIL (clicks): %d lines on standard output for two clicks on the part and one beside it:\n%s" % (len(out), "\n".join(out)))
line = re.compile(r"^X(-?[0-9.]+) Y(-?[0-9.]+): top Z(-?[0-9.]+), bottom Z(-?[0-9.]+) mm \(the column at X\1 Y\2, 0\.000 mm away; heights within [0-9.]+ mm\); (last cut by line ([0-9]+)( of .+)?|uncut)$")
m = [line.match(l) for l in out]
for l, k in zip(out, m):
    if not k:
        sys.exit("window-test: FAIL (clicks): not measure --at's line: " + l)
x, y, top, line_no = float(m[0].group(1)), float(m[0].group(2)), m[0].group(3), m[0].group(6)
# The pocket's left side: G1 passes along X5 at Z-3 with a 6 mm flat end
# mill (lines 10-14 of tests/run/pocket.ngc).
if not (2 <= x <= 8 and 2 <= y <= 18 and top == "-3.0000" and line_no and 10 <= int(line_no) <= 14):
    sys.exit("window-test: FAIL (clicks): the pocket floor click measured " + out[0])
if "; design Z" not in out[0]:
    sys.exit("window-test: FAIL (clicks): no design in " + out[0])
d = open(sys.argv[2], "rb").read()
h = struct.unpack(">25I", d[:100])
pos, w, hh, bpl = h[0] + 12 * h[19], h[4], h[5], h[12]
cyan = sum(1 for yy in range(hh) for xx in range(w)
           if struct.unpack("<I", d[pos + yy * bpl + 4 * xx: pos + yy * bpl + 4 * xx + 4])[0] & 0xffffff == 0x28c8ff)
if cyan == 0:
    sys.exit("window-test: FAIL (clicks): no marker (cyan) in the window after the clicks")
print("window-test: ok (clicks): " + out[0])
print("window-test: ok (clicks): " + out[1])
print("window-test: ok (clicks): one line a click on the part, none beside it; the marker shows (%d px)" % cyan)
PY
  # The very line measure --at prints for the stock the run saved.
  while IFS= read -r l; do
    at=$(echo "$l" | sed -n 's/^X\([-0-9.]*\) Y\([-0-9.]*\):.*/\1,\2/p')
    m=$(build/glfw/dexmill measure "$tmp/click.dxstock" --design tests/run/pocket_design.stl --at "$at" 2>&1)
    [ "$m" = "$l" ] || { echo "window-test: FAIL (clicks): the window printed"; echo "  $l"; echo "measure --at $at prints"; echo "  $m"; exit 1; }
  done <"$tmp/click.out"
  echo "window-test: ok (clicks): each line is what dexmill measure --at prints for the saved stock"
}

check_clicks
