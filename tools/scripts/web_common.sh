# web_common.sh - sourced by the browser tests (web-test.sh,
# web-stream-test.sh) from the repository's root.
#   web_setup NAME WEBDIR: says NAME: SKIPPED and exits 0 where Chromium or
#   the page of `make web` is missing; else sets browser, tmp (a scratch
#   folder, removed at exit, holding a copy of the page), web_flags (a
#   headless Chromium with its own traffic off, as sheet-test.sh runs it),
#   web_no_hosts (its flag that makes every host unresolvable; append ",
#   EXCLUDE 127.0.0.1" for a local server) and fail (FAIL: NAME: ..., exit 1).
web_setup() {
  web_name=$1
  browser=$(command -v chromium || command -v chromium-browser || true)
  if [ -z "$browser" ]; then
    echo "$web_name: SKIPPED: chromium not installed (tools/scripts/install-deps.sh web)"
    exit 0
  fi
  if [ ! -s "$2/dexmill.js" ] || [ ! -s "$2/index.html" ]; then
    echo "$web_name: SKIPPED: no $2/dexmill.js (make web; its toolchain: tools/scripts/install-deps.sh web)"
    exit 0
  fi
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  cp "$2/index.html" "$2/dexmill.js" "$tmp/"
  web_flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run --disable-background-networking
             --disable-component-update --disable-sync --disable-default-apps --disable-domain-reliability)
  web_no_hosts="--host-resolver-rules=MAP * ~NOTFOUND"
}
fail() { echo "FAIL: $web_name: $*"; exit 1; }
