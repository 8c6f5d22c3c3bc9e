// core/assess/assess.h: the paper's E and E_rel (§2.5.2) and the figures
// beside them, against a computation in double on random grids.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/assess/assess.h"
#include "core/assess/gouge_watch.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

double u128_to_double(U128 v) { return static_cast<double>(v.hi) * 18446744073709551616.0 + static_cast<double>(v.lo); }

struct Scene {
  GridGeometry geo{};
  std::vector<uint16_t> top, bottom;
  std::vector<int32_t> design;
  DexelGrid<uint16_t> g;
  DesignGrid d;
};

void make_scene(t::Rng& r, Scene* s) {
  s->geo = GridGeometry{static_cast<int32_t>(r.range(2, 70)), static_cast<int32_t>(r.range(2, 70)), -1000000, 2000000,
                        r.range(10000, 500000), -30000000, r.range(1, 2000)};
  const size_t n = static_cast<size_t>(s->geo.nx) * s->geo.ny;
  s->top.assign(n, 0);
  s->bottom.assign(n, 0);
  s->design.assign(n, 0);
  CHECK_EQ(grid_init(&s->g, s->geo, s->top.data(), s->bottom.data(), n), Status::kOk);
  CHECK_EQ(design_init(&s->d, s->geo, s->design.data(), n), Status::kOk);
  for (size_t k = 0; k < n; ++k) {
    const int kind = static_cast<int>(r.range(0, 9));
    s->top[k] = static_cast<uint16_t>(r.range(0, 65535));
    if (kind == 0) s->top[k] = 0;  // a hole (bottom 0 too)
    // The design near the top mostly (small d, both signs), sometimes far, sometimes absent or below z0.
    const int64_t near = static_cast<int64_t>(s->top[k]) + r.range(-300, 300);
    s->design[k] = kind == 1 ? kNoDesign : kind == 2 ? static_cast<int32_t>(r.range(-500, 70000)) : static_cast<int32_t>(near);
  }
}

}  // namespace

TEST(assess_matches_a_double_computation) {
  t::Rng r(25);
  for (int run = 0; run < 60; ++run) {
    Scene s;
    make_scene(r, &s);
    AssessOptions o;
    o.tol_nm = r.range(0, 400000);
    ToleranceBox box{s.geo.x0_nm, s.geo.y0_nm, s.geo.x0_nm + 5 * s.geo.pitch_nm, s.geo.y0_nm + 3 * s.geo.pitch_nm, r.range(0, 100000)};
    if (run % 2) {
      o.boxes = &box;
      o.nboxes = 1;
    }
    AssessResult res;
    CHECK_EQ(assess(s.g, s.d, o, &res), Status::kOk);
    double e = 0, sum_d = 0, gouge = 0, left = 0, max_g = 0, max_l = 0, outside = 0;
    uint64_t cols = 0, within = 0, gc = 0, lc = 0, oc = 0;
    uint64_t hist[kAssessBins] = {};
    for (int32_t j = 0; j < s.geo.ny; ++j)
      for (int32_t i = 0; i < s.geo.nx; ++i) {
        const size_t k = static_cast<size_t>(j) * s.geo.nx + i;
        const double w = s.top[k];
        const double lsb = static_cast<double>(s.geo.lsb_nm);
        if (s.design[k] == kNoDesign) {
          if (w > 0) { ++oc; outside += w; }
          continue;
        }
        ++cols;
        const double dd = w - s.design[k];
        e += dd * dd;
        sum_d += s.design[k] > 0 ? s.design[k] : 0;
        const double x = static_cast<double>(s.geo.x0_nm + i * s.geo.pitch_nm), y = static_cast<double>(s.geo.y0_nm + j * s.geo.pitch_nm);
        const bool in_box = o.nboxes && x >= box.x0_nm && x <= box.x1_nm && y >= box.y0_nm && y <= box.y1_nm;
        const double tol = static_cast<double>(in_box ? box.tol_nm : o.tol_nm);
        int b = 0;
        while (b < kAssessEdges && dd * lsb > static_cast<double>(kAssessBinEdgesNm[b])) ++b;
        ++hist[b];
        if (std::fabs(dd) * lsb <= tol) ++within;
        else if (dd < 0) { ++gc; gouge += -dd; max_g = std::fmax(max_g, -dd); }
        else { ++lc; left += dd; max_l = std::fmax(max_l, dd); }
      }
    CHECK_EQ(res.design_columns, cols);
    CHECK_EQ(res.within_tol_columns, within);
    CHECK_EQ(u128_to_double(res.e_lsb2), e);
    CHECK_EQ(static_cast<double>(res.sum_design_top_lsb), sum_d);
    CHECK_EQ(res.gouge_columns, gc);
    CHECK_EQ(res.leftover_columns, lc);
    CHECK_EQ(static_cast<double>(res.gouge_lsb), gouge);
    CHECK_EQ(static_cast<double>(res.leftover_lsb), left);
    CHECK_EQ(static_cast<double>(res.max_gouge_lsb), max_g);
    CHECK_EQ(static_cast<double>(res.max_leftover_lsb), max_l);
    CHECK_EQ(res.outside_columns, oc);
    CHECK_EQ(static_cast<double>(res.outside_lsb), outside);
    for (int b = 0; b < kAssessBins; ++b) CHECK_EQ(res.histogram[b], hist[b]);
    if (res.max_gouge_lsb > 0) {
      const size_t k = static_cast<size_t>(res.max_gouge_j) * s.geo.nx + res.max_gouge_i;
      CHECK_EQ(static_cast<int64_t>(s.design[k]) - s.top[k], res.max_gouge_lsb);
    }
  }
}

