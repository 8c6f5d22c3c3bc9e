// Cutter radius compensation (core/interp/cutter_comp.h, interp_comp.cpp):
// the integer geometry against double-precision oracles (a transcription
// of LinuxCNC's convert_straight_comp1/comp2 and its queue for polylines),
// the held records, atomic blocks, the tool table's radii, and each rule
// that refuses a code while compensation is on. The moves themselves are
// also checked against LinuxCNC's rs274 by tools/scripts/oracle-check.sh
// (tests/gcode/paths/comp_*.ngc).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/math/trig.h"
#include "core/interp/cutter_comp.h"
#include "core/interp/interp.h"
#include "tests/gcode_test_util.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;
using t::mm;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBamPerRad = 4294967296.0 / (2 * kPi);

// Runs a program afresh (the recorder is emptied first).
GcodeError run(const char* program, t::Recorder* rec, GcodeDiag* d, InterpOptions opt = {}) {
  rec->records.clear();
  Interp in(rec, opt);
  return t::run_program(&in, program, d);
}

// Tools 1..9 with diameter (tool) mm; tool 5 has diameter 6.35.
struct Table final : ToolTable {
  bool tool_length_nm(int32_t tool, int64_t* z) const override {
    *z = 0;
    return tool >= 1 && tool <= 9;
  }
  bool tool_radius_nm(int32_t tool, int64_t* r) const override {
    if (tool < 1 || tool > 9) return false;
    *r = tool == 5 ? 3175000 : mm(tool) / 2;
    return true;
  }
};

// ---- a double-precision model of LinuxCNC's compensation (interp_convert.cc
// convert_straight_comp1/comp2, convert_arc_comp1/comp2, interp_queue.cc),
// written from its rules for G1 lines and I/J arcs in G17.

struct DMove {
  bool arc;
  double x, y;    // end
  double cx, cy;  // arc centre
  int turn;
};

struct LcncComp {
  double r;
  int side;  // +1 left, -1 right
  double cx = 0, cy = 0, px = 0, py = 0;
  bool first = true;
  struct Q {
    DMove m;
    double dx, dy;  // lines: direction
    double sweep;   // arcs: sweep recorded (0: none)
  };
  std::vector<Q> q;
  double ex = 0, ey = 0;
  bool valid = false;
  std::vector<DMove> out;

  static double find_turn(double x1, double y1, double ccx, double ccy, int turn, double x2, double y2) {
    double a = std::atan2(y1 - ccy, x1 - ccx), b = std::atan2(y2 - ccy, x2 - ccx);
    if (turn > 0) {
      if (b <= a) b += 2 * kPi;
      return b - a + (turn - 1) * 2 * kPi;
    }
    if (a <= b) a += 2 * kPi;
    return b - a + (turn + 1) * 2 * kPi;
  }
  bool inside(int turn) const { return (side > 0 && turn > 0) || (side < 0 && turn < 0); }
  void set_endpoint(double x, double y) {
    ex = x;
    ey = y;
    valid = true;
  }
  void dequeue() {
    valid = false;
    for (const Q& e : q) out.push_back(e.m);
    q.clear();
  }
  bool move_end(double x, double y) {
    if (q.empty()) return true;
    for (Q& e : q) {
      if (e.m.arc) {
        if (e.sweep != 0 && valid &&
            std::fabs(find_turn(ex, ey, e.m.cx, e.m.cy, e.m.turn, x, y)) > std::fabs(e.sweep) + 0.0254)
          return false;
      } else if (valid && e.dx * (x - ex) + e.dy * (y - ey) < 0) {
        return false;
      }
      e.m.x = x;
      e.m.y = y;
    }
    dequeue();
    set_endpoint(x, y);
    return true;
  }
  bool front_arc() const { return !q.empty() && q.front().m.arc; }
  // Beta as LinuxCNC normalises it after its own subtraction.
  static double norm(double b) { return b > 1.5 * kPi ? b - 2 * kPi : b < -kPi / 2 ? b + 2 * kPi : b; }

