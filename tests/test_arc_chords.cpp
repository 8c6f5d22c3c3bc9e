// core/canon/arc_chords.h against a double-precision oracle: every chord point on
// the exact arc within the stated bound, every chord's sagitta within the
// requested tolerance plus that bound, the last point exact.
#include <cmath>
#include <random>

#include "core/canon/arc_chords.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

CanonRecord arc(PointNm s, PointNm e, PointNm c, int32_t turns, Plane p = Plane::kXY) {
  CanonRecord r{};
  r.kind = CanonKind::kArc;
  r.start = s;
  r.end = e;
  r.arc.plane = p;
  r.arc.centre = c;
  r.arc.turns = turns;
  return r;
}

}  // namespace

TEST(arc_chords_quarter_and_full) {
  const int64_t r = 10000000;  // 10 mm
  ArcChords ch;
  ch.init(arc({r, 0, 0}, {0, r, 0}, {0, 0, 0}, 1), 1000);
  // theta = 2 acos(1 - 1e-4) = 0.02828 rad: a quarter turn needs 56 chords.
  CHECK_EQ(ch.count(), 56u);
  PointNm p{}, last{};
  uint32_t n = 0;
  while (ch.next(&p)) { last = p; ++n; }
  CHECK_EQ(n, 56u);
  CHECK(last == (PointNm{0, r, 0}));
  ch.init(arc({r, 0, 0}, {r, 0, 0}, {0, 0, 0}, -1), 1000);
  CHECK_EQ(ch.count(), 223u);  // full circle, clockwise
  CHECK_EQ(ch.sweep_bam(), -(int64_t(1) << 32));
  ch.init(arc({r, 0, 0}, {r, 0, 0}, {0, 0, 0}, 3), 1000);
  CHECK_EQ(ch.sweep_bam(), 3 * (int64_t(1) << 32));
}

TEST(arc_chords_error_bound_random) {
  std::mt19937_64 rng(42);
  double worst_point = 0, worst_sag = 0;
  for (int it = 0; it < 400; ++it) {
    const Plane pl = static_cast<Plane>(rng() % 3);
    const double rad = std::exp(std::uniform_real_distribution<double>(std::log(0.01), std::log(5000.0))(rng));  // mm
    const double a0 = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    const double a1 = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    const double ca = std::uniform_real_distribution<double>(-100, 100)(rng);
    const double cb = std::uniform_real_distribution<double>(-100, 100)(rng);
    const double c0 = 3.0, c1 = (rng() % 2) ? -7.0 : 3.0;
    const int32_t turns = static_cast<int32_t>((rng() % 2 ? 1 : -1) * (1 + rng() % 2));
    const int64_t sag_nm = static_cast<int64_t>(1 + rng() % 5000);
    auto nm = [](double mm) { return static_cast<int64_t>(std::llround(mm * 1e6)); };
    auto pt = [&](double a, double b, double c) { return plane_point(pl, nm(a), nm(b), nm(c)); };
    const PointNm s = pt(ca + rad * std::cos(a0), cb + rad * std::sin(a0), c0);
    const PointNm e = pt(ca + rad * std::cos(a1), cb + rad * std::sin(a1), c1);
    const PointNm c = pt(ca, cb, c0);
    ArcChords ch;
    ch.init(arc(s, e, c, turns, pl), sag_nm);
    // Exact geometry in double, from the integer inputs.
    const double sa = plane_a(pl, s) - plane_a(pl, c), sb = plane_b(pl, s) - plane_b(pl, c);
    const double ea = plane_a(pl, e) - plane_a(pl, c), eb = plane_b(pl, e) - plane_b(pl, c);
    const double r0 = std::hypot(sa, sb), r1 = std::hypot(ea, eb);
    const double t0 = std::atan2(sb, sa);
    double sweep = std::atan2(eb, ea) - t0;
    const int dir = turns > 0 ? 1 : -1;
    sweep *= dir;
    while (sweep < 0) sweep += 2 * M_PI;
    while (sweep >= 2 * M_PI) sweep -= 2 * M_PI;
    sweep += (std::abs(turns) - 1) * 2 * M_PI;
    const double bound = 2.0 + 6e-9 * std::max(r0, r1);
    PointNm p, prev = s;
    uint32_t k = 0;
    const uint32_t n = ch.count();
    while (ch.next(&p)) {
      ++k;
      const double t = static_cast<double>(k) / n;
      const double ang = t0 + dir * sweep * t, rr = r0 + (r1 - r0) * t;
      const double xa = plane_a(pl, c) + rr * std::cos(ang), xb = plane_b(pl, c) + rr * std::sin(ang);
      const double dev = std::hypot(plane_a(pl, p) - xa, plane_b(pl, p) - xb);
      worst_point = std::max(worst_point, dev);
      if (!CHECK_LE(dev, bound)) return;
      // Sagitta of this chord: distance of the mid-angle arc point to the chord.
      const double tm = (k - 0.5) / n, am = t0 + dir * sweep * tm, rm = r0 + (r1 - r0) * tm;
      const double ma = plane_a(pl, c) + rm * std::cos(am), mb = plane_b(pl, c) + rm * std::sin(am);
      const double pa = plane_a(pl, prev), pb = plane_b(pl, prev), qa = plane_a(pl, p), qb = plane_b(pl, p);
      const double len = std::hypot(qa - pa, qb - pb);
      const double sag = len > 0 ? std::fabs((qa - pa) * (mb - pb) - (qb - pb) * (ma - pa)) / len : 0;
      worst_sag = std::max(worst_sag, sag - sag_nm);
      if (!CHECK_LE(sag, sag_nm + bound)) return;
      prev = p;
    }
    CHECK(prev == e);
  }
  std::printf("arc_chords: worst point error %.2f nm, worst sagitta excess %.2f nm\n", worst_point, worst_sag);
}
