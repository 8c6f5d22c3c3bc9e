// The merged STL surface against the cell surface it merges, in exact
// integers: closed (every directed edge once, its reverse once: no
// T-junction), no triangle without area, the same volume to the last LSB
// (and the volume the grid's cells give), the same Euler characteristic,
// never more triangles. On blocks, steps, holes through the stock, thin
// walls, lifted bottoms, random patchworks and a milled part.
#include <cstdio>
#include <vector>

#include "core/grid/grid.h"
#include "platform/mesh/stl_ladder.h"
#include "platform/mesh/stl_merge.h"
#include "tests/rng.h"
#include "tests/runner.h"
#include "tests/scene_util.h"
#include "tests/stl_check.h"

using namespace dexmill;

namespace {

template <class H>
struct Block {
  DexelGrid<H> g;
  std::vector<H> top, bottom;
  Block(int nx, int ny, int64_t height_lsb = 5000) : top(static_cast<size_t>(nx) * ny), bottom(top.size()) {
    GridGeometry geo{nx, ny, -kNmPerMm, -2 * kNmPerMm, kNmPerMm, -5 * kNmPerMm, 1000};
    CHECK(ok(grid_init(&g, geo, top.data(), bottom.data(), top.size())));
    grid_block_stock(&g, height_lsb);
  }
  void hole(int i, int j) { top[g.index(i, j)] = bottom[g.index(i, j)] = 0; }
  void set(int i, int j, int64_t t, int64_t b = 0) {
    top[g.index(i, j)] = static_cast<H>(t);
    bottom[g.index(i, j)] = static_cast<H>(b);
  }
};

struct Compared {
  size_t cells = 0, merged = 0;  // triangles
  int64_t volume6 = 0;
};

// Both surfaces of g, checked; prints what fails.
template <class H>
Compared compare(const DexelGrid<H>& g, const char* what) {
  const SurfaceMaterial m(g);
  t::TriangleList cells, merged;
  cell_surface(g, m, &cells);
  merged_surface(g, m, 0, &merged);
  const t::MeshFacts a = t::mesh_facts(cells.tris), b = t::mesh_facts(merged.tris);
  const int64_t v6 = t::cell_volume6(g, m);
  const bool good = a.open_edges == 0 && b.open_edges == 0 && b.flat_tris == 0 && a.volume6 == v6 && b.volume6 == v6 &&
                    a.euler == b.euler && merged.tris.size() <= cells.tris.size();
  if (!good) {
    std::printf("  %s: cells %zu tris, %ld open, volume6 %lld, euler %lld; merged %zu tris, %ld open, %ld flat, volume6 %lld, "
                "euler %lld; grid's volume6 %lld\n",
                what, cells.tris.size(), a.open_edges, static_cast<long long>(a.volume6), static_cast<long long>(a.euler),
                merged.tris.size(), b.open_edges, b.flat_tris, static_cast<long long>(b.volume6),
                static_cast<long long>(b.euler), static_cast<long long>(v6));
    CHECK(false);
  }
  return Compared{cells.tris.size(), merged.tris.size(), b.volume6};
}

}  // namespace

TEST(stl_merge_block_is_twelve_triangles) {
  Block<uint16_t> b(10, 7);
  const Compared c = compare(b.g, "block");
  // Dexel axes 1..8 by 1..5, 5000 LSB high: one rectangle each for the
  // top, the bottom and the four walls.
  CHECK_EQ(c.merged, size_t{12});
  CHECK_EQ(c.volume6, int64_t{6 * 7 * 4 * 5000});
  CHECK_EQ(c.cells, size_t{7 * 4 * 4 + 2 * 2 * (7 + 4)});
}

TEST(stl_merge_steps_holes_thin_walls) {
  Block<uint16_t> b(24, 18);
  for (int j = 3; j < 9; ++j)
    for (int i = 3; i < 10; ++i) b.set(i, j, 2000);  // a pocket floor
  for (int j = 3; j < 9; ++j) b.set(10, j, 5000);     // a wall one dexel wide
  for (int j = 3; j < 9; ++j)
    for (int i = 11; i < 16; ++i) b.set(i, j, 3000);  // another floor
  for (int j = 3; j < 9; ++j) b.set(16, j, 5000), b.set(17, j, 5000);  // two dexels wide
  for (int j = 3; j < 9; ++j)
    for (int i = 18; i < 21; ++i) b.hole(i, j);       // through the stock
  for (int j = 11; j < 16; ++j)
    for (int i = 2; i < 22; ++i) b.set(i, j, 1000 + 100 * (i % 3), 0);  // a ramp of steps
  b.hole(5, 13); b.hole(6, 14);                       // diagonal holes
  for (int i = 4; i < 12; ++i) b.set(i, 10, 5000, 800);  // lifted bottom
  b.set(8, 6, 2500);                                  // a bump on the floor
  compare(b.g, "steps");
}