  // One G1 to (x, y); false on LinuxCNC's error.
  bool line(double x, double y) {
    if (first) {
      if (std::hypot(x - cx, y - cy) <= r) return false;
      const double a = std::atan2(y - cy, x - cx) + side * kPi / 2;
      const double endx = x + r * std::cos(a), endy = y + r * std::sin(a);
      set_endpoint(cx, cy);
      q.push_back(Q{DMove{false, endx, endy, 0, 0, 0}, std::cos(a), std::sin(a), 0});
      first = false;
      cx = endx;
      cy = endy;
      px = x;
      py = y;
      return true;
    }
    if (x == px && y == py) return true;
    double theta = std::atan2(cy - py, cx - px), alpha = std::atan2(y - py, x - px), beta;
    const double gamma = side > 0 ? kPi / 2 : -kPi / 2;
    if (side > 0) {
      if (theta < alpha) theta += 2 * kPi;
      beta = theta - alpha - kPi / 2;
    } else {
      if (alpha < theta) alpha += 2 * kPi;
      beta = alpha - theta - kPi / 2;
    }
    const double endx = x + r * std::cos(alpha + gamma), endy = y + r * std::sin(alpha + gamma);
    const double midx = px + r * std::cos(alpha + gamma), midy = py + r * std::sin(alpha + gamma);
    const double small = 0.05;
    const bool concave = beta < -small || beta > kPi + small ||
                         (beta > kPi - small && front_arc() &&
                          ((side < 0 && q.front().m.turn > 0) || (side > 0 && q.front().m.turn < 0)));
    if (!concave && beta > small) {
      if (!move_end(cx, cy)) return false;
      out.push_back(DMove{true, midx, midy, px, py, side > 0 ? -1 : 1});
      set_endpoint(midx, midy);
    } else if (concave && !front_arc()) {
      const double retreat = r / std::tan((beta + kPi) / 2);
      if (!move_end(cx + retreat * std::cos(theta + gamma), cy + retreat * std::sin(theta + gamma))) return false;
    } else if (concave) {
      const DMove& prev = q.front().m;
      const double oldrad = std::hypot(prev.cy - prev.y, prev.cx - prev.x);
      const double th = prev.turn > 0 ? std::atan2(y - py, x - px) + kPi / 2 : std::atan2(y - py, x - px) - kPi / 2;
      const double phi = std::atan2(prev.cy - py, prev.cx - px);
      const bool in = inside(prev.turn);
      const double d = (in ? oldrad + r : oldrad - r) * std::cos(th - phi);
      const double l = (in ? d - r : d + r) / oldrad;
      if (l > 1 || l < -1) return false;
      const double ang = (in == (prev.turn > 0)) ? th + kPi - std::acos(l) : th + kPi + std::acos(l);
      if (!move_end(prev.cx + oldrad * std::cos(ang), prev.cy + oldrad * std::sin(ang))) return false;
    } else {
      dequeue();
      set_endpoint(cx, cy);
    }
    q.push_back(Q{DMove{false, endx, endy, 0, 0, 0}, x - px, y - py, 0});
    cx = endx;
    cy = endy;
    px = x;
    py = y;
    return true;
  }

