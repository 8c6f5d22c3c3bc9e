// The fixture check (core/safety/safety.h) against a double oracle of the
// geometry: random clamp boxes and straight moves of ball, flat and bull
// tools beside and through them. The oracle takes the tool's lowest point
// over the move at each dexel column inside the box (dense samples along
// the move, refined), against the box's top as the fixture grid holds it
// (rounded up to the LSB); the check must find the deepest entry within
// 1 LSB when the tool goes more than 1 LSB in, and nothing when it stays
// more than 1 LSB clear.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/safety/body.h"
#include "core/safety/safety.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

double profile_mm(const Tool& t, double r) {
  const double R = t.diameter_nm / 2e6;
  switch (t.kind) {
    case ToolKind::kBall: return R - std::sqrt(std::max(0.0, R * R - r * r));
    case ToolKind::kBullNose: {
      const double rc = t.corner_radius_nm / 1e6, f = R - rc;
      if (r <= f) return 0;
      const double d = std::min(r - f, rc);
      return rc - std::sqrt(std::max(0.0, rc * rc - d * d));
    }
    default: return 0;
  }
}

// The tool's lowest point at (x, y) over the move a -> b (mm), or +inf.
double lowest_mm(const Tool& t, const double a[3], const double b[3], double x, double y) {
  const double R = t.diameter_nm / 2e6;
  const auto at = [&](double s) {
    const double cx = a[0] + (b[0] - a[0]) * s, cy = a[1] + (b[1] - a[1]) * s, cz = a[2] + (b[2] - a[2]) * s;
    const double r = std::hypot(x - cx, y - cy);
    return r > R ? INFINITY : cz + profile_mm(t, r);
  };
  double best = INFINITY, best_s = 0;
  const int n = 4000;
  for (int k = 0; k <= n; ++k) {
    const double v = at(double(k) / n);
    if (v < best) { best = v; best_s = double(k) / n; }
  }
  if (best == INFINITY) return best;
  double lo = std::max(0.0, best_s - 1.0 / n), hi = std::min(1.0, best_s + 1.0 / n);
  for (int k = 0; k < 100; ++k) {  // the lower of two points a third in
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (at(m1) <= at(m2)) hi = m2; else lo = m1;
  }
  return std::min(best, at((lo + hi) / 2));
}

}  // namespace

