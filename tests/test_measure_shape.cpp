// The measure queries on grids the tests fill (core/measure/section.h,
// thin_floor.h, thin_wall.h, scallop.h): a section's samples against
// their points computed in double; the thinnest floor against a scan in
// the test; walls of known width across X, Y and a diagonal found within
// one step, and the false alarms the definition rules out (a convex
// corner's tip, a round island's edge, a block with no wall); a
// ball-nose raster's scallops, drawn in double, against
// R - sqrt(R^2 - (s/2)^2) within the stated bound, at several pitches.
#include <cmath>
#include <vector>

#include "core/design/design.h"
#include "core/measure/scallop.h"
#include "core/measure/section.h"
#include "core/measure/thin_floor.h"
#include "core/measure/thin_wall.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// A grid of nx x ny columns at pitch_nm from the origin, LSB 1 um, every
// column from Z-10 (height 0) to `top_lsb`.
struct TestGrid {
  std::vector<uint16_t> top, bottom;
  DexelGrid<uint16_t> g;
  TestGrid(int32_t nx, int32_t ny, int64_t pitch_nm, uint16_t top_lsb)
      : top(static_cast<size_t>(nx) * ny, top_lsb), bottom(static_cast<size_t>(nx) * ny, 0) {
    const GridGeometry geo{nx, ny, 0, 0, pitch_nm, -10000000, 1000};
    grid_init(&g, geo, top.data(), bottom.data(), top.size());
  }
  uint16_t& at(int32_t i, int32_t j) { return top[g.index(i, j)]; }
};

}  // namespace

TEST(measure_section_samples_their_points) {
  TestGrid t(41, 31, 250000, 5000);  // 10 x 7.5 mm at 0.25 mm
  std::vector<int32_t> design(41 * 31, kNoDesign);
  for (int32_t j = 0; j < 31; ++j) {  // the design and a groove along X5
    t.at(20, j) = 3000;
    design[t.g.index(20, j)] = 2500;
  }
  const int64_t x0 = 300000, y0 = 7100000, x1 = 9700000, y1 = 200000;
  const SectionSegment s = section_segment(x0, y0, x1, y1, t.g.pitch_nm, 100000);
  const double len = std::hypot(9.4e6, 6.9e6);
  CHECK_NEAR(static_cast<double>(s.length_nm), len, 1.0);
  CHECK_EQ(s.steps, static_cast<int32_t>(std::lround(len / 250000)));
  bool met = false;
  for (int32_t k = 0; k <= s.steps; ++k) {
    const SectionSample p = section_sample(t.g, s, k, nullptr, nullptr, design.data());
    const double f = static_cast<double>(k) / s.steps;
    CHECK_NEAR(static_cast<double>(p.x_nm), x0 + f * (x1 - x0), 1.0);
    CHECK_NEAR(static_cast<double>(p.y_nm), y0 + f * (y1 - y0), 1.0);
    CHECK_NEAR(static_cast<double>(p.along_nm), f * len, 1.5);
    CHECK(p.at.on_grid);
    CHECK_LE(p.at.distance_nm, 176777);  // pitch / sqrt 2
    CHECK_EQ(p.have_design, p.at.i == 20);
    if (p.have_design) {
      met = true;
      CHECK_EQ(p.design_nm, -10000000 + 2500 * 1000);
      CHECK_EQ(p.at.top_nm, -10000000 + 3000 * 1000);
    }
  }
  CHECK(met);
  // A segment of no length: one step, both samples at the point.
  const SectionSegment z = section_segment(x0, y0, x0, y0, t.g.pitch_nm, 100000);
  CHECK_EQ(z.steps, 1);
  CHECK_EQ(section_sample(t.g, z, 1, nullptr, nullptr, nullptr).x_nm, x0);
}

TEST(measure_thin_floor_is_the_least_column) {
  TestGrid t(30, 20, 100000, 9000);
  uint32_t r = 12345;
  for (auto& v : t.top) v = static_cast<uint16_t>(2000 + (r = r * 1103515245u + 12345u) % 7000);
  t.at(3, 4) = 0;  // a hole is no floor
  t.bottom[t.g.index(17, 9)] = 1500;  // a raised bottom makes a thin floor
  t.at(17, 9) = 1700;
  int64_t least = 1 << 30;
  int32_t li = -1, lj = -1;
  for (int32_t j = 0; j < 20; ++j)
    for (int32_t i = 0; i < 30; ++i) {
      if (t.g.is_hole(i, j)) continue;
      const int64_t d = t.at(i, j) - t.bottom[t.g.index(i, j)];
      if (d < least) least = d, li = i, lj = j;
    }
  const ThinFloor f = thin_floor(t.g);
  CHECK(f.found);
  CHECK_EQ(f.i, li);
  CHECK_EQ(f.j, lj);
  CHECK_EQ(f.i, 17);
  CHECK_EQ(f.thickness_nm, 200 * 1000);
  CHECK_EQ(f.thickness_error_nm, 2000);
  CHECK_EQ(f.x_nm, 1700000);
  // Every column cut through: none.
  for (auto& v : t.top) v = 0;
  for (auto& v : t.bottom) v = 0;
  CHECK(!thin_floor(t.g).found);
}