  // One arc to (x, y) about (start + (i, j)), turn +1 (G3) or -1 (G2).
  bool arc(int turn, double x, double y, double i, double j) {
    const double sx = first ? cx : px, sy = first ? cy : py;
    const double ccx = sx + i, ccy = sy + j;
    const bool in = inside(turn);
    const double gamma = in ? std::atan2(ccy - y, ccx - x) : std::atan2(y - ccy, x - ccx);
    const double endx = x + r * std::cos(gamma), endy = y + r * std::sin(gamma);
    if (first) {
      if (std::hypot(x - cx, y - cy) <= r) return false;
      if (in && std::hypot(ccx - cx, ccy - cy) <= r) return false;
      const double b_len = std::hypot(cy - endy, cx - endx) / 2;
      const double ab = std::atan2(ccy - endy, ccx - endx);
      const double a = std::atan2(cy - endy, cx - endx) - ab;
      if (std::fabs(std::cos(a)) < 1e-4) return false;
      const double c_len = b_len / std::cos(a);
      const double ncx = endx + c_len * std::cos(ab), ncy = endy + c_len * std::sin(ab);
      q.push_back(Q{DMove{true, endx, endy, ncx, ncy, turn}, 0, 0, find_turn(cx, cy, ncx, ncy, turn, endx, endy)});
      first = false;
    } else {
      const double arc_radius = std::hypot(ccx - x, ccy - y);
      double theta = std::atan2(cy - py, cx - px);
      theta = side > 0 ? theta - kPi / 2 : theta + kPi / 2;
      double delta = std::atan2(ccy - py, ccx - px);
      const double alpha = turn > 0 ? delta - kPi / 2 : delta + kPi / 2;
      const double beta = norm(side > 0 ? theta - alpha : alpha - theta);
      if (in) {
        if (arc_radius <= r) return false;
      } else {
        delta += kPi;
      }
      const double small = 0.05;
      if (beta < -small || beta > kPi + small || (std::fabs(beta - kPi) < small && !in)) {
        double midx, midy;
        if (!front_arc()) {
          const double cyy = arc_radius * std::sin(beta - kPi / 2);
          const double dist = in ? arc_radius - r : arc_radius + r;
          const double l = (in ? cyy + r : cyy - r) / dist;
          if (l > 1 || l < -1) return false;
          const double ang = in ? (turn > 0 ? theta + std::asin(l) : theta - std::asin(l))
                                : (turn > 0 ? theta + kPi - std::asin(l) : theta + kPi + std::asin(l));
          midx = ccx + dist * std::cos(ang);
          midy = ccy + dist * std::sin(ang);
        } else {
          const DMove& prev = q.front().m;
          const double oldrad = std::hypot(prev.cy - prev.y, prev.cx - prev.x);
          const double newrad = in ? arc_radius - r : arc_radius + r;
          const double cc = std::hypot(prev.cy - ccy, prev.cx - ccx);
          if (oldrad == 0 || cc == 0) return false;
          const double a = (oldrad * oldrad + cc * cc - newrad * newrad) / (2 * oldrad * cc);
          if (a > 1 || a < -1) return false;
          const double pull = std::acos(a), dir = std::atan2(ccy - prev.cy, ccx - prev.cx);
          const double ang = (inside(prev.turn) == (turn > 0)) ? dir + pull : dir - pull;
          midx = prev.cx + oldrad * std::cos(ang);
          midy = prev.cy + oldrad * std::sin(ang);
        }
        if (!move_end(midx, midy)) return false;
      } else if (beta > small) {
        const double midx = px + r * std::cos(delta), midy = py + r * std::sin(delta);
        dequeue();
        out.push_back(DMove{true, midx, midy, px, py, side > 0 ? -1 : 1});
        set_endpoint(midx, midy);
      } else {
        dequeue();
        set_endpoint(cx, cy);
      }
      q.push_back(Q{DMove{true, endx, endy, ccx, ccy, turn}, 0, 0, find_turn(px, py, ccx, ccy, turn, x, y)});
    }
    cx = endx;
    cy = endy;
    px = x;
    py = y;
    return true;
  }
};

double nm_to_mm(int64_t v) { return static_cast<double>(v) * 1e-6; }

// "X1.2345 Y-3.4" for a point in mm with 4 decimals.
std::string xy(double x, double y) {
  char b[64];
  std::snprintf(b, sizeof b, "X%.4f Y%.4f", x, y);
  return b;
}

}  // namespace

