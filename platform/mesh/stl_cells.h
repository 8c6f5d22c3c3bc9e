// The workpiece's closed surface as the STL gives it, cell by cell: the
// display's cells (display/surface/mesh.h, kCellCases) over four neighbouring
// dexels: top triangles at the dexels' tops, the same triangles turned over
// at their bottoms, and side walls where material meets holes (the stock's
// border dexels are holes, so the outer walls come from the same rule).
// Every edge is shared by exactly two triangles with opposite directions
// (consistently outward normals). platform/mesh/stl_merge.h writes the same
// surface with coplanar cells merged; this one-or-two-triangles-a-cell form
// is its definition and the tests' reference.
//
// Material one dexel wide has no width in that surface (its two walls would
// meet on the dexel's axis, where the vertical edge would be shared by four
// triangles, or face each other) and is left out, so the solid is
// 2-manifold; it holds no volume in the surface either way.
#ifndef DEXMILL_PLATFORM_MESH_STL_CELLS_H
#define DEXMILL_PLATFORM_MESH_STL_CELLS_H

#include <cstdint>
#include <vector>

#include "core/grid/grid.h"

namespace dexmill {

// A vertex: the axis of dexel (i, j) at height h_lsb.
struct GridPoint {
  int32_t i, j;
  int64_t h_lsb;
};

// Receives triangles, counterclockwise seen from outside the material.
class TriangleSink {
 public:
  virtual void triangle(const GridPoint& a, const GridPoint& b, const GridPoint& c) = 0;

 protected:
  ~TriangleSink() = default;
};

// Which dexels the surface treats as material: the grid's non-holes less
// the one-dexel-wide features (above), one bit a dexel.
class SurfaceMaterial {
 public:
  template <class H>
  explicit SurfaceMaterial(const DexelGrid<H>& g);
  bool at(int32_t i, int32_t j) const {
    const uint64_t k = static_cast<uint64_t>(j) * static_cast<uint64_t>(nx_) + static_cast<uint64_t>(i);
    return (bits_[k >> 6] >> (k & 63)) & 1u;
  }
  // kCellCases' index of cell (i, j): bit c set when corner c is material.
  int cell_mask(int32_t i, int32_t j) const {
    return at(i, j) | at(i + 1, j) << 1 | at(i + 1, j + 1) << 2 | at(i, j + 1) << 3;
  }

 private:
  void clear(int32_t i, int32_t j) {
    const uint64_t k = static_cast<uint64_t>(j) * static_cast<uint64_t>(nx_) + static_cast<uint64_t>(i);
    bits_[k >> 6] &= ~(uint64_t{1} << (k & 63));
  }
  int wall_starts(int32_t i, int32_t j) const;  // walls of its cells that start at dexel (i, j)
  bool under_top(int32_t i, int32_t j) const;   // dexel (i, j) is a corner of a top triangle
  bool surrounded(int32_t i, int32_t j) const;  // its eight neighbours are material: it stays
  int32_t nx_, ny_;
  std::vector<uint64_t> bits_;
};

// What of a cell to emit.
enum CellPart : unsigned { kCellTop = 1, kCellBottom = 2, kCellWall = 4, kCellAll = 7 };

// The triangles of cell (i, j) with corner mask `mask`, those of `parts`.
template <class H>
void cell_triangles(const DexelGrid<H>& g, int32_t i, int32_t j, int mask, unsigned parts, TriangleSink* out);

// Every cell's triangles, unmerged.
template <class H>
void cell_surface(const DexelGrid<H>& g, const SurfaceMaterial& m, TriangleSink* out);

}  // namespace dexmill

#endif
