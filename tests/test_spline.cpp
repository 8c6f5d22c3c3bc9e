// G5 and G5.1 splines (core/interp/spline.h, core/interp/interp_spline.cpp):
// the chords against a double oracle of the Bezier curve LinuxCNC hands
// NURBS_FEED (spline.h's bound, both ways, and no needless chords), and
// programs against what LinuxCNC 2.9's rs274 does with them, errors
// included. (The chord points themselves are compared with LinuxCNC's own
// preview by tools/scripts/oracle-check.sh --rs274: tests/gcode/paths.)
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/interp/interp.h"
#include "core/interp/spline.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"

using namespace dexmill;
using t::mm;

namespace {

struct P2 {
  double x, y;
};

P2 bezier(const SplinePlan& s, double u) {
  const int deg = s.points - 1;
  double bx = 0, by = 0;
  for (int i = 0; i <= deg; ++i) {
    const double c = deg == 2 ? (i == 1 ? 2 : 1) : (i == 1 || i == 2 ? 3 : 1);
    const double b = c * std::pow(u, i) * std::pow(1 - u, deg - i);
    bx += b * static_cast<double>(s.x[i]);
    by += b * static_cast<double>(s.y[i]);
  }
  return {bx, by};
}

double seg_dist(P2 p, P2 a, P2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 == 0 ? 0 : ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// The chord ends the records of `line` make lie on the curve through
// `ctrl` (x0 y0 x1 y1 ..., mm) at u = k / n, within spline.h's 1.1 nm.
bool on_curve(const t::Recorder& rec, uint32_t line, std::initializer_list<double> ctrl) {
  SplinePlan s{};
  s.points = static_cast<uint8_t>(ctrl.size() / 2);
  // An index loop: GCC 12's sanitizer build took the comma form's counter
  // for uninitialised (-Wmaybe-uninitialized).
  const double* v = ctrl.begin();
  for (size_t i = 0; i < ctrl.size(); ++i) {
    if (i % 2) s.y[i / 2] = mm(v[i]);
    else s.x[i / 2] = mm(v[i]);
  }
  std::vector<PointNm> ends;
  for (const CanonRecord& r : rec.records)
    if (r.line == line && r.kind == CanonKind::kFeed) ends.push_back(r.end);
  if (ends.empty()) return false;
  for (size_t k = 0; k < ends.size(); ++k) {
    const P2 p = bezier(s, static_cast<double>(k + 1) / ends.size());
    if (std::hypot(ends[k].x_nm - p.x, ends[k].y_nm - p.y) > 1.1) return false;
  }
  return true;
}

GcodeError run(const char* program, t::Recorder* rec, GcodeDiag* d, int64_t sagitta_nm = 1000) {
  InterpOptions opt;
  opt.spline_sagitta_nm = sagitta_nm;
  Interp in(rec, opt);
  return t::run_program(&in, program, d);
}

}  // namespace

TEST(spline_chords_against_double_oracle) {
  std::mt19937_64 rng(2105);
  double worst_point = 0, worst_sag = 0;  // nm; sagitta beyond s
  int checked_waste = 0;
  for (int i = 0; i < 3000; ++i) {
    SplinePlan s{};
    s.points = i % 2 ? 4 : 3;
    // Sizes from a micrometre to the 20 m range.
    const int64_t span = static_cast<int64_t>(std::pow(10.0, 3 + (i % 8) * 1.0)) + 1;
    std::uniform_int_distribution<int64_t> c(-span, span);
    for (int k = 0; k < s.points; ++k) {
      s.x[k] = c(rng);
      s.y[k] = c(rng);
    }
    if (i < 16) {  // the range's corners
      for (int k = 0; k < s.points; ++k) {
        s.x[k] = (k + i) % 2 ? kSplineMaxControlNm : -kSplineMaxControlNm;
        s.y[k] = (k + i / 2) % 2 ? kSplineMaxControlNm : -kSplineMaxControlNm;
      }
    }
    const int64_t sag = i % 3 == 0 ? 1 : i % 3 == 1 ? 1000 : 100000;
    s.chords = spline_chord_count(s, sag);
    CHECK(s.chords >= 1 && s.chords <= kSplineMaxChords);
    P2 prev{static_cast<double>(s.x[0]), static_cast<double>(s.y[0])};
    double max_sag = 0, max_dev = 0;  // distance to the chord; |P(u) - L(u)|
    for (uint32_t k = 1; k <= s.chords; ++k) {
      int64_t x, y;
      spline_point(s, k, &x, &y);
      const P2 cur{static_cast<double>(x), static_cast<double>(y)};
      const P2 exact = bezier(s, static_cast<double>(k) / s.chords);
      worst_point = std::max(worst_point, std::hypot(cur.x - exact.x, cur.y - exact.y));
      // The curve between the two points, against the chord.
      for (int j = 1; j < 16; ++j) {
        const double u = (k - 1 + j / 16.0) / s.chords;
        const P2 p = bezier(s, u);
        max_sag = std::max(max_sag, seg_dist(p, prev, cur));
        max_dev = std::max(max_dev, std::hypot(p.x - prev.x - (cur.x - prev.x) * j / 16.0,
                                               p.y - prev.y - (cur.y - prev.y) * j / 16.0));
      }
      prev = cur;
      if (s.chords > 2000 && k > 2000) break;  // enough of the long ones
    }
    worst_sag = std::max(worst_sag, max_sag - static_cast<double>(sag));
    // No needless chords: for a quadratic the bound of |P(u) - L(u)| is
    // exact (|P''| is constant), so n - 1 chords would have been too few.
    if (s.points == 3 && s.chords >= 2 && sag >= 1000 && s.chords <= 2000) {
      ++checked_waste;
      const double n = s.chords;
      if (!CHECK(max_dev >= 0.99 * sag * ((n - 1) / n) * ((n - 1) / n)))
        std::printf("  deviation %.1f nm with %u chords for s = %lld\n", max_dev, s.chords, static_cast<long long>(sag));
    }
  }
  std::printf("  spline chords: points within %.3f nm, sagitta beyond s by at most %.3f nm (%d checked for waste)\n",
              worst_point, worst_sag, checked_waste);
  CHECK(worst_point <= 1.1);
  CHECK(worst_sag <= 1.1);
  CHECK(checked_waste > 100);
}

// Programs as rs274 runs them: NURBS_FEED with the curve's control points
// (checked through the chords' ends and a middle point), the modal motion
// left alone, G5's continuation, G93.
TEST(spline_programs_as_linuxcnc) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 F100\nG1 X0 Y0 Z-1\nG5.1 X10 Y10 I5 J0\nX12 Y11", &rec, &d), GcodeError::kOk);
  std::vector<PointNm> ends;
  for (const CanonRecord& r : rec.records) {
    if (r.line != 3) continue;
    CHECK(r.kind == CanonKind::kFeed);
    CHECK_EQ(r.end.z_nm, -mm(1));
    ends.push_back(r.end);
  }
  // |P''| = 2 |(0,0) - 2 (5,0) + (10,10)| = 20 mm: sqrt(20 mm / 8 um) = 50 chords.
  CHECK_EQ(ends.size(), 50u);
  CHECK(ends.size() == 50 && ends[24].x_nm == mm(5) && ends[24].y_nm == mm(2.5));  // u = 1/2
  CHECK(on_curve(rec, 3, {0, 0, 5, 0, 10, 10}));
  // LinuxCNC 2.9 leaves the modal motion as G1: X12 Y11 is one straight feed.
  CHECK(rec.records.back().kind == CanonKind::kFeed);
  CHECK_EQ(rec.records.back().line, 4u);
  CHECK_EQ(rec.records.back().start.x_nm, mm(10));
  t::Recorder rapid;
  CHECK_EQ(run("G21 F100\nG0 X0 Y0\nG5.1 X10 Y10 I5 J0\nX12 Y11", &rapid, &d), GcodeError::kOk);
  CHECK(rapid.records.back().kind == CanonKind::kTraverse);
  // After G80 (no motion), bare axis words have none to use them.
  CHECK_EQ(run("G21 F100\nG80\nG5.1 X10 Y10 I5 J0\nX12 Y11", &rapid, &d), GcodeError::kAxisWordsUnused);
  CHECK_EQ(d.line, 4u);

