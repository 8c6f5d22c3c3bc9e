// Golden section "stamp": the programs of golden_programs.h cut by instances
// of motion (core/cut/stamp.h, paper §2.3) into grids of m = 8, 16 and 32 bits.
// Per program and m, one line: the grid hash (core grid_hash, little-endian
// bytes by construction), a hash of the per-move trace (instances, dexel
// updates, dirty rectangle after each move, which pins down a diverging move
// without hashing the grid each time), the counters, and a hash of the
// height-gradient normals (paper §2.1 eq. 1) over every dexel.
#include <stdint.h>

#include "core/cut/stamp.h"
#include "core/grid/grid.h"
#include "core/math/hash.h"
#include "core/status.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/golden/golden.h"
#include "tests/golden/golden_programs.h"

using namespace dexmill;

namespace golden {
namespace {

constexpr int kMaxTools = 8;

Tool tool_of(const ProgramTool& pt) {
  Tool t;
  t.kind = pt.kind;
  t.diameter_nm = pt.diameter_nm;
  t.corner_radius_nm = pt.corner_nm;
  t.tip_angle_mdeg = pt.tip_mdeg;
  t.flute_length_nm = pt.flute_nm;
  t.length_nm = pt.length_nm;
  return t;
}

void hash_rect(Hash64* h, const GridRect& r) {
  h->uint_le(static_cast<uint32_t>(r.i0), 4);
  h->uint_le(static_cast<uint32_t>(r.j0), 4);
  h->uint_le(static_cast<uint32_t>(r.i1), 4);
  h->uint_le(static_cast<uint32_t>(r.j1), 4);
}

template <class H>
void run_program(Out& out, const Program& p) {
  const int bits = static_cast<int>(sizeof(H) * 8);
  out.str("stamp ").str(p.name).kv("m", bits);
  Arena& a = arena();
  a.reset();
  const int64_t lsb = lsb_for_range(p.range_nm, bits);
  const size_t cells = static_cast<size_t>(p.nx) * static_cast<size_t>(p.ny);
  H* top = a.take<H>(cells);
  H* bottom = a.take<H>(cells);
  DexelGrid<H> g;
  const GridGeometry geo{p.nx, p.ny, p.x0_nm, p.y0_nm, p.pitch_nm, p.z0_nm, lsb};
  if (!top || !bottom || !ok(grid_init(&g, geo, top, bottom, cells)) || p.ntools > kMaxTools) {
    out.end();
    fail(out, "stamp: grid set-up");
    return;
  }
  CutterDexels cutters[kMaxTools];
  for (int t = 0; t < p.ntools; ++t) {
    const Tool tool = tool_of(p.tools[t]);
    const ToolProfile prof = tool_profile(tool);
    const size_t words = cutter_storage_words(cutter_reach_dex(prof, p.pitch_nm));
    int32_t* w = a.take<int32_t>(words);
    if (!ok(tool_check(tool)) || !w || !ok(cutter_build(prof, p.pitch_nm, lsb, w, words, &cutters[t]))) {
      out.end();
      fail(out, "stamp: cutter set-up");
      return;
    }
  }
  grid_block_stock(&g, grid_height_of_z(g, p.stock_top_nm));

  CutStats st;
  Hash64 trace;
  for (int m = 0; m < p.nmoves; ++m) {
    const ProgramMove& mv = p.moves[m];
    g.dirty = GridRect::none();
    stamp_line(&g, cutters[mv.tool], mv.from, mv.to, &st);
    trace.uint_le(st.instances, 8);
    trace.uint_le(st.dexel_updates, 8);
    hash_rect(&trace, g.dirty);
  }

  int64_t holes = 0, min_top = height_max<H>(), max_top = 0;
  Hash64 normals;
  for (int32_t j = 0; j < g.ny; ++j) {
    for (int32_t i = 0; i < g.nx; ++i) {
      if (g.is_hole(i, j)) {
        ++holes;
      } else {
        const int64_t t = g.top[g.index(i, j)];
        min_top = t < min_top ? t : min_top;
        max_top = t > max_top ? t : max_top;
      }
      const GradientLsb n = grid_gradient(g, i, j);
      normals.uint_le(static_cast<uint64_t>(n.dx), 8);
      normals.uint_le(static_cast<uint64_t>(n.dy), 8);
      normals.uint_le(static_cast<uint64_t>(n.dz), 8);
    }
  }
  out.kv("lsb_nm", lsb).kx("grid", grid_hash(g)).kx("trace", trace.value()).end();
  out.str("  counts").kv("moves", p.nmoves).kv("instances", static_cast<int64_t>(st.instances));
  out.kv("updates", static_cast<int64_t>(st.dexel_updates)).kv("holes", holes).kv("min_top", min_top);
  out.kv("max_top", max_top).kx("normals", normals.value()).end();
}

}  // namespace

void golden_stamp(Out& out) {
  for (int i = 0; i < programs::kCount; ++i) {
    run_program<uint8_t>(out, programs::kAll[i]);
    run_program<uint16_t>(out, programs::kAll[i]);
    run_program<uint32_t>(out, programs::kAll[i]);
  }
}

}  // namespace golden
