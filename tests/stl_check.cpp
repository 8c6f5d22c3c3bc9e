// Exact mesh checks for the STL tests; see stl_check.h.
#include "tests/stl_check.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "display/surface/mesh.h"

namespace t {

void TriangleList::triangle(const dexmill::GridPoint& a, const dexmill::GridPoint& b, const dexmill::GridPoint& c) {
  IntTri t{};
  const dexmill::GridPoint* p[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    t.v[k][0] = p[k]->i;
    t.v[k][1] = p[k]->j;
    t.v[k][2] = p[k]->h_lsb;
  }
  tris.push_back(t);
}

MeshFacts mesh_facts(const std::vector<IntTri>& tris) {
  using P = std::array<int64_t, 3>;
  MeshFacts f;
  std::map<std::pair<P, P>, int> edges;
  std::set<P> points;
  for (const IntTri& t : tris) {
    P p[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = P{t.v[k][0], t.v[k][1], t.v[k][2]};
      points.insert(p[k]);
    }
    for (int k = 0; k < 3; ++k) ++edges[{p[k], p[(k + 1) % 3]}];
    const int64_t u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const int64_t w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    if (u[1] * w[2] - u[2] * w[1] == 0 && u[2] * w[0] - u[0] * w[2] == 0 && u[0] * w[1] - u[1] * w[0] == 0) ++f.flat_tris;
    // det(a, b, c): the signed volume of the tetrahedron with the origin, x6.
    f.volume6 += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                 p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  for (const auto& e : edges) {
    const auto r = edges.find({e.first.second, e.first.first});
    if (e.second != 1 || r == edges.end() || r->second != 1) ++f.open_edges;
  }
  f.euler = static_cast<int64_t>(points.size()) - static_cast<int64_t>(edges.size() / 2) + static_cast<int64_t>(tris.size());
  return f;
}

template <class H>
int64_t cell_volume6(const dexmill::DexelGrid<H>& g, const dexmill::SurfaceMaterial& m) {
  const int kDi[4] = {0, 1, 1, 0}, kDj[4] = {0, 0, 1, 1};
  int64_t v6 = 0;
  for (int32_t j = 0; j + 1 < g.ny; ++j)
    for (int32_t i = 0; i + 1 < g.nx; ++i) {
      const dexmill::CellCase& cc = dexmill::kCellCases[m.cell_mask(i, j)];
      for (int t = 0; t < cc.ntop; ++t)
        for (int k = 0; k < 3; ++k) {
          const size_t d = g.index(i + kDi[cc.top[t][k]], j + kDj[cc.top[t][k]]);
          v6 += static_cast<int64_t>(g.top[d]) - static_cast<int64_t>(g.bottom[d]);
        }
    }
  return v6;
}

template int64_t cell_volume6<uint16_t>(const dexmill::DexelGrid<uint16_t>&, const dexmill::SurfaceMaterial&);
template int64_t cell_volume6<uint32_t>(const dexmill::DexelGrid<uint32_t>&, const dexmill::SurfaceMaterial&);

}  // namespace t
