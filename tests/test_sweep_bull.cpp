// core/cut/bull_flank.h: the bull nose's flank on ramps from the torus's
// contact. Its w* against a double-precision minimiser of F(w) - m w, and
// whole bull-nose ramps in many directions and slopes, several corner radii,
// against the dense double oracle with core/cut/sweep.h's backward bound.
#include <cmath>
#include <cstdio>
#include <random>

#include "core/cut/bull_flank.h"
#include "core/cut/sweep.h"
#include "core/cut/sweep_internal.h"
#include "core/tool/tool.h"
#include "tests/cut_fixtures.h"
#include "tests/runner.h"
#include "tests/sweep_oracle.h"

using namespace dexmill;

namespace {

using fixtures::mm;

Tool bull(int64_t d_nm, int64_t rc_nm) { return fixtures::test_tool(ToolKind::kBullNose, d_nm, rc_nm, 0, mm(60)); }

// F(w) - m w at cross-track v (nm), the double profile.
double flank_cost(const Tool& t, double m, double v, double w) {
  return oracle::profile_nm(t, std::min(std::hypot(w, v), t.diameter_nm / 2.0)) - m * w;
}

// min over w in the chord of F(w) - m w (a fine ternary search: convex).
double flank_min(const Tool& t, double m, double v) {
  const double R = t.diameter_nm / 2.0, rho = std::sqrt(std::max(0.0, R * R - v * v));
  double lo = -rho, hi = rho;
  for (int it = 0; it < 300; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (flank_cost(t, m, v, m1) <= flank_cost(t, m, v, m2)) hi = m2; else lo = m1;
  }
  return flank_cost(t, m, v, (lo + hi) / 2);
}

// Every bull-nose ramp cut, with the column loops in W-bit words
// (core/config.h), against the oracle: within 1 LSB of the exact lowest
// point at the column or at the column moved 1 nm (core/cut/sweep.h).
template <int W>
int check_ramp_w(const Tool& tool, PointNm a, PointNm b, int64_t pitch, int64_t lsb) {
  fixtures::TestGrid<uint16_t> f(64, 48, pitch, lsb);
  f.fill(mm(30));
  SweepTool st_tool;
  if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &st_tool), Status::kOk)) return 1;
  CutStats st;
  sweep_line_w<uint16_t, W>(&f.g, st_tool, kSweepDefaults, a, b, &st, true);
  const oracle::P3 pa{double(a.x_nm), double(a.y_nm), double(a.z_nm)}, pb{double(b.x_nm), double(b.y_nm), double(b.z_nm)};
  const double hmax = static_cast<double>(f.stock_lsb);
  int bad = 0;
  for (int32_t j = 0; j < f.g.ny; ++j) {
    for (int32_t i = 0; i < f.g.nx; ++i) {
      const double px = double(i) * pitch, py = double(j) * pitch;
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (auto& o : oracle::kNeighbours) {
        const double h = oracle::lowest_on_line(tool, pa, pb, px + o[0], py + o[1]);
        const double lsbs = std::max(0.0, h == HUGE_VAL ? hmax : std::min(hmax, h / lsb));
        lo = std::min(lo, lsbs);
        hi = std::max(hi, lsbs);
      }
      const double got = f.g.top[f.g.index(i, j)];
      if ((got < lo - 1.0 || got > hi + 1.0) && ++bad <= 3)
        std::printf("  bull %lld/%lld w=%d: dexel (%d,%d) top %.0f, oracle [%.3f, %.3f], move (%lld,%lld,%lld)->(%lld,%lld,%lld)\n",
                    (long long)tool.diameter_nm, (long long)tool.corner_radius_nm, W, i, j, got, lo, hi,
                    (long long)a.x_nm, (long long)a.y_nm, (long long)a.z_nm, (long long)b.x_nm, (long long)b.y_nm,
                    (long long)b.z_nm);
    }
  }
  return bad;
}

// Both word widths.
int check_ramp(const Tool& tool, PointNm a, PointNm b, int64_t pitch, int64_t lsb) {
  return check_ramp_w<32>(tool, a, b, pitch, lsb) + check_ramp_w<64>(tool, a, b, pitch, lsb);
}

}  // namespace

