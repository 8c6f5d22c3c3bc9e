// core/engage/engage.h against the analytic engagement of a tool in a cut
// (a double oracle): a full slot, 50 % and 10 % radial immersion with a
// flat end mill on a grid of D/50 (angles within 3 degrees), either
// spindle direction, a ball at a shallow depth (its effective diameter),
// a bull nose, a tool in air; and the chip thickness with its thinning.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <vector>

#include "core/engage/engage.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t kPitch = 120000;  // D / 50 for a 6 mm tool
constexpr int64_t kLsb = 1000;

// A 40 x 24 mm block, top at Z0 where `solid(x, y)` (mm), else cut down to
// Z-8; z0 at -10 mm.
struct Block {
  DexelGrid<uint16_t> g;
  std::vector<uint16_t> top, bottom;
  template <class F>
  explicit Block(F solid) {
    const int32_t nx = 40000000 / kPitch + 1, ny = 24000000 / kPitch + 1;
    top.assign(static_cast<size_t>(nx) * ny, 0);
    bottom.assign(top.size(), 0);
    GridGeometry geo{nx, ny, 0, 0, kPitch, -10000000, kLsb};
    CHECK(ok(grid_init(&g, geo, top.data(), bottom.data(), top.size())));
    for (int32_t j = 0; j < ny; ++j)
      for (int32_t i = 0; i < nx; ++i)
        top[g.index(i, j)] = static_cast<uint16_t>(solid(i * kPitch * 1e-6, j * kPitch * 1e-6) ? 10000 : 2000);
  }
};

Tool tool(ToolKind kind, double d_mm, double rc_mm = 0) {
  Tool t{};
  t.kind = kind;
  t.diameter_nm = static_cast<int64_t>(d_mm * 1e6);
  t.corner_radius_nm = static_cast<int64_t>(rc_mm * 1e6);
  t.length_nm = 40000000;
  return t;
}

double deg(uint32_t bam) { return bam * (360.0 / 4294967296.0); }

EngageAt at(const Block& b, const Tool& t, double x, double y, double z, bool cw = true, double ex = 1, double ey = 0) {
  EngageTool et;
  engage_tool_init(t, kPitch, &et);
  EngageAt e;
  engage_at(b.g, et, PointNm{static_cast<int64_t>(x * 1e6), static_cast<int64_t>(y * 1e6), static_cast<int64_t>(z * 1e6)},
            static_cast<int64_t>(ex * (1 << 30)), static_cast<int64_t>(ey * (1 << 30)), cw, &e);
  return e;
}

}  // namespace

TEST(engage_flat_slot_and_radial_immersion) {
  const Tool flat = tool(ToolKind::kFlat, 6);
  const double R = 3, pitch_mm = kPitch * 1e-6;
  double worst_deg = 0;
  // A full slot: the whole front half, 2 mm deep.
  const Block full([](double, double) { return true; });
  EngageAt e = at(full, flat, 20, 12, -2);
  CHECK(e.engaged);
  worst_deg = std::max({worst_deg, std::fabs(deg(e.entry_bam) - 0), std::fabs(deg(e.exit_bam) - 180)});
  CHECK(std::fabs(e.ae_nm * 1e-6 - 6) <= pitch_mm);
  CHECK_EQ(e.ap_nm, 2000000);
  // Immersions a_e of the diameter on the climb side (the right of the
  // feed for M3: material at y <= yc - (R - a_e)), and on the left for M4.
  for (double frac : {0.5, 0.1, 0.25, 0.75}) {
    const double ae = frac * 2 * R, edge = 12 - (R - ae);
    const Block right([edge](double, double y) { return y <= edge + 1e-9; });
    const Block left([edge](double, double y) { return y >= 24 - edge - 1e-9; });
    const double want_entry = 180 - std::acos(1 - ae / R) * 180 / M_PI;  // from the entry side
    for (int way = 0; way < 2; ++way) {
      e = way == 0 ? at(right, flat, 20, 12, -2, true) : at(left, flat, 20, 12, -2, false);
      CHECK(e.engaged);
      const double d_entry = std::fabs(deg(e.entry_bam) - want_entry), d_exit = std::fabs(deg(e.exit_bam) - 180);
      worst_deg = std::max({worst_deg, d_entry, d_exit});
      CHECK(std::fabs(e.ae_nm * 1e-6 - ae) <= pitch_mm + 1e-6);
    }
  }
  // Feeding along a diagonal: the same slot.
  e = at(full, flat, 20, 12, -2, true, std::sqrt(0.5), std::sqrt(0.5));
  worst_deg = std::max({worst_deg, deg(e.entry_bam), std::fabs(deg(e.exit_bam) - 180)});
  std::printf("  engage: worst angle %.2f degrees off the analytic (grid D/50)\n", worst_deg);
  CHECK(worst_deg <= 3.0);
  // In air, nothing.
  const Block air([](double, double) { return false; });
  e = at(air, flat, 20, 12, -2);
  CHECK(!e.engaged && e.angle_bam() == 0 && e.ae_nm == 0);
}

