// The tool's shank and holder as rings of a lower surface (core/safety/body.h):
// the lowest point of a ring over a straight piece against a double
// oracle (flat parts at their spans' ends, cones by ternary search), on
// random pieces (level, ramps, plunges, steep and shallow) and rings (discs,
// rings with a hole, cones), with the backward bound of body.h; the first
// cover along a piece; and the body a tool spec builds.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/safety/body.h"
#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double h_of(const BodyRing& g, double d) {
  if (d <= g.r0_nm) return static_cast<double>(g.h0_nm);
  return g.h0_nm + static_cast<double>(g.h1_nm - g.h0_nm) * (d - g.r0_nm) / static_cast<double>(g.r1_nm - g.r0_nm);
}

// Exact lowest point of the ring's lower surface over the piece, in double.
double oracle(const BodyRing& g, PointNm a, PointNm b, double x, double y) {
  const double dx = double(b.x_nm - a.x_nm), dy = double(b.y_nm - a.y_nm), dz = double(b.z_nm - a.z_nm);
  const double l = std::hypot(dx, dy);
  const double px = x - a.x_nm, py = y - a.y_nm;
  if (l == 0) {
    const double d = std::hypot(px, py);
    if (d < g.r_in_nm || d > g.r1_nm) return kInf;
    return std::min(a.z_nm, b.z_nm) + h_of(g, d);
  }
  const double s0 = (px * dx + py * dy) / l, v = std::fabs(px * dy - py * dx) / l;
  const auto z = [&](double s) { return a.z_nm + dz * s / l; };
  const auto d_of = [&](double s) { return std::hypot(s - s0, v); };
  double best = kInf;
  // Spans where r_lo <= d <= r_hi, then f evaluated by `each`.
  const auto spans = [&](double r_lo, double r_hi, auto each) {
    if (v > r_hi) return;
    const double w = std::sqrt(r_hi * r_hi - v * v);
    const double lo = std::max(0.0, s0 - w), hi = std::min(l, s0 + w);
    if (lo > hi) return;
    if (v >= r_lo) { each(lo, hi); return; }
    const double wi = std::sqrt(r_lo * r_lo - v * v);
    if (lo <= s0 - wi) each(lo, std::min(hi, s0 - wi));
    if (s0 + wi <= hi) each(std::max(lo, s0 + wi), hi);
  };
  spans(double(g.r_in_nm), double(g.r0_nm), [&](double lo, double hi) {
    best = std::min(best, std::min(z(lo), z(hi)) + g.h0_nm);
  });
  if (g.r1_nm > g.r0_nm)
    spans(std::max(double(g.r_in_nm), double(g.r0_nm)), double(g.r1_nm), [&](double lo, double hi) {
      const auto f = [&](double s) { return z(s) + h_of(g, std::min(std::max(d_of(s), double(g.r0_nm)), double(g.r1_nm))); };
      double u = lo, w2 = hi;
      for (int k = 0; k < 200; ++k) {
        const double m1 = u + (w2 - u) / 3, m2 = w2 - (w2 - u) / 3;
        if (f(m1) <= f(m2)) w2 = m2; else u = m1;
      }
      best = std::min(best, std::min(f((u + w2) / 2), std::min(f(lo), f(hi))));
    });
  return best;
}

BodyRing random_ring(t::Rng* rng) {
  BodyRing g;
  g.part = BodyPart::kHolder;
  g.r0_nm = rng->range(1000, 30 * kNmPerMm);
  g.r_in_nm = rng->range(0, 3) == 0 ? rng->range(0, g.r0_nm) : 0;
  g.r1_nm = rng->range(0, 1) ? g.r0_nm : g.r0_nm + rng->range(1000, 20 * kNmPerMm);
  g.h0_nm = rng->range(0, 60 * kNmPerMm);
  g.h1_nm = g.r1_nm > g.r0_nm ? g.h0_nm + rng->range(1000, 40 * kNmPerMm) : g.h0_nm;
  return g;
}

}  // namespace

