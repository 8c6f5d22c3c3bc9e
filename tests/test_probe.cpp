// core/cut/probe.h against a double-precision oracle: a probe along Z stops
// at the highest of top - height(r) over its footprint, to the nanometre
// profile_height_r2_nm gives (its own error: core/tool/tool.h); a probe
// across stops within 1 nm of the first sampled contact and never inside
// the stock; away-moves stop where contact ends; a start in contact and a
// move that never trips are told apart. And `dexmill run`: probes onto an
// untouched top, a pocket floor cut earlier, a flipped part; a miss.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/cut/probe.h"
#include "tests/rng.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

struct Grid {
  DexelGrid<uint16_t> g;
  std::vector<uint16_t> top, bottom;
  explicit Grid(uint64_t seed) : top(60 * 50), bottom(top.size(), 0) {
    GridGeometry geo{60, 50, -1000000, -2000000, 250000, -10000000, 1000};
    CHECK(ok(grid_init(&g, geo, top.data(), bottom.data(), top.size())));
    t::Rng rng(seed);
    for (size_t k = 0; k < top.size(); ++k) top[k] = static_cast<uint16_t>(rng.range(2000, 9000));
    top[5] = bottom[5] = 0;  // a hole
  }
};

Tool tool_of(ToolKind kind, double d_mm, double r_mm, double angle_deg) {
  Tool t{};
  t.kind = kind;
  t.diameter_nm = static_cast<int64_t>(d_mm * 1e6);
  t.corner_radius_nm = static_cast<int64_t>(r_mm * 1e6);
  t.tip_angle_mdeg = static_cast<int32_t>(angle_deg * 1000);
  t.length_nm = 30000000;
  return t;
}

// The double oracle: the lower surface's height at r for each shape.
double height_mm(const Tool& t, double r) {
  const double R = t.diameter_nm * 1e-6 / 2;
  switch (t.kind) {
    case ToolKind::kFlat: return 0;
    case ToolKind::kBall: return R - std::sqrt(std::max(0.0, R * R - r * r));
    case ToolKind::kBullNose: {
      const double rc = t.corner_radius_nm * 1e-6, flat = R - rc;
      if (r <= flat) return 0;
      const double d = r - flat;
      return rc - std::sqrt(std::max(0.0, rc * rc - d * d));
    }
    default: return r / std::tan(t.tip_angle_mdeg * 1e-3 * M_PI / 360.0);
  }
}

}  // namespace

TEST(probe_along_z_stops_at_the_contact_height) {
  const Tool tools[] = {tool_of(ToolKind::kFlat, 3, 0, 0), tool_of(ToolKind::kBall, 3, 0, 0),
                        tool_of(ToolKind::kBullNose, 4, 1, 0), tool_of(ToolKind::kVBit, 3, 0, 90)};
  double worst_nm = 0;
  int probes = 0;
  for (const Tool& tool : tools) {
    const ToolProfile prof = tool_profile(tool);
    Grid grid(3 + static_cast<uint64_t>(tool.kind));
    t::Rng rng(11);
    for (int n = 0; n < 50; ++n) {
      const PointNm from{rng.range(2000000, 10000000), rng.range(1000000, 8000000), 5000000};
      const PointNm to{from.x_nm, from.y_nm, -20000000};
      PointNm stop{0, 0, 0};
      CHECK_EQ(probe_move(grid.g, prof, from, to, true, &stop), ProbeResult::kTripped);
      // The oracle: max over the columns within R of top - height(r).
      double want = -1e300;
      const double R = tool.diameter_nm * 1e-6 / 2;
      for (int32_t j = 0; j < grid.g.ny; ++j)
        for (int32_t i = 0; i < grid.g.nx; ++i) {
          const double dx = (grid.g.x0_nm + i * grid.g.pitch_nm - from.x_nm) * 1e-6;
          const double dy = (grid.g.y0_nm + j * grid.g.pitch_nm - from.y_nm) * 1e-6;
          const double r = std::sqrt(dx * dx + dy * dy);
          if (r > R || grid.g.is_hole(i, j)) continue;
          want = std::max(want, (grid.g.z0_nm + grid.top[grid.g.index(i, j)] * grid.g.lsb_nm) * 1e-6 - height_mm(tool, r));
        }
      worst_nm = std::max(worst_nm, std::fabs(stop.z_nm * 1e-6 - want) * 1e6);
      CHECK(stop.x_nm == from.x_nm && stop.y_nm == from.y_nm);
      // Moving away from there: out of contact 1 nm up.
      PointNm up{0, 0, 0};
      CHECK_EQ(probe_move(grid.g, prof, stop, from, false, &up), ProbeResult::kTripped);
      CHECK_EQ(up.z_nm, stop.z_nm + 1);
      ++probes;
    }
  }
  std::printf("  probe along z: %d probes, worst %.2f nm off the double oracle\n", probes, worst_nm);
  CHECK(worst_nm <= 2.0);  // profile_height_r2_nm rounds within 1 nm; the oracle's sqrt within 1e-6 nm
}