TEST(engage_ball_and_bull_meet_a_shallow_cut_at_their_effective_diameter) {
  const Block full([](double, double) { return true; });
  const double pitch_mm = kPitch * 1e-6;
  for (double ap : {0.25, 0.5, 1.5}) {
    EngageAt e = at(full, tool(ToolKind::kBall, 6), 20, 12, -ap);
    const double d_eff = 2 * std::sqrt(ap * (6 - ap));
    CHECK(e.engaged);
    CHECK(std::fabs(e.ae_nm * 1e-6 - d_eff) <= 2 * pitch_mm);  // a pitch for the grid, one for the ring step
    CHECK(std::fabs(e.ap_nm * 1e-6 - ap) <= 1e-6);
    CHECK(deg(e.exit_bam) - deg(e.entry_bam) >= 177);
  }
  // A bull nose 6 mm with a 1 mm corner at 0.3 mm: 2 (a + sqrt(rc^2 - (rc - ap)^2)).
  EngageAt e = at(full, tool(ToolKind::kBullNose, 6, 1), 20, 12, -0.3);
  const double want = 2 * (2 + std::sqrt(1 - 0.7 * 0.7));
  CHECK(std::fabs(e.ae_nm * 1e-6 - want) <= 2 * pitch_mm);
}

TEST(engage_chip_thins_with_the_arc) {
  const Block full([](double, double) { return true; });
  const Tool flat = tool(ToolKind::kFlat, 6);
  const int64_t fz = 50000;  // 0.05 mm a tooth
  EngageTool et;
  engage_tool_init(flat, kPitch, &et);
  EngageChip c = engage_chip(et, at(full, flat, 20, 12, -2), fz);
  CHECK(std::llabs(c.max_nm - fz) <= 2);
  // The slot's mean: fz (cos 0 - cos 180) / pi = 2 fz / pi.
  CHECK(std::fabs(c.mean_nm - 2 * fz / M_PI) <= 3);
  // 10 % immersion: fz sin(entry) and fz (cos entry + 1) / (pi - entry), at
  // the measured entry (the formula's own error, not the grid's).
  const double edge = 12 - 2.4;
  const Block right([edge](double, double y) { return y <= edge + 1e-9; });
  const EngageAt e = at(right, flat, 20, 12, -2);
  c = engage_chip(et, e, fz);
  const double a = e.entry_bam * (2 * M_PI / 4294967296.0), b = e.exit_bam * (2 * M_PI / 4294967296.0);
  CHECK(std::fabs(c.max_nm - fz * std::sin(a)) <= 2 + 1e-8 * fz);
  CHECK(std::fabs(c.mean_nm - fz * (std::cos(a) - std::cos(b)) / (b - a)) <= 2 + 1e-8 * fz);
  CHECK(c.max_nm < fz * 0.65 && c.max_nm > fz * 0.55);  // chip thinning: about 0.6 fz
  CHECK_EQ(engage_chip(et, EngageAt{}, fz).max_nm, 0);
}

