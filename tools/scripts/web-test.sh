#!/usr/bin/env bash
# web-test.sh - make test-web: the page of `make web` (build/web/) in headless
# Chromium draws the pixels `dexmill run --image` draws. For each case the
# page's own form and Run path (index.html's dexmillPage.run) cuts a fixture
# program fed from a Blob in pieces, draws the frame into its canvas, and
# hashes the canvas's pixels (getImageData, FNV-1a of the R, G, B bytes, in
# the page); the native run's PPM is hashed the same way, and the two RGB
# byte strings are compared whole, the first differing pixel named. No
# request may leave the page (tools/scripts/web_page.py watches). Then the
# same page from a static server on 127.0.0.1 draws the same frames. Also
# the times of the job in the page and natively, and the page's size.
# SKIPPED, said so, where the wasm build or Chromium is missing
# (tools/scripts/install-deps.sh web). WEB_PAGE_SCREENSHOT=FILE.png keeps a
# picture of the page after the last case (web_page.py).
#   tools/scripts/web-test.sh BIN [WEBDIR [CASE...]]   (WEBDIR default build/web)
# A CASE more is a line as those below, e.g. a long program for the times
# (platform/web/README.md has the one its figures come from).
set -eu
bin=${1:?usage: web-test.sh BIN [WEBDIR [CASE...]]}
bin=$(realpath "$bin")
extra=("${@:3}")
web=${2:+$(realpath "$2")}
cd "$(dirname "$0")/../.."
web=${web:-build/web}
. tools/scripts/web_common.sh
web_setup web-test "$web"

# program | stock | tool | grid | size | view | the look: plain (aliased, no
# triad or scale bar: --no-antialias --no-decorations) or cli (run's default).
# An 8th column, optional: more of the CLI's options ("--color tool",
# "--color thin --thin 0.5"), given to dexmill run and set in the page's
# form, each --NAME VALUE into the field of id NAME (page_colour.js's;
# --design FILE: the file chosen in its file input).
# A view iso+DX+DY is the iso view dragged by DX, DY pixels after the cut
# (the page's orbit: synthetic pointer events), against dexmill run's
# --azimuth and --elevation of iso's turned half a degree a pixel.
cases='tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|plain
tests/run/arcs_inch.ngc|0,0,-5,45,35,0|vbit:3:90|200x160|400x300|top|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso+30+10|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|640x480|iso|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color slope
tests/run/tool_change.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|top|cli|--color tool
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color material --material wood-on-aluminium
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color thin --thin 8
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color error --design tests/run/pocket_floor.stl'
for c in "${extra[@]}"; do cases="$cases"$'\n'"$c"; done

# The page: build/web/ as served, plus job.js, which sets the form per case
# and runs it the way the Run button does, then hands back the canvas's RGB.
{
  echo "var DEXMILL_CASES = ["
  while IFS='|' read -r prog stock tool grid size view look more; do
    design=$(sed -n 's/.*--design \([^ ]*\).*/\1/p' <<< "$more")
    printf '{program: "%s", stock: "%s", tool: "%s", grid: "%s", size: "%s", view: "%s", cli: %s, more: "%s", design: "%s"},\n' \
      "$(base64 -w0 "$prog")" "$stock" "$tool" "$grid" "$size" "$view" "$([ "$look" = cli ] && echo true || echo false)" "$more" \
      "$([ -n "$design" ] && base64 -w0 "$design")"
  done <<< "$cases"
  echo "];"
  cat tools/scripts/web_probe.js
  cat <<'EOF'
window.dexmillTest = (async function () {
  var out = [], $ = function (id) { return document.getElementById(id); };
  for (var c of DEXMILL_CASES) {
    var s = atob(c.program), b = new Uint8Array(s.length);
    for (var i = 0; i < s.length; ++i) b[i] = s.charCodeAt(i);
    $("stock").value = c.stock; $("tool").value = c.tool; $("grid").value = c.grid; $("size").value = c.size;
    var view = c.view.split("+");
    $("view").value = view[0]; $("antialias").checked = c.cli; $("decorations").checked = c.cli;
    $("color").value = "plain"; $("thin").value = "1"; $("material").value = "";
    var more = c.more ? c.more.split(/\s+/) : [];
    var files = new DataTransfer();  /* --design: the file as a user chooses it */
    if (c.design) {
      var d = atob(c.design), db = new Uint8Array(d.length);
      for (var i = 0; i < d.length; ++i) db[i] = d.charCodeAt(i);
      files.items.add(new File([db], "design.stl"));
    }
    $("design").files = files.files;
    for (var k = 0; k + 1 < more.length; k += 2) if (more[k] !== "--design") $(more[k].replace(/^--/, "")).value = more[k + 1];
    var r = await dexmillPage.run(dexmill.blobSource(new Blob([b])));
    if (view.length === 3) {  /* a drag across the canvas, as a finger or mouse makes it */
      var canvas = $("view-canvas"), at = function (dx, dy) { return { bubbles: true, pointerId: 1, clientX: 100 + dx, clientY: 100 + dy }; };
      canvas.dispatchEvent(new PointerEvent("pointerdown", at(0, 0)));
      canvas.dispatchEvent(new PointerEvent("pointermove", at(+view[1], +view[2])));
      await new Promise(function (done) { requestAnimationFrame(done); });
      canvas.dispatchEvent(new PointerEvent("pointerup", at(+view[1], +view[2])));
      await new Promise(function (done) { requestAnimationFrame(function () { requestAnimationFrame(done); }); });
      r.hash = $("hash").textContent;
    }
    out.push(dexmillProbe(r));
  }
  return out;
})();
EOF
} > "$tmp/job.js"
sed 's|</body>|<script src="job.js"></script></body>|' "$web/index.html" > "$tmp/test.html"

