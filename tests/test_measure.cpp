// `dexmill measure STOCK --at X,Y` (core/measure/measure_at.h, tools/cli/cmd_measure.cpp):
// on a grid the test fills, the nearest column to points between
// columns, never farther than pitch / sqrt 2, a hole, the lines kept; from
// the CLI, a slot and a drilled hole cut and saved, then measured at both,
// at uncut stock and between columns, with the line of the program that
// cut each; usage and input errors.
#include <cmath>
#include <cstdio>
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

// Parts of known shape, cut and saved by the CLI, then measured: two
// pockets 8 mm deep in a 10 mm block leave a 2 mm floor and a 2 mm wall
// between them; one pocket in the middle leaves no wall thinner than its
// sides (4 mm across Y); a slot's section at known points; a ball-nose
// raster's scallop against the formula.
TEST(run_measure_thickness_of_pockets) {
  using namespace run_cli;
  if (skip()) return;
  write_tmp("pockets.ngc", "G21 G90 G94\nS10000 M3\nG0 X5 Y5 Z5\nG1 Z-8 F300\nG1 X11 F600\nG1 Y15\nG1 X5\nG1 Y5\nG0 Z5\n"
                           "G0 X19 Y5\nG1 Z-8 F300\nG1 X25 F600\nG1 Y15\nG1 X19\nG1 Y5\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/pockets.ngc --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.1 -q --save-stock %/pockets.dxstock").code, 0);
  Result r = run_command("measure %/pockets.dxstock --thickness");
  CHECK_EQ(r.code, 0);
  // The floor: stock bottom Z-10 to the pocket's Z-8, within two LSB.
  CHECK(has(r.out, "thinnest floor: 2.0000 mm at "));
  CHECK(has(r.out, "(top Z-8.0000, bottom Z-10.0000; within 0.0004 mm"));
  // The wall X14..X16: 2 mm within one step (0.1 mm); its columns X14.1..X15.9.
  CHECK(has(r.out, "thinnest wall: 1.900 mm across X at X15.000 "));
  CHECK(has(r.out, "top Z0.0000 over Z-8.0000; within 0.100 mm; walls at least 1.000 mm high)"));
  // Higher than the pockets are deep: no wall but the block's own sides.
  r = run_command("measure %/pockets.dxstock --thickness --wall-height 8.5");
  CHECK(has(r.out, "thinnest wall: 20.100 mm across Y"));
  CHECK(has(r.out, "air on both sides"));
  // One pocket in the middle (cut X8..22, Y4..16): its sides are 8 and 4 mm.
  write_tmp("pocket1.ngc", "G21 G90 G94\nS10000 M3\nG0 X11 Y7 Z5\nG1 Z-8 F300\nG1 X19 F600\nG1 Y13\nG1 X11\nG1 Y7\n"
                           "G0 Z5\nM30\n");
  CHECK_EQ(run("%/pocket1.ngc --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.1 -q --save-stock %/pocket1.dxstock").code, 0);
  r = run_command("measure %/pocket1.dxstock --thickness");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "thinnest wall: 4.000 mm across Y at "));  // Y0..Y3.9 and Y16.1..Y20: 40 columns
  // The picture: a PNG of the part in run's thin colouring.
  r = run_command("measure %/pocket1.dxstock --thickness --image %/pocket1.png --thin 3");
  CHECK_EQ(r.code, 0);
  CHECK_EQ(slurp(tmp_dir() + "/pocket1.png").compare(0, 8, "\x89PNG\r\n\x1a\n"), 0);
  CHECK_EQ(run_command("measure %/pocket1.dxstock --image %/x.png").code, 2);  // --image needs --thickness
  CHECK_EQ(run_command("measure %/pocket1.dxstock --thickness --image %/pocket1.dxstock").code, 2);
  CHECK_EQ(run_command("measure %/pocket1.dxstock --thickness --thin -1").code, 2);
  // Usage: a wall height of 0, --wall-height needs a number.
  CHECK_EQ(run_command("measure %/pocket1.dxstock --thickness --wall-height 0").code, 2);
  CHECK_EQ(run_command("measure %/pocket1.dxstock --thickness --wall-height x").code, 2);
}

