// core/grid/grid.h: dexel set set-up (paper §2.2.1), gradient (§2.1 eq. 1), LSB.
#include <cstdint>
#include <vector>

#include "core/grid/grid.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
GridGeometry geometry(int32_t nx, int32_t ny) {
  GridGeometry g{};
  g.nx = nx;
  g.ny = ny;
  g.x0_nm = -500000;
  g.y0_nm = 250000;
  g.pitch_nm = 1000000;
  g.z0_nm = -20 * kNmPerMm;
  g.lsb_nm = 1000;
  return g;
}
}  // namespace

TEST(grid_init_rejects_bad_input) {
  std::vector<uint16_t> t(100), b(100);
  DexelGrid<uint16_t> g;
  CHECK_EQ(grid_init(&g, geometry(10, 10), t.data(), b.data(), 100), Status::kOk);
  CHECK_EQ(grid_init(&g, geometry(10, 11), t.data(), b.data(), 100), Status::kBufferTooSmall);
  CHECK_EQ(grid_init(&g, geometry(1, 10), t.data(), b.data(), 100), Status::kBadArgument);
  GridGeometry bad = geometry(10, 10);
  bad.pitch_nm = 0;
  CHECK_EQ(grid_init(&g, bad, t.data(), b.data(), 100), Status::kBadArgument);
  bad = geometry(10, 10);
  bad.lsb_nm = -3;
  CHECK_EQ(grid_init(&g, bad, t.data(), b.data(), 100), Status::kBadArgument);
  bad = geometry(10, 10);
  bad.x0_nm = INT64_MIN;
  CHECK_EQ(grid_init(&g, bad, t.data(), b.data(), 100), Status::kBadArgument);
  CHECK_EQ(grid_init<uint16_t>(&g, geometry(10, 10), nullptr, b.data(), 100), Status::kBufferTooSmall);
}

template <class H>
static void check_block_stock() {
  const int32_t nx = 7, ny = 5;
  std::vector<H> t(nx * ny, H(77)), b(nx * ny, H(3));
  DexelGrid<H> g;
  CHECK_EQ(grid_init(&g, geometry(nx, ny), t.data(), b.data(), t.size()), Status::kOk);
  grid_block_stock(&g, 200);
  for (int32_t j = 0; j < ny; ++j) {
    for (int32_t i = 0; i < nx; ++i) {
      bool border = i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
      CHECK_EQ(static_cast<int64_t>(g.top[g.index(i, j)]), border ? 0 : 200);
      CHECK_EQ(static_cast<int64_t>(g.bottom[g.index(i, j)]), 0);
      CHECK_EQ(g.is_hole(i, j), border);
    }
  }
  CHECK_EQ(g.dirty.i0, 0);
  CHECK_EQ(g.dirty.j1, ny);
  // Heights beyond 2^m - 1 saturate.
  grid_block_stock(&g, int64_t(1) << 40);
  CHECK_EQ(static_cast<int64_t>(g.top[g.index(2, 2)]), height_max<H>());
  grid_block_stock(&g, -5);
  CHECK_EQ(static_cast<int64_t>(g.top[g.index(2, 2)]), 0);
}

TEST(grid_block_stock_borders_all_m) {
  check_block_stock<uint8_t>();
  check_block_stock<uint16_t>();
  check_block_stock<uint32_t>();
}

TEST(grid_gradient_central_differences) {
  const int32_t nx = 6, ny = 4;
  std::vector<uint16_t> t(nx * ny), b(nx * ny);
  DexelGrid<uint16_t> g;
  CHECK_EQ(grid_init(&g, geometry(nx, ny), t.data(), b.data(), t.size()), Status::kOk);
  // A plane: top = 100 + 3 i + 5 j.
  for (int32_t j = 0; j < ny; ++j)
    for (int32_t i = 0; i < nx; ++i) t[g.index(i, j)] = static_cast<uint16_t>(100 + 3 * i + 5 * j);
  for (int32_t j = 0; j < ny; ++j) {
    for (int32_t i = 0; i < nx; ++i) {
      GradientLsb n = grid_gradient(g, i, j);
      CHECK_EQ(n.dx, 6);   // 2 * 3, central or doubled one-sided
      CHECK_EQ(n.dy, 10);  // 2 * 5
      CHECK_EQ(n.dz, 2000);  // 2 * pitch / lsb
    }
  }
}

TEST(grid_height_and_index_mapping) {
  std::vector<uint16_t> t(100), b(100);
  DexelGrid<uint16_t> g;
  CHECK_EQ(grid_init(&g, geometry(10, 10), t.data(), b.data(), 100), Status::kOk);
  CHECK_EQ(grid_height_of_z(g, -20 * kNmPerMm), 0);
  CHECK_EQ(grid_height_of_z(g, -20 * kNmPerMm + 1499), 1);
  CHECK_EQ(grid_height_of_z(g, -20 * kNmPerMm + 1500), 2);
  CHECK_EQ(grid_height_of_z(g, -21 * kNmPerMm), -1000);
  CHECK_EQ(grid_i_of_x(g, -500000), 0);
  CHECK_EQ(grid_i_of_x(g, -500000 + 499999), 0);
  CHECK_EQ(grid_i_of_x(g, -500000 + 500000), 1);
  CHECK_EQ(grid_j_of_y(g, -10 * kNmPerMm), -10);
}

TEST(grid_lsb_for_range) {
  CHECK_EQ(lsb_for_range(20 * kNmPerMm, 16), 500);    // 40 000 steps of 0.5 um
  CHECK_EQ(lsb_for_range(100 * kNmPerMm, 16), 2000);  // 50 000 steps of 2 um
  CHECK_EQ(lsb_for_range(20 * kNmPerMm, 8), 100000);  // 200 steps of 0.1 mm
  CHECK_EQ(lsb_for_range(20 * kNmPerMm, 32), 1);
  CHECK_EQ(lsb_for_range(0, 16), 1);
}

TEST(grid_rect_union) {
  GridRect r = GridRect::none();
  CHECK(r.empty());
  r.include(GridRect{2, 3, 4, 5});
  r.include(GridRect{0, 4, 1, 9});
  r.include(GridRect{5, 5, 5, 9});  // empty: ignored
  CHECK_EQ(r.i0, 0);
  CHECK_EQ(r.j0, 3);
  CHECK_EQ(r.i1, 4);
  CHECK_EQ(r.j1, 9);
}
