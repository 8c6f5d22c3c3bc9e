// Golden sections "mill", "path" and "flow": a G-code program stored as text
// (as a panel would keep it in flash) read by the interpreter
// (core/interp/interp.h) and (mill) cut by core/cut/mill.h in sweep and
// stamp mode into m = 8, 16, 32 grids, one grid hash per mode and m; (path)
// every canonical record and arc chord point hashed in order, the same trace
// `dexmill path` prints; (flow) the same trace of a program computed by
// parameters, expressions and o-word loops and calls: the
// fixed-point functions and the flow, on every target.
#include <stdint.h>
#include <string.h>

#include "core/cut/mill.h"
#include "core/grid/grid.h"
#include "core/math/hash.h"
#include "core/canon/arc_chords.h"
#include "core/interp/interp.h"
#include "core/tool/tool.h"
#include "tests/golden/golden.h"
#include "tests/golden/path_hash.h"

using namespace dexmill;

namespace golden {
namespace {

const char kProgram[] =
    "%\n"
    "G21 G90 G17 G94 (golden mill program)\n"
    "T1 M6\n"
    "G0 Z25\n"
    "G0 X4 Y4\n"
    "G1 Z15 F300\n"
    "G1 X26 Y4 F800\n"
    "G1 X26 Y20 Z13\n"
    "G2 X18 Y12 I-8 J0\n"
    "G3 X10 Y20 R8\n"
    "G2 X10 Y20 I0 J-4 Z10\n"
    "T2 M6\n"
    "G1 X4 Y4 Z14\n"
    "G18 G2 X14 Z14 I5 K0\n"
    "G17 G91 G1 X4 Y3 Z-1\n"
    "G90 G81 X22 Y16 Z-1 R18 F200\n"
    "X24 Y10\n"
    "G80 G0 Z25\n"
    "T3 M6\n"
    "G1 X6 Y18 Z16 F500\n"
    "G3 X6 Y18 I3 J-3 Z13 P2\n"
    "G0 Z25\n"
    "M30\n"
    "%\n";

// Every function and operator of RS274/NGC expressions, in the positions
// and lengths of a real program's moves, and each o-word statement.
const char kFlowProgram[] =
    "G21 G90 G17 F400\n"
    "#<_r> = [SQRT[2] * 5]\n"
    "o<petal> sub\n"
    "  #<a> = [#1 * 360 / #2]\n"
    "  G1 X[#<_r> * COS[#<a>]] Y[#<_r> * SIN[#<a>]] Z[-LN[#1 + 1]]\n"
    "  G3 X[#<_r> * COS[#<a> + 30]] Y[#<_r> * SIN[#<a> + 30]] R[#<_r>]\n"
    "  o<petal> return [TAN[#<a> / 8] + ATAN[#1]/[#2]]\n"
    "o<petal> endsub\n"
    "o1 repeat [7]\n"
    "  #10 = [#10 + 1]\n"
    "  o<petal> call [#10] [7]\n"
    "  G0 Z[#<_value>]\n"
    "o1 endrepeat\n"
    "o2 while [#10 GT 0]\n"
    "  #10 = [#10 - 1]\n"
    "  o3 if [#10 MOD 2 EQ 0]\n"
    "    G1 X[EXP[#10 / 4]] Y[ASIN[#10 / 8] / 10]\n"
    "  o3 elseif [#10 EQ 5]\n"
    "    o2 continue\n"
    "  o3 else\n"
    "    G1 X[ACOS[#10 / 8] / 10] Y[2 ** [#10 / 3]]\n"
    "  o3 endif\n"
    "o2 endwhile\n"
    "o4 do\n"
    "  #11 = [#11 + 0.75]\n"
    "  G1 Z[FIX[#11] - FUP[#11] + ROUND[#11 * 3] / 10]\n"
    "  o4 break\n"
    "o4 while [1]\n"
    "M2\n";

class Library : public ToolLibrary {
 public:
  bool tool(int32_t number, Tool* out) const override {
    Tool t;
    t.flute_length_nm = 20 * kNmPerMm;
    t.length_nm = 50 * kNmPerMm;
    switch (number) {
      case 1: t.kind = ToolKind::kBall; t.diameter_nm = 6 * kNmPerMm; break;
      case 2: t.kind = ToolKind::kFlat; t.diameter_nm = 3 * kNmPerMm; break;
      case 3:
        t.kind = ToolKind::kBullNose;
        t.diameter_nm = 5 * kNmPerMm;
        t.corner_radius_nm = kNmPerMm;
        break;
      default: return false;
    }
    *out = t;
    return true;
  }
};

// Feeds the program line by line; returns the number of lines in error.
int interpret(CanonSink* sink) {
  InterpOptions opt;
  Interp in(sink, opt);
  return static_cast<int>(interp_run_text(&in, kProgram, strlen(kProgram), nullptr));
}

template <class H>
void mill_one(Out& out, CutMode mode) {
  const int bits = static_cast<int>(sizeof(H) * 8);
  Arena& a = arena();
  a.reset();
  const int32_t nx = 64, ny = 48;
  const size_t cells = static_cast<size_t>(nx) * ny;
  H* top = a.take<H>(cells);
  H* bottom = a.take<H>(cells);
  const size_t words = cutter_storage_words(12);
  int32_t* w = a.take<int32_t>(words);
  DexelGrid<H> g;
  const GridGeometry geo{nx, ny, 0, 0, 500000, 0, lsb_for_range(25 * kNmPerMm, bits)};
  if (!top || !bottom || !w || !ok(grid_init(&g, geo, top, bottom, cells))) {
    fail(out, "mill: set-up");
    return;
  }
  grid_block_stock(&g, grid_height_of_z(g, 20 * kNmPerMm));
  Library lib;
  Mill<H> mill(&g, mode, &lib, w, words);
  const int errors = interpret(&mill);
  mill.flush();
  out.str("mill ").str(mode == CutMode::kSweep ? "sweep" : "stamp").kv("m", bits).kx("grid", grid_hash(g));
  out.kv("instances", static_cast<int64_t>(mill.stats().instances));
  out.kv("updates", static_cast<int64_t>(mill.stats().dexel_updates)).kv("errors", errors);
  out.kv("status", static_cast<int64_t>(mill.status())).end();
}


}  // namespace

void golden_mill(Out& out) {
  for (int mode = 0; mode < 2; ++mode) {
    const CutMode m = mode ? CutMode::kStamp : CutMode::kSweep;
    mill_one<uint8_t>(out, m);
    mill_one<uint16_t>(out, m);
    mill_one<uint32_t>(out, m);
  }
}

void golden_path(Out& out) {
  PathHash ph;
  const int errors = interpret(&ph);
  out.str("path").kv("records", ph.records).kv("points", ph.points).kx("trace", ph.h.value()).kv("errors", errors).end();
}

int trace_with_flow(const char* program, PathHash* sink, int64_t* blocks) {
  // The parameters' and the control flow's memory, as a panel keeps it (one
  // set for every section that needs it: they run one after another).
  static ParamStore params;
  static OwordStore control;
  InterpOptions opt;
  opt.params = &params;
  opt.control = &control;
  Interp in(sink, opt);
  const int errors = static_cast<int>(interp_run_text(&in, program, strlen(program), nullptr));
  if (blocks) *blocks = static_cast<int64_t>(control.blocks);
  return errors;
}

void golden_flow(Out& out) {
  PathHash ph;
  int64_t blocks = 0;
  const int errors = trace_with_flow(kFlowProgram, &ph, &blocks);
  out.str("flow").kv("records", ph.records).kv("points", ph.points).kx("trace", ph.h.value()).kv("errors", errors);
  out.kv("blocks", blocks).end();
}

}  // namespace golden
