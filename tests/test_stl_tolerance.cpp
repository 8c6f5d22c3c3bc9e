// The STL surface merged within a height tolerance (platform/mesh/stl_plane.h)
// against the exact one, in exact integers where it can be: closed and
// 2-manifold (every directed edge once, its reverse once), no triangle
// without area, the same Euler characteristic, the volume within the
// tolerance times the top area, and every dexel top within the tolerance
// of the surface written over it (a double-precision oracle); at one LSB
// or less, the exact surface's triangles themselves. On ball-cut reliefs,
// smooth bumps, slopes, steps, holes, thin walls, random grids and a
// milled part, at several tolerances; and `dexmill run --stl-tolerance`.
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/cut/stamp.h"
#include "core/grid/grid.h"
#include "platform/mesh/stl_merge.h"
#include "tests/golden_check.h"
#include "tests/rng.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/scene_util.h"
#include "tests/stl_check.h"

using namespace dexmill;

namespace {

const int64_t kTolerancesLsb[] = {2, 3, 5, 20, 100, 5000};

struct Merged {
  size_t exact = 0, within = 0;  // triangles
};

// The surface of g at tolerance_lsb, checked against the exact one.
template <class H>
Merged check_tolerance(const DexelGrid<H>& g, int64_t tolerance_lsb, const char* what) {
  const SurfaceMaterial m(g);
  t::TriangleList exact, within;
  merged_surface(g, m, 0, &exact);
  merged_surface(g, m, tolerance_lsb, &within);
  const t::MeshFacts a = t::mesh_facts(exact.tris), b = t::mesh_facts(within.tris);
  const t::TopError ea = t::top_error(exact.tris, g, m), eb = t::top_error(within.tris, g, m);
  // Volume x6 moves by at most 6 x tolerance x area = 3 x tolerance x area2.
  const int64_t dv6 = b.volume6 - a.volume6, bound6 = 3 * tolerance_lsb * ea.area2;
  const bool good = a.open_edges == 0 && b.open_edges == 0 && b.flat_tris == 0 && a.euler == b.euler &&
                    (dv6 < 0 ? -dv6 : dv6) <= bound6 && ea.max_lsb == 0 && ea.uncovered == 0 && eb.uncovered == 0 &&
                    eb.max_lsb <= static_cast<double>(tolerance_lsb) + 1e-9 && eb.area2 == ea.area2;
  if (!good) {
    std::printf("  %s at %lld LSB: exact %zu tris, euler %lld, error %.3f; within %zu tris, %ld open, %ld flat, euler "
                "%lld, volume6 %+lld of %lld allowed, error %.3f LSB, %ld uncovered, area2 %lld of %lld\n",
                what, static_cast<long long>(tolerance_lsb), exact.tris.size(), static_cast<long long>(a.euler),
                ea.max_lsb, within.tris.size(), b.open_edges, b.flat_tris, static_cast<long long>(b.euler),
                static_cast<long long>(dv6), static_cast<long long>(bound6), eb.max_lsb, eb.uncovered,
                static_cast<long long>(eb.area2), static_cast<long long>(ea.area2));
    CHECK(false);
  }
  return Merged{exact.tris.size(), within.tris.size()};
}

template <class H>
void check_all(const DexelGrid<H>& g, const char* what) {
  for (const int64_t tol : kTolerancesLsb) check_tolerance(g, tol, what);
}

template <class H>
void set(t::TestGrid<H>* tg, int32_t i, int32_t j, int64_t top_lsb, int64_t bottom_lsb = 0) {
  tg->top[tg->g.index(i, j)] = static_cast<H>(top_lsb);
  tg->bottom[tg->g.index(i, j)] = static_cast<H>(bottom_lsb);
}

// A relief under ball passes along x, 0.5 mm apart, their depth rolling
// with x and y: scallops on a curved surface, nearly nothing level.
template <class H>
void ball_relief(t::TestGrid<H>* tg, int32_t n, int64_t pitch_nm) {
  const int64_t mm = kNmPerMm;
  t::make_block(tg, n, n, pitch_nm, 10 * mm);
  t::TestCutter ball;
  t::make_cutter(tg->g, t::ball_tool(3 * mm), &ball);
  CutStats st;
  const int64_t side_nm = (n - 1) * pitch_nm;
  for (int64_t y = 0; y <= side_nm; y += mm / 2) {
    PointNm from{-2 * mm, y, 8 * mm};
    for (int k = 1; k <= 16; ++k) {
      const int64_t x = -2 * mm + k * (side_nm + 4 * mm) / 16;
      const double u = static_cast<double>(x) / side_nm, v = static_cast<double>(y) / side_nm;
      const PointNm to{x, y, 8 * mm + static_cast<int64_t>(1.5e6 * std::sin(3 * u + 1) * std::cos(2 * v))};
      stamp_line(&tg->g, ball.c, from, to, &st);
      from = to;
    }
  }
}

}  // namespace

