// The STL file: written, read back with the project's own reader
// (platform/format/stl_read.h), every vertex exactly on a grid point, closed
// (every directed edge once, its reverse once), the cell surface's volume
// to the last LSB, the count in its header the one stl_triangle_count
// gives; on grids with holes, islands, diagonal contacts and through holes;
// and within a tolerance (platform/mesh/stl_plane.h).
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "platform/format/stl.h"
#include "platform/format/stl_read.h"
#include "tests/runner.h"
#include "tests/stl_check.h"

using namespace dexmill;

namespace {

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

// Writes g's STL (its tops within tolerance_lsb) and reads it back in grid units; false if a vertex is off
// the grid's points.
bool write_and_read(const DexelGrid<uint16_t>& g, std::vector<t::IntTri>* tris, int64_t tolerance_lsb = 0) {
  const std::string path = tmp_path("t.stl");
  char err[256];
  CHECK(write_stl(path.c_str(), g, tolerance_lsb, err, sizeof err));
  bool on_grid = true;
  StlReadInfo info;
  std::string msg;
  const StlRead r = stl_read(
      path, PointNm{0, 0, 0},
      [&](const PointNm* v, std::string*) {
        t::IntTri tr{};
        for (int k = 0; k < 3; ++k) {
          const int64_t d[3] = {v[k].x_nm - g.x0_nm, v[k].y_nm - g.y0_nm, v[k].z_nm - g.z0_nm};
          const int64_t unit[3] = {g.pitch_nm, g.pitch_nm, g.lsb_nm};
          for (int a = 0; a < 3; ++a) {
            on_grid = on_grid && d[a] % unit[a] == 0;
            tr.v[k][a] = d[a] / unit[a];
          }
        }
        tris->push_back(tr);
        return true;
      },
      &info, &msg);
  std::remove(path.c_str());
  CHECK(r == StlRead::kOk);
  CHECK(info.binary);
  CHECK_EQ(info.triangles, stl_triangle_count(g, tolerance_lsb));
  return on_grid;
}

void check_closed(const DexelGrid<uint16_t>& g, const char* what) {
  std::vector<t::IntTri> tris;
  CHECK(write_and_read(g, &tris));
  const t::MeshFacts f = t::mesh_facts(tris);
  const int64_t v6 = t::cell_volume6(g, SurfaceMaterial(g));
  if (f.open_edges || f.flat_tris || f.volume6 != v6) {
    std::printf("  %s: %ld open or doubled edges, %ld flat triangles, volume6 %lld for %lld\n", what, f.open_edges, f.flat_tris,
                static_cast<long long>(f.volume6), static_cast<long long>(v6));
    CHECK(false);
  }
}

}  // namespace

TEST(stl_block_is_closed_with_exact_volume) {
  G b(10, 7);
  std::vector<t::IntTri> tris;
  CHECK(write_and_read(b.g, &tris));
  const t::MeshFacts f = t::mesh_facts(tris);
  CHECK_EQ(f.open_edges, 0L);
  // Dexel axes 1..8 by 1..5 (1 mm pitch), 5000 LSB high: 7 x 4 x 5 mm, and
  // one rectangle (two triangles) each for the top, the bottom, four walls.
  CHECK_EQ(f.volume6, int64_t{6 * 7 * 4 * 5000});
  CHECK_EQ(tris.size(), size_t{12});
  CHECK_EQ(f.euler, int64_t{2});
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
        else if (r < 70) { b.bottom[k] = static_cast<uint16_t>(rnd() % 2 * 500); b.top[k] = static_cast<uint16_t>(3000 + rnd() % 2 * 1000); }
        else { b.bottom[k] = static_cast<uint16_t>(rnd() % 1000); b.top[k] = static_cast<uint16_t>(2000 + rnd() % 3000); }
      }
    }
    check_closed(b.g, "random");
  }
  G empty(6, 6);
  for (auto& h : empty.top) h = 0;
  CHECK_EQ(stl_triangle_count(empty.g, 0), uint64_t{0});
}

TEST(stl_size_is_said_before_a_huge_file) {
  // 10 M triangles are half a gigabyte: said before writing; 1 M is not.
  const std::string note = dexmill::stl_size_note(10000000, "part.stl");
  CHECK(note.find("writing a 0.5 GB STL (10000000 triangles) to 'part.stl'") != std::string::npos);
  CHECK(dexmill::stl_size_note(1000000, "part.stl").empty());
}

// Within a tolerance the file is closed too, its lifted points on the
// grid's, the volume within the tolerance times the top area.
TEST(stl_file_within_tolerance_is_closed) {
  G b(30, 24);
  for (int j = 1; j < 23; ++j)
    for (int i = 1; i < 29; ++i) b.top[b.g.index(i, j)] = static_cast<uint16_t>(4000 + 13 * i + 7 * j + (i * j) % 5);
  b.top[b.g.index(9, 9)] = b.bottom[b.g.index(9, 9)] = 0;  // a hole
  std::vector<t::IntTri> tris;
  CHECK(write_and_read(b.g, &tris, 8));
  const t::MeshFacts f = t::mesh_facts(tris);
  const int64_t v6 = t::cell_volume6(b.g, SurfaceMaterial(b.g));
  const int64_t dv6 = f.volume6 > v6 ? f.volume6 - v6 : v6 - f.volume6;
  CHECK_EQ(f.open_edges, 0L);
  CHECK_EQ(f.flat_tris, 0L);
  CHECK(dv6 <= 6 * 8 * 27 * 21);
  CHECK(tris.size() * 3 < stl_triangle_count(b.g, 0));  // the walls under sloped tops stay a cell's each
}
