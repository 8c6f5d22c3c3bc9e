#!/usr/bin/env bash
# check_layers.sh - the pipeline runs one way (README "Where things live",
# core/README.md, habit 1): each folder of core/ and display/ includes only the
# stages it is allowed to below. `make test` runs it; a new stage adds a row.
#
# Usage: tests/check_layers.sh   (from the repository root)
# Exit: 0 every include is allowed, 1 otherwise (each offence listed).
set -u
cd "$(dirname "$0")/.."

# folder -> the folders its files may include (itself always; the shared
# basics of core/ itself: config.h, status.h, point.h, integer_only.h)
allowed() {
  case $1 in
    core) echo "core/math";;
    core/math) echo "";;
    core/gcode) echo "core/math";;
    core/motion) echo "core/gcode core/math";;
    core/grid) echo "core/math";;
    core/tool) echo "core/math";;
    core/cut) echo "core/motion core/grid core/tool core/math";;
    core/design) echo "core/grid core/math";;
    core/assess) echo "core/design core/grid core/tool core/math";;
    core/cam) echo "core/design core/grid core/tool core/math";;  # tool paths from a design part
    core/material) echo "core/math";;  # noise, textures, materials: maths only
    core/check) echo "core/motion core/grid core/tool core/math core/cut core/material";;  # fixtures: the cut swept into them; process rules: materials
    core/sim) echo "core/check core/assess core/material core/cut core/design core/motion core/gcode core/grid core/tool core/math";;  # the engine: a run's stages and observers, tied together once
    display) echo "core/sim core/check core/assess core/cut core/motion core/gcode core/design core/grid core/tool core/math core/material";;
    display/api) echo "display core/sim core/check core/assess core/cut core/motion core/gcode core/design core/grid core/tool core/math core/material";;  # the C API: the engine and its view
    *) echo "?";;
  esac
}

bad=0; files=0
while IFS= read -r f; do
  files=$((files + 1))
  dir=$(dirname "$f")
  ok=$(allowed "$dir")
  if [ "$ok" = "?" ]; then
    echo "check_layers: $dir/ is not in the table of tests/check_layers.sh (add its row)"; bad=1; continue
  fi
  while IFS=: read -r line inc; do
    to=$(dirname "$inc")
    [ "$to" = "$dir" ] && continue
    [ "$to" = core ] && [ "${dir%%/*}" = core -o "${dir%%/*}" = display ] && continue
    case " $ok " in *" $to "*) continue;; esac
    echo "$f:$line: includes $inc, but $dir/ may include only: ${ok:-(nothing)}"
    bad=1
  done < <(grep -n '^#include "' "$f" | sed 's/^\([0-9]*\):#include "\([^"]*\)".*/\1:\2/')
done < <(find core display -name '*.h' -o -name '*.cpp' | LC_ALL=C sort)
[ $files -gt 0 ] || { echo "check_layers: no sources found" >&2; exit 1; }
[ $bad = 0 ] && echo "ok: $files files of core/ and display/ include only the stages below them"
exit $bad
