// G5.2/G5.3 NURBS (core/interp/nurbs.h) against a double-precision oracle
// written from LinuxCNC's own definition (nurbs_additional_functions.cc: the
// clamped integer knot vector, Cox-de Boor basis, rational sum): every chord
// point within 2 nm of the curve, the curve within the sagitta + 3 nm of the
// chords, the ends exact; and the interpreter's reading of G5.2 blocks.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "core/interp/interp.h"
#include "core/interp/nurbs.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

struct Oracle {
  std::vector<double> x, y, w;
  int k;
  int n() const { return static_cast<int>(x.size()) - 1; }
  double knot(int i) const { return i < k ? 0 : i <= n() ? i - k + 1 : n() - k + 2; }
  // The rational point at u: de Boor's algorithm on (x w, y w, w), the
  // span found from the knots (the last span closed at its right end).
  void at(double u, double* px, double* py) const {
    const int d = k - 1;
    int j = d;
    while (j < n() && knot(j + 1) <= u) ++j;
    double hx[16], hy[16], hw[16];
    for (int i = 0; i <= d; ++i) {
      const int g = j - d + i;
      hx[i] = x[g] * w[g];
      hy[i] = y[g] * w[g];
      hw[i] = w[g];
    }
    for (int r = 1; r <= d; ++r)
      for (int i = d; i >= r; --i) {
        const int g = j - d + i;
        const double a = (u - knot(g)) / (knot(g + d + 1 - r) - knot(g));
        hx[i] = (1 - a) * hx[i - 1] + a * hx[i];
        hy[i] = (1 - a) * hy[i - 1] + a * hy[i];
        hw[i] = (1 - a) * hw[i - 1] + a * hw[i];
      }
    *px = hx[d] / hw[d];
    *py = hy[d] / hw[d];
  }
};

double seg_dist(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

}  // namespace

TEST(nurbs_against_double_oracle) {
  std::mt19937_64 rng(52);
  double worst_point = 0, worst_sag = 0;  // nm; the second past the sagitta
  long chords = 0;
  static NurbsCurve c;  // 3 KB: off the stack
  for (int trial = 0; trial < 200; ++trial) {
    Oracle o;
    o.k = 3 + static_cast<int>(rng() % 5);
    const int count = o.k + static_cast<int>(rng() % 12);
    const double extent = trial % 10 == 0 ? 9e9 : 2e6 + static_cast<double>(rng() % 100000000);  // nm
    std::uniform_real_distribution<double> coord(-extent, extent), weight(0.3, 3.0);
    c.count = count;
    c.order = o.k;
    for (int i = 0; i < count; ++i) {
      const int64_t xi = static_cast<int64_t>(coord(rng)), yi = static_cast<int64_t>(coord(rng));
      const int64_t wi = static_cast<int64_t>(weight(rng) * 1e9);
      c.x_nm[i] = xi;
      c.y_nm[i] = yi;
      c.weight[i] = wi;
      o.x.push_back(static_cast<double>(xi));
      o.y.push_back(static_cast<double>(yi));
      o.w.push_back(static_cast<double>(wi));
    }
    CHECK(nurbs_weights_ok(c));
    nurbs_prepare(&c);
    const int64_t sagitta = trial % 10 == 0 ? 100000 : trial % 3 == 0 ? 1000 : trial % 3 == 1 ? 20000 : 100;
    int64_t ax = c.x_nm[0], ay = c.y_nm[0];
    for (int32_t s = 0; s < nurbs_spans(c); ++s) {
      const uint32_t m = nurbs_pieces(c, s, sagitta);
      chords += m;
      for (uint32_t i = 1; i <= m; ++i) {
        int64_t bx, by;
        nurbs_point(c, s, i, m, &bx, &by);
        const double u1 = s + static_cast<double>(i) / m, u0 = s + static_cast<double>(i - 1) / m;
        double ex, ey;
        o.at(u1, &ex, &ey);
        const double perr = std::hypot(static_cast<double>(bx) - ex, static_cast<double>(by) - ey);
        worst_point = std::fmax(worst_point, perr);
        // The curve between the two chord ends, against the chord.
        for (int q = 1; q < 16; ++q) {
          double cx, cy;
          o.at(u0 + (u1 - u0) * q / 16, &cx, &cy);
          const double dd = seg_dist(cx, cy, static_cast<double>(ax), static_cast<double>(ay), static_cast<double>(bx),
                                     static_cast<double>(by));
          worst_sag = std::fmax(worst_sag, dd - static_cast<double>(sagitta));
        }
        ax = bx;
        ay = by;
      }
    }
    // The end is the last control point, exactly.
    CHECK_EQ(ax, c.x_nm[count - 1]);
    CHECK_EQ(ay, c.y_nm[count - 1]);
  }
  std::printf("  nurbs: %ld chords; points within %.2f nm of the curve, curve within the sagitta + %.2f nm\n", chords,
              worst_point, worst_sag);
  CHECK(worst_point <= 2.0);
  CHECK(worst_sag <= 3.0);
}