TEST(body_ring_lowest_matches_double_oracle) {
  t::Rng rng(20);
  int checked = 0, never = 0;
  double worst = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const BodyRing g = random_ring(&rng);
    const int64_t mm = kNmPerMm;
    PointNm a{rng.range(-50 * mm, 50 * mm), rng.range(-50 * mm, 50 * mm), rng.range(-30 * mm, 30 * mm)};
    PointNm b = a;
    switch (rng.range(0, 5)) {
      case 0: break;  // a point
      case 1: b.z_nm += rng.range(-20 * mm, 20 * mm); break;  // a plunge
      case 2: b.x_nm += rng.range(-60 * mm, 60 * mm); b.y_nm += rng.range(-60 * mm, 60 * mm); break;  // level
      case 3:  // short, as most moves are: the ring covers much of the reach all along
        b.x_nm += rng.range(-mm, mm);
        b.y_nm += rng.range(-mm, mm);
        b.z_nm += rng.range(-mm, mm);
        break;
      default:
        b.x_nm += rng.range(-60 * mm, 60 * mm);
        b.y_nm += rng.range(-60 * mm, 60 * mm);
        b.z_nm += rng.range(-40 * mm, 40 * mm);
    }
    if (b.x_nm - a.x_nm > kBodyPieceMaxNm || a.x_nm - b.x_nm > kBodyPieceMaxNm) continue;
    const BodyPiece p = body_piece(a, b);
    for (int q = 0; q < 8; ++q) {
      const int64_t reach = g.r1_nm + 2000;
      const int64_t x = rng.range(std::min(a.x_nm, b.x_nm) - reach, std::max(a.x_nm, b.x_nm) + reach);
      const int64_t y = rng.range(std::min(a.y_nm, b.y_nm) - reach, std::max(a.y_nm, b.y_nm) + reach);
      const int64_t got = ring_lowest_nm(g, p, x, y);
      // Backward bound: the oracle at the column moved by up to 1 nm.
      double lo = kInf, hi = -kInf;
      bool any_never = false;
      for (int ox = -1; ox <= 1; ++ox)
        for (int oy = -1; oy <= 1; ++oy) {
          const double o = oracle(g, a, b, double(x + ox), double(y + oy));
          if (o == kInf) { any_never = true; continue; }
          lo = std::min(lo, o);
          hi = std::max(hi, o);
        }
      const double slope = g.r1_nm > g.r0_nm ? double(g.h1_nm - g.h0_nm) / double(g.r1_nm - g.r0_nm) : 0;
      const double tol = 4 + 2 * slope;
      if (got == kBodyNever) {
        ++never;
        if (!any_never) std::printf("  never, oracle %.1f..%.1f (trial %d)\n", lo, hi, trial);
        CHECK(any_never);
        continue;
      }
      CHECK(lo != kInf);
      const double err = double(got) < lo ? lo - double(got) : double(got) > hi ? double(got) - hi : 0;
      if (err > tol)
        std::printf("  trial %d: got %lld, oracle %.1f..%.1f ring r_in %lld r0 %lld r1 %lld h0 %lld h1 %lld piece %lld %lld %lld -> %lld %lld %lld at %lld %lld\n",
                    trial, static_cast<long long>(got), lo, hi, (long long)g.r_in_nm, (long long)g.r0_nm, (long long)g.r1_nm,
                    (long long)g.h0_nm, (long long)g.h1_nm, (long long)a.x_nm, (long long)a.y_nm, (long long)a.z_nm,
                    (long long)b.x_nm, (long long)b.y_nm, (long long)b.z_nm, (long long)x, (long long)y);
      CHECK(err <= tol);
      worst = std::max(worst, err);
      ++checked;
    }
  }
  std::printf("  %d columns within the bound (worst %.2f nm beyond the 1 nm neighbourhood), %d never\n", checked, worst, never);
  CHECK_GT(checked, 15000);
}

TEST(body_first_cover_is_where_the_cutter_arrives) {
  const int64_t mm = kNmPerMm;
  // A ramp down 10 mm over 100 mm along x, cutter radius 3 mm.
  const BodyPiece p = body_piece(PointNm{0, 0, 0}, PointNm{100 * mm, 0, -10 * mm});
  // On the axis at x = 50: first covered with the centre at 47 mm.
  CHECK(std::llabs(piece_first_cover_z(p, 3 * mm, 50 * mm, 0) - (-4700000)) <= 2);
  // 3 mm aside: only the centre right abeam covers it.
  CHECK(std::llabs(piece_first_cover_z(p, 3 * mm, 50 * mm, 3 * mm) - (-5 * mm)) <= 2);
  // Behind the start: the tool standing there.
  CHECK_EQ(piece_first_cover_z(p, 3 * mm, -2 * mm, 0), 0);
  CHECK_EQ(piece_first_cover_z(p, 3 * mm, -4 * mm, 0), kBodyNever);
  CHECK_EQ(piece_first_cover_z(p, 3 * mm, 50 * mm, 4 * mm), kBodyNever);
}

TEST(body_of_a_tool_spec) {
  Tool t;
  const char* spec = "flat:6,len=20,stick=30,shank=8,holder=20x10,30-40x15,10x5";
  CHECK_EQ(tool_spec_parse(spec, std::strlen(spec), &t), ToolSpecError::kOk);
  ToolBody b;
  tool_body_build(t, &b);
  CHECK_EQ(b.nrings, 4);
  CHECK_EQ(b.ring[0].part, BodyPart::kShank);  // a disc of the shank's radius at the flutes' end
  CHECK_EQ(b.ring[0].r0_nm, 4 * kNmPerMm);
  CHECK_EQ(b.ring[0].h0_nm, 20 * kNmPerMm);
  CHECK_EQ(b.ring[1].h0_nm, 30 * kNmPerMm);  // the holder's face at the stick-out
  CHECK_EQ(b.ring[2].h0_nm, 40 * kNmPerMm);  // the cone's bottom disc, then its flank
  CHECK_EQ(b.ring[2].r0_nm, 15 * kNmPerMm);
  CHECK_EQ(b.ring[2].r1_nm, 20 * kNmPerMm);
  CHECK_EQ(b.ring[2].h1_nm, 55 * kNmPerMm);
  CHECK_EQ(b.ring[3].r1_nm, 5 * kNmPerMm);   // narrower on top: a disc under the cone's shadow
  CHECK_EQ(b.reach_nm, 20 * kNmPerMm);
  CHECK_EQ(b.lowest_nm, 20 * kNmPerMm);
  // No flute length: no shank ring; a ball's flutes end no lower than its top.
  CHECK_EQ(tool_spec_parse("ball:6", 6, &t), ToolSpecError::kOk);
  tool_body_build(t, &b);
  CHECK_EQ(b.nrings, 0);
  CHECK_EQ(tool_spec_parse("ball:6,len=1", 12, &t), ToolSpecError::kOk);
  tool_body_build(t, &b);
  CHECK_EQ(b.flute_nm, 3 * kNmPerMm);
}