TEST(run_measure_a_slot_section) {
  using namespace run_cli;
  if (skip()) return;
  // A slot 6 mm wide (Y7..Y13), 2 mm deep, along X5..X25.
  write_tmp("slot.ngc", "G21 G90 G94\nS10000 M3\nG0 X5 Y10 Z5\nG1 Z-2 F300\nG1 X25 F600\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/slot.ngc --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.1 -q --save-stock %/slot.dxstock").code, 0);
  Result r = run_command("measure %/slot.dxstock --distance 15,0,15,20");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "along_mm,x_mm,y_mm,column_x_mm,column_y_mm,material,top_mm,bottom_mm,design_mm,line\n"));
  CHECK(has(r.out, "\n0.0000,15.0000,0.0000,15.0000,0.0000,1,0.0000,-10.0000,,0\n"));
  CHECK(has(r.out, "\n6.9000,15.0000,6.9000,15.0000,6.9000,1,0.0000,-10.0000,,0\n"));
  CHECK(has(r.out, "\n7.1000,15.0000,7.1000,15.0000,7.1000,1,-2.0000,-10.0000,,5\n"));
  CHECK(has(r.out, "\n10.0000,15.0000,10.0000,15.0000,10.0000,1,-2.0000,-10.0000,,5\n"));
  CHECK(has(r.out, "\n12.9000,15.0000,12.9000,15.0000,12.9000,1,-2.0000,-10.0000,,5\n"));
  CHECK(has(r.out, "\n13.1000,15.0000,13.1000,15.0000,13.1000,1,0.0000,-10.0000,,0\n"));
  CHECK(has(r.out, "\n20.0000,15.0000,20.0000,15.0000,20.0000,1,0.0000,-10.0000,,0\n"));
  size_t rows = 0;
  for (char ch : r.out) rows += ch == '\n';
  CHECK_EQ(rows, 202u);  // the header and 201 samples, one a pitch
  // Into files: the CSV the same, the chart an SVG with the section's title and axes.
  const std::string csv = r.out;
  r = run_command("measure %/slot.dxstock --distance 15,0,15,20 --csv %/slot.csv --svg %/slot.svg");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "section X15.000 Y0.000 to X15.000 Y20.000: 201 samples over 20.000 mm (heights within 0.0002 mm; "
                   "each sample's column within 0.071 mm of its point)"));
  CHECK_EQ(slurp(tmp_dir() + "/slot.csv"), csv);
  const std::string svg = slurp(tmp_dir() + "/slot.svg");
  CHECK(has(svg, "<svg xmlns="));
  CHECK(has(svg, "section X15.000 Y0.000 to X15.000 Y20.000"));
  CHECK(has(svg, "distance along the section (mm)"));
  CHECK(has(svg, ">-10</text>"));
  CHECK(has(svg, "</svg>\n"));
  // Errors: off the grid, --csv without --distance, the CSV onto the stock, a malformed segment.
  r = run_command("measure %/slot.dxstock --distance 15,0,15,25");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "off the stock's grid"));
  CHECK_EQ(run_command("measure %/slot.dxstock --at 1,1 --csv %/x.csv").code, 2);
  CHECK_EQ(run_command("measure %/slot.dxstock --distance 1,1,2 ").code, 2);
  r = run_command("measure %/slot.dxstock --distance 1,1,2,2 --csv %/slot.dxstock");
  CHECK_EQ(r.code, 2);
  CHECK_EQ(run_command("measure %/slot.dxstock --at 12,10").code, 0);  // the stock is intact
  // A design 1 mm below the top (a flat PGM, white at Z-1): the slot's
  // floor is 1 mm under it, the uncut top 1 mm over, within two LSB.
  write_tmp("flat.pgm", "P2\n2 2\n255\n255 255\n255 255\n");
  r = run_command("measure %/slot.dxstock --design %/flat.pgm --design-z -3,-1 --at 15,10 --at 2,2");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "slot.ngc; design Z-1.0000, cut - design -1.0000 mm (within 0.0004 mm)\n"));
  CHECK(has(r.out, "uncut; design Z-1.0000, cut - design +1.0000 mm (within 0.0004 mm)\n"));
  r = run_command("measure %/slot.dxstock --design %/flat.pgm --design-z -3,-1 --distance 15,0,15,20 --svg %/slotd.svg");
  CHECK(has(r.out, "\n10.0000,15.0000,10.0000,15.0000,10.0000,1,-2.0000,-10.0000,-1.0000,5\n"));
  CHECK(has(slurp(tmp_dir() + "/slotd.svg"), "(dashed: the design)"));
  // A design that is not there, or is the CSV's name.
  CHECK_EQ(run_command("measure %/slot.dxstock --design %/none.pgm --at 1,1").code, 3);
  CHECK_EQ(run_command("measure %/slot.dxstock --design %/flat.pgm --distance 1,1,2,2 --csv %/flat.pgm").code, 2);
}

