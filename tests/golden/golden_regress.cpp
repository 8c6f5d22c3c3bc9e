// Golden section "regress": regression cases named after the bug they pin
// (core/README.md, habit 11). Each prints a line whose value must not change, and
// runs under the sanitizer targets of xcheck, where the bug was found.
#include <stdint.h>

#include "core/cut/stamp.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/golden/golden.h"
#include "tests/golden/golden_programs.h"

using namespace dexmill;

namespace golden {
namespace {

// stamp_overhang_left_edge: stamp_instance formed its row pointer as
// g->top + index(ci - K, j); when the cutter overhangs the grid's left edge
// (ci < K) on row 0 that points before the array, which is undefined even
// though only in-grid dexels are touched (clang -fsanitize=pointer-overflow,
// xcheck target ubsan-clang, core/cut/stamp.cpp). Instances at every corner and
// edge, overhanging by less than, exactly and more than K.
template <class H>
void stamp_overhang_left_edge(Out& out) {
  const int bits = static_cast<int>(sizeof(H) * 8);
  Arena& a = arena();
  a.reset();
  constexpr int32_t kNx = 24, kNy = 16;
  const int64_t pitch = mm(1), lsb = lsb_for_range(mm(25), bits);
  H* top = a.take<H>(kNx * kNy);
  H* bottom = a.take<H>(kNx * kNy);
  Tool t;
  t.kind = ToolKind::kBall;
  t.diameter_nm = mm(6);
  t.length_nm = mm(40);
  const ToolProfile p = tool_profile(t);
  const size_t words = cutter_storage_words(cutter_reach_dex(p, pitch));
  int32_t* w = a.take<int32_t>(words);
  DexelGrid<H> g;
  CutterDexels c;
  if (!top || !bottom || !w || !ok(grid_init(&g, GridGeometry{kNx, kNy, 0, 0, pitch, 0, lsb}, top, bottom, kNx * kNy)) ||
      !ok(cutter_build(p, pitch, lsb, w, words, &c))) {
    fail(out, "regress: set-up");
    return;
  }
  grid_block_stock(&g, grid_height_of_z(g, mm(20)));
  const int32_t k = c.reach_dex;
  const int32_t spots[][2] = {{0, 0}, {1, 0}, {-1, 0}, {-k, 0}, {-k - 1, 0}, {0, 5}, {kNx - 1, 0}, {kNx + k - 1, 0},
                              {0, kNy - 1}, {-2, kNy + 1}, {kNx - 1, kNy - 1}, {kNx + 1, kNy + 2}};
  CutStats st;
  int64_t z = mm(14);
  for (const auto& s : spots) {
    stamp_instance(&g, c, s[0], s[1], grid_height_of_z(g, z), &st);
    z += um(250);
  }
  out.str("stamp_overhang_left_edge").kv("m", bits).kv("K", k).kv("instances", static_cast<int64_t>(st.instances));
  out.kv("updates", static_cast<int64_t>(st.dexel_updates)).kx("grid", grid_hash(g)).end();
}

}  // namespace

void golden_regress(Out& out) {
  stamp_overhang_left_edge<uint8_t>(out);
  stamp_overhang_left_edge<uint16_t>(out);
  stamp_overhang_left_edge<uint32_t>(out);
}

}  // namespace golden