  // G5: the cubic from (0,0) with handles (0,3) and (1,1)+(0,-3); a G5
  // without I, J continues it: its first handle is -P, -Q.
  t::Recorder cub;
  CHECK_EQ(run("G21 F100\nG5 I0 J3 P0 Q-3 X1 Y1\nG5 P0 Q-3 X2 Y1", &cub, &d), GcodeError::kOk);
  CHECK(on_curve(cub, 2, {0, 0, 0, 3, 1, -2, 1, 1}));
  CHECK(on_curve(cub, 3, {1, 1, 1, 4, 2, -2, 2, 1}));  // handles (1,1)+(0,3), (2,1)+(0,-3)
  CHECK(!on_curve(cub, 3, {1, 1, 1, 1, 2, -2, 2, 1}));  // (the check can fail)
  CHECK_EQ(cub.records.back().end.x_nm, mm(2));
  // G87 shares G5's sticky I and J (LinuxCNC's cycle_i, cycle_j).
  t::Recorder g87;
  CHECK_EQ(run("G21 F100 S100 M3\nG0 Z5\nG87 X0 Y0 Z-2 R1 I0 J3 K-1\nG80\nG5 X1 Y1 P0 Q-3", &g87, &d),
           GcodeError::kOk);
  CHECK(on_curve(g87, 5, {0, 0, 0, 3, 1, -2, 1, 1}));

