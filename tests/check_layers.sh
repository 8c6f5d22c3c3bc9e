#!/usr/bin/env bash
# check_layers.sh - the pipeline runs one way (core/README.md "Where things
# live" and habit 1): each stage folder of core/, display/, platform/ and
# tools/ includes only the stages it is allowed to. `make test` runs it,
# after its self-test; a new stage adds a row.
#
# Usage: tests/check_layers.sh              (from anywhere in the repository)
#        tests/check_layers.sh --self-test  plants, in a scratch tree, one
#          include each row forbids and one it allows, and a folder with no
#          row; fails unless exactly the forbidden ones and the folder are caught
# Exit: 0 every include is allowed, 1 otherwise (each offence listed).
set -u
SELF=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
cd "$(dirname "$0")/.."

# folder -> the folders its files may include (itself always; the shared
# basics of core/ itself, config.h, status.h, point.h, integer_only.h, for
# everyone). An include without a folder is the file beside it, or one of
# the C headers an embedder puts on its path (display/api/dexmill.h,
# platform/api/dexmill_io.h), or else a header generated into the build
# (tools/panel/panel_w3_main.cpp's w3_path.h), which has no stage.
allowed() {
  case $1 in
    core) echo "core/math";;
    core/math) echo "";;
    core/gcode) echo "core/math";;
    core/canon) echo "core/math";;  # the canonical records: what every stage after the interpreter reads
    core/interp) echo "core/canon core/gcode core/math";;
    core/grid) echo "core/math";;
    core/tool) echo "core/math";;
    core/cut) echo "core/canon core/grid core/tool core/math";;
    core/design) echo "core/grid core/math";;
    core/assess) echo "core/design core/grid core/tool core/math";;
    core/cam) echo "core/design core/grid core/tool core/math";;  # tool paths from a design part
    core/material) echo "core/math";;  # noise, textures, materials: maths only
    core/safety) echo "core/canon core/grid core/tool core/math core/cut core/material";;  # fixtures: the cut swept into them; a material's limits
    core/stock) echo "core/grid core/math";;  # the stock file: a stock between runs
    core/engage) echo "core/canon core/grid core/tool core/math";;  # what the cutting edge meets: engagement, chip, load
    core/measure) echo "core/design core/grid core/math";;  # measurements of a simulated part (against its design too)
    core/sim) echo "core/engage core/stock core/safety core/assess core/material core/cut core/design core/canon core/interp core/gcode core/grid core/tool core/math";;  # the engine: a run's stages and observers, tied together once
    display/raster) echo "core/math";;  # the frame, spans, clipping, the camera
    display/colour) echo "display/raster core/sim core/engage core/stock core/assess core/design core/grid core/material core/math";;  # a cell's colour by mode (tool colours: the provenance)
    display/surface) echo "display/colour display/raster core/grid core/tool core/math";;
    display/overlay) echo "display/raster core/math";;
    display/view) echo "display/surface display/overlay display/colour display/raster core/grid core/tool core/math";;  # the whole still
    display/api) echo "display/view display/surface display/overlay display/colour display/raster core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # the C API: the engine and its view
    platform/os) echo "";;  # the OS seam: below every other platform stage
    platform/format) echo "platform/os platform/mesh display/raster core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # files: images, STL, tool tables, materials
    platform/mesh) echo "display/surface core/grid core/math";;  # surface extraction for STL: hosted, so not in display/
    platform/report) echo "platform/format platform/os display/overlay core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # a run's result
    platform/live) echo "platform/format platform/os display/raster";;  # screens: window, framebuffer, frame files; the progress bar
    platform/input) echo "platform/live platform/os core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # the G-code file driver; the input guard knows the frames' names
    platform/api) echo "platform/format display/api display/raster";;  # the C header of the image files, over dexmill.h
    platform/web) echo "display/api";;  # the browser's glue: wasm32, freestanding, the C API only (platform/web/README.md)
    tools/bench) echo "platform/os platform/format display/view display/surface display/overlay display/colour display/raster display/api core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;
    tools/cam) echo "tools/cli platform/os platform/format platform/mesh platform/report platform/live platform/input platform/api core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # cli.h: the exit codes
    tools/run) echo "tools/cli tools/cam platform/os platform/format platform/mesh platform/report platform/live platform/input platform/api display/view display/surface display/overlay display/colour display/raster display/api core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # cli/: the exit codes and option values; cam/: zig's program
    tools/cli) echo "tools/run tools/cam tools/bench platform/os platform/format platform/mesh platform/report platform/live platform/input platform/api display/view display/surface display/overlay display/colour display/raster display/api core/sim core/measure core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # the commands: everything
    tools/panel) echo "tools/bench display/view display/surface display/overlay display/colour display/raster display/api core/sim core/engage core/stock core/safety core/assess core/cam core/cut core/canon core/interp core/gcode core/design core/grid core/tool core/math core/material";;  # integer-only like core/ (w3_path_dump, a host program, reads the bench's workload)
    tools/panel/cm) echo "tools/panel";;  # the Cortex-M board under the panel
    tools/examples) echo "display/api platform/api";;  # an embedder: the installed C headers only
    *) echo "?";;
  esac
}


