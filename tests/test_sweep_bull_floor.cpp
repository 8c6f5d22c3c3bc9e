// core/cut/sweep_piece.h, bull_row_above: leaving out the bull nose's rows
// along x whose tops are all under the row's floor changes no bit. Each path
// is cut twice, with the skip and without (SweepTuning::bull_row_floor),
// chained and move by move, and the grids and the visits must be equal; the
// skip must also have happened, often.
//
// The paths: rasters along x (fixtures::raster_path: ramps of every slope,
// pieces of a few um to a few mm, passes over what the earlier ones left),
// ramps along x of random steepness and length over a grid cut at random
// heights before, and moves of 1 to 60 um (slopes from heights rounded to V
// over a few U). Each path is cut a second time a little lower (0 to 3 LSB
// and a fraction), so that many rows' highest tops sit within a few V of the
// heights they would take. And rows right at the floor: level and rising
// moves whose floor on one row is one V under the keep height of the tops
// (sweep_keep_v), where that row must be cut: a floor one V too high fails
// the test.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/cut/sweep.h"
#include "core/cut/sweep_internal.h"
#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "tests/cut_fixtures.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using fixtures::mm;

enum class Path { kRaster, kRamps, kTiny };

std::vector<PointNm> make_path(Path kind, double size_mm, double r_mm, double pitch_mm, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * u01(*rng); };
  auto at = [](double x, double y, double z) {
    return PointNm{std::llround(x * 1e6), std::llround(y * 1e6), std::llround(z * 1e6)};
  };
  std::vector<PointNm> p;
  switch (kind) {
    case Path::kRaster:
      return fixtures::raster_path(size_mm, r_mm, pitch_mm, rng);
    case Path::kRamps:
      // Rows of ramps along x, each at its own y (on a row, half way or
      // anywhere), of random slope (gentle to 80 degrees) and length.
      for (int k = 0; k < 30; ++k) {
        const double y = std::round(rnd(r_mm, size_mm - r_mm) / pitch_mm) * pitch_mm +
                         (k % 3 == 0 ? 0.0 : k % 3 == 1 ? pitch_mm / 2 : rnd(0, pitch_mm));
        double x = rnd(r_mm, size_mm - r_mm), z = rnd(16, 24);
        p.push_back(at(x, y, z));
        for (int s = 0; s < 6; ++s) {
          const double len = rnd(0.001, 1.0) * (u01(*rng) < 0.3 ? 10 : 1);
          const double slope = std::tan(rnd(-1.4, 1.4)) * (u01(*rng) < 0.3 ? 0.01 : 1);
          x = std::min(size_mm - r_mm, std::max(r_mm, x + (u01(*rng) < 0.5 ? len : -len)));
          z = std::min(25.0, std::max(15.0, z + slope * len));
          p.push_back(at(x, y, z));
        }
      }
      break;
    case Path::kTiny: {
      double x = size_mm / 2, y = std::round(size_mm / 2 / pitch_mm) * pitch_mm, z = 20;
      for (int k = 0; k < 400; ++k) {
        if (k % 50 == 0) y += pitch_mm * std::floor(rnd(0, 3)) + (k % 100 == 0 ? pitch_mm / 2 : 0);
        const double len = rnd(0.001, 0.06);
        x = std::min(size_mm - r_mm, std::max(r_mm, x + (u01(*rng) < 0.7 ? len : -len)));
        y = std::min(size_mm - r_mm, y);
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
  uint64_t row_skips = 0, updates = 0;
};

// Cuts path (and the same path dz_nm lower) with and without the skip, and
// needs the same grids and visits.
template <class H>
void compare(const Tool& tool, const std::vector<PointNm>& path, int32_t n, int64_t pitch, int64_t lsb, bool chained,
             int64_t dz_nm, Count* c) {
  // Both passes through one chain a grid, ended after each pass.
  auto cut = [&](DexelGrid<H>* g, const fixtures::Sweep<H>& sw, CutStats* st, SweepChain* ch) {
    for (int64_t drop : {int64_t{0}, dz_nm}) {
      for (size_t k = 1; k < path.size(); ++k) {
        PointNm a = path[k - 1], b = path[k];
        a.z_nm -= drop;
        b.z_nm -= drop;
        if (chained) sw.chain_line(g, a, b, st, ch);
        else sw.line(g, a, b, st);
      }
      sw.chain_end(g, st, ch);
    }
  };
  CutStats s_on, s_off;
  bool equal = false;
  if (!CHECK(fixtures::cut_on_and_off<H>(tool, n, pitch, lsb, &SweepTuning::bull_row_floor, cut, &s_on, &s_off, &equal)))
    return;
  ++c->runs;
  c->row_skips += s_on.row_skips;
  c->updates += s_on.dexel_updates;
  CHECK_EQ(s_off.row_skips, uint64_t{0});
  CHECK_EQ(s_on.dexel_updates, s_off.dexel_updates);  // a skipped row's columns still count as visited
  if (!equal) {
    if (++c->unequal <= 5)
      std::printf("  m=%d lsb %lld pitch %lld tool d=%lld rc=%lld %s: grids differ\n", int(sizeof(H) * 8),
                  static_cast<long long>(lsb), static_cast<long long>(pitch),
                  static_cast<long long>(tool.diameter_nm), static_cast<long long>(tool.corner_radius_nm),
                  chained ? "chained" : "move by move");
  }
}

template <class H>
void run_all(int64_t lsb, uint64_t seed, Count* c) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  // Corners from nearly none to nearly a ball, small tools to large.
  const Tool tools[] = {fixtures::test_tool(ToolKind::kBullNose, mm(3), 500000, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, mm(6), mm(1), 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, mm(6), 2900000, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, mm(4), 50000, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, 1500000, 300000, 0, mm(60))};
  const int64_t pitches[] = {100000, 170000, 250000, 40000};
  int k = 0;
  for (const Tool& tool : tools) {
    const double r_mm = tool.diameter_nm / 2e6;
    for (Path kind : {Path::kRaster, Path::kRamps, Path::kTiny}) {
      const int64_t pitch = pitches[k++ % 4];
      const int32_t n = kind == Path::kTiny ? 60 : 72;
      const double size_mm = n * pitch / 1e6;
      if (size_mm < 4 * r_mm) continue;
      const std::vector<PointNm> path = make_path(kind, size_mm, r_mm, pitch / 1e6, &rng);
      // 0 to 3 LSB lower and a fraction of one (or exactly none).
      const int64_t dz = u01(rng) < 0.2 ? 0 : static_cast<int64_t>(u01(rng) * 3.5 * static_cast<double>(lsb));
      for (bool chained : {true, false}) compare<H>(tool, path, n, pitch, lsb, chained, dz, c);
    }
  }
}

}  // namespace

