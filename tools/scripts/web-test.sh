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
# An empty stock or grid is an empty field, and no --stock or --grid for
# dexmill run: both choose them from the program (platform/web/page_scan.js).
# The program `demo` is the page's Demo button against `dexmill run --demo
# pocket` (its material, coloured by it).
# In a case's optional eighth column (below), a word that starts with --
# holds more of the CLI's options ("--color tool", "--color thin --thin
# 0.5"), given to dexmill run and set in the page's form, each --NAME VALUE
# into the field of id NAME (page_colour.js's; --design FILE: the file
# chosen in its file input).
# A view iso+DX+DY is the iso view dragged by DX, DY pixels after the cut
# (the page's orbit: synthetic pointer events), against dexmill run's
# --azimuth and --elevation of iso's turned half a degree a pixel. An
# optional eighth column, extras separated by ';': tools=FILE (a --tools
# table: the page's table input and the CLI's option), path (the page's
# --path-overlay box and the CLI's option), check=NAMES (the page's --check
# field and the CLI's; its findings, kind, line and place, must be those
# dexmill run warns of, and the first clicked in the list marks the view
# where dexmill run marks it: one finding in such a case), speed=N (a live
# replay at N times machine time (Replay after a run at full speed), paused
# for 300 ms on the way: the same
# last frame, no cut while paused, and at least machine time / N long),
# keys (after the cut: 1, +, -, 2 on the keyboard: web_controls.py), drop
# (the program dropped on the canvas as a file, not given to the Run path),
# zoom (after the cut: 10 wheel notches in about a point and 10 out give
# the frame before; a pinch of 3x about the same point gives the wheel's
# frame, not an orbit; reset view the frame before).
cases='tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|plain
tests/run/arcs_inch.ngc|0,0,-5,45,35,0|vbit:3:90|200x160|400x300|top|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso+30+10|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|640x480|iso|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|400x300|iso|cli|path
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|plain|speed=100
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|zoom
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|top|cli|keys;drop
tests/run/rapid_through.ngc|0,0,-10,33,23,0|flat:6|330x230|480x360|iso|cli|path;check=rapid
tests/run/pocket.ngc||flat:6||320x240|iso|cli
tests/run/arcs_inch.ngc||vbit:3:90||400x300|top|cli
tests/run/tool_change.ngc||flat:3||320x240|iso|plain
tests/run/pocket.ngc|-2,-2,-12,36,26,1|ball:2||320x240|iso|plain
tests/run/tool_change.ngc||flat:6||400x300|iso|cli|tools=tests/run/tools.tbl
tests/run/tool_change.ngc|-2,-4,-5,24,12,0|flat:6|120x80|320x240|top|plain|tools=tests/run/tools.tbl
demo||flat:6||320x240|iso|plain
demo||flat:6||400x300|top|cli
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color slope
tests/run/tool_change.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|top|cli|--color tool
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color material --material wood-on-aluminium
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color thin --thin 8
tests/run/pocket.ngc|0,0,-10,33,23,0|flat:6|330x230|320x240|iso|cli|--color error --design tests/run/pocket_floor.stl'
for c in "${extra[@]}"; do cases="$cases"$'\n'"$c"; done
# The words of a case's extras that are CLI options (those starting with --),
# joined; and its tools=FILE (empty: none).
extra_more() { tr ';' '\n' <<< "$1" | grep -- '^--' | paste -sd ' '; }
extra_tools() { tr ';' '\n' <<< "$1" | sed -n 's/^tools=//p'; }

