// core/cut/sweep_piece.h, ball_floor_of: leaving out the columns whose top is
// under the ball's floor changes no bit. Each path is cut twice, with the
// skip and without (SweepTuning::skip_under_floor), chained and move by move,
// and the grids must be equal; the skip must also have happened.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/cut/sweep.h"
#include "core/cut/sweep_internal.h"
#include "core/grid/grid.h"
#include "core/canon/canon.h"
#include "core/tool/tool.h"
#include "tests/cut_fixtures.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using fixtures::mm;

enum class Path { kSpiral, kCrossing, kTiny };

// Paths over a w x h mm grid that cut into what earlier moves left (where
// the floor test decides): a spiral pocket on a wavy floor (ramps in every
// direction), long moves across at random depths (steep ramps), and moves
// of 1 to 60 um (slopes from heights rounded to V over a few U: the caps'
// term of the floor).
std::vector<PointNm> make_path(Path kind, double w_mm, double h_mm, double r_mm, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * u01(*rng); };
  auto at = [](double x, double y, double z) {
    return PointNm{std::llround(x * 1e6), std::llround(y * 1e6), std::llround(z * 1e6)};
  };
  std::vector<PointNm> p;
  const double cx = w_mm / 2, cy = h_mm / 2;
  switch (kind) {
    case Path::kSpiral: {
      const double step = rnd(0.2, 0.7) * r_mm, b = step / 6.2832, seg = rnd(0.05, 1.0) * r_mm;
      const double amp = rnd(0.0, 1.5), phase = rnd(0, 6.28);
      for (double th = 0; b * th < std::min(cx, cy) - 1;) {
        const double r = b * th, x = cx + r * std::cos(th), y = cy + r * std::sin(th);
        p.push_back(at(x, y, 20 + amp * std::sin(x / 3 + phase) * std::cos(y / 4) + rnd(-0.02, 0.02)));
        th += seg / std::sqrt(r * r + b * b);
      }
      break;
    }
    case Path::kCrossing:
      for (int k = 0; k < 40; ++k) p.push_back(at(rnd(1, w_mm - 1), rnd(1, h_mm - 1), rnd(14, 26)));
      break;
    case Path::kTiny: {
      double x = cx, y = cy, z = 20, dir = rnd(0, 6.28);
      for (int k = 0; k < 500; ++k) {
        dir += rnd(-0.5, 0.5);
        const double len = rnd(0.001, 0.06);
        x = std::min(w_mm - 1, std::max(1.0, x + len * std::cos(dir)));
        y = std::min(h_mm - 1, std::max(1.0, y + len * std::sin(dir)));
        z = std::min(24.0, std::max(16.0, z + rnd(-0.03, 0.03)));
        p.push_back(at(x, y, z));
      }
      break;
    }
  }
  return p;
}

struct Count {
  int64_t runs = 0, unequal = 0;
  uint64_t skips = 0, updates = 0;
};

// Cuts with cut(grid, sweep, stats, chain) twice, with the skip and without,
// and needs the same grids and visits.
template <class H, class Cut>
void compare_skip(const Tool& tool, int32_t n, int64_t pitch, int64_t lsb, const char* what, Count* c, Cut cut) {
  CutStats s_on, s_off;
  bool equal = false;
  if (!CHECK(fixtures::cut_on_and_off<H>(tool, n, pitch, lsb, &SweepTuning::skip_under_floor, cut, &s_on, &s_off, &equal)))
    return;
  ++c->runs;
  c->skips += s_on.floor_skips;
  c->updates += s_on.dexel_updates;
  CHECK_EQ(s_off.floor_skips, uint64_t{0});
  CHECK_EQ(s_on.dexel_updates, s_off.dexel_updates);  // skipped columns still count as visited
  if (!equal) {
    if (++c->unequal <= 5) std::printf("  %s m=%d lsb %lld tool d=%lld: grids differ\n", what, int(sizeof(H) * 8),
                                       static_cast<long long>(lsb), static_cast<long long>(tool.diameter_nm));
  }
}

template <class H>
void compare(const Tool& tool, const std::vector<PointNm>& path, int32_t n, int64_t pitch, int64_t lsb, bool chained,
             Count* c) {
  compare_skip<H>(tool, n, pitch, lsb, "lines", c, [&](DexelGrid<H>* g, const fixtures::Sweep<H>& sw, CutStats* st, SweepChain* ch) {
    for (size_t k = 1; k < path.size(); ++k) {
      if (chained) sw.chain_line(g, path[k - 1], path[k], st, ch);
      else sw.line(g, path[k - 1], path[k], st);
    }
  });
}

template <class H>
void run_all(int64_t lsb, uint64_t seed, Count* c) {
  std::mt19937_64 rng(seed);
  // Long enough to reach above the stock (a shaft below it turns the skip
  // off), and a short one that does not.
  const Tool tools[] = {fixtures::test_tool(ToolKind::kBall, mm(6), 0, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBall, 3175000, 0, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBall, 700000, 0, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBall, mm(4), 0, 0, mm(12))};
  for (const Tool& tool : tools) {
    const double r_mm = tool.diameter_nm / 2e6;
    for (Path kind : {Path::kSpiral, Path::kCrossing, Path::kTiny}) {
      // Tiny moves on a fine grid (0.04 mm), the others at 0.25 mm.
      const int64_t pitch = kind == Path::kTiny ? 40000 : 250000;
      const int32_t n = kind == Path::kTiny ? 80 : 100;
      const double size_mm = n * pitch / 1e6;
      const std::vector<PointNm> path = make_path(kind, size_mm, size_mm, r_mm, &rng);
      for (bool chained : {true, false}) compare<H>(tool, path, n, pitch, lsb, chained, c);
    }
  }
}

}  // namespace

