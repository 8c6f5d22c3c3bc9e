// The machine-aware time estimate (core/canon/motion_plan.h): against a
// double-precision oracle of the same model, and analytic cases.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/canon/motion_plan.h"
#include "core/canon/summary.h"
#include "core/interp/interp.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
struct Collect final : PlanSink {
  std::vector<int64_t> us;
  void planned(const PlanPayload&, const PlanTimes& t) override {
    us.push_back(t.blended_us);
    ordered = ordered && t.cruise_us <= t.blended_us + 1 && t.blended_us <= t.stop_us;
  }
  bool ordered = true;
};

// One move for both: a line (arc false) or an XY arc about centre with
// rotation turns, and the length and radius the caller measured.
struct Move {
  CanonRecord r;
  int64_t length_nm, radius_nm;
  bool stop_after;
};

CanonRecord line_rec(PointNm a, PointNm b, int64_t feed_mm_per_min, uint16_t mode, int32_t tol_nm) {
  CanonRecord r{};
  r.kind = feed_mm_per_min > 0 ? CanonKind::kFeed : CanonKind::kTraverse;
  r.start = a;
  r.end = b;
  r.feed_nm_per_min = feed_mm_per_min * 1000000;
  r.path_mode = mode;
  r.path_tolerance_nm = tol_nm;
  return r;
}

// ---- the oracle: the model of motion_plan.h in doubles ----------------------
struct OSeg {
  double len, vc, acc, junction;
  double ds[3], de[3];
  uint16_t mode;
  double tol;
};

double axis_limited(const double lim[3], const double u[3]) {
  double best = 1e300;
  for (int i = 0; i < 3; ++i)
    if (lim[i] > 0 && std::fabs(u[i]) > 0) best = std::min(best, lim[i] / std::fabs(u[i]));
  return best;
}

void unit(double v[3]) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int i = 0; i < 3; ++i) v[i] /= n;
}

OSeg oracle_segment(const Move& m, const PlanLimits& L) {
  double vl[3], al[3];
  for (int i = 0; i < 3; ++i) vl[i] = double(L.velocity_nm_per_s[i]), al[i] = double(L.accel_nm_per_s2[i]);
  const CanonRecord& r = m.r;
  OSeg s{};
  s.mode = r.path_mode;
  s.tol = r.path_tolerance_nm;
  const double feed = r.kind == CanonKind::kTraverse ? 1e300 : double(r.feed_nm_per_min) / 60.0;
  if (r.kind != CanonKind::kArc) {
    double d[3] = {double(r.end.x_nm - r.start.x_nm), double(r.end.y_nm - r.start.y_nm), double(r.end.z_nm - r.start.z_nm)};
    s.len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    unit(d);
    std::memcpy(s.ds, d, sizeof d);
    std::memcpy(s.de, d, sizeof d);
    s.vc = std::min(axis_limited(vl, d), feed);
    s.acc = axis_limited(al, d);
  } else {  // XY arcs only here
    s.len = double(m.length_nm);
    const double rise = double(r.end.z_nm - r.start.z_nm);
    const double around = std::sqrt(s.len * s.len - rise * rise), rad = double(m.radius_nm);
    const double sign = r.arc.turns < 0 ? -1 : 1;
    const PointNm ends[2] = {r.start, r.end};
    double* dirs[2] = {s.ds, s.de};
    for (int k = 0; k < 2; ++k) {
      const double ra = double(ends[k].x_nm - r.arc.centre.x_nm), rb = double(ends[k].y_nm - r.arc.centre.y_nm);
      double t[3] = {-sign * rb, sign * ra, rise * rad / around};
      unit(t);
      std::memcpy(dirs[k], t, sizeof t);
    }
    double vc = std::min(vl[0], vl[1]) * s.len / around;
    if (rise != 0) vc = std::min(vc, vl[2] * s.len / std::fabs(rise));
    vc = std::min(vc, feed);
    vc = std::min(vc, std::sqrt(std::sqrt(3.0) / 2 * std::min(al[0], al[1]) * rad));
    s.vc = vc;
    double a = std::min(al[0], al[1]) * s.len / around;
    if (rise != 0) a = std::min(a, al[2] * s.len / std::fabs(rise));
    s.acc = a / 2;
  }
  return s;
}