TEST(sweep_bull_flank_w_is_the_minimum) {
  // w* from the quartic against a double minimiser over the chord, for
  // corner radii from a sliver to nearly a ball, slopes from 2^-16 to 2^4 and
  // every cross offset (the rim and v = a included): the cost at w* is within
  // 0.2 nm (a tenth of the sweep's working unit V on a 0.5 um LSB) of the
  // minimum for the column moved at most 1 nm, and the solver answers for
  // every slope in its range.
  std::mt19937_64 rng(24);
  const int64_t corners[][2] = {{mm(6), 50000}, {mm(6), mm(1) + 500000}, {mm(3), 500000}, {mm(8), mm(2)},
                                {mm(6), 2900000}, {mm(20), mm(1)}};
  int worse = 0, refused = 0, n = 0;
  double worst = 0;
  for (const auto& c : corners) {
    const Tool tool = bull(c[0], c[1]);
    SweepTool t;
    if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), 500, &t), Status::kOk)) return;
    const double R = c[0] / 2.0, a = R - c[1];
    for (int k = 0; k < 3000; ++k) {
      const double m = (rng() & 1 ? 1 : -1) * std::ldexp(1.0, -16 + static_cast<int>(rng() % 20)) *
                       (1.0 + (rng() % 1000) / 1000.0);
      double v_nm = R * ((rng() % 100000) / 100000.0);
      if (k % 5 == 1) v_nm = a * (1.0 + ((rng() % 2001) / 1000.0 - 1.0) * 1e-3);  // the torus's inner edge
      if (k % 5 == 2) v_nm = R * (1.0 - std::ldexp(1.0, -static_cast<int>(rng() % 30)));  // the rim
      const int64_t v_u = std::llround(v_nm * kSweepUnitsPerNm);
      const int64_t m_q30 = std::llround(std::ldexp(m, 30));
      const int64_t sin_q30 = std::llround(std::ldexp(m / std::sqrt(1 + m * m), 30));
      int64_t w_abs = -1;
      ++n;
      if (!bull_flank_w(t, m_q30, sin_q30, v_u, &w_abs)) {
        if (++refused <= 5) std::printf("  refused: bull %lld/%lld m=%.9g v=%lld U\n", (long long)c[0], (long long)c[1], m, (long long)v_u);
        continue;
      }
      const double w_nm = (m < 0 ? -1.0 : 1.0) * double(w_abs) / kSweepUnitsPerNm;
      const double m_used = std::ldexp(double(m_q30), -30), v_used = double(v_u) / kSweepUnitsPerNm;
      // Backward, as core/cut/sweep.h states the bound: no higher than the
      // minimum of the column moved 1 nm outwards (the minimum grows with
      // |v|; where the torus is near vertical, at the rim of a steep ramp,
      // it grows by nanometres a nanometre).
      const double got = flank_cost(tool, m_used, v_used, w_nm);
      const double excess = got - flank_min(tool, m_used, std::min(R, v_used + 1.0));
      worst = std::max(worst, (got - flank_min(tool, m_used, v_used)) / R);
      if (excess > 0.2 && ++worse <= 20)
        std::printf("  bull %lld/%lld m=%.9g v=%.3f nm: w* %.3f nm costs %.3g nm over the minimum\n", (long long)c[0],
                    (long long)c[1], m_used, v_used, w_nm, excess);
    }
  }
  std::printf("  %d cases, worst excess %.3g R\n", n, worst);
  CHECK_EQ(worse, 0);
  CHECK_EQ(refused, 0);
}