# A --tools table with a bad line: before the cases the page must list
# dexmill run's error for it, word for word (the file named as chosen).
printf 'T1 D4 ;flat\nK3\n' > "$tmp/bad.tbl"
bad_table=$("$bin" run tests/run/tool_change.ngc -q --tools "$tmp/bad.tbl" --image "$tmp/bad.ppm" 2>&1 > /dev/null || true)
bad_table=${bad_table#"$tmp/"}
[ -n "$bad_table" ] || fail "dexmill run took a bad tool table"

# The page: build/web/ as served, plus job.js, which sets the form per case
# and runs it the way the Run button does, then hands back the canvas's RGB.
{
  printf 'var DEXMILL_BAD_TABLE = "%s", DEXMILL_BAD_ERROR = "%s";\n' "$(base64 -w0 "$tmp/bad.tbl")" "$bad_table"
  echo "var DEXMILL_CASES = ["
  while IFS='|' read -r prog stock tool grid size view look extra; do
    tools=$(extra_tools "$extra")
    more=$(extra_more "$extra")
    design=$(sed -n 's/.*--design \([^ ]*\).*/\1/p' <<< "$more")
    printf '{program: "%s", stock: "%s", tool: "%s", grid: "%s", size: "%s", view: "%s", cli: %s, extra: "%s", tools: "%s", toolsName: "%s", more: "%s", design: "%s"},\n' \
      "$([ "$prog" = demo ] && echo demo || base64 -w0 "$prog")" "$stock" "$tool" "$grid" "$size" "$view" "$([ "$look" = cli ] && echo true || echo false)" \
      "$extra" "$([ -z "$tools" ] || base64 -w0 "$tools")" "$(basename "${tools:-none}")" "$more" "$([ -n "$design" ] && base64 -w0 "$design")"
  done <<< "$cases"
  echo "];"
  cat tools/scripts/web_probe.js
  cat <<'EOF'
/* n display frames, or 2 s if the browser draws none (a headless tab can
 * stall its frames): a drawing that never came then fails the case's
 * pixels instead of hanging the test. */
function frames(n) {
  return new Promise(function (done) {
    var t = setTimeout(done, 2000);
    (function next(k) { requestAnimationFrame(function () { if (k > 1) next(k - 1); else { clearTimeout(t); done(); } }); })(n);
  });
}
window.dexmillTest = (async function () {
  var out = [], $ = function (id) { return document.getElementById(id); };
  /* First the bad table (the cases after it leave the page as the last one made it, for a picture). */
  var dt = new DataTransfer(), bad = atob(DEXMILL_BAD_TABLE), said = "(no error)";
  dt.items.add(new File([bad], "bad.tbl"));
  $("tools-file").files = dt.files;
  try { await dexmillPage.run(dexmill.blobSource(new Blob([atob(DEXMILL_CASES[0].program)]))); } catch (err) { said = $("errors").textContent; }
  if (said !== DEXMILL_BAD_ERROR) throw new Error("the bad tool table: the page said '" + said + "', not '" + DEXMILL_BAD_ERROR + "'");
  for (var c of DEXMILL_CASES) {
    window.dexmillTestAt = "case " + (out.length + 1) + ": " + c.view + " " + c.extra + " " + c.more;  /* web_page.py says it on a timeout */
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
      for (var q = 0; q < d.length; ++q) db[q] = d.charCodeAt(q);
      files.items.add(new File([db], "design.stl"));
    }
    $("design").files = files.files;
    for (var m = 0; m + 1 < more.length; m += 2) if (more[m] !== "--design") $(more[m].replace(/^--/, "")).value = more[m + 1];
    var extra = c.extra.split(";"), check = extra.filter(function (w) { return /^check=/.test(w); })[0];
    $("path-overlay").checked = extra.indexOf("path") >= 0;
    $("check").value = check ? check.slice(6) : "";
    var speed = extra.filter(function (w) { return /^speed=/.test(w); })[0];
    $("speed").value = "0";
    if (c.program === "demo") {
      $("tool").value = c.tool; $("size").value = c.size; $("view").value = c.view;
      $("antialias").checked = c.cli; $("decorations").checked = c.cli;
      out.push(dexmillProbe(await dexmillPage.demo()));
      continue;
    }
    var dt = new DataTransfer();  /* the table as a user would choose it (none: an empty input) */
    if (c.tools) dt.items.add(new File([Uint8Array.from(atob(c.tools), function (ch) { return ch.charCodeAt(0); })], c.toolsName));
    $("tools-file").files = dt.files;
    var running = null, sleep = function (ms) {
      return new Promise(function (done) { setTimeout(done, ms); });
    };
    if (extra.indexOf("drop") >= 0) {  /* the file dropped on the canvas, as from a file manager: the Run button's path */
      var dropped = new DataTransfer();
      dropped.items.add(new File([b], "dropped.ngc"));
      dexmillPage.running = null;
      $("view-canvas").dispatchEvent(new DragEvent("drop", { dataTransfer: dropped, bubbles: true, cancelable: true }));
      if (!dexmillPage.running) throw new Error("a dropped file did not run");
      running = dexmillPage.running.then(function (res) { res.dropped = $("file").files[0].name; return res; });
    } else {
      running = dexmillPage.run(dexmill.blobSource(new Blob([b])));
    }
    if (speed) {  /* Replay, paced, paused on the way: the status line (the cut's progress) stands still */
      await running;
      $("speed").value = speed.slice(6);
      $("replay").click();
      running = dexmillPage.running;
      await sleep(150);
      $("pause").click();
      await sleep(100);
      var before = $("status").textContent;
      await sleep(300);
      var paused = { before: before, after: $("status").textContent };
      $("pause").click();
    }
    var r = await running;
    if (speed) { r.paused = paused; r.speed = +speed.slice(6); }
    if (extra.indexOf("zoom") >= 0) {
      var cv = $("view-canvas"), h = function () { return $("hash").textContent; }, z = { before: h() };
      var wheel = function (dy) { cv.dispatchEvent(new WheelEvent("wheel", { bubbles: true, cancelable: true, deltaY: dy, clientX: 125, clientY: 125 })); };
      var pointer = function (type, id, x) { cv.dispatchEvent(new PointerEvent(type, { bubbles: true, pointerId: id, clientX: x, clientY: x })); };
      for (var k = 0; k < 10; ++k) wheel(-100);
      z.wheelIn = h();
      for (k = 0; k < 10; ++k) wheel(100);
      z.wheelOut = h();
      pointer("pointerdown", 11, 50); pointer("pointerdown", 12, 100); pointer("pointermove", 12, 200);
      await frames(2);
      z.pinch = h();
      pointer("pointerup", 12, 200); pointer("pointerup", 11, 50);
      $("zoom-reset").click();
      z.reset = h();
      r.zoom = z;
      r.hash = h();
    }
    if (view.length === 3) {  /* a drag across the canvas, as a finger or mouse makes it */
      var canvas = $("view-canvas"), at = function (dx, dy) { return { bubbles: true, pointerId: 1, clientX: 100 + dx, clientY: 100 + dy }; };
      canvas.dispatchEvent(new PointerEvent("pointerdown", at(0, 0)));
      canvas.dispatchEvent(new PointerEvent("pointermove", at(+view[1], +view[2])));
      await frames(1);
      canvas.dispatchEvent(new PointerEvent("pointerup", at(+view[1], +view[2])));
      await frames(2);
      r.hash = $("hash").textContent;
    }
    if (extra.indexOf("keys") >= 0) {  /* the keyboard, as a user presses it on the page */
      var key = function (name) { document.body.dispatchEvent(new KeyboardEvent("keydown", { key: name, bubbles: true, cancelable: true })); };
      var kh = function () { return $("hash").textContent; }, keys = { before: kh() };
      key("1");
      keys.iso = kh();
      key("+");
      keys.zoomed = kh();
      key("-");
      key("2");
      keys.after = kh();
      r.keys = keys;
      r.hash = kh();
    }
    var marked = document.querySelector("#findings button[data-mark='0']");
    if (check && marked) {  /* the first finding clicked: a light blue mark over dexmill run's magenta one */
      var unmarked = $("hash").textContent, other = document.querySelector("#findings button[data-mark='-1']");
      marked.click();
      r.clicked = { before: unmarked, marked: $("hash").textContent };
      await new Promise(function (done) { setTimeout(done, 200); });  /* its line read again from the file */
      r.status = $("status").textContent;
      if (other) other.click();  /* a warning clicked: no mark of the page's own, the frame dexmill run's again */
      r.clicked.after = $("hash").textContent;
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
while IFS='|' read -r prog stock tool grid size view look extra; do
  tools=$(extra_tools "$extra")
  more=$(extra_more "$extra")
  n=$((n + 1))
  opts=(-q --tool "$tool" --size "$size")
  [ -z "$stock" ] || opts+=(--stock "$stock")
  [ -z "$grid" ] || opts+=(--grid "$grid")
  [ -z "$tools" ] || opts+=(--tools "$tools")
  case $view in
    iso+*) IFS=+ read -r _ dx dy <<< "$view"
           opts+=(--azimuth "$(awk -v d="$dx" 'BEGIN { printf "%.3f", -45 - d / 2 }')"
                  --elevation "$(awk -v d="$dy" 'BEGIN { printf "%.3f", 35.264 + d / 2 }')");;
    *) opts+=(--view "$view");;
  esac
  [ "$look" = cli ] || opts+=(--no-antialias --no-decorations)
  IFS=';' read -ra extras <<< "$extra"
  for x in "${extras[@]}"; do
    case $x in path) opts+=(--path-overlay);; check=*) opts+=(--check "${x#check=}");; esac
  done
  read -r -a more_opts <<< "$more"
  opts+=("${more_opts[@]}")
  t0=$(date +%s%N)
  if [ "$prog" = demo ]; then  # its out/ in the scratch folder
    (cd "$tmp" && "$bin" run --demo pocket "${opts[@]}" --image "$tmp/cli$n.ppm" 2> "$tmp/cli$n.err") || fail "dexmill run --demo pocket failed"
  else
    "$bin" run "$prog" "${opts[@]}" --image "$tmp/cli$n.ppm" 2> "$tmp/cli$n.err" || fail "dexmill run $prog failed"
  fi
  t1=$(date +%s%N)
  echo "$prog|$size|$view|$look${more:+ $more}|$(( (t1 - t0) / 1000000 ))" >> "$tmp/native.txt"
done <<< "$cases"

python3 tools/scripts/web_compare.py "$tmp" || fail "the page's pixels are not dexmill run's"
python3 tools/scripts/web_findings.py "$tmp" || fail "the page's findings are not those dexmill run warns of"
python3 tools/scripts/web_controls.py "$tmp" || fail "a paced replay did not keep to machine time or pause, or a zoom did not come back"

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
echo "ok: web-test: the page lists a bad --tools table's error as dexmill run says it: $bad_table"
echo "ok: web-test: the page from a static server (http://127.0.0.1:$port/) draws the same $(grep -c . <<< "$cases") frames"
js=$(wc -c < "$web/dexmill.js"); html=$(wc -c < "$web/index.html"); wasm=$(wc -c < "$web/dexmill.wasm")
gz=$(( $(gzip -9c "$web/index.html" | wc -c) + $(gzip -9c "$web/dexmill.js" | wc -c) ))
echo "ok: web-test: no request left the page; dexmill.wasm $wasm B; the page (index.html + dexmill.js) $((js + html)) B, $gz B gzipped (each file gzip -9)"