double oracle_corner(const OSeg& a, const OSeg& b, const PlanLimits& L) {
  if (a.mode == 610 || a.mode == 611) return 0;
  const double vmax = std::min(a.vc, b.vc);
  double sum[3], diff[3];
  for (int i = 0; i < 3; ++i) sum[i] = a.de[i] + b.ds[i], diff[i] = b.ds[i] - a.de[i];
  const double d = std::sqrt(diff[0] * diff[0] + diff[1] * diff[1] + diff[2] * diff[2]);
  const double c = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  if (d * 1073741824.0 <= 4) return vmax;
  if (c == 0) return 0;
  double R = std::min(a.len, b.len) / 2 * c / d;
  const double tol = a.tol > 0 ? a.tol : double(L.default_tolerance_nm);
  if (tol > 0) R = std::min(R, tol * c * (2 + c) / (d * d));
  double al[3], n[3];
  for (int i = 0; i < 3; ++i) al[i] = double(L.accel_nm_per_s2[i]), n[i] = diff[i] / d;
  const double an = axis_limited(al, n) * std::sqrt(3.0) / 2;
  return std::min(vmax, std::sqrt(an * R));
}

double oracle_trapezoid(double len, double v0, double v1, double vc, double a) {
  if (2 * a * len + v0 * v0 + v1 * v1 >= 2 * vc * vc)
    return len / vc + ((vc - v0) * (vc - v0) + (vc - v1) * (vc - v1)) / (2 * a * vc);
  const double vp = std::sqrt(a * len + (v0 * v0 + v1 * v1) / 2);
  return (2 * vp - v0 - v1) / a;
}

// Each move's time in us, with the planner's ring of kPlanRing segments.
std::vector<double> oracle(const std::vector<Move>& moves, const PlanLimits& L) {
  std::vector<OSeg> s;
  std::vector<size_t> group_end;  // index one past the last segment before a stop
  for (const Move& m : moves) s.push_back(oracle_segment(m, L));
  for (size_t i = 0; i < s.size(); ++i) { s[i].junction = i == 0 || moves[i - 1].stop_after ? 0 : oracle_corner(s[i - 1], s[i], L); }
  std::vector<double> out(s.size());
  size_t first = 0;
  double v0 = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    size_t end = i;
    while (end + 1 < s.size() && !moves[end].stop_after) ++end;
    const size_t w = std::min(end, i + kPlanRing - 1);
    double e = 0;
    for (size_t k = w; k > i; --k) e = std::min(s[k].junction, std::sqrt(e * e + 2 * s[k].acc * s[k].len));
    const double v1 = std::min(e, std::sqrt(v0 * v0 + 2 * s[i].acc * s[i].len));
    out[i] = oracle_trapezoid(s[i].len, v0, v1, s[i].vc, s[i].acc) * 1e6;
    v0 = moves[i].stop_after ? 0 : v1;
    (void)first;
  }
  return out;
}

std::vector<int64_t> planned(const std::vector<Move>& moves, const PlanLimits& L) {
  Collect c;
  MotionPlanner p;
  p.init(L, &c);
  const PlanPayload pay{0, 0};
  for (const Move& m : moves) {
    if (m.r.kind == CanonKind::kArc) p.arc(m.r, m.length_nm, m.radius_nm, pay);
    else p.line(m.r.start, m.r.end, m.r.kind == CanonKind::kTraverse ? 0 : m.r.feed_nm_per_min, m.r, pay);
    if (m.stop_after) p.stop();
  }
  p.stop();
  CHECK(c.ordered);  // every segment: cruise <= blended <= stop (motion_plan.h PlanTimes)
  return c.us;
}

PlanLimits machine(int64_t v_mm_per_min, int64_t a_mm_per_s2) {
  PlanLimits L;
  for (int i = 0; i < 3; ++i) L.velocity_nm_per_s[i] = v_mm_per_min * 1000000 / 60, L.accel_nm_per_s2[i] = a_mm_per_s2 * 1000000;
  return L;
}

PointNm mm(double x, double y, double z) {
  return PointNm{int64_t(std::llround(x * 1e6)), int64_t(std::llround(y * 1e6)), int64_t(std::llround(z * 1e6))};
}
}  // namespace

