// The table of built-in design parts and their grids; see builtin.h.
#include "core/design/builtin.h"

#include "core/design/builtin_parts.h"
#include "core/math/fixed.h"

namespace dexmill {

namespace {

// The paper's §3 order: Table 2's three workpieces, then the tsuba.
const BuiltinDesign* const kBuiltins[] = {&kBuiltinPanel, &kBuiltinSmiley, &kBuiltinFreeform, &kBuiltinTsuba};
constexpr int32_t kBuiltinCount = static_cast<int32_t>(sizeof kBuiltins / sizeof kBuiltins[0]);

bool same_name(const char* a, const char* b) {
  while (*a && *a == *b) ++a, ++b;
  return *a == *b;
}

}  // namespace

int32_t builtin_design_count() { return kBuiltinCount; }

const BuiltinDesign& builtin_design_at(int32_t i) { return *kBuiltins[i >= 0 && i < kBuiltinCount ? i : 0]; }

const BuiltinDesign* builtin_design_find(const char* name) {
  if (!name) return nullptr;
  for (const BuiltinDesign* b : kBuiltins)
    if (same_name(b->name, name)) return b;
  return nullptr;
}

GridGeometry builtin_geometry(const BuiltinDesign& b, int height_bits) {
  GridGeometry g{};
  g.nx = b.nx;
  g.ny = b.ny;
  g.x0_nm = 0;
  g.y0_nm = 0;
  g.pitch_nm = b.pitch_nm;
  g.z0_nm = 0;
  g.lsb_nm = lsb_for_range(b.stock_height_nm + b.stock_height_nm / 4, height_bits);
  return g;
}

int32_t builtin_top_lsb(const BuiltinDesign& b, const GridGeometry& geo, int32_t i, int32_t j) {
  const int64_t h_nm = b.height_nm(static_cast<int64_t>(i) * b.pitch_nm, static_cast<int64_t>(j) * b.pitch_nm);
  return sat_i32(div_round(h_nm - geo.z0_nm, geo.lsb_nm));
}

Status builtin_design_fill(const BuiltinDesign& b, DesignGrid* d) {
  const GridGeometry& g = d->geo;
  if (g.nx != b.nx || g.ny != b.ny || g.pitch_nm != b.pitch_nm || g.x0_nm != 0 || g.y0_nm != 0 || g.lsb_nm <= 0)
    return Status::kBadArgument;
  for (int32_t j = 0; j < g.ny; ++j)
    for (int32_t i = 0; i < g.nx; ++i) d->top_lsb[d->index(i, j)] = builtin_top_lsb(b, g, i, j);
  return Status::kOk;
}

}  // namespace dexmill
