// Dexel grid set-up and queries, paper §2.1-2.2.1.
#include "core/grid/grid.h"

#include "core/math/hash.h"

namespace dexmill {

Status grid_check_geometry(const GridGeometry& geo) {
  constexpr int64_t kMetre = 1000 * kNmPerMm;
  if (geo.nx < 2 || geo.ny < 2 || geo.nx > 65535 || geo.ny > 65535) return Status::kBadArgument;
  if (geo.pitch_nm < 1 || geo.pitch_nm > kMetre || geo.lsb_nm < 1 || geo.lsb_nm > kMetre) return Status::kBadArgument;
  const int64_t lim = 1000 * kMetre;
  if (abs_u64(geo.x0_nm) > static_cast<uint64_t>(lim) || abs_u64(geo.y0_nm) > static_cast<uint64_t>(lim) ||
      abs_u64(geo.z0_nm) > static_cast<uint64_t>(lim))
    return Status::kBadArgument;
  return Status::kOk;
}

template <class H>
Status grid_init(DexelGrid<H>* g, const GridGeometry& geo, H* top, H* bottom, size_t cells) {
  Status s = grid_check_geometry(geo);
  if (!ok(s)) return s;
  if (!top || !bottom || cells < static_cast<size_t>(geo.nx) * static_cast<size_t>(geo.ny)) return Status::kBufferTooSmall;
  g->nx = geo.nx;
  g->ny = geo.ny;
  g->top = top;
  g->bottom = bottom;
  g->x0_nm = geo.x0_nm;
  g->y0_nm = geo.y0_nm;
  g->pitch_nm = geo.pitch_nm;
  g->z0_nm = geo.z0_nm;
  g->lsb_nm = geo.lsb_nm;
  g->dirty = GridRect::none();
  g->bottoms_zero = false;
  g->top_bound_lsb = height_max<H>();
  return Status::kOk;
}

template <class H>
void grid_block_stock(DexelGrid<H>* g, int64_t height_lsb) {
  const H h = static_cast<H>(clamp<int64_t>(height_lsb, 0, height_max<H>()));
  for (int32_t j = 0; j < g->ny; ++j) {
    const bool border_row = (j == 0 || j == g->ny - 1);
    H* t = g->top + g->index(0, j);
    H* b = g->bottom + g->index(0, j);
    for (int32_t i = 0; i < g->nx; ++i) {
      const bool border = border_row || i == 0 || i == g->nx - 1;
      t[i] = border ? H(0) : h;
      b[i] = 0;
    }
  }
  g->dirty = g->bounds();
  g->bottoms_zero = true;
  g->top_bound_lsb = h;
}

template <class H>
GradientLsb grid_gradient(const DexelGrid<H>& g, int32_t i, int32_t j) {
  const int32_t il = i > 0 ? i - 1 : i, ir = i < g.nx - 1 ? i + 1 : i;
  const int32_t jd = j > 0 ? j - 1 : j, ju = j < g.ny - 1 ? j + 1 : j;
  GradientLsb n;
  // A one-sided difference spans one pitch instead of two: double it.
  n.dx = (static_cast<int64_t>(g.top[g.index(ir, j)]) - g.top[g.index(il, j)]) * (ir - il == 1 ? 2 : 1);
  n.dy = (static_cast<int64_t>(g.top[g.index(i, ju)]) - g.top[g.index(i, jd)]) * (ju - jd == 1 ? 2 : 1);
  n.dz = div_round(2 * g.pitch_nm, g.lsb_nm);
  return n;
}

template <class H>
uint64_t grid_hash(const DexelGrid<H>& g) {
  Hash64 h;
  h.uint_le(static_cast<uint32_t>(g.nx), 4);
  h.uint_le(static_cast<uint32_t>(g.ny), 4);
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  for (size_t k = 0; k < n; ++k) h.uint_le(g.top[k], sizeof(H));
  for (size_t k = 0; k < n; ++k) h.uint_le(g.bottom[k], sizeof(H));
  return h.value();
}

int64_t lsb_for_range(int64_t range_nm, int bits) {
  const int64_t hmax = (bits >= 32) ? 4294967295LL : ((static_cast<int64_t>(1) << bits) - 1);
  if (range_nm <= 0) return 1;
  for (int64_t decade = 1; decade <= 1000 * kNmPerMm; decade *= 10) {
    static const int64_t kSteps[3] = {1, 2, 5};
    for (int64_t f : kSteps) {
      int64_t lsb = f * decade;
      if (div_ceil(range_nm, lsb) <= hmax) return lsb;
    }
  }
  return 1000 * kNmPerMm;
}

template Status grid_init<uint8_t>(DexelGrid<uint8_t>*, const GridGeometry&, uint8_t*, uint8_t*, size_t);
template Status grid_init<uint16_t>(DexelGrid<uint16_t>*, const GridGeometry&, uint16_t*, uint16_t*, size_t);
template Status grid_init<uint32_t>(DexelGrid<uint32_t>*, const GridGeometry&, uint32_t*, uint32_t*, size_t);
template void grid_block_stock<uint8_t>(DexelGrid<uint8_t>*, int64_t);
template void grid_block_stock<uint16_t>(DexelGrid<uint16_t>*, int64_t);
template void grid_block_stock<uint32_t>(DexelGrid<uint32_t>*, int64_t);
template GradientLsb grid_gradient<uint8_t>(const DexelGrid<uint8_t>&, int32_t, int32_t);
template GradientLsb grid_gradient<uint16_t>(const DexelGrid<uint16_t>&, int32_t, int32_t);
template GradientLsb grid_gradient<uint32_t>(const DexelGrid<uint32_t>&, int32_t, int32_t);
template uint64_t grid_hash<uint8_t>(const DexelGrid<uint8_t>&);
template uint64_t grid_hash<uint16_t>(const DexelGrid<uint16_t>&);
template uint64_t grid_hash<uint32_t>(const DexelGrid<uint32_t>&);

}  // namespace dexmill