TEST(run_measure_a_ball_nose_scallop) {
  using namespace run_cli;
  if (skip()) return;
  // Passes along X at Y5, 6, ... 15 with a 6 mm ball (R 3): stepover 1 mm,
  // scallop R - sqrt(R^2 - 0.25) = 0.041742 mm.
  std::string prog = "G21 G90 G94\nS10000 M3\nG0 X2 Y5 Z5\nG1 Z-2 F300\n";
  for (int k = 0; k <= 10; ++k) {
    prog += std::string("G1 X") + (k % 2 ? "2" : "28") + " F600\n";
    if (k < 10) prog += "G1 Y" + std::to_string(6 + k) + "\n";
  }
  prog += "G0 Z5\nM30\n";
  write_tmp("raster.ngc", prog.c_str());
  CHECK_EQ(run("%/raster.ngc --tool ball:6 --stock 0,0,-10,30,20,0 --pitch 0.05 -q --save-stock %/raster.dxstock").code, 0);
  Result r = run_command("measure %/raster.dxstock --scallop 8,6,22,14");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "scallop region: X8.000 Y6.000 to X22.000 Y14.000 (281 x 161 columns)\n"));
  CHECK(has(r.out, "scallop across X: none"));  // along the feed: flat
  const size_t at = r.out.find("scallop across Y: ");
  CHECK(at != std::string::npos);
  double h = 0, bound = 0;
  const size_t within = r.out.find("within ", at);
  CHECK(within != std::string::npos);
  CHECK_EQ(std::sscanf(r.out.c_str() + at, "scallop across Y: %lf", &h), 1);
  CHECK_EQ(std::sscanf(r.out.c_str() + within, "within %lf", &bound), 1);
  const double want = 3.0 - std::sqrt(9.0 - 0.25);
  CHECK_NEAR(h, want, bound);
  // One dexel's worth of height: the cusp's slope (0.5 / sqrt(8.75)) times
  // the pitch, at the crest and the valley, and two LSB.
  CHECK_LE(bound, 2 * 0.0002 + 2 * 0.05 * 0.5 / std::sqrt(8.75) + 0.0002);
  // Errors: a box off the grid, a box that is not four numbers. The
  // operand after a bare --scallop is not its box.
  CHECK_EQ(run_command("measure %/raster.dxstock --scallop 40,40,50,50").code, 2);
  CHECK_EQ(run_command("measure %/raster.dxstock --scallop 8,6,22").code, 2);
  CHECK_EQ(run_command("measure --scallop %/raster.dxstock").code, 0);
  CHECK_EQ(run_command("measure %/raster.dxstock --scallop=8,6,22,14").code, 0);
}