TEST(motion_plan_single_move_is_a_trapezoid) {
  const PlanLimits L = machine(6000, 500);  // 100 mm/s, 500 mm/s2
  // 100 mm at 60 mm/s (F3600): L / v + v / a = 1.6667 + 0.12 s.
  std::vector<Move> m{{line_rec(mm(0, 0, 0), mm(100, 0, 0), 3600, 640, 0), 0, 0, false}};
  const std::vector<int64_t> us = planned(m, L);
  CHECK_EQ(us.size(), 1u);
  CHECK_NEAR(us[0], 1666667 + 120000, 2);
  // 1 mm: a triangle, 2 sqrt(L / a) = 2 sqrt(0.002) s.
  m[0].r.end = mm(1, 0, 0);
  CHECK_NEAR(planned(m, L)[0], int64_t(std::llround(2e6 * std::sqrt(0.002))), 2);
  // A diagonal rapid on a machine with a slow Z: Z's limits over |u_z|.
  PlanLimits slow_z = L;
  slow_z.velocity_nm_per_s[2] = 10000000;  // 10 mm/s
  slow_z.accel_nm_per_s2[2] = 50000000;    // 50 mm/s2
  m[0].r = line_rec(mm(0, 0, 0), mm(30, 0, 40), 0, 640, 0);  // u = (0.6, 0, 0.8)
  CHECK_NEAR(planned(m, slow_z)[0], int64_t(std::llround((50 / 12.5 + 12.5 / 62.5) * 1e6)), 2);
}

TEST(motion_plan_collinear_pieces_take_the_whole_time) {
  const PlanLimits L = machine(6000, 200);
  std::vector<Move> whole{{line_rec(mm(0, 0, 0), mm(70, 35, -7), 4000, 640, 0), 0, 0, false}};
  int64_t t_whole = planned(whole, L)[0];
  std::vector<Move> pieces;
  const int n = 150;  // more pieces than the ring holds
  for (int k = 0; k < n; ++k)
    pieces.push_back(Move{line_rec(mm(70.0 * k / n, 35.0 * k / n, -7.0 * k / n), mm(70.0 * (k + 1) / n, 35.0 * (k + 1) / n, -7.0 * (k + 1) / n), 4000, 640, 1000), 0, 0, false});
  int64_t t_sum = 0;
  for (int64_t us : planned(pieces, L)) t_sum += us;
  CHECK_NEAR(t_sum, t_whole, n);  // within 1 us a piece
  // Under G61 every piece stops: far longer.
  for (Move& m : pieces) m.r.path_mode = 610;
  int64_t t_stop = 0;
  for (int64_t us : planned(pieces, L)) t_stop += us;
  CHECK_GT(t_stop, t_whole + 1000000);
}

TEST(motion_plan_corner_exact_stop_and_blend) {
  const PlanLimits L = machine(6000, 500);
  const auto two = [&](uint16_t mode, int32_t tol) {
    std::vector<Move> m{{line_rec(mm(0, 0, 0), mm(50, 0, 0), 3000, mode, tol), 0, 0, false},
                        {line_rec(mm(50, 0, 0), mm(50, 50, 0), 3000, mode, tol), 0, 0, false}};
    const std::vector<int64_t> us = planned(m, L);
    return us[0] + us[1];
  };
  // G61: two moves from rest to rest, each L / v + v / a = 1 + 0.1 s.
  CHECK_NEAR(two(610, 0), 2200000, 4);
  CHECK_EQ(two(611, 0), two(610, 0));
  // G64 P0.01: R = P (sqrt 2 + 1), a_n = sqrt(2) a along the bisector,
  // v = sqrt((sqrt 3 / 2) a_n R); each move loses (vc - v)^2 / (2 a vc) once.
  const double R = 10000 * (std::sqrt(2.0) + 1), an = std::sqrt(2.0) * 500e6 * std::sqrt(3.0) / 2, vc = 50e6;
  const double v = std::sqrt(an * R);
  const double want = 2 * (1.0 + (vc * vc + (vc - v) * (vc - v)) / (2 * 500e6 * vc));
  CHECK_NEAR(two(640, 10000), int64_t(std::llround(want * 1e6)), 4);
  // A looser tolerance is faster, none at all (half the segments) faster still.
  CHECK_LT(two(640, 100000), two(640, 10000));
  CHECK_LT(two(640, 0), two(640, 100000));
  CHECK_LT(two(640, 10000), two(610, 0));
  // A reversal stops even under G64.
  std::vector<Move> back{{line_rec(mm(0, 0, 0), mm(50, 0, 0), 3000, 640, 0), 0, 0, false},
                         {line_rec(mm(50, 0, 0), mm(0, 0, 0), 3000, 640, 0), 0, 0, false}};
  const std::vector<int64_t> b = planned(back, L);
  CHECK_NEAR(b[0] + b[1], 2200000, 4);
}

