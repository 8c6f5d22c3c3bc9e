// Rotated coordinate systems (core/interp/rotation.h): the integer turn
// against a double oracle within its stated bound, whole turns exact, and
// a point turned and turned back within twice the bound.
#include <cmath>
#include <cstdio>
#include <random>

#include "core/interp/rotation.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// The stated bound for a point d nm from the origin it turns about, per coordinate.
double bound_nm(double d) { return 4.5e-9 * d + 1.5; }

}  // namespace

TEST(rotation_against_double_oracle) {
  std::mt19937_64 rng(20261127);
  std::uniform_int_distribution<int64_t> coord(-10000000000LL, 10000000000LL);  // +-10 m
  std::uniform_int_distribution<int64_t> angle(-720LL * 1000000000, 720LL * 1000000000);
  double worst = 0, worst_back = 0;
  for (int k = 0; k < 200000; ++k) {
    const int64_t deg_e9 = k % 7 == 0 ? angle(rng) / 1000000000 * 1000000000 : angle(rng);  // whole degrees too
    const XyRotation r = xy_rotation(deg_e9);
    const PointNm p{coord(rng), coord(rng), coord(rng)};
    const int64_t ox = coord(rng), oy = coord(rng);
    const PointNm q = rotate_about(r, p, ox, oy);
    const double t = static_cast<double>(deg_e9) * 1e-9 * M_PI / 180.0;
    const double dx = static_cast<double>(p.x_nm - ox), dy = static_cast<double>(p.y_nm - oy);
    const double ex = static_cast<double>(ox) + dx * std::cos(t) - dy * std::sin(t);
    const double ey = static_cast<double>(oy) + dx * std::sin(t) + dy * std::cos(t);
    const double d = std::hypot(dx, dy);
    const double err = std::fmax(std::fabs(static_cast<double>(q.x_nm) - ex), std::fabs(static_cast<double>(q.y_nm) - ey));
    worst = std::fmax(worst, err - 4.5e-9 * d);
    CHECK(err <= bound_nm(d));
    CHECK_EQ(q.z_nm, p.z_nm);
    // Turned back: within twice the bound of where it began.
    const PointNm b = rotate_about(xy_rotation_inverse(r), q, ox, oy);
    const double back = std::fmax(std::fabs(static_cast<double>(b.x_nm - p.x_nm)), std::fabs(static_cast<double>(b.y_nm - p.y_nm)));
    worst_back = std::fmax(worst_back, back / (2 * bound_nm(d)));
    CHECK(back <= 2 * bound_nm(d));
  }
  std::printf("  rotation: worst error past 4.5e-9 d: %.2f nm (bound 1.5); turned back: %.2f of the bound\n", worst,
              worst_back);
}

TEST(rotation_whole_turns_are_exact) {
  const PointNm p{123456789, -987654321, 5};
  for (int64_t turns = -3; turns <= 3; ++turns) {
    const XyRotation r = xy_rotation(turns * 360LL * 1000000000);
    CHECK(!r.on);
    CHECK(rotate_about(r, p, 7, 9) == p);
  }
  // A quarter turn is exact to the nm: CORDIC gives cos 0 and sin 1 within 2 q30 LSB.
  const PointNm q = rotate_about(xy_rotation(90LL * 1000000000), PointNm{1000000, 0, 0}, 0, 0);
  CHECK_EQ(q.x_nm, 0);
  CHECK_EQ(q.y_nm, 1000000);
}
