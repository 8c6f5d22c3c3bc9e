// The sweep's column loops in both word widths (core/config.h,
// kSweepWordBits; core/cut/sweep_piece.h, the row kernels): 32-bit words
// on CPUs without 128-bit integers, 64-bit ones elsewhere, so a host's
// golden output checks only the 64-bit kernels. Here both cut the same
// moves, chains and arcs, for every tool kind and height type, and must
// leave the same grids and count the same visits; test_sweep.cpp and
// test_sweep_bull.cpp hold both to the double oracle.
#include <algorithm>
#include <cstdint>
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

// Tools of every kind; the last two: a ball 300 mm across (R beyond the
// 32-bit kernels' 2^28 U, so they take their 64-bit form) and one whose
// shaft sinks below the stock's top (figure 2 in full, not a min()).
const Tool kTools[] = {fixtures::test_tool(ToolKind::kBall, mm(6), 0, 0, mm(60)),
                       fixtures::test_tool(ToolKind::kBall, 3175000, 0, 0, mm(60)),
                       fixtures::test_tool(ToolKind::kFlat, mm(5), 0, 0, mm(60)),
                       fixtures::test_tool(ToolKind::kBullNose, mm(8), mm(2), 0, mm(60)),
                       fixtures::test_tool(ToolKind::kVBit, mm(6), 0, 90000, mm(60)),
                       fixtures::test_tool(ToolKind::kVBit, mm(4), 0, 30000, mm(60)),
                       fixtures::test_tool(ToolKind::kBall, mm(300), 0, 0, mm(400)),
                       fixtures::test_tool(ToolKind::kBall, mm(4), 0, 0, mm(12))};
constexpr int kToolCount = sizeof(kTools) / sizeof(kTools[0]);

// Random moves over a size_mm square at heights z in [zlo, zhi] mm: general
// directions, plunges, lines along x and y, on a row and half way between
// two (mirrored rows), short and steep ones, joined or not.
std::vector<PointNm> random_path(double size_mm, double zlo, double zhi, int64_t pitch, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto nm = [](double v_mm) { return static_cast<int64_t>(v_mm * 1e6); };
  std::vector<PointNm> p;
  PointNm at{nm(size_mm * u01(*rng)), nm(size_mm * u01(*rng)), nm(zhi)};
  p.push_back(at);
  for (int k = 0; k < 60; ++k) {
    const double r = u01(*rng);
    PointNm b{nm(size_mm * (u01(*rng) * 1.2 - 0.1)), nm(size_mm * (u01(*rng) * 1.2 - 0.1)),
              nm(zlo + (zhi - zlo) * u01(*rng))};
    if (r < 0.1) b = PointNm{at.x_nm, at.y_nm, nm(zlo + (zhi - zlo) * u01(*rng))};   // plunge
    else if (r < 0.3) b.y_nm = at.y_nm;                                              // along x
    else if (r < 0.4) b.x_nm = at.x_nm;                                              // along y
    else if (r < 0.5) b = PointNm{at.x_nm + nm(u01(*rng) - 0.5), at.y_nm + 1, b.z_nm};  // short, steep
    if (r >= 0.1 && r < 0.2) b.y_nm = at.y_nm = (at.y_nm / pitch) * pitch + (k % 2) * (pitch / 2);  // mirrored
    p.push_back(b);
    at = b;
  }
  return p;
}

struct Tally {
  int runs = 0, differ = 0;
  uint64_t updates = 0;
};

// Cuts with cut(grid, sweep, stats, chain) in both widths into fresh grids
// of stock 30 mm deep; the grids and the stats must be the same.
template <class H, class Cut>
void both_widths(const Tool& tool, int32_t n, int64_t pitch, int64_t lsb, const char* what, Cut cut, Tally* tally) {
  fixtures::TestGrid<H> g32(n, n, pitch, lsb), g64(n, n, pitch, lsb);
  g32.fill(mm(30));
  g64.fill(mm(30));
  SweepTool t;
  if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &t), Status::kOk)) return;
  const fixtures::Sweep<H, 32> w32{t, kSweepDefaults};
  const fixtures::Sweep<H, 64> w64{t, kSweepDefaults};
  CutStats s32, s64;
  SweepChain c32, c64;
  cut(&g32.g, w32, &s32, &c32);
  cut(&g64.g, w64, &s64, &c64);
  w32.chain_end(&g32.g, &s32, &c32);
  w64.chain_end(&g64.g, &s64, &c64);
  ++tally->runs;
  tally->updates += s64.dexel_updates;
  const bool same = g32.top == g64.top && g32.bottom == g64.bottom && s32.dexel_updates == s64.dexel_updates &&
                    s32.instances == s64.instances && s32.floor_skips == s64.floor_skips &&
                    s32.row_skips == s64.row_skips;
  if (!same && ++tally->differ <= 5)
    std::printf("  %s m=%d d=%lld pitch %lld lsb %lld: the widths differ\n", what, int(sizeof(H) * 8),
                static_cast<long long>(tool.diameter_nm), static_cast<long long>(pitch), static_cast<long long>(lsb));
}