TEST(comp_geometry_helpers_against_doubles) {
  t::Rng rng(21);
  double worst_polar = 0, worst_turn = 0, worst_asin = 0;
  for (int i = 0; i < 20000; ++i) {
    const int64_t r = rng.range(0, mm(1000));
    const uint32_t a = static_cast<uint32_t>(rng.next());
    const Vec2 p{rng.range(-mm(10000), mm(10000)), rng.range(-mm(10000), mm(10000))};
    const Vec2 q = comp_polar(p, r, a);
    const double t = a / kBamPerRad;
    const double ex = p.a + r * std::cos(t), ey = p.b + r * std::sin(t);
    const double err = std::hypot(q.a - ex, q.b - ey) - 1e-8 * r;
    worst_polar = std::max(worst_polar, err);
    // find_turn: the sweep from s to e around c, 1 to 3 turns either way.
    const Vec2 c{rng.range(-mm(100), mm(100)), rng.range(-mm(100), mm(100))};
    const Vec2 s{c.a + rng.range(-mm(50), mm(50)), c.b + rng.range(-mm(50), mm(50))};
    const Vec2 e{c.a + rng.range(-mm(50), mm(50)), c.b + rng.range(-mm(50), mm(50))};
    const int32_t turn = static_cast<int32_t>(rng.range(1, 3)) * (rng.next() & 1 ? 1 : -1);
    double al = std::atan2(static_cast<double>(s.b - c.b), static_cast<double>(s.a - c.a));
    double be = std::atan2(static_cast<double>(e.b - c.b), static_cast<double>(e.a - c.a));
    double want;
    if (turn > 0) {
      if (be <= al) be += 2 * kPi;
      want = be - al + (turn - 1) * 2 * kPi;
    } else {
      if (al <= be) al += 2 * kPi;
      want = be - al + (turn + 1) * 2 * kPi;
    }
    worst_turn = std::max(worst_turn, std::fabs(comp_find_turn(s, c, turn, e) - want * kBamPerRad));
    // asin and acos of a ratio.
    const int64_t den = rng.range(1, mm(1000)), num = rng.range(-den, den);
    const double ratio = static_cast<double>(num) / static_cast<double>(den);
    const double da = std::fabs(static_cast<int32_t>(comp_asin_bam(num, den) - static_cast<uint32_t>(static_cast<int64_t>(std::llround(std::asin(ratio) * kBamPerRad)))));
    const double dc = std::fabs(static_cast<int32_t>(comp_acos_bam(num, den) - static_cast<uint32_t>(static_cast<int64_t>(std::llround(std::acos(ratio) * kBamPerRad)))));
    worst_asin = std::max(worst_asin, std::max(da, dc));
    // The sign of a dot product, exact.
    const int64_t a1 = rng.range(-mm(20000), mm(20000)), b1 = rng.range(-mm(20000), mm(20000));
    const int64_t a2 = rng.range(-mm(20000), mm(20000)), b2 = rng.range(-mm(20000), mm(20000));
    const __int128 dot = static_cast<__int128>(a1) * a2 + static_cast<__int128>(b1) * b2;
    CHECK_EQ(comp_dot_sign(a1, b1, a2, b2), dot > 0 ? 1 : dot < 0 ? -1 : 0);
  }
  std::printf("  comp geometry: polar %.2f nm past 1e-8 r, find_turn %.1f bam, asin/acos %.1f bam\n", worst_polar,
              worst_turn, worst_asin);
  CHECK_LE(worst_polar, 1.0);
  CHECK_LE(worst_turn, 4.0);
  CHECK_LE(worst_asin, 3.0);
  CHECK_EQ(comp_dot_sign(0, 5, 7, 0), 0);
  CHECK_EQ(comp_dot_sign(INT64_MAX, -INT64_MAX, INT64_MAX, INT64_MAX), 0);
}