TEST(motion_plan_against_double_oracle) {
  t::Rng rng(40);
  double worst = 0;
  for (int trial = 0; trial < 60; ++trial) {
    PlanLimits L;
    for (int i = 0; i < 3; ++i) {
      L.velocity_nm_per_s[i] = rng.range(20, 400) * 1000000;
      L.accel_nm_per_s2[i] = rng.range(50, 3000) * 1000000;
    }
    L.default_tolerance_nm = trial % 3 == 0 ? int64_t(rng.range(1, 100000)) : 0;
    std::vector<Move> moves;
    PointNm at = mm(0, 0, 0);
    const int n = int(rng.range(1, 140));
    for (int k = 0; k < n; ++k) {
      const int what = int(rng.range(0, 9));
      const uint16_t mode = rng.range(0, 5) == 0 ? uint16_t(rng.range(0, 1) ? 610 : 611) : uint16_t(640);
      const int32_t tol = rng.range(0, 1) ? int32_t(rng.range(0, 200000)) : 0;
      const int64_t feed = rng.range(0, 6) == 0 ? 0 : rng.range(10, 20000);
      Move m{};
      if (what <= 5) {  // a line: long, short, tiny
        const int64_t scale = what <= 2 ? 50000000 : what <= 4 ? 500000 : 5000;
        const PointNm to{at.x_nm + rng.range(-scale, scale), at.y_nm + rng.range(-scale, scale), at.z_nm + rng.range(-scale / 4, scale / 4)};
        m.r = line_rec(at, to, feed, mode, tol);
      } else if (what <= 7) {  // the same direction again (a collinear split)
        if (moves.empty() || moves.back().r.kind == CanonKind::kArc) continue;
        const CanonRecord& p = moves.back().r;
        const PointNm to{at.x_nm + (p.end.x_nm - p.start.x_nm), at.y_nm + (p.end.y_nm - p.start.y_nm), at.z_nm + (p.end.z_nm - p.start.z_nm)};
        if (to.x_nm == at.x_nm && to.y_nm == at.y_nm && to.z_nm == at.z_nm) continue;
        m.r = line_rec(at, to, feed ? feed : 1000, mode, tol);
      } else {  // an XY arc, maybe a helix
        const double rad = double(rng.range(100000, 30000000)), a0 = double(rng.range(0, 6283)) / 1000;
        const double sweep = double(rng.range(50, 6000)) / 1000, sign = rng.range(0, 1) ? 1 : -1;
        const double cx = double(at.x_nm) - rad * std::cos(a0), cy = double(at.y_nm) - rad * std::sin(a0);
        const double a1 = a0 + sign * sweep;
        const PointNm to{int64_t(std::llround(cx + rad * std::cos(a1))), int64_t(std::llround(cy + rad * std::sin(a1))), at.z_nm + (rng.range(0, 1) ? rng.range(-3000000, 3000000) : 0)};
        m.r = line_rec(at, to, feed ? feed : 500, mode, tol);
        m.r.kind = CanonKind::kArc;
        m.r.arc = CanonArc{Plane::kXY, PointNm{int64_t(std::llround(cx)), int64_t(std::llround(cy)), at.z_nm}, sign > 0 ? 1 : -1};
        const double rise = double(to.z_nm - at.z_nm);
        m.radius_nm = int64_t(rad);
        m.length_nm = int64_t(std::sqrt(rad * sweep * rad * sweep + rise * rise));
      }
      m.stop_after = rng.range(0, 30) == 0;
      at = m.r.end;
      if (m.r.start.x_nm == at.x_nm && m.r.start.y_nm == at.y_nm && m.r.start.z_nm == at.z_nm) continue;
      moves.push_back(m);
    }
    const std::vector<double> want = oracle(moves, L);
    const std::vector<int64_t> got = planned(moves, L);
    if (!CHECK_EQ(got.size(), want.size())) continue;
    for (size_t i = 0; i < got.size(); ++i) {
      const double err = std::fabs(double(got[i]) - want[i]);
      worst = std::max(worst, err - 1e-6 * want[i]);
      if (!CHECK_LE(err, 3 + 1e-6 * want[i])) {
        const OSeg o = oracle_segment(moves[i], L);
        std::printf("  trial %d move %zu of %zu: %lld us, oracle %.3f (kind %d, vc %.1f nm/s)\n", trial, i, got.size(), (long long)got[i], want[i], int(moves[i].r.kind), o.vc);
        break;
      }
    }
  }
  std::printf("  worst error beyond 1e-6 relative: %.3f us\n", worst);
}

