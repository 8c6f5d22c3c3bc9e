// Exact mesh checks for the STL tests; see stl_check.h.
#include "tests/stl_check.h"

#include <algorithm>
#include <array>
#include <cmath>
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

template <class H>
TopError top_error(const std::vector<IntTri>& tris, const dexmill::DexelGrid<H>& g, const dexmill::SurfaceMaterial& m) {
  TopError e;
  std::vector<uint8_t> covered(static_cast<size_t>(g.nx) * g.ny, 0);
  for (const IntTri& t : tris) {
    const int64_t* a = t.v[0];
    const int64_t* b = t.v[1];
    const int64_t* c = t.v[2];
    const int64_t area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (area2 <= 0) continue;  // a wall, or a bottom
    e.area2 += area2;
    const int64_t i0 = std::min({a[0], b[0], c[0]}), i1 = std::max({a[0], b[0], c[0]});
    const int64_t j0 = std::min({a[1], b[1], c[1]}), j1 = std::max({a[1], b[1], c[1]});
    for (int64_t j = j0; j <= j1; ++j)
      for (int64_t i = i0; i <= i1; ++i) {
        // Barycentric weights times area2, exact; inside (or on a side)
        // when all are >= 0.
        const int64_t wa = (b[0] - i) * (c[1] - j) - (b[1] - j) * (c[0] - i);
        const int64_t wb = (c[0] - i) * (a[1] - j) - (c[1] - j) * (a[0] - i);
        const int64_t wc = area2 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        const double z = (static_cast<double>(wa) * a[2] + static_cast<double>(wb) * b[2] + static_cast<double>(wc) * c[2]) /
                         static_cast<double>(area2);
        const size_t d = g.index(static_cast<int32_t>(i), static_cast<int32_t>(j));
        e.max_lsb = std::max(e.max_lsb, std::fabs(z - static_cast<double>(g.top[d])));
        covered[d] = 1;
      }
  }
  for (int32_t j = 0; j + 1 < g.ny; ++j)
    for (int32_t i = 0; i + 1 < g.nx; ++i)
      if (m.cell_mask(i, j) == 15)
        for (int k = 0; k < 4; ++k) e.uncovered += !covered[g.index(i + (k & 1), j + (k >> 1))];
  return e;
}

template TopError top_error<uint16_t>(const std::vector<IntTri>&, const dexmill::DexelGrid<uint16_t>&,
                                      const dexmill::SurfaceMaterial&);
template TopError top_error<uint32_t>(const std::vector<IntTri>&, const dexmill::DexelGrid<uint32_t>&,
                                      const dexmill::SurfaceMaterial&);
template int64_t cell_volume6<uint16_t>(const dexmill::DexelGrid<uint16_t>&, const dexmill::SurfaceMaterial&);
template int64_t cell_volume6<uint32_t>(const dexmill::DexelGrid<uint32_t>&, const dexmill::SurfaceMaterial&);

}  // namespace t
