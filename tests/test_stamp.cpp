// core/cut/stamp.h: the five cases of figure 2, straight pocketing passes with
// every cutter against an analytic expectation, golden grid hashes for
// m = 8, 16, 32, hostile moves, and zero heap use while cutting.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/cut/stamp.h"
#include "core/grid/grid.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/alloc_count.h"
#include "tests/cut_fixtures.h"
#include "tests/golden_check.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using fixtures::mm;
using fixtures::TestGrid;

struct TestCutter {
  std::vector<int32_t> words;
  CutterDexels c;
  Tool tool;
  TestCutter(const Tool& t, int64_t pitch_nm, int64_t lsb_nm) : tool(t) {
    ToolProfile p = tool_profile(t);
    words.resize(cutter_storage_words(cutter_reach_dex(p, pitch_nm)));
    cutter_build(p, pitch_nm, lsb_nm, words.data(), words.size(), &c);
  }
};

Tool tool_of(ToolKind k, int64_t d, int64_t rc = 0, int32_t mdeg = 0) { return fixtures::test_tool(k, d, rc, mdeg, mm(40)); }

// A one-dexel cutter (K = 0) with the given bottom and top offsets.
struct PairCutter {
  int32_t words[4];
  CutterDexels c;
  PairCutter(int32_t bottom, int32_t top) {
    words[0] = 0;  // row_lo
    words[1] = 0;  // row_hi
    words[2] = bottom;
    words[3] = top;
    c.reach_dex = 0;
    c.side = 1;
    c.row_lo = &words[0];
    c.row_hi = &words[1];
    c.bottom_lsb = &words[2];
    c.top_lsb = &words[3];
    c.min_bottom_lsb = c.max_bottom_lsb = bottom;
    c.min_top_lsb = c.max_top_lsb = top;
  }
};

// Workpiece dexel (1, 1) set to [wb, wt], cut by cutter dexel [cb, ct].
template <class H>
void check_case(int64_t wb, int64_t wt, int64_t cb, int64_t ct, int64_t want_b, int64_t want_t, CutCase want) {
  CHECK_EQ(classify_cut<int64_t>(wt, wb, cb, ct), want);
  TestGrid<H> tg(3, 3, mm(1), 1000);
  tg.g.top[tg.g.index(1, 1)] = static_cast<H>(wt);
  tg.g.bottom[tg.g.index(1, 1)] = static_cast<H>(wb);
  // Place the tip at 0 and express the cutter dexel as offsets from it.
  PairCutter pc(static_cast<int32_t>(cb), static_cast<int32_t>(ct));
  CutStats st;
  stamp_instance(&tg.g, pc.c, 1, 1, 0, &st);
  CHECK_EQ(static_cast<int64_t>(tg.g.bottom[tg.g.index(1, 1)]), want_b);
  CHECK_EQ(static_cast<int64_t>(tg.g.top[tg.g.index(1, 1)]), want_t);
  CHECK_LE(st.dexel_updates, 1u);  // 0 when the instance is out of reach
  const bool changed = want_b != wb || want_t != wt;
  CHECK_EQ(tg.g.dirty.empty(), !changed);
}

}  // namespace

TEST(stamp_cases_a_to_e) {
  // w = [10, 50] throughout; figure 2 of the paper.
  check_case<uint16_t>(10, 50, 60, 100, 10, 50, CutCase::kA);  // a: cutter above
  check_case<uint16_t>(10, 50, 50, 100, 10, 50, CutCase::kA);  // a: touching the top
  check_case<uint16_t>(10, 50, 30, 100, 10, 30, CutCase::kB);  // b: top part removed
  check_case<uint16_t>(10, 50, 30, 50, 10, 30, CutCase::kB);   // b: c.top level with w.top
  check_case<uint16_t>(10, 50, 0, 30, 30, 50, CutCase::kC);    // c: bottom part removed
  check_case<uint16_t>(10, 50, 10, 30, 30, 50, CutCase::kC);   // c: c.bottom level with w.bottom
  check_case<uint16_t>(10, 50, 20, 30, 10, 50, CutCase::kD);   // d: inside, ignored
  check_case<uint16_t>(10, 50, 5, 60, 0, 0, CutCase::kE);      // e: covered, a hole
  check_case<uint16_t>(10, 50, 10, 50, 0, 0, CutCase::kE);     // e: exactly covered
  check_case<uint16_t>(10, 50, 0, 5, 10, 50, CutCase::kA);     // a: cutter below w
  check_case<uint16_t>(0, 0, 0, 100, 0, 0, CutCase::kA);       // a hole stays a hole
  check_case<uint8_t>(10, 50, 30, 100, 10, 30, CutCase::kB);
  check_case<uint32_t>(10, 50, 5, 60, 0, 0, CutCase::kE);
}

