// Shared fixtures of the cutting tests: a grid over vectors, and tools.
#ifndef DEXMILL_TESTS_CUT_FIXTURES_H
#define DEXMILL_TESTS_CUT_FIXTURES_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/config.h"
#include "core/cut/sweep.h"
#include "core/cut/sweep_internal.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "core/canon/canon.h"
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

// A raster along x over a size_mm square, chained as a CAM program would
// be: passes in both directions over a bumpy surface (ramps of every slope),
// the track on a row, half way between two or anywhere (mirrored rows or
// not), steps across between passes, now and then a level stretch or a
// short move across and back (which break the collinear wedge), pieces from
// a few um to a few mm. r_mm: the tool's radius (the margin kept).
inline std::vector<dexmill::PointNm> raster_path(double size_mm, double r_mm, double pitch_mm, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * u01(*rng); };
  const double amp = rnd(0.1, 3.0), fx = rnd(0.3, 2.0), fy = rnd(0.3, 2.0);
  auto z_at = [&](double x, double y) { return 20 + amp * std::sin(x / fx) * std::cos(y / fy); };
  std::vector<dexmill::PointNm> p;
  auto at = [&](double x, double y, double z) {
    p.push_back(dexmill::PointNm{std::llround(x * 1e6), std::llround(y * 1e6), std::llround(z * 1e6)});
  };
  double y = r_mm;
  bool forward = true;
  while (y < size_mm - r_mm) {
    const double x0 = forward ? r_mm : size_mm - r_mm, x1 = forward ? size_mm - r_mm : r_mm;
    const double seg = rnd(0.005, 0.5) * (u01(*rng) < 0.2 ? 8 : 1);
    for (double x = x0; forward ? x <= x1 : x >= x1; x += forward ? seg : -seg) {
      const double r = u01(*rng);
      if (r < 0.03) at(x, y + rnd(0.05, 0.5), z_at(x, y));  // across, then back: the wedge starts over
      else if (r < 0.06) at(x, y, z_at(x - 3 * seg, y));    // a level stretch
      at(x, y, z_at(x, y));
    }
    forward = !forward;
    const double kind = u01(*rng);
    y += kind < 0.3   ? pitch_mm * std::floor(rnd(1, 8))
         : kind < 0.6 ? pitch_mm * (std::floor(rnd(1, 8)) + 0.5)
                      : rnd(0.1, 1.5) * r_mm;
  }
  return p;
}

// The sweep's entry points (core/cut/sweep_internal.h) with a tool, the
// switches k and the column loops' word width W bound: what the tests that
// turn a switch off, or run both widths, cut with.
template <class H, int W = dexmill::kSweepWordBits>
struct Sweep {
  const dexmill::SweepTool& t;
  const dexmill::SweepTuning& k;
  void line(dexmill::DexelGrid<H>* g, dexmill::PointNm a, dexmill::PointNm b, dexmill::CutStats* st,
            bool start_cap = true) const {
    dexmill::sweep_line_w<H, W>(g, t, k, a, b, st, start_cap);
  }
  void chain_line(dexmill::DexelGrid<H>* g, dexmill::PointNm a, dexmill::PointNm b, dexmill::CutStats* st,
                  dexmill::SweepChain* c) const {
    dexmill::sweep_chain_line_w<H, W>(g, t, k, a, b, st, c);
  }
  void chain_end(dexmill::DexelGrid<H>* g, dexmill::CutStats* st, dexmill::SweepChain* c) const {
    dexmill::sweep_chain_end_w<H, W>(g, t, k, st, c);
  }
  void arc(dexmill::DexelGrid<H>* g, const dexmill::CanonRecord& r, dexmill::CutStats* st, bool start_cap = true) const {
    dexmill::sweep_arc_w<H, W>(g, t, k, r, st, start_cap);
  }
  void chain_arc(dexmill::DexelGrid<H>* g, const dexmill::CanonRecord& r, dexmill::CutStats* st,
                 dexmill::SweepChain* c) const {
    dexmill::sweep_chain_arc_w<H, W>(g, t, k, r, st, c);
  }
};

// The test of an exact shortcut: cuts twice with cut(grid, sweep, stats,
// chain) (sweep: a Sweep<H>), with every switch on and with SweepTuning's
// `option` off, each into a fresh n x n grid filled to 30 mm, and ends both
// chains. *equal: the two grids (tops and bottoms) are the same. False when
// the tool cannot be prepared.
template <class H, class Cut>
bool cut_on_and_off(const dexmill::Tool& tool, int32_t n, int64_t pitch, int64_t lsb,
                    bool dexmill::SweepTuning::*option, Cut cut, dexmill::CutStats* s_on, dexmill::CutStats* s_off,
                    bool* equal) {
  TestGrid<H> with(n, n, pitch, lsb), without(n, n, pitch, lsb);
  with.fill(mm(30));
  without.fill(mm(30));
  dexmill::SweepTool t;
  if (dexmill::sweep_tool_prepare(dexmill::tool_profile(tool), lsb, &t) != dexmill::Status::kOk) return false;
  dexmill::SweepTuning k_off;
  k_off.*option = false;
  const Sweep<H> on{t, dexmill::kSweepDefaults}, off{t, k_off};
  dexmill::SweepChain c_on, c_off;
  cut(&with.g, on, s_on, &c_on);
  cut(&without.g, off, s_off, &c_off);
  on.chain_end(&with.g, s_on, &c_on);
  off.chain_end(&without.g, s_off, &c_off);
  *equal = with.top == without.top && with.bottom == without.bottom;
  return true;
}

}  // namespace fixtures

#endif
