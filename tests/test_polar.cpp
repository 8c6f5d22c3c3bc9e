// Polar coordinates (@, ^; core/interp/polar.h and the interpreter's use of
// them): the integer geometry against a double oracle of LinuxCNC's
// find_ends and CYCLE_MACRO (the error bound of polar.h), and programs
// against what LinuxCNC 2.9's rs274 prints for them, errors included.
#include <cmath>
#include <random>
#include <string>

#include "core/interp/interp.h"
#include "core/interp/polar.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"

using namespace dexmill;
using t::mm;

namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

// polar.h's bound for a result at distance rho from the origin, nm.
double bound_nm(double rho) { return 6.4e-9 * std::fabs(rho) + 1.3; }

struct Oracle {
  double x, y;
};

// LinuxCNC's find_ends in doubles (nm).
Oracle absolute_oracle(double x, double y, const PolarWords& w) {
  const double r = w.has_radius ? static_cast<double>(w.radius_nm) : std::hypot(x, y);
  const double th = w.has_angle ? rad(w.angle_deg_e9 / 1e9) : std::atan2(y, x);
  return {r * std::cos(th), r * std::sin(th)};
}

Oracle incremental_oracle(double x, double y, const PolarWords& w) {
  if (w.has_radius) {
    const double th = std::atan2(y, x), r = std::hypot(x, y) + static_cast<double>(w.radius_nm);
    x = r * std::cos(th);
    y = r * std::sin(th);
  }
  if (w.has_angle) {
    const double th = std::atan2(y, x) + rad(w.angle_deg_e9 / 1e9), r = std::hypot(x, y);
    x = r * std::cos(th);
    y = r * std::sin(th);
  }
  return {x, y};
}

GcodeError run(const char* program, t::Recorder* rec, GcodeDiag* d) {
  InterpOptions opt;
  Interp in(rec, opt);
  return t::run_program(&in, program, d);
}

// End points of the moves from line `line` on: "x,y,z " in um, rounded.
std::string ends(const t::Recorder& rec, uint32_t line) {
  std::string s;
  char buf[80];
  for (const CanonRecord& r : rec.records) {
    if (r.line < line || (r.kind != CanonKind::kTraverse && r.kind != CanonKind::kFeed && r.kind != CanonKind::kArc))
      continue;
    std::snprintf(buf, sizeof buf, "%lld,%lld,%lld ", static_cast<long long>(std::llround(r.end.x_nm / 1000.0)),
                  static_cast<long long>(std::llround(r.end.y_nm / 1000.0)),
                  static_cast<long long>(std::llround(r.end.z_nm / 1000.0)));
    s += buf;
  }
  return s;
}

}  // namespace

