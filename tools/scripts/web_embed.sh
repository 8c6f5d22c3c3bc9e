#!/usr/bin/env bash
# web_embed.sh - build/web/dexmill.js for `make web`: the module as base64
# in front of the scripts (the loader platform/web/dexmill.js and its
# engine_*.js, then the page's page.js and page_*.js), one file, so that the
# page needs no fetch() (which file:// refuses) and makes no request at all.
#   tools/scripts/web_embed.sh DEXMILL.WASM SCRIPT.JS... > dexmill.js
set -eu
wasm=${1:?usage: web_embed.sh DEXMILL.WASM SCRIPT.JS...}
shift
[ $# -gt 0 ] || { echo "usage: web_embed.sh DEXMILL.WASM SCRIPT.JS..." >&2; exit 2; }
printf '/* dexmill.wasm (%s bytes), base64; made by tools/scripts/web_embed.sh */\n' "$(wc -c < "$wasm")"
printf 'var DEXMILL_WASM_BASE64 = "%s";\n' "$(base64 -w0 "$wasm")"
for js in "$@"; do
  printf '/* ---- %s ---- */\n' "$js"
  cat "$js"
done