TEST(stl_merge_random_patchworks) {
  t::Rng rng(24);
  for (int round = 0; round < 60; ++round) {
    const int nx = static_cast<int>(rng.range(4, 28)), ny = static_cast<int>(rng.range(4, 22));
    Block<uint16_t> b(nx, ny, 6000);
    const int patches = static_cast<int>(rng.range(0, 12));
    for (int p = 0; p < patches; ++p) {
      const int i0 = static_cast<int>(rng.range(1, nx - 2)), j0 = static_cast<int>(rng.range(1, ny - 2));
      const int i1 = static_cast<int>(rng.range(i0, nx - 2)), j1 = static_cast<int>(rng.range(j0, ny - 2));
      const int kind = static_cast<int>(rng.range(0, 4));
      const int64_t h = 1000 * rng.range(2, 6), lift = 300 * rng.range(0, 3);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          if (kind == 0) b.hole(i, j);
          else if (kind == 1) b.set(i, j, h, b.bottom[b.g.index(i, j)]);
          else if (kind == 2) b.set(i, j, h, lift);
          else if (kind == 3) b.set(i, j, h + 50 * ((i + j) % 2));  // rough
          else if (rng.range(0, 3) == 0) b.hole(i, j);             // speckled
        }
    }
    compare(b.g, "patchwork");
  }
}

TEST(stl_merge_random_heights_and_wide_types) {
  t::Rng rng(7);
  for (int round = 0; round < 20; ++round) {
    Block<uint32_t> b(static_cast<int>(rng.range(5, 16)), static_cast<int>(rng.range(5, 16)), 100000);
    for (int j = 1; j + 1 < b.g.ny; ++j)
      for (int i = 1; i + 1 < b.g.nx; ++i) {
        const int64_t r = rng.range(0, 9);
        if (r < 3) b.hole(i, j);
        else if (r < 6) b.set(i, j, 70000 + 1000 * rng.range(0, 3), 1000 * rng.range(0, 1));
        else b.set(i, j, rng.range(2000, 99000), rng.range(0, 1000));
      }
    compare(b.g, "random");
  }
}

TEST(stl_merge_milled_part_is_smaller) {
  t::TestGrid<uint16_t> tg;
  t::make_pocketed(&tg);
  const Compared c = compare(tg.g, "pocketed");
  std::printf("  pocketed 60x40: %zu cell triangles, %zu merged\n", c.cells, c.merged);
  CHECK(c.merged * 3 < c.cells);
}

// Every subset of kept points on a 3 x 3 rectangle's caps and rails: n
// points give n - 2 triangles, none flat, covering the rectangle once, and
// the polygon's sides each in one triangle, every chord in two.
TEST(stl_ladder_every_subset_of_points) {
  for (unsigned subset = 0; subset < 256; ++subset) {
    std::vector<int64_t> start_cap, end_cap;
    for (int k = 0; k < 2; ++k) {
      if (subset >> k & 1) start_cap.push_back(1 + k);
      if (subset >> (2 + k) & 1) end_cap.push_back(1 + k);
    }
    t::TriangleList tris;
    const LadderPlane plane{LadderPlane::kXY, 0, false, &tris};
    Ladder lad;
    lad.open(0, 3, 0, start_cap);
    int points = 4 + static_cast<int>(start_cap.size() + end_cap.size());
    for (int y = 1; y < 3; ++y)
      for (int rail = 0; rail < 2; ++rail)
        if (subset >> (4 + 2 * rail + (y - 1)) & 1) {
          lad.feed(rail == 1, y, plane);
          ++points;
        }
    lad.close(3, end_cap, plane);
    // Close the polygon with one big face turned over (its fan from a
    // corner would be flat): a triangle per side to a point below.
    CHECK_EQ(tris.tris.size(), static_cast<size_t>(points - 2));
    int64_t area2 = 0;
    t::TriangleList lid;
    for (const t::IntTri& tr : tris.tris) {
      const int64_t* a = tr.v[0];
      const int64_t* b = tr.v[1];
      const int64_t* c = tr.v[2];
      const int64_t cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      CHECK(cross > 0);
      area2 += cross;
    }
    CHECK_EQ(area2, int64_t{18});
    // The sides: a cone from (1, 1, -1) under each side, run backwards,
    // makes a closed surface exactly when the sides are each used once.
    std::vector<t::IntTri> closed = tris.tris;
    std::vector<std::pair<int64_t, int64_t>> ring;  // the polygon, counterclockwise
    ring.push_back({0, 0});
    for (int64_t s : start_cap) ring.push_back({s, 0});
    ring.push_back({3, 0});
    for (int y = 1; y < 3; ++y)
      if (subset >> (4 + 2 + (y - 1)) & 1) ring.push_back({3, y});
    ring.push_back({3, 3});
    for (auto it = end_cap.rbegin(); it != end_cap.rend(); ++it) ring.push_back({*it, 3});
    ring.push_back({0, 3});
    for (int y = 2; y > 0; --y)
      if (subset >> (4 + (y - 1)) & 1) ring.push_back({0, y});
    for (size_t k = 0; k < ring.size(); ++k) {
      const auto& p = ring[k];
      const auto& q = ring[(k + 1) % ring.size()];
      closed.push_back(t::IntTri{{{q.first, q.second, 0}, {p.first, p.second, 0}, {1, 1, -1}}});
    }
    const t::MeshFacts f = t::mesh_facts(closed);
    CHECK_EQ(f.open_edges, 0L);
    CHECK_EQ(f.euler, int64_t{2});
  }
}
