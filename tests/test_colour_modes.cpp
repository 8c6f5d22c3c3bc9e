// The colour modes tool, slope and thin (display/colour/tool_colours.h,
// slope_colours.h, thin_colours.h) on hand-made grids: a dexel cut by T2 is
// T2's, one cut by T1 and then T2 too, untouched stock uncut, a hole's rim
// its drill's; the palette wraps at 8 tools; slopes land in their bands on
// both sides of every limit (against std::tan); floors under the thin limit
// are highlighted and those over it not (misses and false alarms both).
// Incremental redraw with each mode equals a full redraw: test_render.cpp.
#include <cmath>
#include <vector>

#include "core/cut/stamp.h"
#include "display/colour/slope_colours.h"
#include "display/colour/thin_colours.h"
#include "display/colour/tool_colours.h"
#include "tests/runner.h"
#include "tests/scene_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;

// A tool mode over a grid, with its memory.
struct ToolCase {
  t::TestGrid<uint16_t> tg;
  std::vector<uint8_t> cls;
  std::vector<uint32_t> shadow, luts;
  ToolProvenance<uint16_t> tc;
  SurfaceColours colours;
  explicit ToolCase(int32_t first_tool) {
    t::make_block(&tg, 40, 30, mm, 20 * mm);
    const size_t n = size_t(tg.g.nx) * tg.g.ny;
    cls.assign(n, 99);
    shadow.assign(n, 0);
    luts.assign(size_t(kMaxColourClasses) * kShadeLevels, 0);
    provenance_init(&tc, tg.g, first_tool, kToolColourSlots, cls.data(), shadow.data(), nullptr);
    tool_colours_init(&colours, tc, luts.data());
  }
  // Cuts a line as the cut pass does, then reports it.
  bool cut(const t::TestCutter& c, PointNm a, PointNm b) {
    CutStats st;
    stamp_line(&tg.g, c.c, a, b, &st);
    const bool listed = provenance_record(&tc, tg.g.dirty, 1);
    tg.g.dirty = GridRect::none();
    return listed;
  }
  uint8_t at(int32_t i, int32_t j) const { return cls[tg.g.index(i, j)]; }
};

}  // namespace

TEST(tool_colours_class_is_the_last_tool_that_lowered_the_top) {
  ToolCase k(1);
  CHECK_EQ(int(k.at(20, 15)), 0);  // init: all uncut
  CHECK(k.colours.classify == nullptr);
  CHECK_EQ(k.colours.nclasses, kMaxColourClasses);
  t::TestCutter flat, ball;
  t::make_cutter(k.tg.g, t::flat_tool(6 * mm), &flat);
  t::make_cutter(k.tg.g, t::ball_tool(6 * mm), &ball);
  // T1 slots y = 8, x 5..35, 5 mm deep; T2 slots x = 20 across it, 8 mm deep.
  CHECK(k.cut(flat, PointNm{5 * mm, 8 * mm, 15 * mm}, PointNm{35 * mm, 8 * mm, 15 * mm}));
  provenance_set_tool(&k.tc, 2);
  CHECK(k.cut(ball, PointNm{20 * mm, 3 * mm, 12 * mm}, PointNm{20 * mm, 26 * mm, 12 * mm}));
  CHECK_EQ(int(k.at(10, 8)), 1);   // T1 alone
  CHECK_EQ(int(k.at(20, 20)), 2);  // T2 alone
  CHECK_EQ(int(k.at(20, 8)), 2);   // T1, then deeper by T2
  CHECK_EQ(int(k.at(10, 20)), 0);  // no tool
  CHECK_EQ(int(k.at(30, 25)), 0);
  // T1 again, shallower than T2's slot: lowers nothing there, stays T2's.
  provenance_set_tool(&k.tc, 1);
  CHECK(!k.cut(flat, PointNm{14 * mm, 20 * mm, 17 * mm}, PointNm{26 * mm, 20 * mm, 17 * mm}));
  CHECK_EQ(int(k.at(20, 20)), 2);
  CHECK_EQ(int(k.at(15, 20)), 1);  // beside T2's slot: T1's
  CHECK_EQ(k.tc.ntools, 2);
  CHECK_EQ(k.tc.tool[0], 1);
  CHECK_EQ(k.tc.tool[1], 2);
  // A tool that cuts nothing is not listed.
  provenance_set_tool(&k.tc, 7);
  CHECK(!k.cut(flat, PointNm{10 * mm, 20 * mm, 25 * mm}, PointNm{30 * mm, 20 * mm, 25 * mm}));
  CHECK_EQ(k.tc.ntools, 2);
}

TEST(tool_colours_hole_rim_takes_the_drill) {
  ToolCase k(3);
  t::TestCutter drill;
  t::make_cutter(k.tg.g, t::flat_tool(5 * mm), &drill);
  k.cut(drill, PointNm{20 * mm, 15 * mm, 25 * mm}, PointNm{20 * mm, 15 * mm, -2 * mm});
  CHECK(k.tg.g.is_hole(20, 15));
  // The first uncut column out from the axis, whose side is the hole's wall.
  int32_t i = 20;
  while (k.tg.g.is_hole(i, 15)) ++i;
  CHECK_EQ(int(k.at(i, 15)), 1);
  CHECK_EQ(int(k.at(i + 1, 15)), 0);
}

