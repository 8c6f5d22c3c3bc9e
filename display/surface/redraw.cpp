// Grid blocks and screen tiles for incremental redraw (see redraw.h).
#include "display/surface/redraw.h"

#include "display/raster/clip.h"

namespace dexmill {

template <class H>
void block_heights(const DexelGrid<H>& g, int32_t bx, int32_t by, bool bottoms, uint32_t* zlo, uint32_t* zhi) {
  const GridRect c = block_cells(g, bx, by);
  // Dexels of the block's cells: [c.i0, c.i1] x [c.j0, c.j1].
  if (!bottoms) {
    // Side faces start at a material dexel of a cell with a hole corner: a
    // hole within one dexel of the block's dexels.
    const int32_t i0 = max_of<int32_t>(c.i0 - 1, 0), i1 = min_of<int32_t>(c.i1 + 1, g.nx - 1);
    const int32_t j0 = max_of<int32_t>(c.j0 - 1, 0), j1 = min_of<int32_t>(c.j1 + 1, g.ny - 1);
    for (int32_t j = j0; j <= j1 && !bottoms; ++j) {
      const H* t = g.top + g.index(0, j);
      const H* b = g.bottom + g.index(0, j);
      for (int32_t i = i0; i <= i1; ++i) {
        if ((t[i] | b[i]) == 0) {
          bottoms = true;
          break;
        }
      }
    }
  }
  uint32_t lo = UINT32_MAX, hi = 0;
  bool any = false;
  for (int32_t j = c.j0; j <= c.j1; ++j) {
    const H* t = g.top + g.index(0, j);
    const H* b = g.bottom + g.index(0, j);
    for (int32_t i = c.i0; i <= c.i1; ++i) {
      if ((t[i] | b[i]) == 0) continue;
      any = true;
      const uint32_t low = bottoms ? b[i] : t[i];
      lo = low < lo ? low : lo;
      hi = t[i] > hi ? t[i] : hi;
    }
  }
  *zlo = any ? lo : 1;
  *zhi = any ? hi : 0;
}

ScreenRect box_rect(const View& v, int32_t i0, int32_t j0, int32_t i1, int32_t j1, int64_t zlo, int64_t zhi,
                    int32_t width, int32_t height) {
  const ScreenRect all{0, 0, width, height};
  int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  const AffineQ32& a = v.grid;
  for (int c = 0; c < 8; ++c) {
    const int64_t i = (c & 1) ? i1 : i0, j = (c & 2) ? j1 : j0, h = (c & 4) ? zhi : zlo;
    int64_t o[3];
    for (int k = 0; k < 3; ++k) o[k] = (a.m[k][0] * i + a.m[k][1] * j + a.m[k][2] * h + a.c[k]) >> 32;
    if (clip_outcode(v.proj, o[0], o[1], o[2])) return all;
    ClipVertex cv{o[0], o[1], v.proj.kind == Projection::kOrthographic ? 1 : o[2], static_cast<int32_t>(o[2]), 0};
    const RasterVertex r = clip_project(v.proj, cv);
    x0 = min_of<int64_t>(x0, r.x_q4);
    y0 = min_of<int64_t>(y0, r.y_q4);
    x1 = max_of<int64_t>(x1, r.x_q4);
    y1 = max_of<int64_t>(y1, r.y_q4);
  }
  const ScreenRect r{static_cast<int32_t>((x0 >> kSubpixelBits) - 1), static_cast<int32_t>((y0 >> kSubpixelBits) - 1),
                     static_cast<int32_t>((x1 >> kSubpixelBits) + 2), static_cast<int32_t>((y1 >> kSubpixelBits) + 2)};
  return rect_intersect(r, all);
}

void tiles_clear(TileMap* t) {
  const size_t n = static_cast<size_t>(t->tiles_x) * static_cast<size_t>(t->tiles_y);
  for (size_t k = 0; k < n; ++k) t->flags[k] = 0;
  t->ty0 = t->tiles_y;
  t->ty1 = 0;
}

void tiles_mark(TileMap* t, const ScreenRect& r0) {
  const ScreenRect r = rect_intersect(r0, ScreenRect{0, 0, t->width, t->height});
  if (r.empty()) return;
  const int32_t tx0 = r.x0 / kTileSide, tx1 = (r.x1 - 1) / kTileSide;
  const int32_t ty0 = r.y0 / kTileSide, ty1 = (r.y1 - 1) / kTileSide;
  for (int32_t ty = ty0; ty <= ty1; ++ty)
    for (int32_t tx = tx0; tx <= tx1; ++tx) t->flags[static_cast<size_t>(ty) * t->tiles_x + tx] = 1;
  t->ty0 = min_of(t->ty0, ty0);
  t->ty1 = max_of(t->ty1, ty1 + 1);
}

int tiles_rects(TileMap* t, ScreenRect* out, int max) {
  int n = 0;
  ScreenRect rest{0, 0, 0, 0};
  const ScreenRect frame{0, 0, t->width, t->height};
  for (int32_t ty = t->ty0; ty < t->ty1; ++ty) {
    uint8_t* row = t->flags + static_cast<size_t>(ty) * t->tiles_x;
    for (int32_t tx = 0; tx < t->tiles_x; ++tx) {
      if (!row[tx]) continue;
      int32_t ex = tx;
      while (ex < t->tiles_x && row[ex]) ++ex;  // run [tx, ex)
      // Extend down while the next row holds the same run, bounded by
      // unmarked tiles on both sides.
      int32_t ey = ty + 1;
      for (; ey < t->ty1; ++ey) {
        const uint8_t* next = t->flags + static_cast<size_t>(ey) * t->tiles_x;
        bool same = (tx == 0 || !next[tx - 1]) && (ex == t->tiles_x || !next[ex]);
        for (int32_t x = tx; x < ex && same; ++x) same = next[x] != 0;
        if (!same) break;
      }
      for (int32_t y = ty; y < ey; ++y)
        for (int32_t x = tx; x < ex; ++x) t->flags[static_cast<size_t>(y) * t->tiles_x + x] = 0;
      const ScreenRect r = rect_intersect(ScreenRect{tx * kTileSide, ty * kTileSide, ex * kTileSide, ey * kTileSide}, frame);
      if (n < max - 1) out[n++] = r;
      else rest = rect_union(rest, r);
      tx = ex - 1;
    }
  }
  if (!rest.empty()) out[n++] = rest;
  t->ty0 = t->tiles_y;
  t->ty1 = 0;
  return n;
}

template void block_heights<uint8_t>(const DexelGrid<uint8_t>&, int32_t, int32_t, bool, uint32_t*, uint32_t*);
template void block_heights<uint16_t>(const DexelGrid<uint16_t>&, int32_t, int32_t, bool, uint32_t*, uint32_t*);
template void block_heights<uint32_t>(const DexelGrid<uint32_t>&, int32_t, int32_t, bool, uint32_t*, uint32_t*);

}  // namespace dexmill