namespace {
// Summed into *s with the planner's memory at *plan.
void summarise(const char* const* lines, int n, MotionSummary* sum, MotionPlanner* plan) {
  MotionSummary& s = *sum;
  s.set_planner(plan);
  Interp in(&s, InterpOptions());
  for (int k = 0; k < n; ++k) {
    GcodeDiag d;
    CHECK_EQ(in.execute_line(lines[k], std::strlen(lines[k]), static_cast<uint32_t>(k + 1), &d), GcodeError::kOk);
  }
  s.finish();
}
}  // namespace

TEST(motion_plan_in_the_summary_lies_between) {
  const char* prog[] = {
      "G21 G90 G17 G64 P0.02", "G0 X0 Y0 Z5", "G1 Z-1 F600", "G1 X40 F1500", "G1 Y30", "G3 X30 Y40 I-10 J0",
      "G1 X5 Y38", "G1 X0 Y0", "G4 P1", "G61", "G1 X20 Y5", "G1 X20 Y20", "G0 Z5", "M2",
  };
  MotionTimeModel m;
  m.accel_nm_per_s2 = 300 * 1000000LL;
  m.blend = true;
  MotionPlanner plan;
  MotionSummary s(m);
  summarise(prog, 14, &s, &plan);
  CHECK_GT(s.blended_time_us(), s.no_accel_time_us());
  CHECK_LT(s.blended_time_us(), s.stop_time_us());
  // The planner's bounds are of its own model (per-axis limits, arcs at
  // a / 2 along the path), not the flat model's: stop here is above it.
  CHECK_GT(s.stop_time_us(), s.estimated_time_us());
  CHECK_EQ(s.blended_feed_us() + s.blended_rapid_us() + s.dwell_time_us(), s.blended_time_us());
  // Without the planner: every figure is the model's.
  m.blend = false;
  MotionSummary f(m);
  summarise(prog, 14, &f, &plan);
  CHECK_EQ(f.blended_time_us(), f.estimated_time_us());
  CHECK_EQ(f.stop_time_us(), f.estimated_time_us());
  CHECK_EQ(f.estimated_time_us(), s.estimated_time_us());  // the engine's per-move clock: the model's either way
  // Blend asked for but no planner's memory given: the model's figure too.
  m.blend = true;
  MotionSummary g(m);
  summarise(prog, 14, &g, nullptr);
  CHECK_EQ(g.blended_time_us(), g.stop_time_us());
}

namespace {
struct Modes final : CanonSink {
  std::vector<CanonRecord> r;
  void emit(const CanonRecord& x) override { r.push_back(x); }
};
}  // namespace

TEST(motion_plan_interp_carries_path_mode_and_tolerance) {
  const char* prog[] = {"G21 G1 X1 F100", "G64 P0.05 X2", "G20 G64 P0.001 X0.1", "G61 X0.2", "G61.1 X0.3", "G64 X0.4", "G64 P-1 X0.5"};
  Modes m;
  Interp in(&m, InterpOptions());
  for (int k = 0; k < 7; ++k) {
    GcodeDiag d;
    CHECK_EQ(in.execute_line(prog[k], std::strlen(prog[k]), static_cast<uint32_t>(k + 1), &d), GcodeError::kOk);
  }
  CHECK_EQ(m.r.size(), 7u);
  const uint16_t mode[] = {640, 640, 640, 610, 611, 640, 640};
  const int32_t tol[] = {0, 50000, 25400, 0, 0, 0, 0};
  for (size_t k = 0; k < m.r.size() && k < 7; ++k) {
    CHECK_EQ(m.r[k].path_mode, mode[k]);
    CHECK_EQ(m.r[k].path_tolerance_nm, tol[k]);
  }
}
