// The sweep's per-column square roots (core/math/fixed.h, isqrt_fast_u64)
// along the rows the sweep walks, against the definition of floor(sqrt):
// r^2 <= x < (r + 1)^2, checked with exact 64-bit products (and against the
// bit-by-bit isqrt_u64). The root is exact by construction (its correction
// loops stop only there); these cases prove it on the arguments the sweep
// feeds it, and that the seed keeps the loops short.
//
// Rows as core/cut/sweep_piece.h's general direction builds them: v_acc
// (U * 2^30) steps by dv a column, v = (v_acc + 2^29) >> 30, v2 = min(v^2,
// R^2), x = R^2 - v2 (the ball's half chord rho). Level arcs
// (core/cut/sweep_arc.cpp): the radial distance floor(|(qx, qy)|) with qx
// stepping by the pitch. Also the 32-bit products of mul_shift_fit on CPUs
// without 128-bit integers, against the portable four-product path.
#include <cstdint>
#include <initializer_list>

#include "core/math/fixed.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// floor(sqrt(x)) by its definition; r < 2^32, so (r + 1)^2 fits unless r is
// 2^32 - 1, where every x < 2^64 qualifies.
bool is_floor_root(uint64_t x, uint64_t r) {
  if (r > 0xffffffffu || r * r > x) return false;
  return r == 0xffffffffu || (r + 1) * (r + 1) > x;
}

// Counts the roots checked and the wrong ones (with the first argument that
// failed, printed by CHECK_EQ).
struct RowCheck {
  uint64_t roots = 0, bad = 0;
  uint64_t first_bad_x = 0;
  void check(uint64_t x) {
    ++roots;
    const uint32_t r = isqrt_fast_u64(x);
    // The 32-bit CPUs' form too, on every host.
    const uint32_t r_split = detail::isqrt_fast_u64_split(x);
    if (!is_floor_root(x, r) || r != isqrt_u64(x) || r_split != r) {
      if (bad++ == 0) first_bad_x = x;
    }
  }
};

// One row of the general-direction loop: n columns from v_acc0 by dv; as
// there (NarrowRows), only columns with |v_acc| <= (R + 1) 2^30.
void ball_row(RowCheck* c, int64_t r_u, int64_t v_acc0, int64_t dv, int n) {
  const int64_t r2 = r_u * r_u;
  constexpr int64_t kHalf = static_cast<int64_t>(1) << 29;
  const int64_t span = (r_u + 1) * (static_cast<int64_t>(1) << 30);
  int64_t v_acc = v_acc0;
  for (int i = 0; i < n; ++i, v_acc += dv) {
    if (v_acc < -span || v_acc > span) continue;
    const int64_t v = (v_acc + kHalf) >> 30;
    const int64_t v2 = v * v < r2 ? v * v : r2;
    c->check(static_cast<uint64_t>(r2 - v2));
  }
}

}  // namespace

// Random rows: radii from 1 U to 2^30 U (the largest tool sweep_tool_prepare
// accepts), steps from 0 to past the diameter a column, starts anywhere in
// [-R - 1, R + 1] (negative v, rows crossing v = 0 both ways).
TEST(isqrt_rows_ball_random) {
  t::Rng rng(2401);
  RowCheck c;
  for (int row = 0; row < 150000; ++row) {
    const int bits = 1 + static_cast<int>(rng.next() % 30);
    const int64_t r_u = rng.range(1, static_cast<int64_t>(1) << bits);
    const int64_t span_q30 = (r_u + 1) * (static_cast<int64_t>(1) << 30);
    const int64_t v_acc0 = rng.range(-span_q30, span_q30);
    // Log-uniform step magnitude: from a fraction of a U to 4R a column
    // (rows stop before v_acc leaves 5 spans: no overflow).
    const int step_bits = static_cast<int>(rng.next() % static_cast<uint64_t>(bits + 33));
    int64_t dv = rng.range(0, static_cast<int64_t>(1) << step_bits);
    int64_t n = 1 + static_cast<int64_t>(rng.next() % 64);
    if (dv > 0 && n > 4 * span_q30 / dv + 1) n = 4 * span_q30 / dv + 1;
    if (rng.next() & 1) dv = -dv;
    ball_row(&c, r_u, v_acc0, dv, static_cast<int>(n));
  }
  CHECK_EQ(c.bad, uint64_t{0});
  CHECK_EQ(c.first_bad_x, uint64_t{0});
  CHECK_GT(c.roots, uint64_t{1000000});
}