TEST(assess_a_perfect_cut_has_no_error_and_rejects_another_grid) {
  t::Rng r(7);
  Scene s;
  make_scene(r, &s);
  for (size_t k = 0; k < s.top.size(); ++k) {
    if (s.top[k] == 0) s.top[k] = 1;  // no holes: a hole reads as height 0
    s.design[k] = s.top[k];
  }
  AssessOptions o;
  o.tol_nm = 0;
  AssessResult res;
  CHECK_EQ(assess(s.g, s.d, o, &res), Status::kOk);
  CHECK(res.e_lsb2.lo == 0 && res.e_lsb2.hi == 0);
  CHECK_EQ(res.within_tol_columns, res.design_columns);
  CHECK_EQ(res.gouge_columns + res.leftover_columns, uint64_t{0});
  CHECK_EQ(res.max_gouge_i, -1);
  s.d.geo.pitch_nm += 1;
  CHECK_EQ(assess(s.g, s.d, o, &res), Status::kBadArgument);
}

TEST(assess_bands_follow_the_transfer_function) {
  // The band limits: within +-tol white, then beyond 1, 4 and 16 tolerances.
  CHECK_EQ(error_band(0, 10), kBandWithin);
  CHECK_EQ(error_band(10, 10), kBandWithin);
  CHECK_EQ(error_band(-10, 10), kBandWithin);
  CHECK_EQ(error_band(11, 10), kBandLeft1);
  CHECK_EQ(error_band(40, 10), kBandLeft1);
  CHECK_EQ(error_band(41, 10), kBandLeft2);
  CHECK_EQ(error_band(160, 10), kBandLeft2);
  CHECK_EQ(error_band(161, 10), kBandLeft3);
  CHECK_EQ(error_band(-11, 10), kBandGouge1);
  CHECK_EQ(error_band(-41, 10), kBandGouge2);
  CHECK_EQ(error_band(-161, 10), kBandGouge3);
  CHECK_EQ(error_band(1, 0), kBandLeft3);  // a zero tolerance: any error is the darkest band
  // Over random grids, the bands agree with assess()'s counts.
  t::Rng r(19);
  for (int run = 0; run < 20; ++run) {
    Scene s;
    make_scene(r, &s);
    AssessOptions o;
    o.tol_nm = r.range(0, 300000);
    std::vector<uint8_t> band(s.top.size(), 99);
    assess_bands(s.g, s.d, o, s.g.bounds(), band.data());
    AssessResult res;
    CHECK_EQ(assess(s.g, s.d, o, &res), Status::kOk);
    uint64_t count[kErrorBands] = {};
    for (uint8_t b : band) {
      CHECK(b < kErrorBands);
      if (b < kErrorBands) ++count[b];
    }
    CHECK_EQ(count[kBandWithin], res.within_tol_columns);
    CHECK_EQ(count[kBandGouge1] + count[kBandGouge2] + count[kBandGouge3], res.gouge_columns);
    CHECK_EQ(count[kBandLeft1] + count[kBandLeft2] + count[kBandLeft3], res.leftover_columns);
    CHECK_EQ(count[kBandNone], static_cast<uint64_t>(band.size()) - res.design_columns);
  }
}