// The chip's cross-section across the feed against the analytic: a flat's
// a_p x a_e (full slot, 50 % and 10 % immersion), a ball's circular
// segment at a shallow depth. Within 1 % plus a pitch's strip of the depth
// on either edge (the grid places the edge within a pitch).
TEST(engage_cross_section_is_the_chip_area) {
  const Block full([](double, double) { return true; });
  const double pitch_mm = kPitch * 1e-6;
  double worst_rel = 0;
  auto near = [&](double got_um2, double want_mm2, double depth_mm) {
    const double got = got_um2 * 1e-6, slack = 0.01 * want_mm2 + 2 * pitch_mm * depth_mm;
    worst_rel = std::max(worst_rel, std::fabs(got - want_mm2) / want_mm2);
    return std::fabs(got - want_mm2) <= slack;
  };
  const Tool flat = tool(ToolKind::kFlat, 6);
  CHECK(near(at(full, flat, 20, 12, -2).area_um2, 2 * 6, 2));
  for (double frac : {0.5, 0.1}) {
    const double ae = frac * 6, edge = 12 - (3 - ae);
    const Block right([edge](double, double y) { return y <= edge + 1e-9; });
    CHECK(near(at(right, flat, 20, 12, -2).area_um2, 2 * ae, 2));
  }
  // A ball slot d deep: the segment of the circle of radius R below the top.
  for (double d : {0.5, 1.5, 3.0}) {
    const double R = 3, h = d, seg = R * R * std::acos((R - h) / R) - (R - h) * std::sqrt(2 * R * h - h * h);
    CHECK(near(at(full, tool(ToolKind::kBall, 6), 20, 12, -d).area_um2, seg, d));
  }
  // The flute length caps it: a 1 mm flute in a 2 mm slot cuts 1 x 6.
  Tool shortf = flat;
  shortf.flute_length_nm = 1000000;
  CHECK(near(at(full, shortf, 20, 12, -2).area_um2, 6, 1));
  std::printf("  engage: cross-section within %.2f %% of the analytic\n", 100 * worst_rel);
}

TEST(run_engagement_csv_and_report) {
  using namespace run_cli;
  if (skip()) return;
  // A full slot at 1200 mm/min, 10000 rpm (2 flutes: 0.06 mm a tooth),
  // then a pass 2.4 mm over on its climb side: 2.4 mm wide, 78 degrees
  // (the plunge and the step over stand outside the stock, in air).
  write_tmp("eng.ngc", "G21 G90 G94\nS10000 M3\nG0 X-5 Y10 Z5\nG1 Z-2 F300\nG1 X35 F1200\nG1 Y12.4\nG1 X-5\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/eng.ngc -q --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.12 --engagement-csv %/eng.csv "
               "--report %/eng.json").code,
           0);
  const std::string csv = slurp(tmp_dir() + "/eng.csv");
  CHECK(has(csv, "line,time_s,depth_mm,width_mm,angle_deg,mrr_mm3_per_min,chip_max_mm,chip_mean_mm,force_n,power_w,"
                 "feed_mm_per_min,torque_n_m,tool,removed_mm3\n"));
  CHECK(has(csv, "\n5,3.547,2.0000,6.0000,180.00,"));
  CHECK(has(csv, ",0.06000,0.03820,,,1200.0,,0,"));
  CHECK(has(csv, "\n7,5.667,2.0000,2.3763,78.00,"));
  CHECK(has(csv, "\n4,1.547,0.0000,0.0000,0.00,0.0,"));  // the plunge: no front to meet
  const std::string rep = slurp(tmp_dir() + "/eng.json");
  CHECK(has(rep, "\"engagement\": {\"moves\": 4, \"engaged\": 2, \"no_spindle_speed\": 0, \"max_angle\": {\"deg\": 180.00, \"line\": 5, \"at\": \""));
  CHECK(has(rep, "\"max_width\": {\"mm\": 6.0000, \"line\": 5, \"at\": \""));
  CHECK(has(rep, "{\"option\": \"--engagement-csv\""));
  // Three flutes: 0.04 mm a tooth; unsaid, two are assumed, and said.
  const Result three = run("%/eng.ngc -q --tool flat:6,flutes=3 --stock 0,0,-10,30,20,0 --pitch 0.12 --engagement-csv "
                           "%/eng3.csv");
  CHECK(has(slurp(tmp_dir() + "/eng3.csv"), ",0.04000,0.02547,,,1200.0,"));
  CHECK(lacks(three.err, "flutes"));
  const Result two = run("%/eng.ngc --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.12 --engagement-csv %/eng2.csv");
  CHECK(has(two.err, "warning: the chip per tooth takes 2 flutes for flat:6"));
  CHECK(has(rep, "\"max_chip\": {\"mm\": 0.06000, \"line\": 5, \"at\": \""));
  // Off, nothing is measured.
  CHECK_EQ(run("%/eng.ngc -q --tool flat:6 --stock 0,0,-10,30,20,0 --pitch 0.12 --report %/off.json").code, 0);
  CHECK(lacks(slurp(tmp_dir() + "/off.json"), "\"engagement\""));
  // The CSV never replaces the program.
  CHECK_EQ(run("%/eng.ngc -q --tool flat:6 --stock 0,0,-10,30,20,0 --engagement-csv %/eng.ngc").code, 2);
}
