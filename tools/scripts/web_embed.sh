#!/usr/bin/env bash
# web_embed.sh - build/web/dexmill.js for `make web`: the module as base64
# in front of the loader (platform/web/dexmill.js), so that the page needs no
# fetch() (which file:// refuses) and makes no request at all.
#   tools/scripts/web_embed.sh DEXMILL.WASM LOADER.JS > dexmill.js
set -eu
wasm=${1:?usage: web_embed.sh DEXMILL.WASM LOADER.JS}
loader=${2:?usage: web_embed.sh DEXMILL.WASM LOADER.JS}
printf '/* dexmill.wasm (%s bytes), base64; made by tools/scripts/web_embed.sh */\n' "$(wc -c < "$wasm")"
printf 'var DEXMILL_WASM_BASE64 = "%s";\n' "$(base64 -w0 "$wasm")"
cat "$loader"