TEST(sweep_floor_skip_changes_no_bit) {
  Count c;
  run_all<uint8_t>(120000, 21, &c);
  run_all<uint16_t>(1000, 22, &c);
  run_all<uint16_t>(7, 23, &c);
  run_all<uint32_t>(1, 24, &c);
  std::printf("sweep floor skip: %lld runs, %llu of %llu visits skipped, %lld runs differ\n",
              static_cast<long long>(c.runs), static_cast<unsigned long long>(c.skips),
              static_cast<unsigned long long>(c.updates), static_cast<long long>(c.unequal));
  CHECK_EQ(c.unequal, 0);
  // The test means something only where the skip happens often.
  CHECK(c.skips * 10 >= c.updates);
}

// Level arcs: a ring pocket from the centre out (each ring two half turns,
// a step deeper now and then), then arcs across it at random, level and
// helical, at random depths.
std::vector<CanonRecord> make_arcs(double size_nm, double r_nm, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * u01(*rng); };
  std::vector<CanonRecord> arcs;
  const double c = size_nm / 2, step = rnd(0.1, 0.4) * r_nm;
  double z = mm(20);
  for (double ra = step; ra < c - r_nm; ra += step) {
    if (u01(*rng) < 0.3) z -= rnd(0, 3e5);
    arcs.push_back(fixtures::arc_record(c, c, ra, 0, 3.14159, z, z));
    arcs.push_back(fixtures::arc_record(c, c, ra, 3.14159, 3.14159, z, z));
  }
  for (int k = 0; k < 12; ++k) {
    const double z0 = rnd(double(mm(15)), double(mm(24)));
    const double z1 = k % 3 == 0 ? z0 - rnd(0, 2e6) : z0;
    arcs.push_back(fixtures::arc_record(rnd(0.2, 0.8) * size_nm, rnd(0.2, 0.8) * size_nm, rnd(0.3, 1.5) * c,
                                        rnd(0, 6.28), rnd(-6, 6), z0, z1));
  }
  return arcs;
}

template <class H>
void compare_arcs(const Tool& tool, int64_t lsb, uint64_t seed, Count* c) {
  std::mt19937_64 rng(seed);
  const int32_t n = 100;
  const int64_t pitch = 250000;
  const std::vector<CanonRecord> arcs = make_arcs(double(n * pitch), double(tool.diameter_nm / 2), &rng);
  compare_skip<H>(tool, n, pitch, lsb, "arcs", c, [&](DexelGrid<H>* g, const fixtures::Sweep<H>& sw, CutStats* st, SweepChain* ch) {
    for (size_t k = 0; k < arcs.size(); ++k) {
      if (k % 2) sw.chain_arc(g, arcs[k], st, ch);
      else sw.arc(g, arcs[k], st);
    }
  });
}

TEST(sweep_floor_skip_on_arcs_changes_no_bit) {
  Count c;
  for (int64_t d : {mm(6), int64_t{3175000}, int64_t{700000}}) {
    const Tool ball = fixtures::test_tool(ToolKind::kBall, d, 0, 0, mm(60));
    compare_arcs<uint8_t>(ball, 120000, 41 + d, &c);
    compare_arcs<uint16_t>(ball, 1000, 42 + d, &c);
    compare_arcs<uint16_t>(ball, 7, 43 + d, &c);
    compare_arcs<uint32_t>(ball, 1, 44 + d, &c);
  }
  std::printf("sweep floor skip, arcs: %lld runs, %llu of %llu visits skipped, %lld runs differ\n",
              static_cast<long long>(c.runs), static_cast<unsigned long long>(c.skips),
              static_cast<unsigned long long>(c.updates), static_cast<long long>(c.unequal));
  CHECK_EQ(c.unequal, 0);
  // Fewer than along lines: an arc piece visits its box, whose columns off
  // the ring are out of reach before any floor (6.8 % when measured).
  CHECK(c.skips * 20 >= c.updates);
}

TEST(sweep_bowl_against_double) {
  // sweep_bowl_v(r2) = r^2 g / (2R) in V rounded down, g = V per U: never
  // above the exact value, below it by at most 1 V + 2^-30 of the value at
  // the rim (R g / 2; core/cut/sweep_tool.cpp).
  std::mt19937_64 rng(31);
  int64_t cases = 0;
  for (int64_t lsb : {1, 7, 381, 1000, 120000, 1 << 30}) {
    for (int k = 0; k < 200; ++k) {
      Tool tool = fixtures::test_tool(ToolKind::kBall, 2 + static_cast<int64_t>(rng() % (static_cast<uint64_t>(1) << (k % 28 + 1))), 0, 0, mm(60));
      SweepTool t;
      if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &t), Status::kOk)) return;
      const double g = std::ldexp(static_cast<double>(t.v_per_u_q32), -32);
      for (int s = 0; s < 20; ++s) {
        const int64_t r2 = s == 0 ? t.r2_u : static_cast<int64_t>(rng() % static_cast<uint64_t>(t.r2_u + 1));
        const double exact = static_cast<double>(r2) * g / (2.0 * static_cast<double>(t.r_u));
        const double got = static_cast<double>(sweep_bowl_v(t, r2));
        const double rim = static_cast<double>(t.r_u) * g / 2;
        if (!CHECK(got <= exact * (1 + 1e-15)) || !CHECK(got >= exact - 1.0 - std::ldexp(rim, -30))) {
          std::printf("  lsb %lld R %lld U r2 %lld: %.3f vs %.3f\n", static_cast<long long>(lsb),
                      static_cast<long long>(t.r_u), static_cast<long long>(r2), got, exact);
          return;
        }
        ++cases;
      }
    }
  }
  CHECK(cases > 20000);
}
