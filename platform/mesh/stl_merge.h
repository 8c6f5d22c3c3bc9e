// The STL surface (platform/mesh/stl_cells.h) with coplanar cells merged, as
// triangles streamed row by row: the same solid to the last bit, in far
// fewer triangles where the work is flat.
//
// Faces:
// - a top rectangle: cells whose four tops are equal, a maximal run of them
//   along a cell row, continued up through the rows whose run has the same
//   ends and height; the bottoms the same way;
// - a wall strip: the wall quads of consecutive cells along one grid line,
//   facing the same way, with one top and one bottom height along it (only
//   then is the strip a rectangle), higher than the bottom;
// - everything else (sloped cells, walls along diagonals or under sloped
//   tops) stays one or two triangles a cell, as in the cell surface.
//
// Why it stays watertight: a grid point on a face's side is left out of the
// face's polygon exactly when the faces across the two side segments it
// joins are one and the same merged face. Then the two faces meet along a
// straight line through it and nothing else touches it, so the other face
// leaves it out too (the rule reads the same pair of segments from either
// side); every other point, a corner of either face or of anything else
// there, is kept by both. So the side between two kept points is one edge
// in both faces' polygons, with the same two ends, run in opposite
// directions, and platform/mesh/stl_ladder.h triangulates each polygon with no
// point on a triangle's edge. Faces across a segment are known from the
// cells on both sides of it, so three cell rows decide everything.
//
// With a tolerance of more than one LSB the tops merge within it instead:
// nearly planar rectangles (platform/mesh/stl_plane.h: every dexel top
// within the tolerance of the surface written over it), whose points keep
// their own tops, so the rule above still holds: the same point left out
// or kept on both sides, at the same height. Bottoms and walls as above.
//
// Memory: the surface material (one bit a dexel), three rows of cell
// classes, and one face state per place along the row.
#ifndef DEXMILL_PLATFORM_MESH_STL_MERGE_H
#define DEXMILL_PLATFORM_MESH_STL_MERGE_H

#include "core/grid/grid.h"
#include "platform/mesh/stl_cells.h"

namespace dexmill {

// tolerance_lsb <= 1: the exact surface (level faces only).
template <class H>
void merged_surface(const DexelGrid<H>& g, const SurfaceMaterial& m, int64_t tolerance_lsb, TriangleSink* out);

}  // namespace dexmill

#endif
