// A two-sided part made the way a shop makes one, with dexmill's own
// programs: side one cuts a pocket and drills four holes through from the
// top; the part is flipped about X (--setup flip-x); side two cuts a
// pocket from the old bottom that meets two of the holes. The chain
// removes the analytic volume within the grid's bound, the holes show from
// the new top, and the part's surface is closed.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/grid/grid.h"
#include "core/stock/stock_file.h"
#include "platform/mesh/stl_merge.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/stock_util.h"
#include "tests/stl_check.h"

using namespace dexmill;
using namespace run_cli;

namespace {

const char kSide1[] =
    "(side 1: a pocket and four through holes from the top)\n"
    "G21 G90 G17 G94\nG0 Z5\nG0 X12 Y12\nG1 Z-4 F300\nG1 X28 F800\nG1 Y18\nG1 X12\nG1 Y12\nG1 X28 Y15\nG1 X12\n"
    "G0 Z5\nG81 X8 Y8 Z-11 R2 F200\nX32\nY22\nX8\nG80\nG0 Z10\nM30\n";
const char kSide2[] =
    "(side 2, after flip-x: a pocket from the old bottom meeting two holes)\n"
    "G21 G90 G17 G94\nG0 Z5\nG0 X5 Y5\nG1 Z-3 F300\nG1 X35 F800\nG1 Y11\nG1 X5\nG1 Y5\nG1 X35 Y8\nG1 X5\n"
    "G0 Z10\nM30\n";

// A rectangle of paths swept by a disc of radius r: the rectangle grown by
// r with rounded corners.
double rounded_rect(double w, double h, double r) { return (w + 2 * r) * (h + 2 * r) - (4 - M_PI) * r * r; }

}  // namespace

TEST(two_sided_part_from_two_programs_and_a_flip) {
  if (skip()) return;
  write_tmp("side1.ngc", kSide1);
  write_tmp("side2.ngc", kSide2);
  const double pitch = 0.2, lsb_mm = 0.0002;
  CHECK_EQ(run("%/side1.ngc -q --tool flat:3 --stock 0,0,-10,40,30,0 --pitch 0.2 --save-stock %/side1.dxstock").code, 0);
  CHECK_EQ(run("%/side2.ngc -q --tool flat:3 --stock %/side1.dxstock --setup flip-x --save-stock %/part.dxstock "
               "--report %/part.json").code,
           0);
  const t::StockFileColumns part = t::read_stock_file(tmp_dir() + "/part.dxstock");
  CHECK(part.ok);
  if (!part.ok) return;
  const StockMeta& m = part.meta;
  CHECK_EQ(m.nprograms, 2);
  CHECK_EQ(m.geo.lsb_nm, 200);
  // What the two sides remove, analytically: side one's pocket (a 16 x 6
  // rectangle of passes 3 mm apart, a 3 mm cutter: the rectangle grown by
  // 1.5 mm, rounded) 4 mm deep, four holes through 10 mm; side two's pocket
  // (30 x 6) 3 mm deep, less the two holes' 3 mm it meets.
  const double hole = M_PI * 1.5 * 1.5;
  const double side1 = rounded_rect(16, 6, 1.5) * 4 + 4 * hole * 10;
  const double side2 = rounded_rect(30, 6, 1.5) * 3 - 2 * hole * 3;
  uint64_t removed_lsb = 0;
  for (int k = 0; k < m.nprograms; ++k) removed_lsb += m.programs[k].removed_lsb_dexels;
  const double removed = static_cast<double>(removed_lsb) * lsb_mm * pitch * pitch;
  // The grid's bound: each column stands for a pitch-square, so along the
  // cut region's boundary (its length times its depth) at most half a
  // pitch of area is misjudged either way; heights are exact to half an LSB.
  const double boundary = (2 * (19 + 9) - (8 - 2 * M_PI) * 1.5) * 4 + 4 * 2 * M_PI * 1.5 * 10 +
                          (2 * (33 + 9) - (8 - 2 * M_PI) * 1.5) * 3;
  const double bound = boundary * pitch / 2 + 201.0 * 151.0 * 0.5 * lsb_mm * pitch * pitch;
  std::printf("  two-sided: removed %.3f mm^3, analytic %.3f, off by %.3f (bound %.3f)\n", removed, side1 + side2,
              removed - (side1 + side2), bound);
  CHECK(std::fabs(removed - (side1 + side2)) <= bound);
  // The holes drilled from side one show from the new top: at their
  // mirrored places (y -> 30 - y), holes through; beside them, full height.
  auto column = [&](double x, double y) {
    const int32_t i = static_cast<int32_t>(std::lround((x * 1e6 - static_cast<double>(m.geo.x0_nm)) / (pitch * 1e6)));
    const int32_t j = static_cast<int32_t>(std::lround((y * 1e6 - static_cast<double>(m.geo.y0_nm)) / (pitch * 1e6)));
    return static_cast<size_t>(j) * static_cast<size_t>(m.geo.nx) + static_cast<size_t>(i);
  };
  for (const double hx : {8.0, 32.0})
    for (const double hy : {8.0, 22.0}) {
      const size_t k = column(hx, 30 - hy);
      CHECK(part.top[k] == 0 && part.bottom[k] == 0);
    }
  // Side one's pocket floor is now the bottom: 4 mm up from the old top.
  const size_t under_pocket = column(20, 30 - 15);
  CHECK_EQ(part.bottom[under_pocket], 0u + 4 * 5000);
  CHECK_EQ(part.top[under_pocket], 50000u);
  // Side two's pocket, 3 mm down from the new top, away from the holes.
  CHECK_EQ(part.top[column(20, 8)], 50000u - 3 * 5000);
  // Its surface is closed and holds the grid's volume.
  DexelGrid<uint16_t> g;
  CHECK(ok(grid_init(&g, m.geo, const_cast<uint16_t*>(part.top.data()), const_cast<uint16_t*>(part.bottom.data()),
                     part.top.size())));
  const SurfaceMaterial mat(g);
  t::TriangleList tris;
  merged_surface(g, mat, 0, &tris);
  const t::MeshFacts f = t::mesh_facts(tris.tris);
  CHECK_EQ(f.open_edges, 0);
  CHECK_EQ(f.volume6, t::cell_volume6(g, mat));
  CHECK(tris.tris.size() > 100u);
}
