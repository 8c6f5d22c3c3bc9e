// The STL surface is closed: every edge is shared by exactly two triangles
// with opposite directions, on grids with holes, islands, diagonal contacts
// and through holes; a plain block has the block's exact volume.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "platform/stl.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

struct Mesh {
  uint32_t count = 0;
  std::vector<float> v;  // 9 per triangle
  bool ok = false;
};

Mesh read_stl(const char* path) {
  Mesh m;
  std::FILE* f = std::fopen(path, "rb");
  if (!f) return m;
  uint8_t head[84];
  if (std::fread(head, 1, 84, f) == 84) {
    std::memcpy(&m.count, head + 80, 4);
    m.v.resize(static_cast<size_t>(m.count) * 9);
    uint8_t tri[50];
    size_t k = 0;
    for (; k < m.count && std::fread(tri, 1, 50, f) == 50; ++k) std::memcpy(&m.v[k * 9], tri + 12, 36);
    m.ok = k == m.count && std::fgetc(f) == EOF;
  }
  std::fclose(f);
  return m;
}

using P = std::tuple<float, float, float>;

// Directed edges: each must appear once, and its reverse once.
bool closed(const Mesh& m, long* bad) {
  std::map<std::pair<P, P>, int> edges;
  for (uint32_t t = 0; t < m.count; ++t) {
    P p[3];
    for (int k = 0; k < 3; ++k) p[k] = P{m.v[t * 9 + 3 * k], m.v[t * 9 + 3 * k + 1], m.v[t * 9 + 3 * k + 2]};
    for (int k = 0; k < 3; ++k) ++edges[{p[k], p[(k + 1) % 3]}];
  }
  *bad = 0;
  for (const auto& e : edges) {
    auto r = edges.find({e.first.second, e.first.first});
    if (e.second != 1 || r == edges.end() || r->second != 1) {
      if (++*bad <= 12 && std::getenv("DEXMILL_STL_DEBUG"))
        std::printf("  edge (%g %g %g)->(%g %g %g) x%d, reverse x%d\n", std::get<0>(e.first.first), std::get<1>(e.first.first),
                    std::get<2>(e.first.first), std::get<0>(e.first.second), std::get<1>(e.first.second),
                    std::get<2>(e.first.second), e.second, r == edges.end() ? 0 : r->second);
    }
  }
  return *bad == 0;
}

double signed_volume(const Mesh& m) {
  double vol = 0;
  for (uint32_t t = 0; t < m.count; ++t) {
    const float* a = &m.v[t * 9];
    const float *b = a + 3, *c = a + 6;
    vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
  }
  return vol;
}

struct G {
  DexelGrid<uint16_t> g;
  std::vector<uint16_t> top, bottom;
  G(int nx, int ny) : top(static_cast<size_t>(nx) * ny), bottom(top.size()) {
    GridGeometry geo{nx, ny, -kNmPerMm, -2 * kNmPerMm, kNmPerMm, -5 * kNmPerMm, 1000};
    CHECK(ok(grid_init(&g, geo, top.data(), bottom.data(), top.size())));
    grid_block_stock(&g, 5000);
  }
};

std::string tmp_path(const char* name) {
  char p[256];
  std::snprintf(p, sizeof p, "/tmp/dexmill-test-%ld-%s", static_cast<long>(getpid()), name);
  return p;
}

void check_closed(const DexelGrid<uint16_t>& g, const char* what) {
  const std::string path = tmp_path("t.stl");
  char err[256];
  CHECK(write_stl(path.c_str(), g, err, sizeof err));
  const Mesh m = read_stl(path.c_str());
  std::remove(path.c_str());
  CHECK(m.ok);
  CHECK_EQ(static_cast<uint64_t>(m.count), stl_triangle_count(g));
  long bad = 0;
  if (!closed(m, &bad)) {
    std::printf("  %s: %ld open or doubled edges\n", what, bad);
    CHECK(false);
  }
  CHECK(m.count == 0 || signed_volume(m) > 0);
}

}  // namespace

TEST(stl_block_is_closed_with_exact_volume) {
  G b(10, 7);
  check_closed(b.g, "block");
  const std::string path = tmp_path("b.stl");
  char err[256];
  CHECK(write_stl(path.c_str(), b.g, err, sizeof err));
  const Mesh m = read_stl(path.c_str());
  std::remove(path.c_str());
  // Dexel axes 1..8 by 1..5 (1 mm pitch), 5 mm high: 7 x 4 x 5.
  CHECK_NEAR(signed_volume(m), 140.0, 1e-3);
  // 8x5 interior cells: 2 tops + 2 bottoms each; 2 x (7 + 4) border walls, 2 triangles each.
  CHECK_EQ(m.count, 7u * 4u * 4u + 2u * 2u * (7u + 4u));
}

TEST(stl_holes_islands_and_diagonals_are_closed) {
  G b(12, 10);
  auto hole = [&](int i, int j) { b.top[b.g.index(i, j)] = 0; b.bottom[b.g.index(i, j)] = 0; };
  hole(3, 3); hole(4, 4);               // diagonal pair of holes
  hole(7, 2); hole(8, 2); hole(7, 3);   // an L
  for (int i = 2; i < 10; ++i) hole(i, 6);  // a slot cutting an island off
  for (int j = 6; j < 9; ++j) hole(5, j);
  b.top[b.g.index(9, 8)] = 2000;        // a step
  b.bottom[b.g.index(2, 2)] = 1000;     // material lifted off the bottom
  check_closed(b.g, "shapes");
}

TEST(stl_random_grids_are_closed) {
  uint64_t s = 12345;
  auto rnd = [&s]() { s = s * 6364136223846793005ull + 1442695040888963407ull; return static_cast<uint32_t>(s >> 33); };
  for (int round = 0; round < 40; ++round) {
    G b(9 + round % 5, 8 + round % 3);
    for (int j = 1; j + 1 < b.g.ny; ++j) {
      for (int i = 1; i + 1 < b.g.nx; ++i) {
        const size_t k = b.g.index(i, j);
        const uint32_t r = rnd() % 100;
        if (r < 35) { b.top[k] = 0; b.bottom[k] = 0; }
        else { b.bottom[k] = static_cast<uint16_t>(rnd() % 1000); b.top[k] = static_cast<uint16_t>(2000 + rnd() % 3000); }
      }
    }
    check_closed(b.g, "random");
  }
  G empty(6, 6);
  for (auto& h : empty.top) h = 0;
  check_closed(empty.g, "empty");
}

TEST(stl_size_is_said_before_a_huge_file) {
  // 10 M triangles are half a gigabyte: said before writing; 1 M is not.
  const std::string note = dexmill::stl_size_note(10000000, "part.stl");
  CHECK(note.find("writing a 0.5 GB STL (10000000 triangles) to 'part.stl'") != std::string::npos);
  CHECK(dexmill::stl_size_note(1000000, "part.stl").empty());
}
