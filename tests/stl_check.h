// Checks of a triangle mesh in exact integers, for the STL tests: every
// directed edge once with its reverse once (closed, consistently oriented,
// no T-junction), no triangle without area, six times the enclosed volume,
// and the Euler characteristic.
#ifndef DEXMILL_TESTS_STL_CHECK_H
#define DEXMILL_TESTS_STL_CHECK_H

#include <cstdint>
#include <vector>

#include "core/grid/grid.h"
#include "platform/mesh/stl_cells.h"

namespace t {

// A triangle with integer coordinates (grid units or nm).
struct IntTri {
  int64_t v[3][3];
};

// Collects what a surface emits, in grid units (i, j, h_lsb).
class TriangleList final : public dexmill::TriangleSink {
 public:
  void triangle(const dexmill::GridPoint& a, const dexmill::GridPoint& b, const dexmill::GridPoint& c) override;
  std::vector<IntTri> tris;
};

struct MeshFacts {
  long open_edges = 0;   // directed edges without exactly one reverse, or doubled
  long flat_tris = 0;    // triangles of zero area
  int64_t volume6 = 0;   // six times the enclosed volume, in the coordinates' units cubed
  int64_t euler = 0;     // vertices - edges + faces
};
MeshFacts mesh_facts(const std::vector<IntTri>& tris);

// Six times the cell surface's volume in grid units (pitch^2 x LSB),
// straight from the grid: each top triangle of a cell covers half a cell,
// so it adds the sum of its three tops; each bottom one takes its bottoms.
template <class H>
int64_t cell_volume6(const dexmill::DexelGrid<H>& g, const dexmill::SurfaceMaterial& m);

// How far the top surface of `tris` (the triangles facing up, seen from
// above) lies from the grid's tops, in LSB, by double-precision
// interpolation at every dexel a top triangle covers (its sides too); and
// how many dexels of full cells (four material corners) none covers.
struct TopError {
  double max_lsb = 0;
  long uncovered = 0;
  int64_t area2 = 0;  // twice the top triangles' area seen from above, in cells
};
template <class H>
TopError top_error(const std::vector<IntTri>& tris, const dexmill::DexelGrid<H>& g, const dexmill::SurfaceMaterial& m);

}  // namespace t

#endif