TEST(sweep_bull_ramps_against_oracle) {
  // Ramps in 24 directions (every 15 degrees: on the axes, the diagonals and
  // between), slopes from 1:600 to 4:1, five corner radii (down to a 10 um
  // sliver, whose torus is near vertical): every dexel within
  // the backward bound of the dense oracle.
  const int64_t pitch = 250000, lsb = 500;
  const Tool tools[] = {bull(mm(8), mm(2)), bull(mm(6), 1500000), bull(mm(3), 500000), bull(mm(6), 300000),
                        bull(mm(6), 10000)};
  const int64_t drops_nm[] = {10000, 400000, 3000000, 24000000};
  int bad = 0, moves = 0;
  for (int dir = 0; dir < 24; ++dir) {
    const double ang = dir * 3.14159265358979323846 / 12;
    const Tool& tool = tools[dir % 5];
    const int64_t drop = drops_nm[(dir / 4) % 4];
    const int64_t len = mm(6);
    const PointNm a{mm(8) - std::llround(len / 2 * std::cos(ang)), mm(6) - std::llround(len / 2 * std::sin(ang)), mm(20)};
    const PointNm b{mm(8) + std::llround(len / 2 * std::cos(ang)), mm(6) + std::llround(len / 2 * std::sin(ang)),
                    mm(20) - (dir % 2 ? drop : -drop)};
    bad += check_ramp(tool, a, b, pitch, lsb);
    ++moves;
  }
  CHECK_EQ(bad, 0);
  CHECK_EQ(moves, 24);
}

namespace {

// Through a memo with row_inv_q32 (0: hashed slots), w* for pieces of
// three slopes in ways 0, 1, 0 against bull_flank_w's bits, each asked
// twice (the second time a hit).
void check_memo(uint64_t row_inv_q32, std::mt19937_64* rng, int* differ, int* hits, int* calls) {
  BullFlankMemo memo;
  memo.row_inv_q32 = row_inv_q32;
  for (const int64_t rc : {1500000, 500000}) {
    SweepTool t;
    if (!CHECK_EQ(sweep_tool_prepare(tool_profile(bull(mm(6), rc)), 500, &t), Status::kOk)) return;
    SweepLine pieces[3] = {};
    const double slopes[3] = {0.05, -0.7, 0.05 + 1e-9};
    for (int k = 0; k < 3; ++k) {
      pieces[k].m_geo_q30 = std::llround(std::ldexp(slopes[k], 30));
      pieces[k].ball_sin_q30 = std::llround(std::ldexp(slopes[k] / std::sqrt(1 + slopes[k] * slopes[k]), 30));
      pieces[k].bull_memo = &memo;
      pieces[k].bull_way = static_cast<uint8_t>(k & 1);
    }
    for (int it = 0; it < 5000; ++it) {
      const SweepLine& lp = pieces[(*rng)() % 3];
      const int64_t v_abs = static_cast<int64_t>((*rng)() % 200) * 100000;  // 200 row offsets, 25 um apart
      int64_t w_memo = 0, w_abs = 0;
      const bool ok_memo = bull_flank_w_memo(t, lp, v_abs, &w_memo);
      const bool ok = bull_flank_w(t, lp.m_geo_q30, lp.ball_sin_q30, v_abs, &w_abs);
      const int64_t w = lp.m_geo_q30 < 0 ? -w_abs : w_abs;
      ++*calls;
      if (ok_memo != ok || (ok && w_memo != w)) ++*differ;
      // Ask again at once: now a hit, the same bits.
      int64_t w_again = 0;
      if (ok && bull_flank_w_memo(t, lp, v_abs, &w_again) && w_again == w) ++*hits;
    }
  }
}

}  // namespace

TEST(sweep_bull_memo_gives_the_computed_bits) {
  // The chain's memo is a cache: through it (hashed slots, or row slots
  // with the pieces in ways 0, 1, 0), w* is the bits bull_flank_w computes,
  // for pieces of several slopes met in turn (as a chain's rows meet the
  // last piece's), past collisions and evictions, and after a change of
  // tool (which empties it).
  std::mt19937_64 rng(7);
  int differ = 0, hits = 0, calls = 0;
  check_memo(0, &rng, &differ, &hits, &calls);
  check_memo(((uint64_t{1} << 32) + 49999) / 50000, &rng, &differ, &hits, &calls);  // a 25 um pitch's
  CHECK_EQ(differ, 0);
  CHECK_EQ(hits, calls);
}