// Random paths of lines and arcs compensated left and right with
// G41.1/G42.1: every move end and arc centre as the double model of
// LinuxCNC's code has them, and the same errors on the same lines.
TEST(comp_paths_against_double_oracle) {
  t::Rng rng(4121);
  double worst = 0, worst_entry = 0;
  int compared = 0, refused = 0, arcs = 0;
  auto coord = [&rng](int64_t lo, int64_t hi) { return rng.range(lo * 10000, hi * 10000) / 10000.0; };
  for (int iter = 0; iter < 4000; ++iter) {
    const int side = rng.next() & 1 ? 1 : -1;
    const double r = rng.range(5, 800) / 100.0;  // 0.05 .. 8 mm
    double x = coord(-50, 50), y = coord(-50, 50);
    std::string prog = "G21 G90 G17 F100\nG0 " + xy(x, y) + "\n";
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s D%.2f\n", side > 0 ? "G41.1" : "G42.1", 2 * r);
    prog += buf;
    LcncComp lc;
    lc.r = r;
    lc.side = side;
    lc.cx = lc.px = x;
    lc.cy = lc.py = y;
    const int n = static_cast<int>(rng.range(2, 8));
    const bool lines_only = iter % 2 == 0;
    int want_err_line = 0;
    for (int k = 0; k < n; ++k) {
      bool ok;
      if (lines_only || rng.next() % 2) {
        x = coord(-50, 50);
        y = coord(-50, 50);
        prog += "G1 " + xy(x, y) + "\n";
        ok = want_err_line || lc.line(x, y);
      } else {
        // An arc of radius 2 to 25 mm from here, sweeping 0.2 to 5.5 rad.
        const int turn = rng.next() % 2 ? 1 : -1;
        const double rad = rng.range(200, 2500) / 100.0, a0 = rng.range(0, 6283) / 1000.0;
        const double sweep = rng.range(200, 5500) / 1000.0 * turn;
        const double i = std::round(-rad * std::cos(a0) * 10000) / 10000, j = std::round(-rad * std::sin(a0) * 10000) / 10000;
        const double ex = std::round((x + i + rad * std::cos(a0 + sweep)) * 10000) / 10000;
        const double ey = std::round((y + j + rad * std::sin(a0 + sweep)) * 10000) / 10000;
        std::snprintf(buf, sizeof buf, "G%d %s I%.4f J%.4f\n", turn > 0 ? 3 : 2, xy(ex, ey).c_str(), i, j);
        prog += buf;
        ok = want_err_line || lc.arc(turn, ex, ey, i, j);
        x = ex;
        y = ey;
      }
      if (!ok) want_err_line = 4 + k;
    }
    prog += "M2\n";
    if (!want_err_line && !lc.move_end(lc.cx, lc.cy)) want_err_line = 4 + n;
    t::Recorder rec;
    GcodeDiag d{};
    const GcodeError e = run(prog.c_str(), &rec, &d);
    if (want_err_line) {
      ++refused;
      if (!CHECK(e != GcodeError::kOk) || !CHECK_EQ(d.line, static_cast<uint32_t>(want_err_line)))
        std::printf("%s", prog.c_str());
      continue;
    }
    if (!CHECK_EQ(e, GcodeError::kOk)) {
      std::printf("%s", prog.c_str());
      continue;
    }
    std::vector<const CanonRecord*> moves;
    for (const CanonRecord& m : rec.records)
      if (m.line >= 4 && (m.kind == CanonKind::kFeed || m.kind == CanonKind::kArc)) moves.push_back(&m);
    if (!CHECK_EQ(moves.size(), lc.out.size())) continue;
    ++compared;
    for (size_t i = 0; i < moves.size(); ++i) {
      const DMove& w = lc.out[i];
      CHECK_EQ(moves[i]->kind == CanonKind::kArc, w.arc);
      const double ee = std::hypot(nm_to_mm(moves[i]->end.x_nm) - w.x, nm_to_mm(moves[i]->end.y_nm) - w.y);
      worst = std::max(worst, ee);
      if (w.arc) {
        ++arcs;
        CHECK_EQ(moves[i]->arc.turns, w.turn);
        const double ce = std::hypot(nm_to_mm(moves[i]->arc.centre.x_nm) - w.cx, nm_to_mm(moves[i]->arc.centre.y_nm) - w.cy);
        // The entry arc's new centre may lie far off (ill-conditioned as
        // LinuxCNC's own): its error is relative to the radius.
        if (moves[i]->line == 4) worst_entry = std::max(worst_entry, ce / std::hypot(w.x - w.cx, w.y - w.cy));
        else worst = std::max(worst, ce);
      }
    }
  }
  std::printf("  comp paths: %d compared (%d arcs), %d refused alike, worst %.1f nm, entry arc centres %.2g R\n",
              compared, arcs, refused, worst * 1e6, worst_entry);
  CHECK_GT(compared, 1500);
  CHECK_GT(refused, 500);
  // cutter_comp.h's bounds: ends met on a held arc come within a few nm
  // over the sine of the corner's angle (>= 0.05 rad for a concave one).
  CHECK_LE(worst * 1e6, 50.0);
  CHECK_LE(worst_entry, 2e-6);
}