// The extremes: R = 2^30 U with the rim (x = 0 and x = 2R - 1 steps in),
// the centre, rows of unit steps (every v of a window), rows that cross v = 0
// in one step, and steps of exactly the pitch the bench uses (0.1 mm = 4e5 U)
// for scale-1k's 3 mm ball.
TEST(isqrt_rows_ball_extremes) {
  RowCheck c;
  constexpr int64_t kQ30 = static_cast<int64_t>(1) << 30;
  const int64_t radii[] = {1, 2, 3, 7, 8, 1000, 6000000, (int64_t{1} << 28) + 1, (int64_t{1} << 30) - 1, int64_t{1} << 30};
  for (int64_t r_u : radii) {
    // Unit steps through the rim, both ways, and through the centre.
    ball_row(&c, r_u, (r_u + 1) * kQ30, -kQ30, 2000);
    ball_row(&c, r_u, -(r_u + 1) * kQ30, kQ30, 2000);
    ball_row(&c, r_u, -1000 * kQ30, kQ30, 2001);
    // Fractional steps (a move a hair off the x axis).
    ball_row(&c, r_u, -(r_u / 2) * kQ30, 1, 1000);
    ball_row(&c, r_u, (r_u / 3) * kQ30 + kQ30 / 2 - 1, 3, 1000);
    // Across the whole chord in a few columns, and one column per side of v = 0.
    ball_row(&c, r_u, -(r_u + 1) * kQ30, (2 * r_u + 2) * kQ30 / 7, 8);
    ball_row(&c, r_u, -kQ30 / 2, kQ30, 2);
    ball_row(&c, r_u, kQ30 / 2 - 1, -kQ30, 2);
  }
  // scale-1k: R = 1.5 mm = 6e6 U, pitch 4e5 U, every direction.
  for (int k = 0; k < 3600; ++k) {
    const int64_t r_u = 6000000;
    // dv = -p e_y for e_y = sin(k / 10 degrees), as a q30 unit vector's y.
    const int64_t ey_q30 = (static_cast<int64_t>(k) - 1800) * (kQ30 / 1800);
    ball_row(&c, r_u, -(r_u + 1) * kQ30 + k * 12345, -400000 * ey_q30, 40);
  }
  CHECK_EQ(c.bad, uint64_t{0});
  CHECK_EQ(c.first_bad_x, uint64_t{0});
}

// Level arcs: floor(|(qx, qy)|) along a row of columns, radii up to 2^31 U
// (the ring test's bound), every octant.
TEST(isqrt_rows_arc_radius) {
  t::Rng rng(2402);
  RowCheck c;
  for (int row = 0; row < 20000; ++row) {
    const int bits = 1 + static_cast<int>(rng.next() % 30);
    const int64_t lim = static_cast<int64_t>(1) << bits;
    const int64_t qy = rng.range(-lim, lim);
    int64_t qx = rng.range(-lim, lim);
    const int64_t p_u = rng.range(1, lim / 32 + 1);  // |qx| < 2^31: squares fit
    for (int i = 0; i < 48; ++i, qx += p_u) c.check(static_cast<uint64_t>(qx * qx + qy * qy));
  }
  CHECK_EQ(c.bad, uint64_t{0});
  CHECK_EQ(c.first_bad_x, uint64_t{0});
}

// Every knot interval of the seed table at its ends and middle, for every
// exponent, and the squares around them: the interpolation and the
// normalisation at their edges.
TEST(isqrt_rows_seed_knots) {
  RowCheck c;
  for (int e = 1; e < 32; ++e) {
    for (uint64_t knot = 64; knot < 256; ++knot) {
      // m = knot / 64 * 4^e and its neighbours.
      const int sh = 2 * e - 6;
      const uint64_t x = sh >= 0 ? knot << sh : knot >> -sh;
      const uint64_t step = sh >= 6 ? uint64_t{1} << (sh - 6) : 1;
      for (uint64_t d : {uint64_t{0}, uint64_t{1}, step, 32 * step})
        for (uint64_t v : {x + d, x - d}) c.check(v);
    }
  }
  for (uint64_t r = 1; r < (uint64_t{1} << 32); r = r + 1 + r / 97) {
    c.check(r * r);
    c.check(r * r - 1);
    if (r < 0xffffffffu) c.check(r * r + 2 * r);  // (r + 1)^2 - 1
  }
  c.check(UINT64_MAX);
  c.check(UINT64_MAX - 1);
  CHECK_EQ(c.bad, uint64_t{0});
  CHECK_EQ(c.first_bad_x, uint64_t{0});
}