python3 tools/scripts/web_page.py "$browser" "file://$(realpath "$tmp/test.html")" window.dexmillTest 300 "${web_flags[@]}" "$web_no_hosts" \
  > "$tmp/page.json" || fail "the page did not run"

# The native runs, timed, each as the CLI draws it.
n=0
while IFS='|' read -r prog stock tool grid size view look more; do
  n=$((n + 1))
  opts=(-q --stock "$stock" --tool "$tool" --grid "$grid" --size "$size")
  case $view in
    iso+*) IFS=+ read -r _ dx dy <<< "$view"
           opts+=(--azimuth "$(awk -v d="$dx" 'BEGIN { printf "%.3f", -45 - d / 2 }')"
                  --elevation "$(awk -v d="$dy" 'BEGIN { printf "%.3f", 35.264 + d / 2 }')");;
    *) opts+=(--view "$view");;
  esac
  [ "$look" = cli ] || opts+=(--no-antialias --no-decorations)
  read -r -a more_opts <<< "$more"
  opts+=("${more_opts[@]}")
  t0=$(date +%s%N)
  "$bin" run "$prog" "${opts[@]}" --image "$tmp/cli$n.ppm" || fail "dexmill run $prog failed"
  t1=$(date +%s%N)
  echo "$prog|$size|$view|$look${more:+ $more}|$(( (t1 - t0) / 1000000 ))" >> "$tmp/native.txt"
done <<< "$cases"

python3 tools/scripts/web_compare.py "$tmp" || fail "the page's pixels are not dexmill run's"

# The same page from a static server (Python's, on a free local port): the
# same frames, and no request but to that server.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server --bind 127.0.0.1 --directory "$tmp" "$port" > /dev/null 2>&1 &
server=$!
trap 'kill "$server" 2> /dev/null; rm -rf "$tmp"' EXIT
for _ in $(seq 50); do python3 -c "import socket; socket.create_connection(('127.0.0.1', $port))" 2> /dev/null && break; sleep 0.1; done
WEB_PAGE_ALLOW="http://127.0.0.1:$port/" python3 tools/scripts/web_page.py "$browser" "http://127.0.0.1:$port/test.html" \
  window.dexmillTest 300 "${web_flags[@]}" "$web_no_hosts, EXCLUDE 127.0.0.1" > "$tmp/page-http.json" || fail "the page did not run from http://127.0.0.1:$port/"
python3 - "$tmp" <<'PY' || fail "the page's frames from a server are not those from file://"
import json, sys
a, b = (json.load(open(sys.argv[1] + f)) for f in ("/page.json", "/page-http.json"))
sys.exit(0 if [r["rgb"] for r in a] == [r["rgb"] for r in b] else 1)
PY
echo "ok: web-test: the page from a static server (http://127.0.0.1:$port/) draws the same $(grep -c . <<< "$cases") frames"
js=$(wc -c < "$web/dexmill.js"); html=$(wc -c < "$web/index.html"); wasm=$(wc -c < "$web/dexmill.wasm")
gz=$(( $(gzip -9c "$web/index.html" | wc -c) + $(gzip -9c "$web/dexmill.js" | wc -c) ))
echo "ok: web-test: no request left the page; dexmill.wasm $wasm B; the page (index.html + dexmill.js) $((js + html)) B, $gz B gzipped (each file gzip -9)"