TEST(stamp_case_values_outside_range) {
  // c.bottom below the grid floor and c.top far above the m-bit range: the
  // dexel is covered, case e; nothing out of range is stored.
  check_case<uint8_t>(0, 200, -1000, 100000, 0, 0, CutCase::kE);
  check_case<uint8_t>(0, 200, 100, 100000, 0, 100, CutCase::kB);
  check_case<uint16_t>(0, 65535, 70000, 90000, 0, 65535, CutCase::kA);
}

template <class H>
static void pocket_pass(const Tool& tool, const char* what) {
  // A pass along x at y = 8 mm (a dexel axis), tip 5 mm below the 20 mm stock.
  const int64_t pitch = 250000, lsb = lsb_for_range(mm(25), static_cast<int>(sizeof(H) * 8));
  TestGrid<H> tg(96, 64, pitch, lsb);
  grid_block_stock(&tg.g, grid_height_of_z(tg.g, mm(20)));
  TestCutter tc(tool, pitch, lsb);
  CutStats st;
  const int64_t z = mm(15);
  stamp_line(&tg.g, tc.c, PointNm{mm(4), mm(8), z}, PointNm{mm(20), mm(8), z}, &st);
  const int32_t k = tc.c.reach_dex;
  const int32_t j0 = 32;  // y = 8 mm
  const double stock = static_cast<double>(grid_height_of_z(tg.g, mm(20)));
  const double R = static_cast<double>(tool.diameter_nm) / 2;
  int bad = 0;
  // Away from the ends (the cutter's reach from the first and last instance).
  for (int32_t i = 16 + k; i <= 80 - k; ++i) {
    for (int32_t j = 1; j < tg.g.ny - 1; ++j) {
      const double dy = std::fabs(static_cast<double>(j - j0)) * pitch;
      double want = stock;
      if (dy <= R) {
        double prof = 0;
        switch (tool.kind) {
          case ToolKind::kFlat: prof = 0; break;
          case ToolKind::kBall: prof = R - std::sqrt(R * R - dy * dy); break;
          case ToolKind::kBullNose: {
            double rc = static_cast<double>(tool.corner_radius_nm), f = R - rc;
            prof = dy <= f ? 0 : rc - std::sqrt(rc * rc - (dy - f) * (dy - f));
            break;
          }
          case ToolKind::kVBit:
            prof = dy / std::tan(tool.tip_angle_mdeg / 2000.0 * 3.14159265358979323846 / 180.0);
            break;
        }
        want = std::min(stock, (static_cast<double>(z) + prof) / lsb);
      }
      const double got = tg.g.top[tg.g.index(i, j)];
      if (std::fabs(got - want) > 1.0 && ++bad <= 3) {
        std::printf("%s m=%d: dexel (%d, %d) top %.0f, expected %.3f\n", what, static_cast<int>(sizeof(H) * 8), i, j,
                    got, want);
      }
    }
  }
  CHECK_EQ(bad, 0);
  CHECK_EQ(st.instances, 65u);  // 16 mm at 0.25 mm: 64 steps, 65 instances
}

TEST(stamp_pocket_pass_every_cutter) {
  const Tool tools[] = {tool_of(ToolKind::kBall, mm(6)), tool_of(ToolKind::kFlat, mm(6)),
                        tool_of(ToolKind::kBullNose, mm(8), mm(2)), tool_of(ToolKind::kVBit, mm(6), 0, 90000)};
  const char* names[] = {"ball", "flat", "bull", "vbit"};
  for (int t = 0; t < 4; ++t) {
    pocket_pass<uint8_t>(tools[t], names[t]);
    pocket_pass<uint16_t>(tools[t], names[t]);
    pocket_pass<uint32_t>(tools[t], names[t]);
  }
}