  // Incremental ends, polar ends, offsets: the curve is where the move is.
  t::Recorder inc;
  CHECK_EQ(run("G21 F100\nG10 L2 P2 X100\nG55 G0 X0 Y0\nG91 G5.1 X10 Y0 I5 J5\nG90 G5.1 @10 ^90 I0 J0", &inc, &d),
           GcodeError::kOk);
  CHECK(on_curve(inc, 4, {100, 0, 105, 5, 110, 0}));
  CHECK(on_curve(inc, 5, {110, 0, 110, 0, 100, 10}));
  CHECK_EQ(inc.records.back().end.x_nm, mm(100));
  CHECK_EQ(inc.records.back().end.y_nm, mm(10));

  // G93: the whole curve takes 1/F minutes (each chord's feed is F times
  // the curve's length).
  t::Recorder inv;
  CHECK_EQ(run("G21\nG93 G5.1 X10 Y0 I5 J0 F2", &inv, &d), GcodeError::kOk);
  for (const CanonRecord& r : inv.records)
    if (r.kind == CanonKind::kFeed) CHECK_EQ(r.feed_nm_per_min, 2 * mm(10));

  // The sagitta option: 10 times coarser, about sqrt(10) times fewer chords.
  t::Recorder coarse;
  CHECK_EQ(run("G21 F100\nG5.1 X10 Y10 I5 J0", &coarse, &d, 10000), GcodeError::kOk);
  CHECK_EQ(coarse.count(CanonKind::kFeed), 16u);  // ceil(sqrt(20 mm / 80 um)) = 16
}

TEST(spline_errors_as_linuxcnc) {
  // rs274's message after each.
  const t::LineError cases[] = {
      {"G5.1 I1 J1", GcodeError::kSplineNoAxis, 1},          // All axes missing with motion code
      {"G5.1 X2 Y2 I1", GcodeError::kSplineIJ, 12},          // Must specify both I and J with G5.1
      {"G5.1 X2 Y2 J1", GcodeError::kSplineIJ, 12},
      {"G5.1 X2 Y2", GcodeError::kSplineIJ, 1},
      {"G5.1 X2 Y2 I1 J1 Z1", GcodeError::kSplineZ, 18},     // Splines may not have motion in Z, A, B, or C
      {"G18 G5.1 X2 Y2 I1 J0", GcodeError::kSplinePlane, 5}, // Splines must be in the XY plane
      {"G5 X2 Y2 I1 J0", GcodeError::kSplinePQ, 1},          // Must specify both P and Q with G5
      {"G5 X2 Y2 I1 J0 P1", GcodeError::kSplinePQ, 1},
      {"G5 X2 Y2 I1 P1 Q0", GcodeError::kSplineIJ, 10},      // Must specify both I and J, or neither
      {"G5.1 X2 Y2 I1 J0 K1", GcodeError::kWordUnused, 18},  // K word with no G2, G3, ... to use it
      {"G5.1 X2 Y2 I1 J0 P1", GcodeError::kWordUnused, 18},  // P word with no ...
      {"G5.1 X2 Y2 I1 J0 R1", GcodeError::kWordUnused, 18},
      {"G5 X2 Y2 P1 Q1 L1", GcodeError::kWordUnused, 16},    // L word with no ...
      {"G93 G5.1 X2 Y2 I1 J0", GcodeError::kInverseTimeNoF, 5},  // F word missing with inverse time arc move
      {"G5.2 X1", GcodeError::kNurbsXY, 1},                  // both X and Y for control points (NURBS: test_nurbs)
      {"G5.1 X2 Y2 I10001 J0", GcodeError::kNumberTooLarge, 12},
  };
  t::check_line_errors("G21 F100\nG0 X1 Y1\n", cases);
  t::Recorder rec;
  GcodeDiag d;
  // A spline before any F: LinuxCNC's "Cannot make arc with zero feed rate".
  CHECK_EQ(run("G21\nG5.1 X2 Y2 I1 J0", &rec, &d), GcodeError::kFeedZero);
  // A curve that bulges beyond the 10 m range, though its ends are in it.
  CHECK_EQ(run("G21 F100\nG0 X9000\nG5.1 X9000 Y10 I5000 J0", &rec, &d), GcodeError::kPositionOutOfRange);
  // A failed spline changes nothing (G5's sticky handle included).
  t::Recorder keep;
  CHECK_EQ(run("G21 F100\nG5 I0 J3 P0 Q-3 X1 Y1\nG5 P1 X2 Y1", &keep, &d), GcodeError::kSplinePQ);
  CHECK_EQ(keep.records.back().end.x_nm, mm(1));
}
