// display/surface/redraw.h: tiles merged into rectangles, block height ranges.
#include <cstdint>
#include <vector>

#include "display/surface/redraw.h"
#include "tests/rng.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

TEST(tiles_merge_into_rectangles_that_cover_exactly_the_marks) {
  t::Rng rng(3);
  const int32_t w = 203, h = 117;  // not multiples of the tile side
  std::vector<uint8_t> flags(tile_count(w, h));
  TileMap tm;
  tm.flags = flags.data();
  tm.width = w;
  tm.height = h;
  tm.tiles_x = (w + kTileSide - 1) / kTileSide;
  tm.tiles_y = (h + kTileSide - 1) / kTileSide;
  for (int rep = 0; rep < 300; ++rep) {
    tiles_clear(&tm);
    std::vector<uint8_t> want(size_t(w) * h, 0);
    const int n = int(rng.range(0, rep % 3 == 0 ? 40 : 4));
    for (int k = 0; k < n; ++k) {
      const int32_t x0 = int32_t(rng.range(-10, w)), y0 = int32_t(rng.range(-10, h));
      const ScreenRect r{x0, y0, x0 + int32_t(rng.range(1, 60)), y0 + int32_t(rng.range(1, 40))};
      tiles_mark(&tm, r);
      // What a tile-granular cover must include: every tile the rectangle touches.
      const ScreenRect c = rect_intersect(r, ScreenRect{0, 0, w, h});
      if (c.empty()) continue;
      auto up = [](int32_t v) { return (v + kTileSide - 1) / kTileSide * kTileSide; };
      for (int32_t y = c.y0 / kTileSide * kTileSide; y < up(c.y1) && y < h; ++y)
        for (int32_t x = c.x0 / kTileSide * kTileSide; x < up(c.x1) && x < w; ++x) want[size_t(y) * w + x] = 1;
    }
    ScreenRect out[kMaxDirtyRects];
    const int m = tiles_rects(&tm, out, kMaxDirtyRects);
    CHECK_LE(m, kMaxDirtyRects);
    std::vector<uint8_t> got(size_t(w) * h, 0);
    bool overflow = m == kMaxDirtyRects;
    for (int k = 0; k < m; ++k) {
      CHECK(!out[k].empty());
      CHECK(out[k].x0 >= 0 && out[k].y0 >= 0 && out[k].x1 <= w && out[k].y1 <= h);
      for (int32_t y = out[k].y0; y < out[k].y1; ++y)
        for (int32_t x = out[k].x0; x < out[k].x1; ++x) ++got[size_t(y) * w + x];
    }
    int missing = 0, extra = 0;
    for (size_t q = 0; q < got.size(); ++q) {
      missing += want[q] && !got[q];
      extra += !want[q] && got[q];
      if (!overflow) CHECK_LE(int(got[q]), 1);  // disjoint unless merged on overflow
    }
    CHECK_EQ(missing, 0);
    if (!overflow) CHECK_EQ(extra, 0);
    for (uint8_t f : flags) CHECK_EQ(int(f), 0);
  }
}

TEST(block_heights_cover_tops_and_reachable_bottoms) {
  t::TestGrid<uint16_t> tg;
  t::make_block(&tg, 30, 20, kNmPerMm, 10 * kNmPerMm);
  DexelGrid<uint16_t>& g = tg.g;
  // An interior block of a fresh stock: all tops, no side faces.
  uint32_t lo, hi;
  block_heights(g, 1, 1, false, &lo, &hi);
  CHECK_EQ(lo, uint32_t(g.top[g.index(10, 10)]));
  CHECK_EQ(hi, lo);
  // With bottoms drawn, or next to a hole, the range reaches the bottoms.
  block_heights(g, 1, 1, true, &lo, &hi);
  CHECK_EQ(lo, 0u);
  g.top[g.index(17, 12)] = 0;  // a hole just outside block (1, 1)'s dexels 8..16
  block_heights(g, 1, 1, false, &lo, &hi);
  CHECK_EQ(lo, 0u);
  // A block of holes only is empty.
  for (int32_t j = 0; j < g.ny; ++j)
    for (int32_t i = 0; i < g.nx; ++i) g.top[g.index(i, j)] = 0;
  block_heights(g, 0, 0, false, &lo, &hi);
  CHECK_GT(lo, hi);
}