TEST(probe_thinner_than_the_cells_touches_its_cell) {
  // A 0.1 mm tip on a 0.25 mm grid, between four axes (none within its
  // radius): it touches the column of the cell it is in, at its tip, and
  // never goes through the stock.
  Grid grid(9);
  const ToolProfile prof = tool_profile(tool_of(ToolKind::kFlat, 0.1, 0, 0));
  const PointNm from{-1000000 + 10 * 250000 + 110000, -2000000 + 7 * 250000 + 120000, 5000000};
  PointNm stop{0, 0, 0};
  CHECK_EQ(probe_move(grid.g, prof, from, PointNm{from.x_nm, from.y_nm, -20000000}, true, &stop), ProbeResult::kTripped);
  const size_t cell = grid.g.index(10, 7);  // the nearest axis: (10, 7)
  CHECK_EQ(stop.z_nm, grid.g.z0_nm + grid.top[cell] * grid.g.lsb_nm);
  // Nearer the next axis, the next column.
  const PointNm near_next{from.x_nm + 30000, from.y_nm, from.z_nm};
  CHECK_EQ(probe_move(grid.g, prof, near_next, PointNm{near_next.x_nm, near_next.y_nm, -20000000}, true, &stop),
           ProbeResult::kTripped);
  CHECK_EQ(stop.z_nm, grid.g.z0_nm + grid.top[grid.g.index(11, 7)] * grid.g.lsb_nm);
}

TEST(probe_across_stops_at_first_contact_and_outside_the_stock) {
  Grid grid(5);
  // A wall: columns with i >= 40 at 9 mm above z0, the rest at 2 mm.
  for (int32_t j = 0; j < grid.g.ny; ++j)
    for (int32_t i = 0; i < grid.g.nx; ++i) grid.top[grid.g.index(i, j)] = static_cast<uint16_t>(i >= 40 ? 9000 : 2000);
  const ToolProfile prof = tool_profile(tool_of(ToolKind::kFlat, 3, 0, 0));
  const int64_t wall_x = grid.g.x0_nm + 40 * grid.g.pitch_nm, z = -10000000 + 5000000;
  PointNm stop{0, 0, 0};
  CHECK_EQ(probe_move(grid.g, prof, PointNm{0, 4000000, z}, PointNm{20000000, 4000000, z}, true, &stop), ProbeResult::kTripped);
  // The flat tool's rim (1.5 mm) reaches the wall's first column: the stop is 1.5 mm short of it.
  CHECK_EQ(stop.x_nm, wall_x - 1500000);
  CHECK(probe_depth_nm(grid.g, prof, PointNm{stop.x_nm - 1, stop.y_nm, stop.z_nm}) < 0);
  // Starting in contact; and a move that stays above everything.
  CHECK_EQ(probe_move(grid.g, prof, stop, PointNm{0, 4000000, z}, true, &stop), ProbeResult::kAlreadyTripped);
  CHECK_EQ(probe_move(grid.g, prof, PointNm{0, 4000000, 0}, PointNm{5000000, 4000000, 0}, true, &stop),
           ProbeResult::kNoContact);
}