TEST(sweep_bull_row_floor_changes_no_bit) {
  Count c;
  run_all<uint8_t>(120000, 31, &c);
  run_all<uint16_t>(1000, 32, &c);
  run_all<uint16_t>(500, 33, &c);
  run_all<uint16_t>(460, 34, &c);
  run_all<uint32_t>(1, 35, &c);
  run_all<uint32_t>(3, 36, &c);
  std::printf("bull row floor: %lld runs, %llu rows skipped, %llu visits, %lld runs differ\n",
              static_cast<long long>(c.runs), static_cast<unsigned long long>(c.row_skips),
              static_cast<unsigned long long>(c.updates), static_cast<long long>(c.unequal));
  CHECK_EQ(c.unequal, 0);
  // The test means something only where the skip happens often.
  CHECK(c.row_skips * 200 >= c.updates);
}

// Level and rising moves along +x over flat tops T, their height chosen so
// that a row of the flat part (or any row: v = k pitches, P(v2) its profile)
// has za + P(v2) = sweep_keep_v(T) - 1, one V under: its flank takes
// za + P(v2) exactly (w* = 0 when level; a rise of a few V over the move
// leaves the first flank column there too), so the row's dexels drop to
// T - 1 (level pieces are left to the row loop, bull_trim_rows: they check
// only that nothing changes). And runs that fall with zlo + P(v2) = sweep_keep_v(T), whose
// lowest flank heights are under it by the roundings. With lsb = 256 nm,
// V = 1 nm: z in nm is za in V.
TEST(sweep_bull_row_floor_at_its_edge) {
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  const Tool tools[] = {fixtures::test_tool(ToolKind::kBullNose, mm(3), 500000, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, mm(6), mm(1), 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, mm(4), 50000, 0, mm(60)),
                        fixtures::test_tool(ToolKind::kBullNose, 1500000, 300000, 0, mm(60))};
  const int64_t lsb = 256, pitches[] = {100000, 170000, 250000};
  int runs = 0, differ = 0, cut_rows[2] = {0, 0}, family_runs[2] = {0, 0};
  for (int trial = 0; trial < 240; ++trial) {
    const Tool& tool = tools[trial % 4];
    const int64_t pitch = pitches[(trial / 4) % 3];
    const int32_t n = 64;
    SweepTool on;
    if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &on), Status::kOk)) return;
    SweepTuning k_off;
    k_off.bull_row_floor = false;
    const fixtures::Sweep<uint16_t> off{on, k_off};
    const int64_t r_nm = tool.diameter_nm / 2;
    // The track on row j0; the row k pitches off it is the one at the edge.
    const int32_t j0 = n / 2;
    const int64_t k = pick(rng) % (r_nm / pitch + 1);
    const int64_t v_u = k * pitch * kSweepUnitsPerNm;
    const int64_t p_v = sweep_profile_v(on, std::min(v_u * v_u, on.r2_u));
    const int64_t top = 40000 + pick(rng) % 20000;
    const int64_t keep = (top << kSweepVBits) - 128;  // sweep_keep_v(top), V = nm
    const int64_t x0 = r_nm + pitch * (pick(rng) % 8) + pick(rng) % pitch;
    PointNm a, b;
    int64_t len;
    if (trial % 5 < 3) {  // level or rising along +x: za + P(v2) = keep - 1
      const int64_t za = keep - 1 - p_v, rise = trial % 5 == 0 ? 0 : pick(rng) % 8;
      len = mm(1) + pick(rng) % mm(2);
      a = PointNm{x0, j0 * pitch, za};
      b = PointNm{x0 + len, j0 * pitch, za + rise};
    } else {
      // Runs that fall (falling along +x, rising along -x), 2^20 nm long so
      // that S(l) = zb - za exactly: zlo + P(v2) = keep, where only the
      // floor's allowance for the falling run (bull_row_above's e) keeps the
      // row from being left.
      len = int64_t{1} << 20;
      const int64_t zlo = keep - p_v, drop = 1 + pick(rng) % 8;
      if (trial % 5 == 3) {
        a = PointNm{x0, j0 * pitch, zlo + drop};
        b = PointNm{x0 + len, j0 * pitch, zlo};
      } else {
        a = PointNm{x0 + len, j0 * pitch, zlo};
        b = PointNm{x0, j0 * pitch, zlo + drop};
      }
    }
    fixtures::TestGrid<uint16_t> with(n, n, pitch, lsb), without(n, n, pitch, lsb);
    with.fill(top * lsb);
    without.fill(top * lsb);
    CutStats s_on, s_off;
    if (trial % 2) {
      sweep_line(&with.g, on, a, b, &s_on);
      off.line(&without.g, a, b, &s_off);
    } else {  // chained: a level lead-in first, then the move
      SweepChain c_on, c_off;
      const PointNm lead{a.x_nm + (b.x_nm > a.x_nm ? -pitch / 2 : pitch / 2), a.y_nm, a.z_nm};
      sweep_chain_line(&with.g, on, lead, a, &s_on, &c_on);
      off.chain_line(&without.g, lead, a, &s_off, &c_off);
      sweep_chain_line(&with.g, on, a, b, &s_on, &c_on);
      off.chain_line(&without.g, a, b, &s_off, &c_off);
      sweep_chain_end(&with.g, on, &s_on, &c_on);
      off.chain_end(&without.g, &s_off, &c_off);
    }
    ++runs;
    CHECK_EQ(s_on.dexel_updates, s_off.dexel_updates);
    // The row at the edge was cut (the test's premise).
    const int family = trial % 5 < 3 ? 0 : 1;
    ++family_runs[family];
    bool row_cut = false;  // somewhere along the edge row
    for (int32_t i = 0; i < n; ++i) row_cut = row_cut || without.top[without.g.index(i, static_cast<int32_t>(j0 + k))] < top;
    if (row_cut) ++cut_rows[family];
    if ((with.top != without.top || with.bottom != without.bottom) && ++differ <= 5)
      std::printf("  trial %d: d=%lld rc=%lld pitch %lld row %lld: grids differ\n", trial,
                  static_cast<long long>(tool.diameter_nm), static_cast<long long>(tool.corner_radius_nm),
                  static_cast<long long>(pitch), static_cast<long long>(k));
  }
  std::printf("bull row floor at its edge: %d runs, the edge row cut in %d of %d level or rising, %d of %d falling; %d differ\n",
              runs, cut_rows[0], family_runs[0], cut_rows[1], family_runs[1], differ);
  CHECK_EQ(differ, 0);
  // The premise: the edge rows are cut, most of the time (a falling run's
  // lowest heights are under zlo + P(v2) only by the roundings).
  CHECK(cut_rows[0] * 4 >= family_runs[0] * 3);
  CHECK(cut_rows[1] * 5 >= family_runs[1]);
}
