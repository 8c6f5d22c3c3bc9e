// The cell surface; see stl_cells.h.
#include "platform/mesh/stl_cells.h"

#include <utility>

#include "display/surface/mesh.h"

namespace dexmill {
namespace {

const int kDi[4] = {0, 1, 1, 0}, kDj[4] = {0, 0, 1, 1};

}  // namespace

template <class H>
SurfaceMaterial::SurfaceMaterial(const DexelGrid<H>& g)
    : nx_(g.nx), ny_(g.ny), bits_((static_cast<uint64_t>(g.nx) * static_cast<uint64_t>(g.ny) + 63) / 64) {
  for (int32_t j = 0; j < ny_; ++j)
    for (int32_t i = 0; i < nx_; ++i)
      if (!g.is_hole(i, j)) {
        const uint64_t k = static_cast<uint64_t>(j) * static_cast<uint64_t>(nx_) + static_cast<uint64_t>(i);
        bits_[k >> 6] |= uint64_t{1} << (k & 63);
      }
  // A dexel where two walls start (one on each side) is one dexel wide,
  // and one that is a corner of no top triangle holds no volume in the
  // surface, only walls, which would meet those of its other side face to
  // face (a fin two dexels long starts no two walls). Both are left out:
  // every dexel in row order, then the neighbours of each one left out,
  // until none is left (in this order: the surface is defined by it).
  std::vector<std::pair<int32_t, int32_t>> again;
  auto check = [&](int32_t i, int32_t j) {
    if (!at(i, j) || surrounded(i, j) || (wall_starts(i, j) <= 1 && under_top(i, j))) return;
    clear(i, j);
    for (int32_t dj = -1; dj <= 1; ++dj)
      for (int32_t di = -1; di <= 1; ++di)
        if ((di || dj) && i + di >= 0 && j + dj >= 0 && i + di < nx_ && j + dj < ny_) again.emplace_back(i + di, j + dj);
  };
  for (int32_t j = 0; j < ny_; ++j)
    for (int32_t i = 0; i < nx_; ++i) check(i, j);
  while (!again.empty()) {
    const std::pair<int32_t, int32_t> d = again.back();
    again.pop_back();
    check(d.first, d.second);
  }
}

bool SurfaceMaterial::surrounded(int32_t i, int32_t j) const {
  if (i < 1 || j < 1 || i + 1 >= nx_ || j + 1 >= ny_) return false;
  for (int32_t dj = -1; dj <= 1; ++dj)
    for (int32_t di = -1; di <= 1; ++di)
      if (!at(i + di, j + dj)) return false;
  return true;
}

bool SurfaceMaterial::under_top(int32_t i, int32_t j) const {
  for (int c = 0; c < 4; ++c) {
    const int32_t ci = i - kDi[c], cj = j - kDj[c];
    if (ci < 0 || cj < 0 || ci + 1 >= nx_ || cj + 1 >= ny_) continue;
    if (kCellCases[cell_mask(ci, cj)].ntop) return true;
  }
  return false;
}

int SurfaceMaterial::wall_starts(int32_t i, int32_t j) const {
  int starts = 0;
  for (int c = 0; c < 4; ++c) {  // the cells that have (i, j) as corner c
    const int32_t ci = i - kDi[c], cj = j - kDj[c];
    if (ci < 0 || cj < 0 || ci + 1 >= nx_ || cj + 1 >= ny_) continue;
    const CellCase& cc = kCellCases[cell_mask(ci, cj)];
    if (cc.has_wall && cc.wall[0] == c) ++starts;
  }
  return starts;
}

template <class H>
void cell_triangles(const DexelGrid<H>& g, int32_t i, int32_t j, int mask, unsigned parts, TriangleSink* out) {
  GridPoint top[4], bot[4];
  for (int c = 0; c < 4; ++c) {
    const int32_t ci = i + kDi[c], cj = j + kDj[c];
    const size_t k = g.index(ci, cj);
    top[c] = GridPoint{ci, cj, static_cast<int64_t>(g.top[k])};
    bot[c] = GridPoint{ci, cj, static_cast<int64_t>(g.bottom[k])};
  }
  const CellCase& cc = kCellCases[mask];
  for (int t = 0; t < cc.ntop; ++t) {
    const uint8_t* v = cc.top[t];
    if (parts & kCellTop) out->triangle(top[v[0]], top[v[1]], top[v[2]]);
    if (parts & kCellBottom) out->triangle(bot[v[0]], bot[v[2]], bot[v[1]]);
  }
  if (cc.has_wall && (parts & kCellWall)) {
    // The wall runs from a to b with the material on its left: its outward
    // side faces right, which these windings give.
    const int a = cc.wall[0], b = cc.wall[1];
    out->triangle(top[a], bot[a], bot[b]);
    out->triangle(top[a], bot[b], top[b]);
  }
}

template <class H>
void cell_surface(const DexelGrid<H>& g, const SurfaceMaterial& m, TriangleSink* out) {
  for (int32_t j = 0; j + 1 < g.ny; ++j)
    for (int32_t i = 0; i + 1 < g.nx; ++i)
      if (const int mask = m.cell_mask(i, j)) cell_triangles(g, i, j, mask, kCellAll, out);
}

#define DEXMILL_STL_CELLS_INSTANTIATE(H)                                                                 \
  template SurfaceMaterial::SurfaceMaterial(const DexelGrid<H>&);                                        \
  template void cell_triangles<H>(const DexelGrid<H>&, int32_t, int32_t, int, unsigned, TriangleSink*); \
  template void cell_surface<H>(const DexelGrid<H>&, const SurfaceMaterial&, TriangleSink*);
DEXMILL_STL_CELLS_INSTANTIATE(uint8_t)
DEXMILL_STL_CELLS_INSTANTIATE(uint16_t)
DEXMILL_STL_CELLS_INSTANTIATE(uint32_t)

}  // namespace dexmill
