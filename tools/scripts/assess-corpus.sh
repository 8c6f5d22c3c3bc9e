#!/usr/bin/env bash
# assess-corpus.sh - error assessment on real programs of ../shared/corpus
# against design parts this project makes for them (issue 18): the part
# each program is written to make, as an STL the script writes, and the
# tool its header names. Prints each run's assessment in one line; fails
# when dexmill fails or finds a gouge (these programs make their parts
# without one), so a regression in the design rasterizing, the assessment
# or the gouge watch shows on real files.
#
#   tools/scripts/assess-corpus.sh [DEXMILL]
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus="$root/../shared/corpus"
dexmill=${1:-$root/build/dexmill}
if [ ! -d "$corpus" ]; then
  echo "assess-corpus: ../shared/corpus is absent; skipping"
  exit 0
fi
[ -x "$dexmill" ] || { echo "assess-corpus: $dexmill not built (run make)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The designs, as ASCII STL (top surfaces; the highest point over each
# column is what counts).
python3 - "$tmp" <<'PY'
import math, sys
out = sys.argv[1]
def write(name, tris):
    with open(f"{out}/{name}.stl", "w") as f:
        f.write(f"solid {name}\n")
        for t in tris:
            f.write("  facet normal 0 0 1\n    outer loop\n")
            for v in t:
                f.write("      vertex %.6f %.6f %.6f\n" % v)
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")
def quad(x0, y0, x1, y1, z):
    return [((x0, y0, z), (x1, y0, z), (x1, y1, z)), ((x0, y0, z), (x1, y1, z), (x0, y1, z))]
# FreeCAD's profile test: a 3 x 3 mm boss at Z0, the 5 mm end mill's
# profile leaves it standing on a floor 1 mm down.
write("freecad_boss", quad(-20, -20, 23, 23, -1) + quad(0, 0, 3, 3, 0))
# grbl's high-speed pocketing test: a 20 mm circular pocket 6 mm deep (its
# outer circle at r 8.4125 for a 1/8 in end mill).
n, r, r2, tris = 256, 10.0, 30.0, []
for k in range(n):
    a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
    p = lambda rr, a, z: (rr * math.cos(a), rr * math.sin(a), z)
    tris.append(((0.0, 0.0, -6.0), p(r, a0, -6.0), p(r, a1, -6.0)))
    tris += [(p(r, a0, 0.0), p(r2, a0, 0.0), p(r2, a1, 0.0)), (p(r, a0, 0.0), p(r2, a1, 0.0), p(r, a1, 0.0))]
write("hsm_pocket", tris)
PY

fail=0
run() {  # run PROGRAM TOOL DESIGN
  local prog=$1 tool=$2 design=$3
  if ! "$dexmill" run "$corpus/$prog" -q --tool "$tool" --design "$tmp/$design.stl" --fail-on-gouge \
       --report "$tmp/r.json" 2> "$tmp/err"; then
    echo "FAIL     $prog against $design: exit $? $(head -c 300 "$tmp/err")"; fail=1; return
  fi
  python3 - "$tmp/r.json" "$prog" "$design" <<'PY'
import json, sys
a = json.load(open(sys.argv[1]))["assessment"]
g, l = a["max_gouge"], a["max_leftover"]
print("OK       %s against %s: E_rel %s, rms %s mm, %s %% within %s mm, max gouge %s, max leftover %s mm, gouges %d"
      % (sys.argv[2], sys.argv[3], a["E_rel"], a["rms_mm"], a["within_tolerance_percent"], a["tolerance_mm"],
         g["mm"] if g else "none", l["mm"] if l else "none", a["gouges_total"]))
PY
}
run FreeCAD/test_linuxcnc_metric_ref.ngc flat:5 freecad_boss
run grbl/HSM_test.nc flat:3.175 hsm_pocket
exit $fail