TEST(measure_thin_wall_across_x_y_and_a_diagonal) {
  // Two pockets 8 mm deep leave a wall 13 columns (1.3 mm) wide along Y.
  {
    TestGrid t(100, 60, 100000, 10000);
    for (int32_t j = 0; j < 60; ++j)  // the pockets open to the grid's edges
      for (int32_t i = 0; i < 100; ++i)
        if (i < 40 || i >= 53) t.at(i, j) = 2000;
    const ThinWall w = thin_wall(t.g, 1000000);
    CHECK(w.found);
    CHECK(w.scan == WallScan::kRow);
    CHECK_EQ(w.width_nm, 1300000);
    CHECK_EQ(w.width_error_nm, 100000);
    CHECK_EQ(w.i0, 40);
    CHECK_EQ(w.i1, 52);
    CHECK_EQ(w.floor_nm, -8000000);
    CHECK_EQ(w.top_nm, 0);
    // Higher than the wall stands: none that high but the block's sides.
    const ThinWall hi = thin_wall(t.g, 9000000);
    CHECK(hi.found);
    CHECK(hi.floor_air);
    CHECK_GE(hi.width_nm, 5900000);  // the 6 mm block across Y, 60 columns
    // The same wall along X (transposed).
    TestGrid u(60, 100, 100000, 10000);
    for (int32_t j = 0; j < 100; ++j)
      for (int32_t i = 0; i < 60; ++i)
        if (j < 40 || j >= 53) u.at(i, j) = 2000;
    const ThinWall wy = thin_wall(u.g, 1000000);
    CHECK(wy.scan == WallScan::kColumn);
    CHECK_EQ(wy.width_nm, 1300000);
  }
  // A wall along the diagonal, 1.0 mm wide across it: |i - j| * pitch / sqrt 2 <= 0.5 mm.
  {
    TestGrid t(120, 120, 100000, 10000);
    for (int32_t j = 0; j < 120; ++j)
      for (int32_t i = 0; i < 120; ++i) {
        const double d = std::fabs(static_cast<double>(i - j)) * 0.1 / std::sqrt(2.0);
        if (d > 0.5) t.at(i, j) = 3000;
      }
    const ThinWall w = thin_wall(t.g, 2000000);
    CHECK(w.found);
    CHECK(w.scan == WallScan::kDiagonalDown);
    CHECK_NEAR(static_cast<double>(w.width_nm), 1.0e6, static_cast<double>(w.width_error_nm));
    CHECK_EQ(w.width_error_nm, 141421);
  }
}

TEST(measure_thin_wall_no_false_alarms) {
  // A square island 4 mm wide and a round one 3 mm across in a 3 mm deep
  // pocket: their corners' tips and chords near their edges are no walls;
  // the thinnest is the round island's diameter, within a step (no
  // thinner), or the square's width.
  TestGrid t(200, 100, 100000, 10000);
  for (int32_t j = 0; j < 100; ++j)
    for (int32_t i = 0; i < 200; ++i) {
      const bool square = i >= 30 && i < 70 && j >= 30 && j < 70;
      const bool disk = std::hypot(i - 140.0, j - 50.0) <= 15.0;
      const bool rim = i < 10 || j < 10 || i >= 190 || j >= 90;  // a 1 mm rim around the pocket
      if (!square && !disk && !rim) t.at(i, j) = 7000;
    }
  ThinWall w = thin_wall(t.g, 1000000);
  CHECK(w.found);
  CHECK_EQ(w.width_nm, 1000000);  // the rim, 10 columns
  // Without the rim (the pocket open to the edge): the round island.
  for (int32_t j = 0; j < 100; ++j)
    for (int32_t i = 0; i < 200; ++i)
      if (i < 10 || j < 10 || i >= 190 || j >= 90) t.at(i, j) = 7000;
  w = thin_wall(t.g, 1000000);
  CHECK(w.found);
  CHECK_GE(w.width_nm, 0.894 * 3000000 - w.width_error_nm);
  CHECK_LE(w.width_nm, 3100000 + w.width_error_nm);
  CHECK_NEAR(static_cast<double>(w.x_nm), 14.0e6, 1.6e6);
  // Only the square: its width, not a corner's tip.
  for (int32_t j = 0; j < 100; ++j)
    for (int32_t i = 100; i < 200; ++i) t.at(i, j) = 7000;
  w = thin_wall(t.g, 1000000);
  CHECK(w.found);
  CHECK_EQ(w.width_nm, 4000000);
  // A flat block: its own width (the grid's edge is air), 100 columns.
  for (auto& v : t.top) v = 10000;
  w = thin_wall(t.g, 1000000);
  CHECK(w.found && w.floor_air);
  CHECK_EQ(w.width_nm, 10000000);
}