TEST(tool_colours_palette_wraps_after_seven_tools) {
  ToolCase k(0);
  t::TestCutter flat;
  t::make_cutter(k.tg.g, t::flat_tool(2 * mm), &flat);
  for (int32_t n = 0; n < 9; ++n) {
    provenance_set_tool(&k.tc, 10 + n);
    const int64_t x = (3 + 4 * n) * mm;
    CHECK(k.cut(flat, PointNm{x, 5 * mm, 18 * mm}, PointNm{x, 25 * mm, 18 * mm}));
    CHECK_EQ(int(k.at(3 + 4 * n, 15)), 1 + n % kToolColourSlots);
  }
  CHECK_EQ(k.tc.ntools, 9);
  CHECK_EQ(int(tool_colours_class_of(7)), 1);
  CHECK_EQ(k.tc.unlisted, 0);
}

namespace {

// A grid of 1 mm pitch and 1 um LSB whose tops rise along x at `deg`
// degrees from 10 mm (bottoms 0).
struct RampGrid {
  std::vector<uint16_t> top, bottom;
  DexelGrid<uint16_t> g;
  explicit RampGrid(double deg) {
    const int32_t nx = 9, ny = 5;
    top.assign(size_t(nx) * ny, 0);
    bottom.assign(size_t(nx) * ny, 0);
    (void)grid_init(&g, GridGeometry{nx, ny, 0, 0, mm, 0, 1000}, top.data(), bottom.data(), top.size());
    for (int32_t j = 0; j < ny; ++j)
      for (int32_t i = 0; i < nx; ++i) top[g.index(i, j)] = uint16_t(std::lround(10000 + 1000.0 * i * std::tan(deg * M_PI / 180)));
  }
};

}  // namespace

TEST(slope_bands_on_both_sides_of_every_limit) {
  CHECK_EQ(int(slope_band(RampGrid(0).g, 4, 2)), int(kSlopeFlat));
  CHECK_EQ(int(slope_band(RampGrid(45).g, 4, 2)), int(kSlopeSteep));
  CHECK_EQ(int(slope_band(RampGrid(80).g, 4, 2)), int(kSlopeWall));
  for (int k = 0; k < kSlopeBands - 1; ++k) {
    const double limit = kSlopeLimitDeg[k];
    CHECK_EQ(int(slope_band(RampGrid(limit - 0.3).g, 4, 2)), k);
    CHECK_EQ(int(slope_band(RampGrid(limit + 0.3).g, 4, 2)), k + 1);
  }
  // Along y and falling: the same bands.
  RampGrid r(45);
  for (int32_t j = 0; j < r.g.ny; ++j)
    for (int32_t i = 0; i < r.g.nx; ++i) r.top[r.g.index(i, j)] = uint16_t(20000 - 1000 * j);
  CHECK_EQ(int(slope_band(r.g, 4, 2)), int(kSlopeSteep));
}

TEST(slope_colours_reclassify_the_neighbours_of_a_change) {
  RampGrid r(0);
  std::vector<uint8_t> cls(r.top.size(), 0);
  std::vector<uint32_t> luts(size_t(kSlopeBands) * kShadeLevels);
  SlopeColours<uint16_t> s;
  slope_colours_init(&s, r.g, cls.data(), luts.data());
  s.colours.classify(s.colours.ctx, r.g.bounds(), cls.data());
  CHECK_EQ(int(cls[r.g.index(3, 2)]), int(kSlopeFlat));
  // A pit at (4, 2): its neighbours become walls, though only it changed.
  r.top[r.g.index(4, 2)] = 0;
  s.colours.classify(s.colours.ctx, GridRect{4, 2, 5, 3}, cls.data());
  CHECK_EQ(int(cls[r.g.index(3, 2)]), int(kSlopeWall));
  CHECK_EQ(int(cls[r.g.index(5, 2)]), int(kSlopeWall));
  CHECK_EQ(int(cls[r.g.index(4, 1)]), int(kSlopeWall));
  CHECK_EQ(int(cls[r.g.index(2, 2)]), int(kSlopeFlat));
}

TEST(thin_floors_are_highlighted_and_thick_ones_not) {
  RampGrid r(0);
  const int64_t limit_nm = mm;
  auto band = [&](int32_t top_um, int32_t bottom_um) {
    r.top[r.g.index(4, 2)] = uint16_t(top_um);
    r.bottom[r.g.index(4, 2)] = uint16_t(bottom_um);
    return int(thin_band(r.g, 4, 2, limit_nm));
  };
  CHECK_EQ(band(400, 0), int(kThinUnderHalf));   // 0.4 mm: under half of 1 mm
  CHECK_EQ(band(499, 0), int(kThinUnderHalf));
  CHECK_EQ(band(500, 0), int(kThinUnder));       // half exactly: not under half
  CHECK_EQ(band(700, 0), int(kThinUnder));
  CHECK_EQ(band(999, 0), int(kThinUnder));
  CHECK_EQ(band(1000, 0), int(kThinNot));        // the limit exactly: not under it
  CHECK_EQ(band(1500, 0), int(kThinNot));        // 1.5 mm: no false alarm
  CHECK_EQ(band(5000, 4600), int(kThinUnderHalf));  // top - bottom, not top
  CHECK_EQ(band(5000, 3500), int(kThinNot));
  // Through the callback, over a rectangle.
  std::vector<uint8_t> cls(r.top.size(), 0);
  std::vector<uint32_t> luts(size_t(kThinBands) * kShadeLevels);
  ThinColours<uint16_t> tc;
  thin_colours_init(&tc, r.g, limit_nm, cls.data(), luts.data());
  band(400, 0);
  tc.colours.classify(tc.colours.ctx, GridRect{-3, -3, 30, 30}, cls.data());  // clipped to the grid
  CHECK_EQ(int(cls[r.g.index(4, 2)]), int(kThinUnderHalf));
  CHECK_EQ(int(cls[r.g.index(3, 2)]), int(kThinNot));  // 10 mm
}