# The folders of the table, in its order.
rows() { sed -n 's/^    \([a-z][a-z/]*\)) echo .*/\1/p' "$SELF"; }

# check_tree ROOT: every source under ROOT's core/, display/, platform/ and
# tools/ against the table; prints each offence, fails if there was one.
check_tree() (
  cd "$1" || exit 1
  bad=0; files=0
  while IFS= read -r f; do
    files=$((files + 1))
    dir=$(dirname "$f")
    ok=$(allowed "$dir")
    if [ "$ok" = "?" ]; then
      echo "check_layers: $dir/ is not in the table of tests/check_layers.sh (add its row)"; bad=1; continue
    fi
    while IFS=: read -r line inc; do
      case $inc in
        */*) to=$(dirname "$inc");;
        *) if [ -e "$dir/$inc" ]; then to=$dir
           elif [ -e "display/api/$inc" ]; then to=display/api
           elif [ -e "platform/api/$inc" ]; then to=platform/api
           else continue; fi;;
      esac
      [ "$to" = "$dir" ] && continue
      [ "$to" = core ] && continue
      case " $ok " in *" $to "*) continue;; esac
      echo "$f:$line: includes $inc, but $dir/ may include only: ${ok:-(nothing)}"
      bad=1
    done < <(grep -n '^#include "' "$f" | sed 's/^\([0-9]*\):#include "\([^"]*\)".*/\1:\2/')
  done < <(find core display platform tools \( -name '*.h' -o -name '*.cpp' -o -name '*.c' \) 2>/dev/null | LC_ALL=C sort)
  [ $files -gt 0 ] || { echo "check_layers: no sources found" >&2; exit 1; }
  [ $bad = 0 ] && echo "ok: $files files of core/, display/, platform/ and tools/ include only the stages they may"
  exit $bad
)

self_test() {
  local t d ok b good want=() n=0 out st w
  t=$(mktemp -d); trap 'rm -rf "$t"' RETURN
  for d in $(rows); do
    mkdir -p "$t/$d"; ok=$(allowed "$d")
    good=${ok%% *}; [ -n "$good" ] || good=core
    printf '#include "%s/x.h"\n' "$good" > "$t/$d/good.h"
    b=
    for b in $(rows); do
      [ "$b" = "$d" ] || [ "$b" = core ] && continue
      case " $ok " in *" $b "*) continue;; esac
      break
    done
    [ -n "$b" ] && [ "$b" != "$d" ] || { echo "check_layers self-test: $d/ forbids nothing to plant" >&2; return 1; }
    printf '#include "%s/x.h"\n' "$b" > "$t/$d/bad.h"
    want+=("$d/bad.h:1: includes $b/x.h"); n=$((n + 1))
  done
  mkdir -p "$t/platform/nowhere"; : > "$t/platform/nowhere/a.h"
  want+=("check_layers: platform/nowhere/ is not in the table")
  out=$(check_tree "$t"); st=$?
  [ $st = 1 ] || { echo "check_layers self-test: the planted tree passed (status $st)" >&2; return 1; }
  for w in "${want[@]}"; do
    grep -qF -- "$w" <<< "$out" || { echo "check_layers self-test: not caught: $w" >&2; return 1; }
  done
  if grep -q 'good\.h' <<< "$out"; then
    echo "check_layers self-test: an allowed include was refused:" >&2; grep 'good\.h' <<< "$out" >&2; return 1
  fi
  [ "$(grep -c ': includes ' <<< "$out")" = $n ] || { echo "check_layers self-test: other offences than the planted:" >&2; echo "$out" >&2; return 1; }
  echo "ok: check_layers catches a forbidden include in each of its $n rows, and a folder with no row"
}

if [ "${1:-}" = --self-test ]; then self_test; exit; fi
check_tree .