TEST(comp_holds_the_last_move_until_the_next_fixes_the_corner) {
  t::Recorder rec;
  Interp in(&rec, InterpOptions{});
  GcodeDiag d;
  const char* lines[] = {"G21 G90 F100", "G41.1 D2", "G1 X10 Y0", "G1 Z-1", "M8", "G1 X10 Y-10"};
  for (uint32_t i = 0; i < 5; ++i) CHECK_EQ(in.execute_line(lines[i], std::strlen(lines[i]), i + 1, &d), GcodeError::kOk);
  // The entry move, the Z move and the coolant wait for the corner.
  CHECK_EQ(rec.records.size(), 0u);
  CHECK_EQ(in.execute_line(lines[5], std::strlen(lines[5]), 6, &d), GcodeError::kOk);
  // Left of X+ then Y-: a convex corner at (10, 0). The entry ends at
  // (10, 1) (the left normal of the entry), the Z move follows it, then
  // the arc round the corner to (11, 0); the new line is held.
  if (CHECK_EQ(rec.records.size(), 4u)) {
    CHECK(rec.records[0].end == (PointNm{mm(10), mm(1), 0}));
    CHECK(rec.records[1].start == rec.records[0].end);
    CHECK(rec.records[1].end == (PointNm{mm(10), mm(1), mm(-1)}));
    CHECK_EQ(rec.records[2].kind, CanonKind::kCoolant);
    CHECK_EQ(rec.records[3].kind, CanonKind::kArc);
    CHECK(rec.records[3].end == (PointNm{mm(11), 0, mm(-1)}));
    CHECK(rec.records[3].arc.centre == (PointNm{mm(10), 0, mm(-1)}));
    CHECK_EQ(rec.records[3].arc.turns, -1);
  }
  // The end of the input lets the held line go.
  in.end_of_input(6);
  if (CHECK_EQ(rec.records.size(), 5u)) CHECK(rec.records[4].end == (PointNm{mm(11), mm(-10), mm(-1)}));
  // The position the interpreter reports is the tool's; the programmed
  // point is kept apart.
  CHECK(in.position() == (PointNm{mm(11), mm(-10), mm(-1)}));
  CHECK(in.state().comp.prog == (PointNm{mm(10), mm(-10), mm(-1)}));
}

TEST(comp_exit_move_starts_from_the_tool) {
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G21 G90 F100\nG41.1 D2\nG1 X10 Y0\nG40\nG1 X20 Y0\nG91 G1 X1\nM2", &rec, &d), GcodeError::kOk);
  // G40: the entry goes as it is (to (10, 1)); the exit starts there and
  // ends at the programmed point; incremental moves count from it.
  if (CHECK_EQ(rec.count(CanonKind::kFeed), 3u)) {
    CHECK(rec.records[0].end == (PointNm{mm(10), mm(1), 0}));
    CHECK(rec.records[1].start == (PointNm{mm(10), mm(1), 0}));
    CHECK(rec.records[1].end == (PointNm{mm(20), 0, 0}));
    CHECK(rec.records[2].end == (PointNm{mm(21), 0, 0}));
  }
  // An arc right after G40 is refused, a line first makes it fine.
  CHECK_EQ(run("G21 F100\nG41.1 D2\nG1 X10\nG40\nG2 X20 R5", &rec, &d), GcodeError::kCompArcAfterExit);
  CHECK_EQ(d.line, 5u);
  CHECK_EQ(run("G21 F100\nG41.1 D2\nG1 X10\nG40\nG1 X11\nG2 X20 R5", &rec, &d), GcodeError::kOk);
  // G40 before any compensated move, or with radius 0, changes nothing.
  CHECK_EQ(run("G21 F100\nG41.1 D2\nG40\nG2 X20 R15", &rec, &d), GcodeError::kOk);
}