TEST(stl_tolerance_ball_relief_closed_within_and_smaller) {
  t::TestGrid<uint16_t> tg;
  ball_relief(&tg, 160, kNmPerMm / 20);  // 8 mm at 0.05 mm
  // The LSB here: 0.0002 mm for 12.5 mm in 16 bits; 0.005 mm is 25 LSB.
  CHECK_EQ(tg.g.lsb_nm, int64_t{200});
  check_all(tg.g, "ball relief");
  const Merged at = check_tolerance(tg.g, 25, "ball relief");
  std::printf("  ball relief 160x160 at 0.05 mm: %zu triangles exact, %zu within 0.005 mm\n", at.exact, at.within);
  CHECK(at.within * 4 < at.exact);
}

TEST(stl_tolerance_bumps_and_slopes) {
  t::TestGrid<uint32_t> tg;
  t::make_block(&tg, 90, 70, kNmPerMm / 10, 20 * kNmPerMm);
  for (int32_t j = 1; j + 1 < 70; ++j)
    for (int32_t i = 1; i + 1 < 89; ++i) {
      double z = 60000;
      if (i < 30) z += 37.3 * i - 11.1 * j;  // a slope, not a multiple of the LSB
      else if (i < 60) z += 4000 * std::exp(-((i - 45) * (i - 45) + (j - 35) * (j - 35)) / 120.0);  // a bump
      else z += 900 * std::sin(i / 3.0) * std::cos(j / 5.0);  // ripples
      set(&tg, i, j, static_cast<int64_t>(std::lround(z)), 100);
    }
  check_all(tg.g, "bumps");
  for (const int64_t tol : {20, 200}) {
    const Merged at = check_tolerance(tg.g, tol, "bumps");
    std::printf("  bumps at %lld LSB: %zu triangles exact, %zu within\n", static_cast<long long>(tol), at.exact, at.within);
    if (tol == 200) CHECK(at.within * 4 < at.exact);
  }
}

TEST(stl_tolerance_steps_holes_thin_walls) {
  t::TestGrid<uint16_t> tg;
  t::make_block(&tg, 40, 30, kNmPerMm / 10, 10 * kNmPerMm);
  for (int32_t j = 1; j < 29; ++j)
    for (int32_t i = 1; i < 39; ++i) set(&tg, i, j, 30000 + 7 * i + 3 * j);  // a gentle slope everywhere
  for (int32_t j = 4; j < 12; ++j)
    for (int32_t i = 4; i < 14; ++i) set(&tg, i, j, 20000 + 5 * i);  // a sloped pocket floor: steps to it
  for (int32_t j = 4; j < 12; ++j) set(&tg, 15, j, 31000);           // a wall one dexel wide
  for (int32_t j = 4; j < 12; ++j) set(&tg, 17, j, 31000), set(&tg, 18, j, 31000);  // two wide
  for (int32_t j = 4; j < 12; ++j)
    for (int32_t i = 20; i < 24; ++i) set(&tg, i, j, 0);             // through the stock
  for (int32_t j = 14; j < 26; ++j)
    for (int32_t i = 3; i < 35; ++i) set(&tg, i, j, 25000 + 40 * (i % 4), 300 * (j % 3));  // ramps on lifted bottoms
  set(&tg, 8, 20, 0), set(&tg, 9, 21, 0);                              // diagonal holes
  for (int32_t i = 26; i < 34; ++i) set(&tg, i, 6, 30000, 29998);     // material thinner than the tolerance
  check_all(tg.g, "steps");
}

