// core/cut/sweep.h: the swept envelope of straight moves against a double
// oracle (random moves, every shape), against stamping, ramps at the right
// depth along their whole length, golden hashes, no heap.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/cut/stamp.h"
#include "core/cut/sweep.h"
#include "core/cut/sweep_internal.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/alloc_count.h"
#include "tests/cut_fixtures.h"
#include "tests/runner.h"
#include "tests/sweep_oracle.h"

using namespace dexmill;

namespace {

using fixtures::mm;

// A grid with material up to z = 30 mm (or the top of the m-bit range).
template <class H>
struct Fixture : fixtures::TestGrid<H> {
  Fixture(int32_t nx, int32_t ny, int64_t pitch, int64_t lsb) : fixtures::TestGrid<H>(nx, ny, pitch, lsb) {
    this->fill(mm(30));
  }
};

Tool make_tool(ToolKind k, int64_t d, int64_t rc = 0, int32_t mdeg = 0) { return fixtures::test_tool(k, d, rc, mdeg, mm(60)); }

const Tool kTools[] = {make_tool(ToolKind::kBall, mm(6)),         make_tool(ToolKind::kFlat, mm(5)),
                       make_tool(ToolKind::kBullNose, mm(8), mm(2)), make_tool(ToolKind::kVBit, mm(6), 0, 90000),
                       make_tool(ToolKind::kVBit, mm(4), 0, 30000), make_tool(ToolKind::kBall, 3175000)};
const char* const kToolNames[] = {"ball6", "flat5", "bull8r2", "vbit90", "vbit30", "ball3.175"};

// Checks every dexel of the grid after one move, cut with the column loops
// in W-bit words (core/config.h, kSweepWordBits), against the oracle with
// the backward bound of core/cut/sweep.h: within 1 LSB of the exact height at
// the column or at the column moved by 1 nm in x or y.
template <class H, int W>
int check_move_w(const Tool& tool, const char* name, PointNm a, PointNm b, int64_t pitch, int64_t lsb, int report) {
  Fixture<H> f(64, 48, pitch, lsb);
  SweepTool st_tool;
  if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &st_tool), Status::kOk)) return 1;
  CutStats st;
  sweep_line_w<H, W>(&f.g, st_tool, kSweepDefaults, a, b, &st, true);
  oracle::P3 pa{double(a.x_nm), double(a.y_nm), double(a.z_nm)}, pb{double(b.x_nm), double(b.y_nm), double(b.z_nm)};
  int bad = 0;
  const double hmax = static_cast<double>(f.stock_lsb);
  for (int32_t j = 0; j < f.g.ny; ++j) {
    for (int32_t i = 0; i < f.g.nx; ++i) {
      const double px = double(i) * pitch, py = double(j) * pitch;
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (auto& o : oracle::kNeighbours) {
        double h = oracle::lowest_on_line(tool, pa, pb, px + o[0], py + o[1]);
        double lsbs = h == HUGE_VAL ? hmax : std::min(hmax, h / lsb);
        if (lsbs < 0) lsbs = 0;  // below the floor: a hole
        lo = std::min(lo, lsbs);
        hi = std::max(hi, lsbs);
      }
      const double got = f.g.top[f.g.index(i, j)];
      if (got < lo - 1.0 || got > hi + 1.0) {
        if (++bad <= report)
          std::printf("  %s m=%d w=%d: dexel (%d,%d) top %.0f, oracle [%.3f, %.3f] for move (%lld,%lld,%lld)->(%lld,%lld,%lld)\n",
                      name, int(sizeof(H) * 8), W, i, j, got, lo, hi, (long long)a.x_nm, (long long)a.y_nm,
                      (long long)a.z_nm, (long long)b.x_nm, (long long)b.y_nm, (long long)b.z_nm);
      }
    }
  }
  return bad;
}

