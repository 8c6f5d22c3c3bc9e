#!/usr/bin/env bash
# make test-sheet: `dexmill run --sheet` in a real browser. A sheet of a job
# with findings of every kind it draws (tests/run/pocket.ngc against its
# design, all checks, a material, engagement measured); the page's static
# rules (no script, nothing fetched: no http src, url(), @import, <link>);
# then, where Debian's chromium is installed (tools/scripts/install-deps.sh
# browser), the page rendered headless to PNG and printed to PDF (1 or 2
# A4 pages), with the net log showing no http(s) or ws request the page
# made (the browser's own traffic aside). A page that fetches an image is checked the same way and must be
# caught, so the check can fail. Without chromium it says SKIPPED and
# runs the static checks only.
#   tools/scripts/sheet-test.sh BIN [OUTDIR]   (OUTDIR keeps the PNG and PDF)
set -eu
bin=${1:?usage: sheet-test.sh BIN [OUTDIR]}
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=${2:-$tmp}
mkdir -p "$out"
fail() { echo "FAIL: sheet-test: $*"; exit 1; }

"$bin" run tests/run/pocket.ngc -q --tool flat:6 --design tests/run/pocket_design.stl --material aluminium \
  --check all,load --sheet "$out/sheet.html" --report "$tmp/sheet.json" 2> "$tmp/run.err" ||
  { cat "$tmp/run.err"; fail "dexmill run --sheet failed"; }
page=$out/sheet.html
[ -s "$page" ] || fail "no sheet"
for bad in '<script' 'src="http' 'url(http' '@import' '<link' '<iframe'; do
  if grep -qiF "$bad" "$page"; then fail "the sheet has '$bad'"; fi
done
grep -qF 'class="verdict fail">1 gouge' "$page" || fail "the verdict line is not the report's"
echo "ok: sheet-test: the sheet is self-contained ($(wc -c < "$page") bytes)"

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "sheet-test: SKIPPED: chromium not installed (tools/scripts/install-deps.sh browser)"
  exit 0
fi

# The browser's own traffic (updates, sync, dictionaries) off; every host
# unresolvable, so that nothing leaves the machine even if asked for.
flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --disable-default-apps --disable-domain-reliability
       --disable-client-side-phishing-detection --disable-features=SpellCheck,Translate,MediaRouter,OptimizationHints
       "--host-resolver-rules=MAP * ~NOTFOUND")
# browse NAME PAGE ARGS...: one headless run with its own profile and net log.
browse() {
  local name=$1 file=$2
  shift 2
  timeout 60 "$browser" "${flags[@]}" --user-data-dir="$tmp/profile-$name" --log-net-log="$tmp/$name.net.json" "$@" \
    "file://$(realpath "$file")" > "$tmp/$name.log" 2>&1 || { tail -5 "$tmp/$name.log"; fail "chromium ($name) failed"; }
}
# The http(s) and ws(s) URLs a net log records the page asking for: a
# request with an origin as its initiator (a file:// page's is "null");
# the browser's own (updates, accounts, dictionaries) have "not an origin".
requests() {
  python3 - "$1" <<'PY'
import json, sys
events = json.load(open(sys.argv[1]))["events"]
seen = set()
for e in events:
    p = e.get("params", {})
    url = p.get("url", "")
    if url.split(":")[0] in ("http", "https", "ws", "wss") and p.get("initiator", "not an origin") != "not an origin":
        seen.add(url)
print("\n".join(sorted(seen)))
PY
}

browse png "$page" --window-size=794,1123 --screenshot="$out/sheet.png"
browse pdf "$page" --no-pdf-header-footer --print-to-pdf="$out/sheet.pdf"
png_bytes=$(wc -c < "$out/sheet.png")
pdf_bytes=$(wc -c < "$out/sheet.pdf")
[ "$png_bytes" -gt 30000 ] || fail "the screenshot is $png_bytes bytes"
[ "$pdf_bytes" -gt 30000 ] || fail "the PDF is $pdf_bytes bytes"
pages=$(grep -a -c '/Type */Page\b' "$out/sheet.pdf" || true)
[ "$pages" -ge 1 ] && [ "$pages" -le 2 ] || fail "the PDF has $pages pages, not 1 or 2"
for log in png pdf; do
  got=$(requests "$tmp/$log.net.json")
  [ -z "$got" ] || fail "the sheet made network requests ($log): $got"
done
# The control: a page that fetches an image is caught.
printf '<!DOCTYPE html><img src="http://example.invalid/x.png">\n' > "$tmp/fetch.html"
browse fetch "$tmp/fetch.html" --screenshot="$tmp/fetch.png"
requests "$tmp/fetch.net.json" | grep -q 'example.invalid' || fail "the net log check missed a page's request"
echo "ok: sheet-test: chromium drew the sheet ($png_bytes-byte PNG, $pages-page $pdf_bytes-byte PDF), no network request"
