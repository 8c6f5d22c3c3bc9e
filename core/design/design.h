// The design part as a dexel set D_D on the workpiece's own grid (paper
// §2.5: the assessment compares D_W with D_D dexel by dexel). One design top
// per column, in the workpiece grid's LSB above its z0: the highest point
// where the vertical line through the dexel's axis meets the design;
// kNoDesign where it misses the design. Caller memory, like the grid: a
// panel without the memory for it simply does not assess.
//
// Two sources: triangles (an STL mesh, vertices already integer nm: the
// floats end in platform/) and height samples (a PGM image stretched over
// the stock's XY). Integer only, no heap.
#ifndef DEXMILL_CORE_DESIGN_DESIGN_H
#define DEXMILL_CORE_DESIGN_DESIGN_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/point.h"
#include "core/status.h"

namespace dexmill {

// A column with no design material.
constexpr int32_t kNoDesign = INT32_MIN;

// Vertices, and the grid's extent, must lie within +-(2^30 - 1) nm (1.07 m)
// of the grid's origin (x0, y0, z0): a coordinate difference is then below
// 2^31 in magnitude, each product of two below 2^62, and an edge function
// (a difference of two products) fits int64 exactly.
constexpr int64_t kDesignRangeNm = (static_cast<int64_t>(1) << 30) - 1;

struct DesignGrid {
  GridGeometry geo{};         // the workpiece grid's geometry
  int32_t* top_lsb = nullptr;  // caller memory of nx*ny: design top, LSB above z0, or kNoDesign
  uint64_t triangles = 0;     // triangles added (for the report)
  uint64_t triangles_vertical = 0;  // of which vertical in XY (no top of their own)

  size_t index(int32_t i, int32_t j) const { return static_cast<size_t>(j) * static_cast<size_t>(geo.nx) + static_cast<size_t>(i); }
};

struct TriangleNm {
  PointNm v[3];  // machine coordinates, nm
};

// Points d at `mem` (`cells` entries) for grid geometry `geo`, every column
// kNoDesign. kBufferTooSmall when cells < nx*ny; kOutOfRange when the grid
// is wider than kDesignRangeNm.
Status design_init(DesignGrid* d, const GridGeometry& geo, int32_t* mem, size_t cells);

// Raises the design top of each column whose axis passes through the
// triangle's XY projection (edges included, so a column on an edge shared by
// two triangles gets the higher of the two: the same z) to the triangle's z
// there. Triangles vertical in XY add nothing (their edges are the
// neighbours' edges). Error bound: the stored top is within 0.5 LSB + 2 nm of
// the exact height of the triangle (its integer-nm vertices) over the axis;
// which columns are inside is decided exactly. kOutOfRange (nothing changed)
// when a vertex lies beyond kDesignRangeNm of the grid's origin.
Status design_add_triangle(DesignGrid* d, const TriangleNm& t);

// A height image over a rectangle of machine XY (the stock's): `w` x `h`
// samples, row 0 at the largest Y (as images are read), sample s mapping to
// z_low + (z_high - z_low) * s / maxval, rounded to the nearest nm. Each
// column whose axis lies inside [x0, x1] x [y0, y1] takes the sample whose
// pixel covers it (pixel k spans [x0 + k (x1 - x0) / w, x0 + (k + 1) (x1 -
// x0) / w)); columns outside get kNoDesign. kBadArgument on an empty
// rectangle or image, or maxval 0.
struct HeightImage {
  const uint16_t* samples;
  int32_t w, h;
  uint32_t maxval;
};
Status design_from_image(DesignGrid* d, const HeightImage& img, int64_t x0_nm, int64_t y0_nm, int64_t x1_nm,
                         int64_t y1_nm, int64_t z_low_nm, int64_t z_high_nm);

// The design as a dexel grid, to draw it (display/overlay/overlay.h): `g`, set up by
// grid_init with the design's geometry, gets tops clamped to [1, 2^m - 1]
// and bottoms 0; columns without design material, and those outside
// `region` (a run's ring of holes around the stock), become holes.
template <class H>
void design_to_grid(const DesignGrid& d, GridRect region, DexelGrid<H>* g);

extern template void design_to_grid<uint8_t>(const DesignGrid&, GridRect, DexelGrid<uint8_t>*);
extern template void design_to_grid<uint16_t>(const DesignGrid&, GridRect, DexelGrid<uint16_t>*);
extern template void design_to_grid<uint32_t>(const DesignGrid&, GridRect, DexelGrid<uint32_t>*);

// Columns with design material.
uint64_t design_columns(const DesignGrid& d);

}  // namespace dexmill

#endif