// Both word widths against the oracle.
template <class H>
int check_move(const Tool& tool, const char* name, PointNm a, PointNm b, int64_t pitch, int64_t lsb, int report) {
  return check_move_w<H, 32>(tool, name, a, b, pitch, lsb, report) +
         check_move_w<H, 64>(tool, name, a, b, pitch, lsb, report);
}

}  // namespace

TEST(sweep_random_moves_against_oracle) {
  std::mt19937_64 rng(2026);
  const int64_t pitch = 250000;  // 64 x 48 dexels = 16 x 12 mm
  int bad = 0, moves = 0;
  for (int t = 0; t < 6; ++t) {
    for (int it = 0; it < 14; ++it) {
      auto coord = [&](int64_t span) { return static_cast<int64_t>(rng() % static_cast<uint64_t>(span)) - mm(2); };
      PointNm a{coord(mm(20)), coord(mm(16)), mm(5) + static_cast<int64_t>(rng() % mm(10))};
      PointNm b{coord(mm(20)), coord(mm(16)), mm(5) + static_cast<int64_t>(rng() % mm(10))};
      if (it == 0) b = PointNm{a.x_nm, a.y_nm, a.z_nm - mm(3)};       // plunge
      if (it == 1) b = PointNm{a.x_nm + mm(9), a.y_nm, a.z_nm};        // level along x
      if (it == 2) b = PointNm{a.x_nm, a.y_nm + mm(7), a.z_nm - mm(2)};  // ramp along y
      if (it == 3) b = a;                                              // zero length
      if (it == 4) b = PointNm{a.x_nm + mm(6), a.y_nm + 1, a.z_nm - mm(6)};  // steep ramp
      // Along x on a row and half way between two: the mirrored rows.
      if (it == 5) a.y_nm = b.y_nm = pitch * 23;
      if (it == 6) a.y_nm = b.y_nm = pitch * 17 + pitch / 2;
      // Level along x on a row and half way: the mirrored rows' level runs.
      if (it == 7) {
        a.y_nm = pitch * 21;
        b = PointNm{a.x_nm + mm(8), a.y_nm, a.z_nm};
      }
      if (it == 8) {
        a.y_nm = pitch * 26 + pitch / 2;
        b = PointNm{a.x_nm - mm(7), a.y_nm, a.z_nm};
      }
      bad += check_move<uint16_t>(kTools[t], kToolNames[t], a, b, pitch, 500, 3);
      if (it % 4 == 0) bad += check_move<uint8_t>(kTools[t], kToolNames[t], a, b, pitch, 100000, 3);
      if (it % 4 == 1) bad += check_move<uint32_t>(kTools[t], kToolNames[t], a, b, pitch, 20, 3);
      ++moves;
    }
  }
  CHECK_EQ(bad, 0);
  CHECK_EQ(moves, 84);
}

TEST(sweep_ramps_cut_full_depth_along_their_length) {
  // Long ramps at several slopes, every shape: every dexel, including the
  // ones along the middle of the ramp, at the oracle's depth. (Height-map
  // simulators that place the tool only at the move's ends or sample it
  // coarsely cut ramps too shallow.)
  int bad = 0;
  for (int t = 0; t < 6; ++t) {
    for (int64_t drop_um : {500, 2000, 8000}) {
      PointNm a{mm(1), mm(6), mm(14)}, b{mm(15), mm(6), mm(14) - drop_um * 1000};
      bad += check_move<uint16_t>(kTools[t], kToolNames[t], a, b, 250000, 500, 3);
      PointNm c{mm(2), mm(1), mm(12)}, d{mm(14), mm(11), mm(12) - drop_um * 1000};
      bad += check_move<uint16_t>(kTools[t], kToolNames[t], c, d, 250000, 500, 3);
    }
  }
  CHECK_EQ(bad, 0);
}