// A bad block emits nothing and changes nothing, the held move included:
// the program after it runs as if the bad line were not there.
TEST(comp_bad_block_changes_nothing) {
  // Line 7 turns left by 139 degrees after a held line 2 mm long (3 mm
  // programmed, 1 of them taken by the corner before): the corner would
  // need it backed up by 2.7 mm.
  const char* with_bad = "G21 G90 F100\nG0 X-10\nG41.1 D2\nG1 X0 Y0\nG1 X20\nG1 Y3\nG1 X17 Y-0.5\nG1 X30 Y3\nM2";
  const char* without = "G21 G90 F100\nG0 X-10\nG41.1 D2\nG1 X0 Y0\nG1 X20\nG1 Y3\n\nG1 X30 Y3\nM2";
  t::Recorder a, b;
  Interp ia(&a, InterpOptions{}), ib(&b, InterpOptions{});
  uint32_t errors = interp_run_text(&ia, with_bad, std::strlen(with_bad), nullptr);
  CHECK_EQ(errors, 1u);
  CHECK_EQ(interp_run_text(&ib, without, std::strlen(without), nullptr), 0u);
  if (CHECK_EQ(a.records.size(), b.records.size()))
    for (size_t i = 0; i < a.records.size(); ++i) CHECK(a.records[i].end == b.records[i].end);
  GcodeDiag d;
  t::Recorder rec;
  CHECK_EQ(run(with_bad, &rec, &d), GcodeError::kCompConcaveStraight);
  CHECK_EQ(d.line, 7u);
}

TEST(comp_queue_capacity_is_named) {
  std::string prog = "G21 F100\nG41.1 D2\nG1 X10\n";
  for (int i = 0; i < kCompQueueMax - 1; ++i) prog += i % 2 ? "G1 Z1\n" : "G1 Z0\n";
  std::string ok = prog + "G1 Y10\nM2";
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run(ok.c_str(), &rec, &d), GcodeError::kOk);
  CHECK_EQ(rec.count(CanonKind::kFeed), static_cast<size_t>(kCompQueueMax + 1));
  std::string full = prog + "G1 Z2\nG1 Y10\nM2";
  CHECK_EQ(run(full.c_str(), &rec, &d), GcodeError::kCompQueueFull);
  CHECK_EQ(d.line, static_cast<uint32_t>(3 + kCompQueueMax));
  char msg[300];
  gcode_format_message(d, msg, sizeof msg);
  CHECK(std::strstr(msg, "16") != nullptr);
}

TEST(comp_radius_from_the_tool_table) {
  Table table;
  InterpOptions opt;
  opt.tools = &table;
  t::Recorder rec;
  GcodeDiag d;
  // D names the tool: tool 4 is 4 mm across.
  CHECK_EQ(run("G21 F100\nG41 D4\nG1 X10 Y0\nM2", &rec, &d, opt), GcodeError::kOk);
  CHECK(rec.records[0].end == (PointNm{mm(10), mm(2), 0}));
  // No D, or D0: the tool in the spindle.
  CHECK_EQ(run("G21 F100\nT6 M6\nG42\nG1 X10 Y0\nM2", &rec, &d, opt), GcodeError::kOk);
  CHECK(rec.records[1].end == (PointNm{mm(10), mm(-3), 0}));
  CHECK_EQ(run("G21 F100\nT5 M6\nG42 D0\nG1 X10 Y0\nM2", &rec, &d, opt), GcodeError::kOk);
  CHECK(rec.records[1].end == (PointNm{mm(10), -3175000, 0}));
  // Nothing in the spindle: radius 0, the moves as programmed.
  CHECK_EQ(run("G21 F100\nG41\nG1 X10 Y0\nM2", &rec, &d, opt), GcodeError::kOk);
  CHECK(rec.records[0].end == (PointNm{mm(10), 0, 0}));
  CHECK_EQ(run("G21\nG41 D12", &rec, &d, opt), GcodeError::kToolUnknown);
  CHECK_EQ(d.col, 5);
  CHECK_EQ(run("G21\nG41 D1.5", &rec, &d, opt), GcodeError::kNotInteger);
  CHECK_EQ(run("G21\nG41 D1.00001", &rec, &d, opt), GcodeError::kOk);  // LinuxCNC: within 1e-4
  CHECK_EQ(run("G21\nG41 D-1", &rec, &d, opt), GcodeError::kNegativeValue);
  CHECK_EQ(run("G21\nG1 X1 D1 F1", &rec, &d, opt), GcodeError::kWordUnused);
  // Without a table: radius 0, one warning.
  t::Warnings w;
  InterpOptions bare;
  bare.warnings = &w;
  CHECK_EQ(run("G21 F100\nG41 D3\nG1 X10 Y0\nG40\nG42 D3\nG1 X20\nM2", &rec, &d, bare), GcodeError::kOk);
  CHECK(rec.records[0].end == (PointNm{mm(10), 0, 0}));
  size_t warned = 0;
  for (const GcodeDiag& g : w.list) warned += g.code == GcodeError::kWarnCompNoTable;
  CHECK_EQ(warned, 1u);
}

