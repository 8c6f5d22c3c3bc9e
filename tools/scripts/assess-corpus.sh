#!/usr/bin/env bash
# assess-corpus.sh - error assessment on real programs of a corpus folder
# (CORPUS; by default the one CI keeps beside the clone) against design
# parts this project makes for them: the part
# each program is written to make, as an STL the script writes, and the
# tool its header names. Prints each run's assessment in one line; fails
# when dexmill fails or finds a gouge (these programs make their parts
# without one), so a regression in the design rasterizing, the assessment
# or the gouge watch shows on real files.
#
#   tools/scripts/assess-corpus.sh [DEXMILL]
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
# CORPUS: a folder of real programs (CI keeps one beside the clone).
corpus="${CORPUS:-$root/../shared/corpus}"
dexmill=${1:-$root/build/dexmill}
if [ ! -d "$corpus" ]; then
  echo "assess-corpus: no corpus at $corpus (set CORPUS=DIR); skipping"
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
# pcb2gcode's drill file: a 1.6 mm board (Z-1.6..0) with the holes its two
# bits (0.8 mm and 1 mm, named in its header) drill through it. The board
# is strips in X; a strip through a column of holes is split into a 2 mm
# square round each hole (the ring between the square and the hole, with
# the square's corners among its vertices) and plain rectangles between.
# Each hole is a 64-gon round the bit's circle plus 1 um, so no column
# the bit clears is design material.
def holed_square(cx, cy, r, n=64):
    rr = (r + 0.001) / math.cos(math.pi / n)
    tris = []
    def on_square(a):
        c, s = math.cos(a), math.sin(a)
        t = 1.0 / max(abs(c), abs(s))
        return (cx + t * c, cy + t * s, 0.0)
    for k in range(n):
        a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        h0 = (cx + rr * math.cos(a0), cy + rr * math.sin(a0), 0.0)
        h1 = (cx + rr * math.cos(a1), cy + rr * math.sin(a1), 0.0)
        s0, s1 = on_square(a0), on_square(a1)
        tris += [(h0, s0, s1), (h0, s1, h1)]
    return tris
def hole_strip(cx, ys, r, y_end):
    tris, y = [], 0.0
    for cy in sorted(ys):
        if cy - 1 > y:
            tris += quad(cx - 1, y, cx + 1, cy - 1, 0.0)
        tris += holed_square(cx, cy, r)
        y = cy + 1
    return tris + (quad(cx - 1, y, cx + 1, y_end, 0.0) if y < y_end else [])
W, H = 25.5, 20.0
big = [1.0 + 2.54 * k for k in range(8)]
tris = quad(0, 0, 0.2, H, 0.0) + quad(2.2, 0, 11.555, H, 0.0) + quad(13.555, 0, 23.06, H, 0.0) + quad(25.06, 0, W, H, 0.0)
tris += hole_strip(1.2, big, 0.5, H) + hole_strip(24.06, big, 0.5, H)
tris += hole_strip(12.555, [4.945, 6.945, 8.945, 10.945], 0.4, H)
write("pcb_drilled", tris)
with open(f"{out}/pcb_drills.tbl", "w") as f:
    f.write("T1 P1 D0.8 Z0 ;drill vbit:0.8:118\nT2 P2 D1 Z0 ;drill vbit:1:118\n")
PY

fail=0
run() {  # run PROGRAM DESIGN MIN_WITHIN_PERCENT DEXMILL_OPTION...
  local prog=$1 design=$2 min_within=$3
  shift 3
  if ! "$dexmill" run "$corpus/$prog" -q "$@" --design "$tmp/$design.stl" --fail-on-gouge \
       --report "$tmp/r.json" 2> "$tmp/err"; then
    echo "FAIL     $prog against $design: exit $? $(head -c 300 "$tmp/err")"; fail=1; return
  fi
  python3 - "$tmp/r.json" "$prog" "$design" "$min_within" <<'PY' || fail=1
import json, sys
a = json.load(open(sys.argv[1]))["assessment"]
g, l = a["max_gouge"], a["max_leftover"]
ok = a["within_tolerance_percent"] >= float(sys.argv[4])
print("%s %s against %s: E_rel %s, rms %s mm, %s %% within %s mm (at least %s expected), max gouge %s, max leftover %s mm, gouges %d"
      % ("OK      " if ok else "FAIL    ", sys.argv[2], sys.argv[3], a["E_rel"], a["rms_mm"],
         a["within_tolerance_percent"], a["tolerance_mm"], sys.argv[4],
         g["mm"] if g else "none", l["mm"] if l else "none", a["gouges_total"]))
sys.exit(0 if ok else 1)
PY
}
# The margins the programs leave by design: FreeCAD's profile never reaches
# the stock's outer 1 mm (about half the area stays high).
run FreeCAD/test_linuxcnc_metric_ref.ngc freecad_boss 50 --tool flat:5
run grbl/HSM_test.nc hsm_pocket 99.9 --tool flat:3.175
run pcb2gcode/drill.ngc pcb_drilled 99.9 --tools "$tmp/pcb_drills.tbl" --stock 0,0,-1.6,25.5,20,0
exit $fail