TEST(sweep_never_leaves_more_than_stamping) {
  // Moves with every instance on a dexel axis (axis-aligned and 45 degrees,
  // end points on dexels), so stamping's nearest-neighbour matching is exact
  // there and only its gaps between instances differ.
  const int64_t pitch = 250000, lsb = 500;
  const PointNm moves[][2] = {
      {{mm(2), mm(5), mm(10)}, {mm(14), mm(5), mm(8)}},
      {{mm(3), mm(2), mm(9)}, {mm(3), mm(10), mm(9)}},
      {{mm(2), mm(2), mm(11)}, {mm(10), mm(10), mm(7)}},
      {{mm(12), mm(3), mm(6)}, {mm(4), mm(11), mm(9)}},
  };
  for (int t = 0; t < 6; ++t) {
    for (const auto& mv : moves) {
      Fixture<uint16_t> fs(64, 48, pitch, lsb), fw(64, 48, pitch, lsb);
      ToolProfile prof = tool_profile(kTools[t]);
      std::vector<int32_t> words(cutter_storage_words(cutter_reach_dex(prof, pitch)));
      CutterDexels c;
      cutter_build(prof, pitch, lsb, words.data(), words.size(), &c);
      SweepTool swt;
      sweep_tool_prepare(prof, lsb, &swt);
      CutStats s1, s2;
      stamp_line(&fs.g, c, mv[0], mv[1], &s1);
      sweep_line(&fw.g, swt, mv[0], mv[1], &s2);
      int more = 0;
      for (size_t k = 0; k < fs.top.size(); ++k) {
        if (fw.top[k] > fs.top[k] + 1 && ++more <= 3)  // sweep left material stamping removed
          std::printf("  %s: dexel %zu sweep %d stamp %d\n", kToolNames[t], k, fw.top[k], fs.top[k]);
      }
      CHECK_EQ(more, 0);
      // And the sweep's dexel visits are fewer: each dexel once.
      CHECK_LT(s2.dexel_updates, s1.dexel_updates);
    }
  }
}

TEST(sweep_buried_shaft_cuts_to_its_highest_top) {
  // A tool shorter than the stock is deep: its shaft top is inside the
  // material, and figure 2 needs the top of the union of the tool's column
  // intervals: on a ramp the shaft top of the highest position still over
  // the column, not of the move's lower end. Ramps down, up, diagonal, a
  // plunge, and a ramp ending more than the tool's length below the floor
  // (which once left material stamping removes), in every case of figure 2.
  const int64_t pitch = 250000, lsb = 500;
  struct Move {
    PointNm a, b;
    int64_t len;
  };
  const Move moves[] = {
      {{mm(1), mm(6), mm(25)}, {mm(15), mm(6), -mm(15)}, mm(10)},
      {{mm(15), mm(5), -mm(12)}, {mm(1), mm(7), mm(24)}, mm(10)},
      {{mm(2), mm(1), mm(22)}, {mm(14), mm(11), -mm(14)}, mm(12)},
      {{mm(8), mm(6), mm(27)}, {mm(8), mm(6), -mm(8)}, mm(10)},
      {{mm(1), mm(6), mm(20)}, {mm(15), mm(6), -mm(100)}, mm(60)},
  };
  int bad = 0, cases[4] = {0, 0, 0, 0};
  for (const Move& mv : moves) {
    for (ToolKind k : {ToolKind::kBall, ToolKind::kFlat, ToolKind::kVBit}) {
      const Tool tool = fixtures::test_tool(k, mm(6), 0, 90000, mv.len);
      Fixture<uint16_t> f(64, 48, pitch, lsb);
      SweepTool swt;
      CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &swt), Status::kOk);
      CutStats st;
      sweep_line(&f.g, swt, mv.a, mv.b, &st);
      const oracle::P3 a{double(mv.a.x_nm), double(mv.a.y_nm), double(mv.a.z_nm)};
      const oracle::P3 b{double(mv.b.x_nm), double(mv.b.y_nm), double(mv.b.z_nm)};
      bad += oracle::check_figure2_grid(
          64, 48, double(pitch), double(lsb), f.top.data(), f.bottom.data(), oracle::Dexel{double(f.stock_lsb), 0},
          double(mv.len), 1.0, [&](double x, double y) { return oracle::lowest_on_line(tool, a, b, x, y); },
          [&](double x, double y) { return oracle::highest_on_line(tool, a, b, x, y); }, cases, "buried line");
    }
  }
  CHECK_EQ(bad, 0);
  // Every case of figure 2 is met, with enough columns to mean something.
  CHECK_GT(cases[1], 100);
  CHECK_GT(cases[2], 100);
  CHECK_GT(cases[3], 100);
}