namespace {

// The fixed multi-move program behind the golden hashes: ramps in every
// direction with four cutter shapes, a plunge through the stock (a hole),
// a zero-length move and moves outside the grid.
template <class H>
uint64_t golden_program(CutStats* st, uint64_t* heap_news) {
  const int64_t pitch = 500000, lsb = lsb_for_range(mm(25), static_cast<int>(sizeof(H) * 8));
  TestGrid<H> tg(82, 62, pitch, lsb);
  TestCutter ball(tool_of(ToolKind::kBall, mm(6)), pitch, lsb);
  TestCutter flat(tool_of(ToolKind::kFlat, mm(4)), pitch, lsb);
  TestCutter bull(tool_of(ToolKind::kBullNose, mm(8), mm(1)), pitch, lsb);
  TestCutter vbit(tool_of(ToolKind::kVBit, mm(6), 0, 90000), pitch, lsb);
  const uint64_t before = t::heap_allocations();
  DexelGrid<H>* g = &tg.g;
  grid_block_stock(g, grid_height_of_z(*g, mm(20)));
  stamp_line(g, ball.c, PointNm{mm(5), mm(5), mm(15)}, PointNm{mm(35), mm(25), mm(12)}, st);
  stamp_line(g, flat.c, PointNm{mm(5), mm(25), mm(18)}, PointNm{mm(35), mm(5), mm(17)}, st);
  stamp_line(g, bull.c, PointNm{mm(20), mm(2), mm(10)}, PointNm{mm(20), mm(28), mm(16)}, st);
  stamp_line(g, vbit.c, PointNm{mm(2), mm(15), mm(19)}, PointNm{mm(38), mm(15), mm(17)}, st);
  stamp_line(g, flat.c, PointNm{mm(30), mm(10), mm(25)}, PointNm{mm(30), mm(10), -mm(2)}, st);  // plunge through
  stamp_line(g, ball.c, PointNm{mm(10), mm(20), mm(14)}, PointNm{mm(10), mm(20), mm(14)}, st);  // zero length
  stamp_line(g, ball.c, PointNm{-mm(500), mm(10), mm(10)}, PointNm{-mm(100), mm(10), mm(10)}, st);  // outside
  stamp_line(g, ball.c, PointNm{-mm(100), -mm(100), mm(13)}, PointNm{mm(100), mm(100), mm(13)}, st);  // across
  *heap_news = t::heap_allocations() - before;
  return grid_hash(*g);
}

}  // namespace

TEST(stamp_golden_grid_hashes) {
  // golden_program() cuts what the golden output's program stamp-test does
  // (tests/golden/golden_programs.h, cut by tests/golden/golden_stamp.cpp),
  // so its grids are pinned once, there: tests/golden/golden.out's `stamp
  // stamp-test` lines (make bless rewrites them; change only with a commit
  // that says why the new grid is right). This checks the test binary's
  // build against them.
  auto pinned = [](int bits) {
    const std::string v = t::golden_out_value("stamp stamp-test m=" + std::to_string(bits) + " ", "grid");
    CHECK_EQ(v.size(), 16u);
    return std::strtoull(v.c_str(), nullptr, 16);
  };
  const uint64_t want8 = pinned(8), want16 = pinned(16), want32 = pinned(32);
  CutStats s8, s16, s32;
  uint64_t news = 0;
  const uint64_t h8 = golden_program<uint8_t>(&s8, &news);
  const uint64_t h16 = golden_program<uint16_t>(&s16, &news);
  const uint64_t h32 = golden_program<uint32_t>(&s32, &news);
  std::printf("golden stamp: m=8 %016llx m=16 %016llx m=32 %016llx instances %llu updates %llu\n",
              static_cast<unsigned long long>(h8), static_cast<unsigned long long>(h16),
              static_cast<unsigned long long>(h32), static_cast<unsigned long long>(s16.instances),
              static_cast<unsigned long long>(s16.dexel_updates));
  CHECK_EQ(h8, want8);
  CHECK_EQ(h16, want16);
  CHECK_EQ(h32, want32);
  CHECK_EQ(s8.instances, s16.instances);
}

TEST(stamp_no_heap_while_cutting) {
  CutStats st;
  uint64_t news = 1;
  golden_program<uint16_t>(&st, &news);
  CHECK_EQ(news, 0u);
  // The counter itself works: a control allocation is seen.
  const uint64_t before = t::heap_allocations();
  int* volatile p = new int(3);
  delete p;
  CHECK_EQ(t::heap_allocations() - before, 1u);
}