// mul_shift_fit's 32 x 32-bit path (taken on CPUs without 128-bit integers)
// against the portable path, on the sweep's shifts and operand ranges.
TEST(isqrt_rows_mul_shift_i32) {
  t::Rng rng(2403);
  uint64_t bad = 0;
  for (int k = 0; k < 200000; ++k) {
    const int64_t a = static_cast<int32_t>(static_cast<uint32_t>(rng.next() >> (rng.next() % 32)));
    const int64_t b = static_cast<int32_t>(static_cast<uint32_t>(rng.next() >> (rng.next() % 32)));
    const int s = static_cast<int>(rng.next() % 63);
    if (!detail::fits_i32(a) || !detail::fits_i32(b) || detail::mul_shift_i32(a, b, s) != mul_shift_portable(a, b, s)) ++bad;
  }
  for (int64_t a : {int64_t{INT32_MIN}, int64_t{INT32_MAX}, int64_t{-1}, int64_t{0}, int64_t{1}})
    for (int64_t b : {int64_t{INT32_MIN}, int64_t{INT32_MAX}, int64_t{-1}, int64_t{1}})
      for (int s : {0, 1, 16, 30, 32, 62})
        if (detail::mul_shift_i32(a, b, s) != mul_shift_portable(a, b, s)) ++bad;
  CHECK_EQ(bad, uint64_t{0});
  CHECK(!detail::fits_i32(int64_t{INT32_MAX} + 1));
  CHECK(!detail::fits_i32(int64_t{INT32_MIN} - 1));
}

// The 32-bit CPUs' set-up paths: the 128 / 64-bit division against the
// compiler's, and the seeded 128-bit root against the digit-by-digit one
// (both exact: any difference is a bug).
TEST(isqrt_rows_u128_portable) {
  t::Rng rng(2404);
  uint64_t bad_div = 0, bad_root = 0;
  for (int k = 0; k < 300000; ++k) {
    uint64_t d = rng.next() >> (rng.next() % 64);
    if (d == 0) d = 1;
    const U128 n{d > 1 ? (rng.next() >> (rng.next() % 64)) % d : 0, rng.next() >> (rng.next() % 64)};
    uint64_t rem = 0;
    const uint64_t q = divmod_u128_portable(n, d, &rem);
#ifdef __SIZEOF_INT128__  // every host the tests run on
    const unsigned __int128 nn = (static_cast<unsigned __int128>(n.hi) << 64) | n.lo;
    if (q != static_cast<uint64_t>(nn / d) || rem != static_cast<uint64_t>(nn % d)) ++bad_div;
#else
    (void)q;
#endif
    const U128 v{rng.next() >> (rng.next() % 64), rng.next()};
    if (isqrt_u128_portable(v) != isqrt_u128_bitwise(v) || isqrt_u128(v) != isqrt_u128_bitwise(v)) ++bad_root;
  }
  for (uint64_t d : {uint64_t{1}, uint64_t{2}, uint64_t{0xffffffffu}, uint64_t{1} << 32, UINT64_MAX, UINT64_MAX - 1, uint64_t{1} << 63}) {
    for (U128 n : {U128{d - 1, UINT64_MAX}, U128{0, 0}, U128{0, d}, U128{d / 2, 0}}) {
      uint64_t rem = 0;
      const uint64_t q = divmod_u128_portable(n, d, &rem);
#ifdef __SIZEOF_INT128__
      const unsigned __int128 nn = (static_cast<unsigned __int128>(n.hi) << 64) | n.lo;
      if (q != static_cast<uint64_t>(nn / d) || rem != static_cast<uint64_t>(nn % d)) ++bad_div;
#else
      (void)q;
#endif
    }
  }
  for (U128 v : {U128{1, 0}, U128{UINT64_MAX, UINT64_MAX}, U128{UINT64_MAX - 1, 1}, U128{0xfffffffffffffffeu, 1}, U128{1u << 31, 0},
                 U128{0, UINT64_MAX}, U128{3, UINT64_MAX}})
    if (isqrt_u128_portable(v) != isqrt_u128_bitwise(v)) ++bad_root;
  for (uint64_t r = uint64_t{1} << 32; r < (uint64_t{1} << 63); r += r / 3 + 12345) {  // squares and their neighbours
    const U128 sq = mul_wide_u64_portable(r, r);
    const U128 below = sub_u128(sq, U128{0, 1});
    if (isqrt_u128_portable(sq) != r || isqrt_u128_portable(below) != r - 1) ++bad_root;
  }
  CHECK_EQ(bad_div, uint64_t{0});
  CHECK_EQ(bad_root, uint64_t{0});
}