TEST(polar_absolute_against_double_oracle) {
  std::mt19937_64 rng(2101);
  std::uniform_int_distribution<int64_t> coord(-5000000000, 5000000000), small(-3000, 3000);
  std::uniform_int_distribution<int64_t> angle(-720000000000, 720000000000);
  double worst = 0;  // in units of the bound
  for (int i = 0; i < 200000; ++i) {
    const int64_t x = i % 4 == 0 ? small(rng) : coord(rng), y = i % 4 == 0 ? small(rng) : coord(rng);
    PolarWords w{i % 3 != 1, i % 3 != 2, coord(rng), angle(rng)};
    if (i % 7 == 0) w.angle_deg_e9 = angle(rng) / 1000000000 * 1000000000;  // whole degrees
    int64_t px, py;
    char word = 0;
    const GcodeError e = polar_absolute(x, y, w, false, &px, &py, &word);
    if (w.has_radius && !w.has_angle && x == 0 && y == 0) {
      CHECK_EQ(e, GcodeError::kPolarNoAngle);
      continue;
    }
    CHECK_EQ(e, GcodeError::kOk);
    const Oracle o = absolute_oracle(static_cast<double>(x), static_cast<double>(y), w);
    const double err = std::hypot(px - o.x, py - o.y);
    const double b = bound_nm(std::hypot(o.x, o.y));
    worst = std::max(worst, err / b);
    if (err > b) {
      CHECK(err <= b);
      std::printf("  x %lld y %lld r %lld a %lld: err %.2f nm > %.2f\n", static_cast<long long>(x),
                  static_cast<long long>(y), static_cast<long long>(w.radius_nm),
                  static_cast<long long>(w.angle_deg_e9), err, b);
      break;
    }
  }
  std::printf("  polar_absolute: worst error %.2f of the bound\n", worst);
  // Exact where the trigonometry is: the axes.
  int64_t px, py;
  char word;
  CHECK_EQ(polar_absolute(0, 0, PolarWords{true, true, mm(2), 90000000000}, false, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(px, 0);
  CHECK_EQ(py, mm(2));
  // A negative distance goes the other way (LinuxCNC: r cos, r sin).
  CHECK_EQ(polar_absolute(0, 0, PolarWords{true, true, -mm(2), 0}, false, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(px, -mm(2));
  // @ alone: at the origin an error for a move, the angle 0 for a cycle;
  // one nm off the origin is a direction.
  CHECK_EQ(polar_absolute(0, 0, PolarWords{true, false, mm(2), 0}, false, &px, &py, &word), GcodeError::kPolarNoAngle);
  CHECK_EQ(word, '@');
  CHECK_EQ(polar_absolute(0, 0, PolarWords{true, false, mm(2), 0}, true, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(px, mm(2));
  CHECK_EQ(polar_absolute(0, -1, PolarWords{true, false, mm(2), 0}, false, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(py, -mm(2));
  // ^ alone keeps the distance (at the origin: 0).
  CHECK_EQ(polar_absolute(mm(3), mm(4), PolarWords{false, true, 0, 180000000000}, false, &px, &py, &word),
           GcodeError::kOk);
  CHECK_EQ(px, -mm(5));
  CHECK_EQ(py, 0);
}

TEST(polar_incremental_against_double_oracle) {
  std::mt19937_64 rng(2102);
  std::uniform_int_distribution<int64_t> coord(-5000000000, 5000000000);
  std::uniform_int_distribution<int64_t> angle(-400000000000, 400000000000);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const int64_t x = coord(rng), y = coord(rng);
    PolarWords w{i % 3 != 1, i % 3 != 2, coord(rng), angle(rng)};
    int64_t px, py;
    char word = 0;
    CHECK_EQ(polar_incremental(x, y, w, &px, &py, &word), GcodeError::kOk);
    const Oracle o = incremental_oracle(static_cast<double>(x), static_cast<double>(y), w);
    const double err = std::hypot(px - o.x, py - o.y);
    const double b = bound_nm(std::hypot(o.x, o.y));
    worst = std::max(worst, err / b);
    if (err > b) {
      CHECK(err <= b);
      break;
    }
  }
  std::printf("  polar_incremental: worst error %.2f of the bound\n", worst);
  int64_t px, py;
  char word = 0;
  // From the origin: indeterminate, for @ and for ^ (LinuxCNC's two errors).
  CHECK_EQ(polar_incremental(0, 0, PolarWords{true, false, mm(1), 0}, &px, &py, &word),
           GcodeError::kPolarIncrementalOrigin);
  CHECK_EQ(word, '@');
  CHECK_EQ(polar_incremental(0, 0, PolarWords{false, true, 0, 1000000000}, &px, &py, &word),
           GcodeError::kPolarIncrementalOrigin);
  CHECK_EQ(word, '^');
  // @ that lands on the origin leaves ^ nothing to turn.
  CHECK_EQ(polar_incremental(mm(1), 0, PolarWords{true, true, -mm(1), 1000000000}, &px, &py, &word),
           GcodeError::kPolarIncrementalOrigin);
  CHECK_EQ(word, '^');
  CHECK_EQ(polar_incremental(mm(1), 0, PolarWords{true, false, -mm(1), 0}, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(px, 0);
  // Past the origin: the other side of it.
  CHECK_EQ(polar_incremental(mm(1), 0, PolarWords{true, false, -mm(3), 0}, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(px, -mm(2));
  CHECK_EQ(py, 0);
  // One nm from the origin is not the origin.
  CHECK_EQ(polar_incremental(1, 0, PolarWords{false, true, 0, 90000000000}, &px, &py, &word), GcodeError::kOk);
  CHECK_EQ(py, 1);
}

// A series of holes, as CYCLE_MACRO makes them from the hole before (here
// in doubles), against PolarSeries, which makes hole k from k: over many
// repeats the integer one does not drift.
TEST(polar_series_against_double_oracle) {
  std::mt19937_64 rng(2103);
  std::uniform_int_distribution<int64_t> coord(-200000000, 200000000), step(-5000000, 5000000);
  std::uniform_int_distribution<int64_t> angle(-90000000000, 90000000000);
  double worst = 0;
  for (int i = 0; i < 300; ++i) {
    const int64_t x = coord(rng), y = coord(rng);
    const int64_t dr = i % 3 == 2 ? 0 : step(rng), da = i % 3 == 1 ? 0 : angle(rng);
    PolarSeries s;
    s.init(x, y, dr, da);
    double ox = static_cast<double>(x), oy = static_cast<double>(y);
    for (int k = 0; k < 2000; ++k) {
      if (dr) {
        const double th = std::atan2(oy, ox), r = std::hypot(ox, oy) + static_cast<double>(dr);
        ox = r * std::cos(th);
        oy = r * std::sin(th);
      }
      if (da) {
        const double th = std::atan2(oy, ox) + rad(da / 1e9), r = std::hypot(ox, oy);
        ox = r * std::cos(th);
        oy = r * std::sin(th);
      }
      int64_t px, py;
      char word;
      if (!CHECK(s.next(&px, &py, &word))) break;
      const double err = std::hypot(px - ox, py - oy), b = bound_nm(std::hypot(ox, oy));
      worst = std::max(worst, err / b);
      if (err > b) {
        CHECK(err <= b);
        std::printf("  series %d hole %d: err %.2f nm > %.2f\n", i, k, err, b);
        i = 1000;
        break;
      }
    }
  }
  std::printf("  PolarSeries over 2000 repeats: worst error %.2f of the bound\n", worst);
  // The origin stops the series where LinuxCNC stops: 3 mm in steps of -1.
  PolarSeries s;
  s.init(mm(3), 0, -mm(1), 0);
  int64_t px, py;
  char word = 0;
  CHECK(s.next(&px, &py, &word));
  CHECK(s.next(&px, &py, &word));
  CHECK(s.next(&px, &py, &word));
  CHECK_EQ(px, 0);
  CHECK(!s.next(&px, &py, &word));
  CHECK_EQ(word, '@');
  // Steps of zero (LinuxCNC skips them): every hole at the first point.
  s.init(0, 0, 0, 0);
  CHECK(s.next(&px, &py, &word));
  CHECK_EQ(px, 0);
}

// polar.ngc's forms, in mm, against rs274's STRAIGHT_* (4 decimals).
TEST(polar_moves_as_linuxcnc) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 G90 F100\nG0 X1 Y1 Z0\nG1 @2 ^45\nG1 @2\nG1 ^90\nG91 G1 @1\nG91 G1 ^90\n"
               "G90 G0 @1 ^2\n@2 ^1",
               &rec, &d),
           GcodeError::kOk);
  // rs274: (1.4142, 1.4142) (1.4142, 1.4142) (0, 2) (0, 3) (-3, 0) (0.9994, 0.0349) (1.9997, 0.0349).
  CHECK_EQ(ends(rec, 3), std::string("1414,1414,0 1414,1414,0 0,2000,0 0,3000,0 -3000,0,0 999,35,0 2000,35,0 "));
  // Arcs and probes take polar end points too.
  t::Recorder arcs;
  CHECK_EQ(run("G21 G90 F100\nG0 X1 Y1\nG2 @2 ^90 R2\nG0 X1 Y1\nG3 @1.4142136 ^90 I-1 J-1\nG38.2 @3 ^0", &arcs, &d),
           GcodeError::kOk);
  CHECK_EQ(ends(arcs, 3), std::string("0,2000,0 1000,1000,0 0,1414,0 3000,0,0 "));
  // Offsets: polar coordinates are about the program origin.
  t::Recorder off;
  CHECK_EQ(run("G21 F100\nG10 L2 P2 X10 Y20\nG55 G0 @5 ^0\nG92 X5 Y0\nG91 G1 ^90", &off, &d), GcodeError::kOk);
  CHECK_EQ(ends(off, 3), std::string("15000,20000,0 10000,25000,0 "));
  // LinuxCNC asks the plane before the block's own G18 (rs274: XY move).
  t::Recorder pl;
  CHECK_EQ(run("G21 F100\nG18 G1 @1 ^90", &pl, &d), GcodeError::kOk);
  CHECK_EQ(ends(pl, 2), std::string("0,1000,0 "));
}

TEST(polar_errors_as_linuxcnc) {
  const t::LineError cases[] = {
      {"G1 @2 X1", GcodeError::kPolarWithXY, 7},     // Cannot specify both polar coordinate and X word
      {"G1 ^30 Y1", GcodeError::kPolarWithXY, 8},    // ... and Y word
      {"G92 @1", GcodeError::kPolarNotMotion, 5},    // Polar coordinates can only be used for motion
      {"G28 @1", GcodeError::kPolarNotMotion, 5},
      {"G10 L20 P1 ^1", GcodeError::kPolarNotMotion, 12},
      {"G53 G0 @1 ^2", GcodeError::kPolarG53, 8},    // Cannot use polar coordinates with G53
      {"G80 @1", GcodeError::kAxisWordsWithG80, 1},  // Cannot use axis values with g80
      {"G1 G28 @1", GcodeError::kTwoAxisUsers, 4},
  };
  t::check_line_errors("G21 F100\nG0 X1 Y1\n", cases);
  t::Recorder rec;
  GcodeDiag d;
  // The plane before the block.
  CHECK_EQ(run("G21 F100\nG18\nG1 @1 ^2", &rec, &d), GcodeError::kPolarPlane);
  CHECK_EQ(d.col, 4);
  // No motion mode (G80 at the start): LinuxCNC's "Cannot use axis values
  // without a G code that uses them".
  CHECK_EQ(run("G21\n^90", &rec, &d), GcodeError::kAxisWordsUnused);
  CHECK_EQ(std::string(d.word), std::string("^"));
  // At the origin (rs274: "Must specify angle in polar coordinate if at the
  // origin", "Incremental motion ... indeterminate", "G91 motion ...").
  CHECK_EQ(run("G21 F100\nG0 X0 Y0\nG1 @2", &rec, &d), GcodeError::kPolarNoAngle);
  CHECK_EQ(run("G21 F100\nG0 X0 Y0\nG91 G1 @2", &rec, &d), GcodeError::kPolarIncrementalOrigin);
  CHECK_EQ(run("G21 F100\nG0 X0 Y0\nG91 G1 ^2", &rec, &d), GcodeError::kPolarIncrementalOrigin);
  CHECK_EQ(std::string(d.word), std::string("^"));
  // ... but ^ alone at the origin stays there, and one off it is fine.
  CHECK_EQ(run("G21 F100\nG0 X0 Y0\nG1 ^45", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G21 F100\nG0 X0.000001 Y0\nG91 G1 @2", &rec, &d), GcodeError::kOk);
  // Range: a distance beyond 10 m, a result beyond it.
  CHECK_EQ(run("G21 F100\nG1 @10001 ^0", &rec, &d), GcodeError::kNumberTooLarge);
  CHECK_EQ(run("G21 F100\nG0 X9000\nG91 G1 @2000", &rec, &d), GcodeError::kPositionOutOfRange);
  CHECK_EQ(run("G21 F100\nG1 @1 ^10000000000", &rec, &d), GcodeError::kNumberTooLarge);
}

// Canned cycles: the holes of polar.ngc (in mm here), rs274's numbers.
TEST(polar_cycles_as_linuxcnc) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 G90\nG0 X0 Y0 Z0\nG0 X2.5 Y0\nG81 R.1 Z-0.5 F60\n^120\n^240\nG90 @1 ^33\n"
               "G91 G81 @1 R.1 Z-0.5 L3\nG90 G0 X2 Y0\nG91 G81 ^21.176470588 R.1 Z-0.5 L3",
               &rec, &d),
           GcodeError::kOk);
  // Only the holes (the moves to each hole at the clearance level).
  std::string holes;
  char buf[64];
  int64_t last_x = INT64_MIN, last_y = INT64_MIN;
  for (const CanonRecord& r : rec.records) {
    if (r.line < 5 || r.kind != CanonKind::kTraverse) continue;
    if (r.end.x_nm == last_x && r.end.y_nm == last_y) continue;
    last_x = r.end.x_nm;
    last_y = r.end.y_nm;
    std::snprintf(buf, sizeof buf, "%.4f,%.4f ", r.end.x_nm / 1e6, r.end.y_nm / 1e6);
    holes += buf;
  }
  // rs274: (2.5000, 0.0000) (up to R first) (-1.2500, 2.1651) (-1.2500, -2.1651) (0.8387, 0.5446) (1.6773, 1.0893)
  // (2.5160, 1.6339) (3.3547, 2.1786) (2.0000, 0.0000) (1.8649, 0.7225) (1.4780, 1.3474) (0.8915, 1.7903)
  CHECK_EQ(holes, std::string("2.5000,0.0000 -1.2500,2.1651 -1.2500,-2.1651 0.8387,0.5446 1.6773,1.0893 2.5160,1.6339 "
                              "3.3547,2.1786 2.0000,0.0000 1.8649,0.7225 1.4780,1.3474 0.8915,1.7903 "));
  // The next move starts at the last hole.
  t::Recorder rec2;
  CHECK_EQ(run("G21 F60\nG0 X1 Y0 Z1\nG91 G81 ^90 R0 Z-1 L2\nG90 G80 G1 Z1", &rec2, &d), GcodeError::kOk);
  CHECK_EQ(ends(rec2, 4), std::string("-1000,0,1000 "));
  // A series that reaches the origin stops where LinuxCNC stops, before
  // anything moves (dexmill's blocks are atomic).
  t::Recorder rec3;
  CHECK_EQ(run("G21 F60\nG0 X2 Y0 Z1\nG91 G81 @-1 R0 Z-1 L3", &rec3, &d), GcodeError::kPolarIncrementalOrigin);
  CHECK_EQ(rec3.count(CanonKind::kFeed), 0u);
  // Polar cycles only in XY: in G18 the bottom is a Y word (LinuxCNC: "Cannot
  // specify both polar coordinate and Y word"); a modal cycle that keeps its
  // bottom would move in XZ, where LinuxCNC ignores polar words.
  CHECK_EQ(run("G21 F60\nG0 X2 Y0 Z1\nG18 G81 @1 R0 Y-1", &rec3, &d), GcodeError::kPolarWithXY);
  CHECK_EQ(run("G21 F60\nG0 X2 Y0 Z1\nG81 X2 R0 Z-1\nG18 @1", &rec3, &d), GcodeError::kPolarPlane);
}