TEST(stamp_hostile_moves) {
  TestGrid<uint16_t> tg(20, 20, mm(1), 1000);
  grid_block_stock(&tg.g, 10000);
  TestCutter ball(tool_of(ToolKind::kBall, mm(6)), mm(1), 1000);
  const uint64_t h0 = grid_hash(tg.g);
  tg.g.dirty = GridRect::none();
  CutStats st;
  // Far outside, huge coordinates, and the extremes of int64: nothing changes,
  // nothing is computed, no overflow (UBSan runs this too).
  stamp_line(&tg.g, ball.c, PointNm{INT64_MIN, INT64_MIN, INT64_MIN}, PointNm{INT64_MAX, INT64_MIN, 0}, &st);
  stamp_line(&tg.g, ball.c, PointNm{mm(1000000), 0, 0}, PointNm{mm(2000000), mm(5), 0}, &st);
  stamp_line(&tg.g, ball.c, PointNm{0, 0, mm(500)}, PointNm{mm(19), mm(19), mm(500)}, &st);  // far above
  stamp_line(&tg.g, ball.c, PointNm{0, 0, -mm(500)}, PointNm{mm(19), mm(19), -mm(500)}, &st);  // far below
  CHECK_EQ(grid_hash(tg.g), h0);
  CHECK(tg.g.dirty.empty());
  CHECK_EQ(st.dexel_updates, 0u);
  // A diagonal from far outside to far outside across the grid costs only
  // the instances in reach.
  CutStats st2;
  stamp_line(&tg.g, ball.c, PointNm{-mm(1000000), -mm(1000000), mm(5)}, PointNm{mm(1000000), mm(1000000), mm(5)},
             &st2);
  CHECK_LE(st2.instances, 40u);
  CHECK_GT(st2.instances, 15u);
  CHECK(!tg.g.dirty.empty());
}

TEST(stamp_cutter_larger_than_grid) {
  TestGrid<uint16_t> tg(10, 8, mm(1), 1000);
  grid_block_stock(&tg.g, 10000);
  TestCutter big(tool_of(ToolKind::kFlat, mm(100)), mm(1), 1000);
  CutStats st;
  stamp_line(&tg.g, big.c, PointNm{mm(5), mm(4), mm(3)}, PointNm{mm(5), mm(4), mm(3)}, &st);
  for (int32_t j = 1; j < 7; ++j)
    for (int32_t i = 1; i < 9; ++i) CHECK_EQ(tg.g.top[tg.g.index(i, j)], 3000);
  CHECK_EQ(st.instances, 1u);  // a zero-length move is one instance
  CHECK_EQ(st.dexel_updates, 80u);
  CHECK_EQ(tg.g.dirty.i0, 0);
  CHECK_EQ(tg.g.dirty.i1, 10);
}

TEST(stamp_plunge_makes_hole_and_dirty_rect) {
  TestGrid<uint16_t> tg(40, 40, mm(1), 1000);
  grid_block_stock(&tg.g, 20000);
  tg.g.dirty = GridRect::none();
  TestCutter flat(tool_of(ToolKind::kFlat, mm(6)), mm(1), 1000);
  CutStats st;
  stamp_line(&tg.g, flat.c, PointNm{mm(20), mm(20), mm(30)}, PointNm{mm(20), mm(20), -mm(1)}, &st);
  CHECK_EQ(st.instances, 2u);  // n = 1: both end points
  CHECK(tg.g.is_hole(20, 20));
  CHECK(tg.g.is_hole(23, 20));
  CHECK(!tg.g.is_hole(24, 20));
  CHECK_EQ(tg.g.dirty.i0, 17);
  CHECK_EQ(tg.g.dirty.i1, 24);
  CHECK_EQ(tg.g.dirty.j0, 17);
  CHECK_EQ(tg.g.dirty.j1, 24);
}

TEST(stamp_instance_spacing) {
  // Consecutive instances at most one pitch apart: a thin flat cutter (one
  // dexel) drawn diagonally leaves a connected 8-path of cut dexels.
  TestGrid<uint16_t> tg(50, 50, mm(1), 1000);
  grid_block_stock(&tg.g, 20000);
  TestCutter thin(tool_of(ToolKind::kFlat, kNmPerMm / 2), mm(1), 1000);
  CutStats st;
  stamp_line(&tg.g, thin.c, PointNm{mm(2), mm(3), mm(10)}, PointNm{mm(45), mm(20), mm(10)}, &st);
  CHECK_EQ(st.instances, 44u);  // 43 pitches in x
  for (int32_t i = 2; i <= 45; ++i) {
    int cut = 0;
    for (int32_t j = 1; j < 49; ++j) cut += tg.g.top[tg.g.index(i, j)] == 10000;
    CHECK_EQ(cut, 1);
  }
}