TEST(stl_tolerance_random_grids) {
  t::Rng rng(41);
  for (int round = 0; round < 40; ++round) {
    const int32_t nx = static_cast<int32_t>(rng.range(4, 30)), ny = static_cast<int32_t>(rng.range(4, 24));
    t::TestGrid<uint16_t> tg;
    t::make_block(&tg, nx, ny, kNmPerMm / 10, 10 * kNmPerMm);
    const int64_t slope_i = rng.range(-20, 20), slope_j = rng.range(-20, 20), noise = rng.range(0, 8);
    for (int32_t j = 1; j + 1 < ny; ++j)
      for (int32_t i = 1; i + 1 < nx; ++i) {
        const int64_t r = rng.range(0, 19);
        const int64_t z = 30000 + slope_i * i + slope_j * j + rng.range(0, noise);
        if (r == 0) set(&tg, i, j, 0);                                 // a hole
        else if (r == 1) set(&tg, i, j, z - 3000, rng.range(0, 2) * 500);  // a pit, maybe on a lifted bottom
        else set(&tg, i, j, z, r == 2 ? z - rng.range(1, 30) : 0);     // thin where r is 2
      }
    check_all(tg.g, "random");
  }
}

TEST(stl_tolerance_milled_part) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  check_all(tg.g, "pocketed");
}

// One LSB or less is the exact surface, triangle for triangle.
TEST(stl_tolerance_one_lsb_is_exact) {
  t::TestGrid<uint16_t> tg;
  ball_relief(&tg, 60, kNmPerMm / 20);
  const SurfaceMaterial m(tg.g);
  t::TriangleList exact, one;
  merged_surface(tg.g, m, 0, &exact);
  merged_surface(tg.g, m, 1, &one);
  CHECK_EQ(one.tris.size(), exact.tris.size());
  bool same = true;
  for (size_t k = 0; k < exact.tris.size() && same; ++k)
    for (int v = 0; v < 3; ++v)
      for (int c = 0; c < 3; ++c) same = same && one.tris[k].v[v][c] == exact.tris[k].v[v][c];
  CHECK(same);
}

// The option: at most the LSB (pocket.ngc's grid: 0.0002 mm) the pinned
// exact STL byte for byte, more a smaller closed one; bad values exit 2.
TEST(stl_tolerance_option_golden) {
  using namespace run_cli;
  if (skip()) return;
  const std::string d = tmp_dir() + "/";
  for (const char* mm : {"0", "0.0002", "0.0003"}) {
    const Result r = run(std::string("pocket.ngc -q --tool flat:6 --stl %/tol.stl --stl-tolerance ") + mm);
    CHECK_EQ(r.code, 0);
    CHECK_GOLDEN_FILE("run-pocket-stl", d + "tol.stl");
  }
  const size_t exact_bytes = slurp(d + "tol.stl").size();
  CHECK_EQ(run("pocket.ngc -q --tool flat:6 --stl %/tol.stl --stl-tolerance 0.01").code, 0);
  const size_t within_bytes = slurp(d + "tol.stl").size();
  std::printf("  pocket.ngc's STL: %zu bytes exact, %zu within 0.01 mm\n", exact_bytes, within_bytes);
  CHECK(within_bytes * 2 < exact_bytes);
  const std::string cases[] = {"-0.001", "abc", "1.5", "1e9", "0.5x", ""};
  for (const std::string& v : cases) {
    const Result r = run("pocket.ngc -q --stl %/bad.stl --stl-tolerance '" + v + "'");
    CHECK_EQ(r.code, 2);
    CHECK(has(r.err, "dexmill: error: --stl-tolerance needs mm from 0 to 1, not '"));
  }
  const Result r = run("pocket.ngc -q --stl-tolerance 0.01");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "dexmill: error: --stl-tolerance needs --stl FILE.stl"));
}