TEST(gouge_watch_charges_each_column_once_to_its_line) {
  // A 40 x 30 grid, 1 mm pitch, 1 um LSB, all tops 10 mm; the design 9 mm everywhere.
  const GridGeometry geo{40, 30, 0, 0, 1000000, 0, 1000};
  std::vector<uint16_t> top(1200, 10000), bottom(1200, 0);
  std::vector<int32_t> design(1200);
  DexelGrid<uint16_t> g;
  DesignGrid d;
  CHECK_EQ(grid_init(&g, geo, top.data(), bottom.data(), top.size()), Status::kOk);
  CHECK_EQ(design_init(&d, geo, design.data(), design.size()), Status::kOk);
  for (int32_t& v : design) v = 9000;
  std::vector<uint8_t> seen(gouge_watch_seen_bytes(40, 30));
  GougeWatch w;
  AssessOptions o;
  o.tol_nm = 50000;
  CHECK_EQ(gouge_watch_init(&w, &d, o, seen.data(), seen.size() - 1), Status::kBufferTooSmall);
  CHECK_EQ(gouge_watch_init(&w, &d, o, seen.data(), seen.size()), Status::kOk);
  const PointNm tool{5000000, 5000000, 8000000};
  // Within tolerance: nothing. 60 um below: a gouge of line 3 at its deepest column.
  top[g.index(5, 5)] = 8950;
  CHECK(!gouge_watch_check(&w, g, GridRect{0, 0, 40, 30}, 2, tool, nullptr));
  top[g.index(6, 5)] = 8940;
  top[g.index(7, 5)] = 8700;
  CHECK(gouge_watch_check(&w, g, GridRect{0, 0, 40, 30}, 3, tool, nullptr));
  CHECK_EQ(w.nevents, size_t{1});
  CHECK_EQ(w.events[0].line, 3u);
  CHECK_EQ(w.events[0].depth_lsb, 300);
  CHECK_EQ(w.events[0].i, 7);
  CHECK_EQ(w.events[0].columns, uint64_t{2});
  // Deeper later at the same columns: already reported, nothing new.
  top[g.index(7, 5)] = 5000;
  CHECK(!gouge_watch_check(&w, g, GridRect{0, 0, 40, 30}, 4, tool, nullptr));
  // Outside the changed rectangle or the region: not looked at.
  top[g.index(20, 20)] = 1000;
  CHECK(!gouge_watch_check(&w, g, GridRect{0, 0, 10, 10}, 5, tool, nullptr));
  // A flat 4 mm tool left at (20, 20, 1 mm) by line 6 explains column (20,
  // 20) at 1 mm: charged to line 6, not to the record of line 7.
  Tool flat;
  flat.kind = ToolKind::kFlat;
  flat.diameter_nm = 4000000;
  flat.length_nm = 30000000;
  const ToolProfile prof = tool_profile(flat);
  const GougeOrigin origin{6, PointNm{20000000, 20000000, 1000000}, &prof};
  top[g.index(30, 20)] = 2000;  // out of that tool's reach: line 7's
  CHECK(gouge_watch_check(&w, g, GridRect{0, 0, 40, 30}, 7, tool, &origin));
  CHECK_EQ(w.nevents, size_t{3});
  CHECK_EQ(w.events[1].line, 6u);
  CHECK_EQ(w.events[1].i, 20);
  CHECK(w.events[1].tool == origin.end);
  CHECK_EQ(w.events[2].line, 7u);
  CHECK_EQ(w.events[2].i, 30);
  // Bounded: past kGougeEventsMax events are counted, not kept.
  for (uint32_t k = 0; k < 100; ++k) {
    const int32_t i = static_cast<int32_t>(k % 40), j = static_cast<int32_t>(25 + k / 40);
    top[g.index(i, j)] = 100;
    CHECK(gouge_watch_check(&w, g, GridRect{i, j, i + 1, j + 1}, 100 + k, tool, nullptr));
  }
  CHECK_EQ(w.nevents, kGougeEventsMax);
  CHECK_EQ(w.total, uint64_t{103});
}
