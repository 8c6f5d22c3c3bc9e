// Golden section "motion": the G-code of this wave's last part on every
// target: G33/G33.1, G95, G43.2, M70-M73, rotated systems (CORDIC turns,
// a G18 arc turned out of its plane as chords) and a NURBS (de Boor in
// q48, rational shares in q62, the hull test's chord counts). Every record's
// kind, line, feed and points hashed.
#include "tests/golden/golden.h"
#include "tests/golden/path_hash.h"

namespace golden {

using namespace dexmill;

namespace {

const char kMotionProgram[] =
    "G21 G90 G17 F300 S1200 M3\n"
    "G0 X1 Y2 Z5\n"
    "G33.1 Z-4 K1.25\n"
    "G33 X3 Z-1 K0.8\n"
    "G95 F0.05\n"
    "G1 X7 Y3\n"
    "S700\n"
    "G2 X9 Y5 R3\n"
    "G94 F250\n"
    "G43.2 Z0.75\n"
    "G0 X0 Y0\n"
    "G49\n"
    "o<keep> sub\n"
    "  M73\n"
    "  G91 F90 S3000 M4 M8\n"
    "  G1 X1.5 Y-0.5\n"
    "o<keep> endsub\n"
    "o<keep> call\n"
    "G1 X4 Y4\n"
    "G10 L2 P1 X12 Y-3 R27.5\n"
    "G0 X2 Y1 Z2\n"
    "G3 X-2 Y4 I-2 J1.5\n"
    "G18 G2 X1 Z2 I1.5 K0\n"
    "G17 G10 L2 P2 X-5 R-61.25\n"
    "G55 G1 X3 Y3\n"
    "G54\n"
    "G5.2 X1 Y6 P1 L4\n"
    "X4 Y7 P2.5\n"
    "X6 Y3 P0.75\n"
    "X9 Y5 P1\n"
    "X10 Y1 P1.5\n"
    "G5.3\n"
    "G10 L2 P1 R0\n"
    "G0 X0 Y0 Z10\n"
    "M2\n";


}  // namespace

void golden_motion(Out& out) {
  PathHash mh(true);
  const int errors = trace_with_flow(kMotionProgram, &mh, nullptr);
  out.str("motion").kv("records", mh.records).kv("points", mh.points).kx("trace", mh.h.value()).kv("errors", errors).end();
}

}  // namespace golden