TEST(nurbs_weights_beyond_the_ratio_are_refused) {
  static NurbsCurve c;
  c.count = 3;
  c.order = 3;
  for (int i = 0; i < 3; ++i) c.x_nm[i] = c.y_nm[i] = i * 1000000;
  c.weight[0] = 1000000000;
  c.weight[1] = 1000000000LL * 4000;
  c.weight[2] = 1000000000;
  CHECK(nurbs_weights_ok(c));
  c.weight[1] = 1000000000LL * 5000;
  CHECK(!nurbs_weights_ok(c));
}

TEST(nurbs_blocks_as_linuxcnc_reads_them) {
  t::Recorder rec;
  GcodeDiag d;
  InterpOptions opt;
  // Order 3 by default; L3 is ignored (only L above 3 counts); the curve
  // ends at the last point and the position follows it there.
  {
    Interp in(&rec, opt);
    CHECK_EQ(t::run_program(&in, "G21 F100\nG5.2 X0 Y10 P1 L3\nX10 Y10 P1\nX10 Y0 P1\nG5.3\nG1 X20\nM2", &d),
             GcodeError::kOk);
    CHECK(rec.records.size() > 4);
    const CanonRecord& last = rec.records[rec.records.size() - 2];
    CHECK(last.start == (PointNm{t::mm(10), 0, 0}));
    CHECK(last.end == (PointNm{t::mm(20), 0, 0}));
  }
  struct Bad {
    const char* program;
    GcodeError e;
    uint32_t line;
  } bad[] = {
      {"G21 F100\nG5.2 X1 P1\nG5.3", GcodeError::kNurbsXY, 2},
      {"G21 F100\nG5.2 X1 Y1 P1\nX2 Y2\nG5.3", GcodeError::kNurbsWeight, 3},
      {"G21 F100\nG5.2 X1 Y1 P1\nP2\nG5.3", GcodeError::kWordUnused, 3},  // P alone moves nothing
      {"G21 F100\nG5.2 X1 Y1 P1\nG5.2 P2", GcodeError::kNurbsPOnlyFirst, 3},
      {"G21 F100\nG5.3", GcodeError::kNurbsNoStart, 2},
      {"G21 F100\nG5.2 X1 Y1 P1 L4\nX2 Y0 P1\nG5.3", GcodeError::kNurbsTooFew, 4},
      {"G21\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3", GcodeError::kFeedZero, 2},
      {"G21 F100\nG5.2 X1 Y1 P1 L11\nG5.3", GcodeError::kNurbsTooMany, 2},
      {"G21 F100\nG5.2 X1 Y1 P1\nX2 Y0 P5000\nG5.3", GcodeError::kNurbsTooMany, 4},
      {"G21 F100\nG5.2 X1 Y1 P1\nG1 X3\nG5.3", GcodeError::kNurbsNoStart, 4},  // G1 dropped the points
  };
  for (const Bad& b : bad) {
    Interp in(&rec, opt);
    d = GcodeDiag{};
    CHECK_EQ(t::run_program(&in, b.program, &d), b.e);
    CHECK_EQ(d.line, b.line);
  }
  // No false alarm at the limit: 64 control points read.
  std::string prog = "G21 F100\nG5.2 X0 Y1 P1\n";
  for (int i = 2; i < 64; ++i) prog += "X" + std::to_string(i) + " Y" + std::to_string(i % 2) + " P1\n";
  prog += "G5.3\nM2\n";
  Interp in(&rec, opt);
  CHECK_EQ(t::run_program(&in, prog.c_str(), &d), GcodeError::kOk);
  prog = "G21 F100\nG5.2 X0 Y1 P1\n";
  for (int i = 2; i < 65; ++i) prog += "X" + std::to_string(i) + " Y" + std::to_string(i % 2) + " P1\n";
  Interp in2(&rec, opt);
  CHECK_EQ(t::run_program(&in2, prog.c_str(), &d), GcodeError::kNurbsTooMany);
}
