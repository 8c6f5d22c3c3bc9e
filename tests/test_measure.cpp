// `dexmill measure STOCK --at X,Y` (core/measure/measure_at.h, tools/cli/cmd_measure.cpp):
// on a grid the test fills, the nearest column to points between
// columns, never farther than pitch / sqrt 2, a hole, the lines kept; from
// the CLI, a slot and a drilled hole cut and saved, then measured at both,
// at uncut stock and between columns, with the line of the program that
// cut each; usage and input errors.
#include <cmath>
#include <string>
#include <vector>

#include "core/measure/measure_at.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

TEST(measure_at_the_nearest_column) {
  constexpr int32_t nx = 11, ny = 7;
  std::vector<uint16_t> top(nx * ny, 500), bottom(nx * ny, 0);
  std::vector<uint32_t> lines(nx * ny, 0);
  DexelGrid<uint16_t> g;
  const GridGeometry geo{nx, ny, 1000000, 2000000, 500000, -10000000, 1000};  // 0.5 mm pitch from X1 Y2, LSB 1 um
  CHECK(ok(grid_init(&g, geo, top.data(), bottom.data(), top.size())));
  top[g.index(4, 3)] = 200;
  lines[g.index(4, 3)] = 17;
  top[g.index(5, 3)] = 0;  // a hole
  // Exactly on column (4, 3): X3 Y3.5.
  MeasureAt m = measure_at(g, lines.data(), nullptr, 3000000, 3500000);
  CHECK(m.on_grid && m.i == 4 && m.j == 3 && m.distance_nm == 0);
  CHECK(m.material);
  CHECK_EQ(m.top_nm, -10000000 + 200 * 1000);
  CHECK_EQ(m.bottom_nm, -10000000);
  CHECK_EQ(m.line, 17u);
  CHECK_EQ(m.height_error_nm, 1000);
  // Between columns: the nearest, at most pitch / sqrt 2 away.
  int64_t worst = 0;
  for (int64_t x = 800000; x <= 6200000; x += 37000)
    for (int64_t y = 1800000; y <= 5200000; y += 41000) {
      const MeasureAt q = measure_at(g, nullptr, nullptr, x, y);
      CHECK(q.on_grid);
      const double d = std::hypot(static_cast<double>(x - q.column_x_nm), static_cast<double>(y - q.column_y_nm));
      CHECK_LE(std::fabs(d - static_cast<double>(q.distance_nm)), 1.0);
      for (int di = -1; di <= 1; ++di)  // no other column is nearer
        for (int dj = -1; dj <= 1; ++dj) {
          const double ox = static_cast<double>(q.column_x_nm + di * 500000 - x), oy = static_cast<double>(q.column_y_nm + dj * 500000 - y);
          CHECK_GE(std::hypot(ox, oy) + 1.0, d);
        }
      worst = std::max(worst, q.distance_nm);
    }
  CHECK_LE(worst, 353554);  // 0.5 mm / sqrt 2
  // The hole, and points off the grid (more than half a pitch past it).
  CHECK(!measure_at(g, nullptr, nullptr, 3500000, 3500000).material);
  CHECK(measure_at(g, nullptr, nullptr, 1000000 - 240000, 2000000).on_grid);
  CHECK(!measure_at(g, nullptr, nullptr, 1000000 - 260000, 2000000).on_grid);
  CHECK(!measure_at(g, nullptr, nullptr, 1000000 + 10 * 500000 + 260000, 2000000).on_grid);
}

TEST(run_measure_a_saved_stock) {
  using namespace run_cli;
  if (skip()) return;
  write_tmp("measure.ngc", "G21 G90 G94\nS10000 M3\nG0 X5 Y10 Z5\nG1 Z-2 F300\nG1 X25 F600\nG0 Z5\nG0 X15 Y15\nG1 Z-12 F100\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/measure.ngc --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.1 -q --save-stock %/measure.dxstock").code, 0);
  Result r = run_command("measure %/measure.dxstock --at 12,10 --at 15,15 --at 2,2 --at 12.03,10.04");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "X12.000 Y10.000: top Z-2.0000, bottom Z-10.0000 mm (the column at X12.000 Y10.000, 0.000 mm away; "
                   "heights within 0.0002 mm); last cut by line 5 of "));
  CHECK(has(r.out, "X15.000 Y15.000: no material (cut through)"));
  CHECK(has(r.out, "; last cut by line 8 of "));
  CHECK(has(r.out, "X2.000 Y2.000: top Z0.0000, bottom Z-10.0000 mm"));
  CHECK(has(r.out, "mm); uncut\n"));
  CHECK(has(r.out, "X12.030 Y10.040: top Z-2.0000, bottom Z-10.0000 mm (the column at X12.000 Y10.000, 0.050 mm away"));
  // Errors: a point off the grid, no query, no file, a file that is not a stock.
  r = run_command("measure %/measure.dxstock --at 40,10");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "X40.000 Y10.000 is off the stock's grid"));
  CHECK_EQ(run_command("measure %/measure.dxstock").code, 2);
  CHECK_EQ(run_command("measure %/measure.dxstock --at 1").code, 2);
  CHECK_EQ(run_command("measure %/no-such.dxstock --at 1,1").code, 3);
  CHECK_EQ(run_command("measure %/measure.ngc --at 1,1").code, 1);
}