// Every tool on one height type: random moves one by one and chained,
// chained rasters along x, and arcs (exact, helices and chords).
template <class H>
void run_type(int64_t lsb, uint64_t seed, Tally* tally) {
  std::mt19937_64 rng(seed);
  for (int k = 0; k < kToolCount; ++k) {
    const Tool& tool = kTools[k];
    const int64_t pitch = k % 2 ? 250000 : 170000;
    const int32_t n = 64;
    const double size = n * pitch / 1e6;
    // Short tools plunge deep (their shaft sinks), the others stay above.
    const double zlo = tool.length_nm < mm(20) ? 10 : 22, zhi = 34;
    const std::vector<PointNm> path = random_path(size, zlo, zhi, pitch, &rng);
    const std::vector<PointNm> raster = fixtures::raster_path(size, std::min(tool.diameter_nm / 2e6, size / 4), pitch / 1e6, &rng);
    both_widths<H>(tool, n, pitch, lsb, "moves", [&](DexelGrid<H>* g, const auto& sw, CutStats* st, SweepChain*) {
      for (size_t i = 1; i < path.size(); ++i) sw.line(g, path[i - 1], path[i], st);
    }, tally);
    both_widths<H>(tool, n, pitch, lsb, "chain", [&](DexelGrid<H>* g, const auto& sw, CutStats* st, SweepChain* c) {
      for (size_t i = 1; i < path.size(); ++i) sw.chain_line(g, path[i - 1], path[i], st, c);
    }, tally);
    both_widths<H>(tool, n, pitch, lsb, "raster", [&](DexelGrid<H>* g, const auto& sw, CutStats* st, SweepChain* c) {
      for (size_t i = 1; i < raster.size(); ++i) sw.chain_line(g, raster[i - 1], raster[i], st, c);
    }, tally);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::vector<CanonRecord> arcs;
    for (int a = 0; a < 8; ++a) {
      const double c_nm = size * 1e6 / 2, ra = (0.1 + 0.4 * u01(rng)) * size * 1e6;
      const double z0 = (zlo + (zhi - zlo) * u01(rng)) * 1e6, z1 = a % 2 ? z0 : (zlo + (zhi - zlo) * u01(rng)) * 1e6;
      arcs.push_back(fixtures::arc_record(c_nm, c_nm, ra, 6.28 * u01(rng), (a % 3 ? 1 : -1) * 6 * u01(rng), z0, z1));
    }
    both_widths<H>(tool, n, pitch, lsb, "arcs", [&](DexelGrid<H>* g, const auto& sw, CutStats* st, SweepChain* c) {
      for (size_t a = 0; a < arcs.size(); ++a) {
        if (a % 2) sw.chain_arc(g, arcs[a], st, c);
        else sw.arc(g, arcs[a], st);
      }
    }, tally);
  }
}

}  // namespace

TEST(sweep_both_word_widths_cut_the_same_bits) {
  Tally tally;
  run_type<uint16_t>(500, 11, &tally);
  run_type<uint8_t>(100000, 12, &tally);
  // The finest LSB: ramps whose V-per-U slope exceeds int32 in q32 (the
  // 32-bit kernels' 64-bit slope products).
  run_type<uint32_t>(20, 13, &tally);
  std::printf("  both widths: %d runs, %llu visits, %d differ\n", tally.runs,
              static_cast<unsigned long long>(tally.updates), tally.differ);
  CHECK_EQ(tally.differ, 0);
  CHECK_EQ(tally.runs, 3 * kToolCount * 4);
}