namespace {

// A ball-nose raster along X at stepover s_mm, radius r_mm, its tip at
// Z-2, drawn into the grid in double (the scallop's oracle).
void ball_raster(TestGrid* t, double pitch_mm, double r_mm, double s_mm) {
  for (int32_t j = 0; j < t->g.ny; ++j) {
    const double y = j * pitch_mm;
    double z = 1e9;
    for (double yc = 1.0; yc < t->g.ny * pitch_mm + r_mm; yc += s_mm) {
      const double d = std::fabs(y - yc);
      if (d < r_mm) z = std::min(z, -2.0 + r_mm - std::sqrt(r_mm * r_mm - d * d));
    }
    z = std::min(z, 0.0);
    for (int32_t i = 0; i < t->g.nx; ++i) t->at(i, j) = static_cast<uint16_t>(std::lround((z + 10.0) * 1000.0));
  }
}

}  // namespace

TEST(measure_scallop_against_the_ball_nose_formula) {
  const double r_mm = 3.0;
  const double cases[][2] = {{1.0, 0.1}, {1.0, 0.05}, {1.0, 0.037}, {2.0, 0.1}, {0.5, 0.02}, {1.5, 0.25}};
  for (const auto& c : cases) {
    const double s_mm = c[0], pitch_mm = c[1];
    const int32_t n = static_cast<int32_t>(std::lround(12.0 / pitch_mm));
    TestGrid t(20, n, static_cast<int64_t>(std::lround(pitch_mm * 1e6)), 10000);
    ball_raster(&t, pitch_mm, r_mm, s_mm);
    const double h = r_mm - std::sqrt(r_mm * r_mm - s_mm * s_mm / 4);
    // Away from the raster's first and last passes.
    const int32_t j0 = static_cast<int32_t>(3.0 / pitch_mm), j1 = static_cast<int32_t>(9.0 / pitch_mm);
    const ScallopAnswer a = scallop(t.g, GridRect{0, j0, 20, j1});
    CHECK(!a.along_x.found);  // along the feed: flat
    const Scallop& y = a.along_y;
    CHECK(y.found);
    CHECK(&a.highest() == &a.along_y);
    CHECK_NEAR(y.height_nm / 1e6, h, y.error_nm / 1e6);
    // The bound: two LSB and one dexel's worth of height beside the crest
    // (the cusp's slope times the pitch) and the valley (round: less).
    const double slope = (s_mm / 2) / std::sqrt(r_mm * r_mm - s_mm * s_mm / 4);
    CHECK_LE(y.error_nm / 1e6, 0.002 + 0.001 + 2 * slope * pitch_mm + 0.001);
    const double off = std::fmod(y.y_nm / 1e6 - 1.0 + s_mm / 2, s_mm);  // a crest half-way between passes
    CHECK_LE(std::min(off, s_mm - off), pitch_mm + 1e-6);
  }
  // A flat region has no scallop, a single groove none either (no crest
  // with valleys both sides), and a hole ends a scan.
  TestGrid f(30, 30, 100000, 8000);
  CHECK(!scallop(f.g, f.g.bounds()).along_y.found);
  for (int32_t i = 0; i < 30; ++i) f.at(i, 15) = 7000;
  CHECK(!scallop(f.g, f.g.bounds()).along_y.found);
  for (int32_t i = 0; i < 30; ++i) f.at(i, 20) = 7500;
  const ScallopAnswer g = scallop(f.g, f.g.bounds());
  CHECK(g.along_y.found);
  CHECK_EQ(g.along_y.height_nm, 500000);  // the crest at 8000 between 7000 and 7500
  for (int32_t i = 0; i < 30; ++i) f.top[f.g.index(i, 18)] = 0;  // a through-cut between: no valley
  CHECK(!scallop(f.g, f.g.bounds()).along_y.found);
}
