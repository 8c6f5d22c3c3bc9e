#!/usr/bin/env bash
# web-stream-test.sh - make test-web-stream: a long program through the
# page's file input, as a user opens it. A raster of 1 885 000 short moves
# (1 885 011 lines, 35.4 MB: the size of the largest program CNCjs users
# reported running out of memory on) is written here, given to index.html's
# file input and cut with the Run button, the file read in 64 KiB pieces
# (Blob.slice); the frame must be dexmill run's byte for byte
# (tools/scripts/web_compare.py). Also the times, and the peak resident
# memory of the tab (its renderer's VmHWM, tools/scripts/web_page.py)
# against the same page cutting the program's first 1000 lines: a tab that
# held the file would need its 35 MB more. Not in `make test` (about 20
# s); SKIPPED, said so, without the wasm build or Chromium.
#   tools/scripts/web-stream-test.sh BIN [WEBDIR]   (WEBDIR default build/web)
set -eu
bin=$(realpath "${1:?usage: web-stream-test.sh BIN [WEBDIR]}")
web=${2:+$(realpath "$2")}
cd "$(dirname "$0")/../.."
web=${web:-build/web}
. tools/scripts/web_common.sh
web_setup web-stream-test "$web"

# The raster: rows 0.1 mm apart, each 1885 points across 100 mm, at Z-1.
python3 - "$tmp/long.ngc" <<'PY'
import sys
rows, cols = 1000, 1885
out = ["%", "(a raster of 1 885 000 short moves)", "G21 G90 G17", "G0 Z5", "G0 X0 Y0", "S12000 M3", "G1 Z-1 F3000"]
for j in range(rows):
    xs = range(cols) if j % 2 == 0 else range(cols - 1, -1, -1)
    out += ["G1 X%.3f Y%.3f" % (i * 100.0 / (cols - 1), j * 0.1) for i in xs]
out += ["G0 Z5", "M5", "M30", "%"]
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY
head -1000 "$tmp/long.ngc" > "$tmp/short.ngc"
stock=0,0,-5,100,100,0 tool=flat:6 grid=400x400 size=640x480
lines=$(wc -l < "$tmp/long.ngc"); bytes=$(wc -c < "$tmp/long.ngc")

# The page: the form filled, the file chosen, Run pressed, its job awaited.
expr="$(cat tools/scripts/web_probe.js)
(async function () {
  var \$ = function (id) { return document.getElementById(id); };
  \$('stock').value = '$stock'; \$('tool').value = '$tool'; \$('grid').value = '$grid'; \$('size').value = '$size';
  \$('run').click();
  return [dexmillProbe(await dexmillPage.running)];
})()"
for prog in short long; do
  WEB_PAGE_FILE="#file=$tmp/$prog.ngc" WEB_PAGE_MEMORY="$tmp/$prog.mem" python3 tools/scripts/web_page.py "$browser" \
    "file://$(realpath "$tmp/index.html")" "$expr" 600 "${web_flags[@]}" "$web_no_hosts" > "$tmp/$prog.json" || fail "the page did not run $prog.ngc"
done
mv "$tmp/long.json" "$tmp/page.json"

t0=$(date +%s%N)
/usr/bin/time -f %M -o "$tmp/native.mem" "$bin" run "$tmp/long.ngc" -q --stock $stock --tool $tool --grid $grid --size $size \
  --image "$tmp/cli1.ppm" || fail "dexmill run failed"
t1=$(date +%s%N)
echo "long.ngc ($lines lines, $bytes B)|$size|iso|cli|$(( (t1 - t0) / 1000000 ))" > "$tmp/native.txt"
python3 tools/scripts/web_compare.py "$tmp" || fail "the page's pixels are not dexmill run's"

peak() { tr ' ' '\n' < "$1" | sort -n | tail -1; }
short_kb=$(peak "$tmp/short.mem"); long_kb=$(peak "$tmp/long.mem")
[ -n "$short_kb" ] && [ -n "$long_kb" ] || fail "no renderer's memory found"
echo "ok: web-stream-test: the tab's peak resident memory $((long_kb / 1024)) MiB cutting the $(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1e6 }') MB program," \
  "$((short_kb / 1024)) MiB cutting its first 1000 lines ($(( (long_kb - short_kb) / 1024 )) MiB more);" \
  "dexmill run's $(( $(cat "$tmp/native.mem") / 1024 )) MiB"
# A tab that held the file would need 35 MB more; measured here: 3.5-7 MiB.
[ $((long_kb - short_kb)) -lt $((bytes / 2048)) ] || fail "the tab held more than half the file's size more than for 1000 lines"
