// What an incremental redraw must repaint.
//
// Grid blocks: the cells are grouped in blocks of kBlockCells x kBlockCells;
// each block keeps the lowest and highest height its geometry can reach and
// the screen rectangle of that box, so a pass over the screen visits only the
// blocks that can touch it. After a cut, the screen area that changed is the
// box of the changed cells (the grid's dirty rectangle widened by the reach
// of the normals) between the lowest and highest heights of their blocks
// before and after the cut, plus the cutter's old and new boxes.
//
// Screen tiles: those areas mark kTileSide-pixel tiles, and the marked tiles
// are merged into at most kMaxDirtyRects rectangles, each cleared and redrawn
// on its own, and each handed to the platform's present().
#ifndef DEXMILL_DISPLAY_SURFACE_REDRAW_H
#define DEXMILL_DISPLAY_SURFACE_REDRAW_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "display/raster/camera.h"
#include "display/raster/framebuffer.h"
#include "display/surface/mesh.h"

namespace dexmill {

// Per block: the height range of its geometry (zlo > zhi: nothing to draw)
// and the pixels that geometry can cover.
struct BlockInfo {
  uint32_t zlo_lsb, zhi_lsb;
  int16_t x0, y0, x1, y1;  // ScreenRect, half-open
};

inline int32_t blocks_across(int32_t n_dexels) { return (n_dexels - 1 + kBlockCells - 1) / kBlockCells; }

// Cells of block (bx, by).
template <class H>
GridRect block_cells(const DexelGrid<H>& g, int32_t bx, int32_t by) {
  return GridRect{bx * kBlockCells, by * kBlockCells, min_of(bx * kBlockCells + kBlockCells, g.nx - 1),
                  min_of(by * kBlockCells + kBlockCells, g.ny - 1)};
}

// The height range of block (bx, by)'s geometry: tops, and bottoms where side
// faces can reach them (a hole in or next to the block) or when bottom faces
// are drawn.
template <class H>
void block_heights(const DexelGrid<H>& g, int32_t bx, int32_t by, bool bottoms, uint32_t* zlo, uint32_t* zhi);

// The pixels of the box of dexels [i0, i1] x [j0, j1] (inclusive) between
// heights zlo and zhi: the bounding rectangle of its eight projected corners
// plus one pixel, clipped to the frame; the whole frame when a corner leaves
// the guard band or the near plane.
ScreenRect box_rect(const View& v, int32_t i0, int32_t j0, int32_t i1, int32_t j1, int64_t zlo, int64_t zhi,
                    int32_t width, int32_t height);

constexpr int32_t kTileSide = 4;
constexpr int kMaxDirtyRects = 32;

struct TileMap {
  uint8_t* flags = nullptr;  // tiles_x * tiles_y, caller memory
  int32_t tiles_x = 0, tiles_y = 0;
  int32_t width = 0, height = 0;
  int32_t ty0 = 0, ty1 = 0;  // rows that may hold marks: [ty0, ty1)
};

inline size_t tile_count(int32_t width, int32_t height) {
  return static_cast<size_t>((width + kTileSide - 1) / kTileSide) * static_cast<size_t>((height + kTileSide - 1) / kTileSide);
}

void tiles_clear(TileMap* t);
void tiles_mark(TileMap* t, const ScreenRect& r);
// Merges the marked tiles into rectangles (clipped to the frame) and clears
// the marks: runs of marked tiles in a row, extended downwards over rows with
// the same run. Beyond `max` rectangles the rest go into one bounding
// rectangle (which may overlap earlier ones). Returns the count.
int tiles_rects(TileMap* t, ScreenRect* out, int max);

#define DEXMILL_REDRAW_EXTERN(H) \
  extern template void block_heights<H>(const DexelGrid<H>&, int32_t, int32_t, bool, uint32_t*, uint32_t*);
DEXMILL_REDRAW_EXTERN(uint8_t)
DEXMILL_REDRAW_EXTERN(uint16_t)
DEXMILL_REDRAW_EXTERN(uint32_t)
#undef DEXMILL_REDRAW_EXTERN

}  // namespace dexmill

#endif