TEST(fixture_check_matches_double_oracle) {
  const int64_t mm = kNmPerMm;
  const int32_t n = 100;
  std::vector<uint16_t> top(n * n), bottom(n * n);
  std::vector<uint32_t> shadow(n * n);
  t::Rng rng(33);
  int found = 0, clear = 0, between = 0;
  double worst_lsb = 0;
  static SafetyWatch w;
  for (int trial = 0; trial < 300; ++trial) {
    DexelGrid<uint16_t> g;
    const GridGeometry geo{n, n, 0, 0, 200000, -20 * mm, 1000};  // 20 x 20 mm, 1 um LSB
    CHECK(ok(grid_init(&g, geo, top.data(), bottom.data(), top.size())));
    grid_block_stock(&g, 0);  // no material: only the fixture can be met
    // A box inside the grid's XY, from the bottom up to its top.
    BoxNm box;
    box.lo = PointNm{rng.range(2 * mm, 9 * mm), rng.range(2 * mm, 9 * mm), -20 * mm};
    box.hi = PointNm{box.lo.x_nm + rng.range(2 * mm, 8 * mm), box.lo.y_nm + rng.range(2 * mm, 8 * mm),
                     rng.range(-12 * mm, -4 * mm)};
    DexelGrid<uint32_t> f;
    CHECK(fixture_grid_size(g, &box, 1, &f));
    std::vector<uint32_t> ft(static_cast<size_t>(f.nx) * f.ny), fb(ft.size());
    f.top = ft.data();
    f.bottom = fb.data();
    fixture_grid_fill(&f, &box, 1);
    CHECK(ok(safety_watch_init(&w, g, shadow.data(), shadow.size())));
    w.check_rapid = w.check_spindle = w.check_below = false;
    w.fixtures = &f;
    w.fixture_boxes = &box;
    w.nfixture_boxes = 1;
    Tool t;
    const int shape = static_cast<int>(rng.range(0, 2));
    t.kind = shape == 0 ? ToolKind::kBall : shape == 1 ? ToolKind::kFlat : ToolKind::kBullNose;
    t.diameter_nm = rng.range(2, 6) * mm;
    t.corner_radius_nm = t.kind == ToolKind::kBullNose ? t.diameter_nm / 4 : 0;
    t.length_nm = 40 * mm;
    const ToolProfile p = tool_profile(t);
    safety_watch_set_tool(&w, p);
    ToolBody body;
    tool_body_build(t, &body);
    // A move near the box: its top +- 2 mm.
    const int64_t zt = box.hi.z_nm;
    CanonRecord r{};
    r.kind = CanonKind::kFeed;
    r.line = 7;
    r.start = PointNm{rng.range(0, 19 * mm), rng.range(0, 19 * mm), zt + rng.range(-2 * mm, 2 * mm)};
    // (Straight up is the way out of the move before, by design no finding:
    // the plunges here go down.)
    r.end = rng.range(0, 3) == 0 ? PointNm{r.start.x_nm, r.start.y_nm, r.start.z_nm - rng.range(0, 3 * mm)}
                                  : PointNm{rng.range(0, 19 * mm), rng.range(0, 19 * mm), zt + rng.range(-2 * mm, 2 * mm)};
    SafetyMove m{7, false, true, true};
    m.end = r.end;
    m.body = &body;
    safety_watch_record(&w, g, GridRect::none(), r, m, nullptr);
    // The oracle over the fixture grid's columns inside the box.
    const double a[3] = {r.start.x_nm / 1e6, r.start.y_nm / 1e6, r.start.z_nm / 1e6};
    const double b[3] = {r.end.x_nm / 1e6, r.end.y_nm / 1e6, r.end.z_nm / 1e6};
    double deepest = -INFINITY;
    for (int32_t j = 0; j < f.ny; ++j)
      for (int32_t i = 0; i < f.nx; ++i) {
        const size_t k = f.index(i, j);
        if (ft[k] == 0 && fb[k] == 0) continue;
        const double x = (f.x0_nm + i * f.pitch_nm) / 1e6, y = (f.y0_nm + j * f.pitch_nm) / 1e6;
        const double low = lowest_mm(t, a, b, x, y);
        const double box_top = (f.z0_nm + double(ft[k]) * f.lsb_nm) / 1e6;
        deepest = std::max(deepest, box_top - low);
      }
    const double lsb_mm = g.lsb_nm / 1e6;
    const bool reported = w.nevents > 0 && w.events[0].kind == SafetyKind::kFixture;
    if (deepest > lsb_mm) {
      ++found;
      if (!reported)
        std::printf("  trial %d: missed %.4f mm, kind %d, %lld %lld %lld -> %lld %lld %lld\n", trial, deepest, shape,
                    (long long)r.start.x_nm, (long long)r.start.y_nm, (long long)r.start.z_nm, (long long)r.end.x_nm,
                    (long long)r.end.y_nm, (long long)r.end.z_nm);
      CHECK(reported);
      if (reported) {
        const double err = std::fabs(w.events[0].depth_nm / 1e6 - deepest) / lsb_mm;
        worst_lsb = std::max(worst_lsb, err);
        if (err > 1.0) std::printf("  trial %d: depth %.4f, oracle %.4f mm\n", trial, w.events[0].depth_nm / 1e6, deepest);
        CHECK(err <= 1.0);
      }
    } else if (deepest < -lsb_mm) {
      ++clear;
      if (reported) std::printf("  trial %d: a finding %.4f mm deep, oracle clear by %.4f mm\n", trial, w.events[0].depth_nm / 1e6, -deepest);
      CHECK(!reported);
    } else {
      ++between;
    }
    // Never cut: the fixture grid is as the box makes it again.
    std::vector<uint32_t> t2(ft), b2(fb);
    fixture_grid_fill(&f, &box, 1);
    CHECK(t2 == ft && b2 == fb);
  }
  std::printf("  %d moves into a box (worst %.2f LSB off the oracle), %d clear of it, %d within 1 LSB\n", found, worst_lsb, clear, between);
  CHECK_GT(found, 50);
  CHECK_GT(clear, 50);
}