TEST(run_probes_touch_the_simulated_stock) {
  using namespace run_cli;
  if (skip()) return;
  // An untouched top, then a slot's floor cut earlier, then a miss the
  // program allows (G38.3: #5070 = 0), each printed.
  write_tmp("probe.ngc",
            "G21 G90\nG0 X10 Y10 Z5\nG38.2 Z-20 F100\n(DEBUG, top #5063 #5070)\nG0 Z5\nG0 X20 Y10\nG1 Z-3 F200\n"
            "G1 X25\nG0 Z5\nG0 X22 Y10\nG38.2 Z-20 F100\n(DEBUG, floor #5063)\nG0 Z5\nG0 X28 Y2\nG38.3 Z1 F100\n"
            "(DEBUG, missed #5070)\nM30\n");
  Result r = run("%/probe.ngc --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25 --report %/probe.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "probe.ngc:4: debug:  top 0.000000 1.000000"));
  CHECK(has(r.err, "probe.ngc:12: debug:  floor -3.000000"));
  CHECK(has(r.err, "probe.ngc:16: debug:  missed 0.000000"));
  CHECK(lacks(r.err, "warning"));
  CHECK(has(slurp(tmp_dir() + "/probe.json"), "\"text\": \" floor -3.000000\""));
  // The time and the bounds are where the probes stopped, not their ends:
  // down 5 mm at F60 onto the top is 5 s, never the 25 s to Z-20.
  write_tmp("timed.ngc", "G21 G90 G94\nG0 X10 Y10 Z5\nG38.2 Z-20 F60\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/timed.ngc -q --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25 --report %/timed.json").code, 0);
  const std::string timed = slurp(tmp_dir() + "/timed.json");
  CHECK(has(timed, "\"feed_s\": 5.000"));
  CHECK(has(timed, "\"bounds_mm\": {\"min\": [0.0000, 0.0000, 0.0000]"));
  // A probe tip of its own: a 2 mm ball on the 3 mm slot's floor edge.
  r = run("%/probe.ngc --tool flat:3 --probe 2 --stock 0,0,-10,30,20,0 --pitch 0.25");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "probe.ngc:12: debug:  floor -3.000000"));
  // A G38.2 that never touches: an error at its line, the cut stops there.
  write_tmp("miss.ngc", "G21 G90\nG0 X10 Y10 Z5\nG38.2 Z1 F100\nG1 Z-2 F100\nM30\n");
  r = run("%/miss.ngc --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "miss.ngc:3:1: error: G38.2: the probe move reached its end without tripping"));
  // The machine stays where the probe stopped: zeroed there (G92, as
  // pcb2gcode's auto-levelling does), the next probe 2 mm up starts clear.
  write_tmp("zero.ngc", "G21 G90\nG0 X5 Y5 Z5\nG38.2 Z-5 F100\nG92 Z0\nG0 Z2\nG0 X20\nG38.2 Z-5 F100\n"
                        "(DEBUG, second #5063)\nM30\n");
  r = run("%/zero.ngc --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "zero.ngc:8: debug:  second 0.000000"));
  // On a flipped part: side one drills a hole through; after flip-x the
  // probe over the hole's mirrored place goes down through it and misses
  // (G38.3), while beside it the new top is the old bottom, at Z0.
  write_tmp("drill.ngc", "G21 G90\nG0 X10 Y5 Z5\nG1 Z-11 F200\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/drill.ngc -q --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25 --save-stock %/drilled.dxstock").code, 0);
  write_tmp("flipped.ngc",
            "G21 G90\nG0 X10 Y15 Z5\nG38.3 Z-9 F100\n(DEBUG, hole #5070)\nG0 Z5\nG0 X20 Y15\nG38.2 Z-9 F100\n"
            "(DEBUG, top #5063)\nG0 Z5\nM30\n");
  r = run("%/flipped.ngc --tool ball:1 --stock %/drilled.dxstock --setup flip-x");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.err, "flipped.ngc:4: debug:  hole 0.000000"));
  CHECK(has(r.err, "flipped.ngc:8: debug:  top 0.000000"));
}
