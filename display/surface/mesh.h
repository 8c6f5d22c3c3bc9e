// Surface extraction, paper §2.4 and figure 5: triangles streamed from the
// dexel grid to the rasterizer, cell by cell; nothing stores the mesh.
//
// A cell is the square of four neighbouring dexels c0 = (i, j),
// c1 = (i+1, j), c2 = (i+1, j+1), c3 = (i, j+1). Each corner is a hole
// (top = bottom = 0) or material, and the four bits index a table:
//   four material: two top triangles (c0 c1 c2, c0 c2 c3);
//   three material: the top triangle of the three, and a side face along the
//     diagonal facing the hole corner (45 degree walls, §2.4.1);
//   two material sharing an edge: a side face along that edge facing the
//     holes;
//   two on a diagonal, one, none: nothing (the paper's "dissolves into basic
//     cases": the neighbouring cells close the surface).
// Side faces run from the two dexels' tops down to their bottoms. Every edge
// of the top surface that borders no top area of the next cell gets a side
// face, so the surface is closed: with grid_block_stock's hole border, the
// stock's outer walls come out of the same table. Seen from below (when the
// camera can), the tops' triangles are drawn again at the bottoms, turned
// over.
#ifndef DEXMILL_DISPLAY_SURFACE_MESH_H
#define DEXMILL_DISPLAY_SURFACE_MESH_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "display/raster/camera.h"
#include "display/raster/raster.h"
#include "display/surface/shade.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

// One row of the marching-squares table: corner indices 0..3, front faces
// counterclockwise seen from outside the material.
struct CellCase {
  uint8_t ntop;        // top triangles: 0, 1 or 2
  uint8_t top[2][3];
  uint8_t has_wall;    // a side face from corner wall[0] to wall[1] (left to right seen from the hole)
  uint8_t wall[2];
};
// Indexed by mask = c0 | c1 << 1 | c2 << 2 | c3 << 3 (bit set: material).
extern const CellCase kCellCases[16];

// What a pass over cells draws with.
template <class H>
struct MeshPass {
  const DexelGrid<H>* grid = nullptr;
  const View* view = nullptr;
  const ShadeCache* shades = nullptr;
  int32_t bottom_shade = 0;  // faces pointing down
  bool bottoms = false;      // draw bottom faces
  RasterTarget* target = nullptr;
  const SurfaceColours* colours = nullptr;  // per-dexel classes, or null: target's lut throughout
  // With colours->texture: the frame's lighting for colours per vertex (the
  // target's vertex_rgb is then set).
  const LitRamp* lit = nullptr;
};

// Block size in cells: the unit of incremental redraw (display/surface/redraw.h).
constexpr int32_t kBlockCells = 8;

// Draws the cells [c.i0, c.i1) x [c.j0, c.j1) (at most kBlockCells each way),
// rows in descending j when j_desc, columns in descending i when i_desc.
// With `cull` (the cells straddle the clip rectangle's edge), cells that
// cannot reach the clip are skipped early: per row, those whose box between
// heights zlo and zhi (bounds of every height the cells draw) projects
// outside it (orthographic views), and cells of top triangles holding no
// pixel centre inside it. The picture is the same either way.
template <class H>
void mesh_draw_cells(const MeshPass<H>& p, GridRect c, bool i_desc, bool j_desc, bool cull, uint32_t zlo, uint32_t zhi);

extern template void mesh_draw_cells<uint8_t>(const MeshPass<uint8_t>&, GridRect, bool, bool, bool, uint32_t,
                                                uint32_t);
extern template void mesh_draw_cells<uint16_t>(const MeshPass<uint16_t>&, GridRect, bool, bool, bool, uint32_t,
                                                uint32_t);
extern template void mesh_draw_cells<uint32_t>(const MeshPass<uint32_t>&, GridRect, bool, bool, bool, uint32_t,
                                                uint32_t);

}  // namespace dexmill

#endif
