// The top faces of the STL surface merged within a height tolerance
// (--stl-tolerance): cell rectangles that are nearly planar, as the merged
// surface (platform/mesh/stl_merge.h) writes them in place of its level
// rectangles when the tolerance is more than one LSB.
//
// A face: a rectangle of full cells (four material corners), grown
// greedily: a run along a cell row, extended cell by cell while it fits,
// then up through the rows while the whole rectangle still fits; a
// rectangle that cannot go on ends, and the row's cells it does not hold
// start new runs. At most kPlaneSideCells a side, so the refit after each
// step stays cheap.
//
// Fits: with the slopes of the rectangle's four corner tops (the mean of
// its two x differences, of its two y differences), every dexel top T of
// the rectangle (all (w + 1) x (h + 1) of them, the sides and corners
// too) lies within one band P - tol/2 <= T <= P + tol/2 of a plane P of
// those slopes (max - min of T - slopes <= tol, in exact integers). And
// its smallest top is above its largest bottom.
//
// The error bound: every written vertex is a dexel at its own top, and
// each triangle of the face has three of the face's dexels as corners, so
// the surface over the face lies in the band too (between its corners'
// heights); a top there is in the band, so it is within tol of the
// surface written over it. A point a face leaves out of its side is in
// both faces' bands, on the edge they share. The exact cell surface lies
// in the same band, so the volume moves by at most tol times the top area,
// and the top never reaches the bottom (its lowest point is a top of the
// face, above every bottom under it).
#ifndef DEXMILL_PLATFORM_MESH_STL_PLANE_H
#define DEXMILL_PLATFORM_MESH_STL_PLANE_H

#include <cstdint>
#include <vector>

#include "core/grid/grid.h"
#include "platform/mesh/stl_cells.h"

namespace dexmill {

constexpr int32_t kPlaneSideCells = 128;

// A rectangle of cells [lo, hi) from cell row j0 on.
struct PlaneRect {
  int32_t lo, hi, j0;
};

template <class H>
class PlaneRuns {
 public:
  PlaneRuns(const DexelGrid<H>& g, int64_t tolerance_lsb) : g_(g), tolerance_lsb_(tolerance_lsb) {}
  // Cell row j's top faces, the rows before it given in order: for each
  // cell the face's run [lo, hi) and first row j0 (lo -1 for none). `mask`
  // holds the row's kCellCases indices.
  void row(int32_t j, const std::vector<uint8_t>& mask, std::vector<int32_t>* lo, std::vector<int32_t>* hi,
           std::vector<int64_t>* j0);
  // The dexel tops of [lo, hi] x [j0, j1] fit one band (above).
  bool fits(int32_t lo, int32_t hi, int32_t j0, int32_t j1) const;

 private:
  int64_t top(int32_t i, int32_t j) const { return static_cast<int64_t>(g_.top[g_.index(i, j)]); }
  const DexelGrid<H>& g_;
  int64_t tolerance_lsb_;
  std::vector<PlaneRect> open_, next_;  // the faces through the last row, by lo; those through this one
};

// Lifts a planar face's points (written at height 0 by its ladder) to
// their dexels' tops.
template <class H>
class TopLift final : public TriangleSink {
 public:
  TopLift(const DexelGrid<H>& g, TriangleSink* out) : g_(g), out_(out) {}
  void triangle(const GridPoint& a, const GridPoint& b, const GridPoint& c) override {
    out_->triangle(lift(a), lift(b), lift(c));
  }

 private:
  GridPoint lift(GridPoint p) const {
    p.h_lsb = static_cast<int64_t>(g_.top[g_.index(p.i, p.j)]);
    return p;
  }
  const DexelGrid<H>& g_;
  TriangleSink* out_;
};

}  // namespace dexmill

#endif