TEST(sweep_equals_infinitely_fine_stamping) {
  // Stamping with exact (not nearest-neighbour) placement at a step of
  // pitch/512 approaches the swept envelope from above; the sweep must agree
  // within the bound: 1 LSB plus the fine stamping's own gap error.
  const int64_t pitch = 250000, lsb = 500;
  Tool ball = make_tool(ToolKind::kBall, mm(6));
  Fixture<uint16_t> f(64, 48, pitch, lsb);
  SweepTool swt;
  sweep_tool_prepare(tool_profile(ball), lsb, &swt);
  PointNm a{mm(3), 5400000, mm(12)}, b{mm(13), 7100000, mm(9)};
  CutStats st;
  sweep_line(&f.g, swt, a, b, &st);
  const int steps = 512 * 44;
  int bad = 0;
  for (int32_t j = 0; j < f.g.ny; ++j) {
    for (int32_t i = 0; i < f.g.nx; ++i) {
      double best = HUGE_VAL;
      for (int k = 0; k <= steps; ++k) {
        const double s = double(k) / steps;
        const double cx = a.x_nm + s * (b.x_nm - a.x_nm), cy = a.y_nm + s * (b.y_nm - a.y_nm);
        const double r = std::hypot(i * double(pitch) - cx, j * double(pitch) - cy);
        if (r > mm(3)) continue;
        best = std::min(best, a.z_nm + s * (b.z_nm - a.z_nm) + oracle::profile_nm(ball, r));
      }
      const double want = best == HUGE_VAL ? double(f.stock_lsb) : std::min(double(f.stock_lsb), best / lsb);
      const double got = f.top[f.g.index(i, j)];
      // Fine stamping is never below the envelope, and is above it by at
      // most its gap error (a step of 20 nm on a 3 mm ball: < 0.01 LSB).
      if (got > want + 1.0 || got < want - 1.0 - 0.05) {
        if (++bad <= 3) std::printf("  fine stamp: dexel (%d,%d) sweep %.0f fine %.3f\n", i, j, got, want);
      }
    }
  }
  CHECK_EQ(bad, 0);
}

TEST(sweep_no_heap_and_clipping) {
  Fixture<uint16_t> f(40, 30, mm(1), 1000);
  SweepTool swt;
  sweep_tool_prepare(tool_profile(kTools[2]), 1000, &swt);
  const uint64_t before = t::heap_allocations();
  CutStats st;
  sweep_line(&f.g, swt, PointNm{INT64_MIN, INT64_MIN, INT64_MIN}, PointNm{INT64_MAX, INT64_MAX, INT64_MAX}, &st);
  sweep_line(&f.g, swt, PointNm{-mm(5000), mm(10), mm(10)}, PointNm{mm(5000), mm(12), mm(10)}, &st);  // 10 m, pieces
  sweep_line(&f.g, swt, PointNm{mm(10), mm(10), mm(500)}, PointNm{mm(30), mm(20), mm(400)}, &st);    // above
  sweep_line(&f.g, swt, PointNm{mm(10), mm(10), mm(20)}, PointNm{mm(10), mm(10), -mm(5)}, &st);      // through
  CHECK_EQ(t::heap_allocations() - before, 0u);
  CHECK(f.g.is_hole(10, 10));
  CHECK(f.g.is_hole(13, 10));
  CHECK(!f.g.is_hole(15, 10));
  CHECK_EQ(static_cast<int64_t>(f.g.top[f.g.index(30, 11)]), 10000);  // the 10 m pass at z = 10 mm
}