TEST(comp_on_refuses_what_linuxcnc_refuses) {
  struct Case {
    const char* line;
    GcodeError e;
    uint16_t col;
  };
  const Case cases[] = {
      {"G42.1 D2", GcodeError::kCompOnWhenOn, 1},     {"G18", GcodeError::kCompChangePlane, 1},
      {"G19", GcodeError::kCompChangePlane, 1},       {"G55", GcodeError::kCompForbidden, 1},
      {"G54", GcodeError::kCompForbidden, 1},         {"G43 H1", GcodeError::kCompForbidden, 1},
      {"G49", GcodeError::kCompForbidden, 1},         {"G64 P0.1", GcodeError::kCompForbidden, 1},
      {"G61", GcodeError::kCompForbidden, 1},         {"G98", GcodeError::kCompForbidden, 1},
      {"G99", GcodeError::kCompForbidden, 1},         {"G92 X0", GcodeError::kCompForbidden, 1},
      {"G92.1", GcodeError::kCompForbidden, 1},       {"G28", GcodeError::kCompForbidden, 1},
      {"G30 Z5", GcodeError::kCompForbidden, 1},      {"G28.1", GcodeError::kCompForbidden, 1},
      {"G10 L2 P1 X1", GcodeError::kCompForbidden, 1}, {"G10 L20 P0 X1", GcodeError::kCompForbidden, 1},
      {"G53 G1 X5", GcodeError::kCompForbidden, 1},   {"G38.2 Z-5", GcodeError::kCompForbidden, 1},
      {"G81 X0 Y0 Z-1 R1", GcodeError::kCompForbidden, 1}, {"T2 M6", GcodeError::kCompForbidden, 4},
      {"M62 P1", GcodeError::kCompForbidden, 1},      {"M48", GcodeError::kCompForbidden, 1},
      {"G40 G18", GcodeError::kCompChangePlane, 5},  // LinuxCNC sets the plane before it reads G40
  };
  for (const Case& c : cases) {
    const std::string prog = std::string("G21 G17 F100\nG41.1 D2\nG1 X10\n") + c.line;
    t::Recorder rec;
    GcodeDiag d;
    if (!CHECK_EQ(run(prog.c_str(), &rec, &d), c.e) || !CHECK_EQ(d.col, c.col)) std::printf("  %s\n", c.line);
    CHECK_EQ(d.line, 4u);
  }
  // Allowed: another system's G10, the plane in force, G43 or G55 in the
  // block that says G40 (LinuxCNC turns it off first), M61.
  const char* fine[] = {"G10 L2 P2 X1", "G17", "G40 G43 H0", "G40 G55", "M61 Q3"};
  for (const char* line : fine) {
    const std::string prog = std::string("G21 G17 F100\nG41.1 D2\nG1 X10\n") + line;
    t::Recorder rec;
    GcodeDiag d;
    if (!CHECK_EQ(run(prog.c_str(), &rec, &d), GcodeError::kOk)) std::printf("  %s\n", line);
  }
  // Turning it on: only in G17 and G18; G41.1/G42.1 need D; L is a lathe's.
  t::Recorder rec;
  GcodeDiag d;
  CHECK_EQ(run("G19\nG41.1 D2", &rec, &d), GcodeError::kCompPlane);
  CHECK_EQ(run("G18\nG41.1 D2", &rec, &d), GcodeError::kOk);
  CHECK_EQ(run("G41.1", &rec, &d), GcodeError::kCompNoD);
  CHECK_EQ(run("G41.1 D2 L3", &rec, &d), GcodeError::kUnsupportedCompOrientation);
  // M2 turns it off.
  Interp in(&rec, InterpOptions{});
  CHECK_EQ(t::run_program(&in, "G21 F100\nG41.1 D2\nG1 X10\nM2", &d), GcodeError::kOk);
  CHECK_EQ(in.state().comp.side, 0);
}
