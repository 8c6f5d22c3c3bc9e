// Shared fixtures of the cutting tests: a grid over vectors, and tools.
#ifndef DEXMILL_TESTS_CUT_FIXTURES_H
#define DEXMILL_TESTS_CUT_FIXTURES_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "core/motion/canon.h"
#include "core/tool/tool.h"

namespace fixtures {

constexpr int64_t mm(int64_t v) { return v * dexmill::kNmPerMm; }

// A grid with dexel (0, 0) at the origin and height 0 at z = 0; heights as
// grid_init leaves them (zero) until fill().
template <class H>
struct TestGrid {
  std::vector<H> top, bottom;
  dexmill::DexelGrid<H> g;
  int64_t stock_lsb = 0;
  TestGrid(int32_t nx, int32_t ny, int64_t pitch_nm, int64_t lsb_nm) : top(nx * ny), bottom(nx * ny) {
    dexmill::GridGeometry geo{nx, ny, 0, 0, pitch_nm, 0, lsb_nm};
    dexmill::grid_init(&g, geo, top.data(), bottom.data(), top.size());
  }
  // Material from 0 up to z (clamped to the m-bit range), borders included.
  TestGrid& fill(int64_t z_nm) {
    stock_lsb = std::min<int64_t>(dexmill::height_max<H>(), z_nm / g.lsb_nm);
    std::fill(top.begin(), top.end(), static_cast<H>(stock_lsb));
    std::fill(bottom.begin(), bottom.end(), H(0));
    // What the grid may assume of such material (core/grid/grid.h): the cutters'
    // fast paths then run as on a real block of stock.
    g.bottoms_zero = true;
    g.top_bound_lsb = stock_lsb;
    return *this;
  }
};

// A tool with 20 mm of flutes and the given stick-out.
inline dexmill::Tool test_tool(dexmill::ToolKind k, int64_t d_nm, int64_t rc_nm, int32_t mdeg, int64_t length_nm) {
  dexmill::Tool t;
  t.kind = k;
  t.diameter_nm = d_nm;
  t.corner_radius_nm = rc_nm;
  t.tip_angle_mdeg = mdeg;
  t.flute_length_nm = mm(20);
  t.length_nm = length_nm;
  return t;
}

// The XY arc about (cx, cy) of radius ra from angle a0 through sweep
// (radians, under a turn), tip height z0 -> z1; lengths in nm.
inline dexmill::CanonRecord arc_record(double cx, double cy, double ra, double a0, double sweep, double z0, double z1) {
  using dexmill::PointNm;
  dexmill::CanonRecord r{};
  r.kind = dexmill::CanonKind::kArc;
  r.start = PointNm{std::llround(cx + ra * std::cos(a0)), std::llround(cy + ra * std::sin(a0)), std::llround(z0)};
  r.end = PointNm{std::llround(cx + ra * std::cos(a0 + sweep)), std::llround(cy + ra * std::sin(a0 + sweep)),
                  std::llround(z1)};
  r.arc.plane = dexmill::Plane::kXY;
  r.arc.centre = PointNm{std::llround(cx), std::llround(cy), std::llround(z0)};
  r.arc.turns = sweep > 0 ? 1 : -1;
  return r;
}

}  // namespace fixtures

#endif
