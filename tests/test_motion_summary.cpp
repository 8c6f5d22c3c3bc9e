// Motion counts, boxes and the time model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/math/fixed.h"
#include "core/interp/interp.h"
#include "core/canon/summary.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
void run(MotionSummary* s, const char* const* lines, int n) {
  Interp in(s, InterpOptions());
  for (int k = 0; k < n; ++k) {
    GcodeDiag d;
    const GcodeError e = in.execute_line(lines[k], std::strlen(lines[k]), static_cast<uint32_t>(k + 1), &d);
    CHECK_EQ(e, GcodeError::kOk);
  }
}
}  // namespace

TEST(motion_summary_counts_boxes_time) {
  const char* prog[] = {
      "G21 G90 G17",
      "G0 X10 Y0 Z5",          // rapid: sqrt(100 + 25) mm
      "G1 Z-1 F600",           // 6 mm at 600 mm/min = 0.6 s
      "G1 X40 F1200",          // 30 mm at 1200 = 1.5 s
      "G3 X50 Y10 I0 J10",     // quarter circle about (40, 10): 15.708 mm at 1200
      "G4 P2.5",               // 2.5 s
      "G0 Z5",
      "M2",
  };
  MotionSummary s;
  run(&s, prog, 8);
  CHECK_EQ(s.count(CanonKind::kTraverse), 2u);
  CHECK_EQ(s.count(CanonKind::kFeed), 2u);
  CHECK_EQ(s.count(CanonKind::kArc), 1u);
  CHECK_EQ(s.count(CanonKind::kDwell), 1u);
  CHECK(s.motion_box().valid);
  CHECK_EQ(s.motion_box().lo.x_nm, 0);
  CHECK_EQ(s.motion_box().hi.x_nm, 50 * kNmPerMm);
  CHECK_EQ(s.motion_box().lo.z_nm, -1 * kNmPerMm);
  CHECK_EQ(s.motion_box().hi.z_nm, 5 * kNmPerMm);
  // The arc bulges to y = 0 .. 10 around (40, 10), x up to 50.
  CHECK_EQ(s.feed_box().lo.x_nm, 10 * kNmPerMm);
  CHECK_EQ(s.feed_box().hi.y_nm, 10 * kNmPerMm);
  CHECK_EQ(s.feed_box().hi.z_nm, 5 * kNmPerMm);  // the plunge starts at z 5
  CHECK_EQ(s.feed_below_zero_box().lo.z_nm, -1 * kNmPerMm);
  CHECK_EQ(s.feed_below_zero_box().lo.x_nm, 10 * kNmPerMm);
  const int64_t arc_nm = 15707963;
  CHECK_NEAR(s.feed_length_nm(), 36 * kNmPerMm + arc_nm, 20);
  const int64_t feed_us = 600000 + 1500000 + 785398;
  CHECK_NEAR(s.feed_time_us(), feed_us, 3);
  // Rapids: sqrt(125) mm + 6 mm at 5000 mm/min.
  CHECK_NEAR(s.rapid_time_us(), (11180340 + 6000000) * 60 / 5000, 2);
  CHECK_EQ(s.dwell_time_us(), 2500000);
  CHECK_EQ(s.estimated_time_us(), s.feed_time_us() + s.rapid_time_us() + 2500000);
}

TEST(motion_summary_distance_exact) {
  CHECK_EQ(distance_nm(PointNm{0, 0, 0}, PointNm{3, 4, 12}), 13);
  CHECK_EQ(distance_nm(PointNm{-kGcodeMaxCoordNm, -kGcodeMaxCoordNm, -kGcodeMaxCoordNm},
                       PointNm{kGcodeMaxCoordNm, kGcodeMaxCoordNm, kGcodeMaxCoordNm}),
           34641016151);
  CHECK_EQ(MotionSummary::piece_time_us(1000 * kNmPerMm, 0), 0);
}

TEST(motion_time_with_acceleration_vs_double) {
  // Trapezoids and triangles against the same formulas in double: within
  // 1.1 us, over lengths from 1 um to 10 m, rates from 1 to 100000 mm/min,
  // accelerations from 1 to 100000 mm/s^2.
  t::Rng rng(3);
  double worst = 0;
  int triangles = 0;
  for (int k = 0; k < 20000; ++k) {
    const int64_t len = static_cast<int64_t>(1000.0 * std::pow(10.0, 7.0 * static_cast<double>(rng.next() % 1000000) / 1e6));
    const int64_t rate = static_cast<int64_t>(1e6 * std::pow(10.0, 5.0 * static_cast<double>(rng.next() % 1000000) / 1e6));
    MotionTimeModel m;
    m.accel_nm_per_s2 = static_cast<int64_t>(1e6 * std::pow(10.0, 5.0 * static_cast<double>(rng.next() % 1000000) / 1e6));
    const double v = static_cast<double>(rate) / 60.0, a = static_cast<double>(m.accel_nm_per_s2), L = static_cast<double>(len);
    const bool tri = L < v * v / a;
    triangles += tri;
    const double exact_us = 1e6 * (tri ? 2.0 * std::sqrt(L / a) : L / v + v / a);
    const double got = static_cast<double>(MotionSummary::move_time_us(m, len, rate));
    worst = std::max(worst, std::fabs(got - exact_us));
    if (std::fabs(got - exact_us) > 1.1)
      std::printf("  L %lld nm, rate %lld nm/min, a %lld nm/s2: %.1f us, exact %.3f\n", static_cast<long long>(len),
                  static_cast<long long>(rate), static_cast<long long>(m.accel_nm_per_s2), got, exact_us);
    CHECK(std::fabs(got - exact_us) <= 1.1);
  }
  std::printf("  move time with acceleration: worst error %.3f us (bound 1.1), %d triangles of 20000\n", worst, triangles);
  CHECK(triangles > 1000 && triangles < 19000);
  // No acceleration: the plain time; zero length: nothing.
  MotionTimeModel plain;
  CHECK_EQ(MotionSummary::move_time_us(plain, 100 * kNmPerMm, 6000 * kNmPerMm), 1000000);
  plain.accel_nm_per_s2 = 100 * kNmPerMm;
  CHECK_EQ(MotionSummary::move_time_us(plain, 0, 6000 * kNmPerMm), 0);
  // 100 mm at 6000 mm/min (100 mm/s), 100 mm/s^2: 1 s cruising + 1 s of ramps.
  CHECK_EQ(MotionSummary::move_time_us(plain, 100 * kNmPerMm, 6000 * kNmPerMm), 2000000);
}
