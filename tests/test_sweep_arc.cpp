// core/cut/sweep_arc.cpp and core/cut/mill.h: arcs against a double oracle, and the
// golden grid hashes of a G-code program of lines, ramps, arcs and helices
// cut through the interpreter and the Mill in both modes.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/cut/mill.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/tool/tool.h"
#include "tests/alloc_count.h"
#include "tests/cut_fixtures.h"
#include "tests/golden_check.h"
#include "tests/runner.h"
#include "tests/sweep_oracle.h"

using namespace dexmill;

namespace {

using fixtures::arc_record;
using fixtures::mm;
const double kPi = 3.14159265358979323846;

Tool tool_of(ToolKind k, int64_t d, int64_t rc = 0, int32_t mdeg = 0) { return fixtures::test_tool(k, d, rc, mdeg, mm(60)); }

// Lowest tool point over a (helical) arc by dense sampling plus ternary
// refinement around the best sample, nm; HUGE_VAL if out of reach.
double oracle_arc(const Tool& t, double cx, double cy, double ra, double a0, double sweep, double z0, double z1,
                  double px, double py) {
  const double R = double(t.diameter_nm / 2);
  auto g = [&](double s) {
    const double a = a0 + s * sweep;
    const double r = std::hypot(px - (cx + ra * std::cos(a)), py - (cy + ra * std::sin(a)));
    if (r > R) return HUGE_VAL;
    return z0 + s * (z1 - z0) + oracle::profile_nm(t, r);
  };
  const int n = 2000;
  int best = -1;
  double bv = HUGE_VAL;
  for (int k = 0; k <= n; ++k) {
    double v = g(double(k) / n);
    if (v < bv) { bv = v; best = k; }
  }
  if (best < 0) return HUGE_VAL;
  // Refine densely around the best sample (the minimum may sit on the edge
  // of the reach window, where g jumps to "out of reach"), then by thirds.
  double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
  double bs = double(best) / n;
  for (int k = 0; k <= 1000; ++k) {
    const double s = lo + (hi - lo) * k / 1000;
    const double v = g(s);
    if (v < bv) { bv = v; bs = s; }
  }
  lo = std::max(0.0, bs - (hi - lo) / 1000);
  hi = std::min(1.0, bs + (hi - lo) / 1000);
  for (int it = 0; it < 60; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (g(m1) <= g(m2)) hi = m2; else lo = m1;
  }
  return std::min(bv, g((lo + hi) / 2));
}

// Highest tip height over the positions of the arc that reach (px, py), nm,
// or -HUGE_VAL: z is monotonic in the angle, so the last (or first) reaching
// sample, refined by bisection to the edge of the reach window.
double oracle_arc_highest(const Tool& t, double cx, double cy, double ra, double a0, double sweep, double z0,
                          double z1, double px, double py) {
  const double R = double(t.diameter_nm / 2);
  auto reaches = [&](double s) {
    const double a = a0 + s * sweep;
    return std::hypot(px - (cx + ra * std::cos(a)), py - (cy + ra * std::sin(a))) <= R;
  };
  const bool rising = z1 > z0;
  const int n = 4000;
  for (int k = 0; k <= n; ++k) {
    const int kk = rising ? n - k : k;
    if (!reaches(double(kk) / n)) continue;
    if (k == 0) return rising ? z1 : z0;
    double in = double(kk) / n, out = double(rising ? kk + 1 : kk - 1) / n;
    for (int it = 0; it < 60; ++it) {
      const double mid = (in + out) / 2;
      (reaches(mid) ? in : out) = mid;
    }
    return z0 + in * (z1 - z0);
  }
  return -HUGE_VAL;
}

// 64 x 64 dexels of 0.25 mm, LSB 0.5 um, 30 mm of material.
struct ArcGrid : fixtures::TestGrid<uint16_t> {
  ArcGrid() : fixtures::TestGrid<uint16_t>(64, 64, 250000, 500) { fill(mm(30)); }
};

// Backward bound of sweep.h, widened to the chord bound (1 um) when the arc
// is cut as chords.
// A sweep past a full turn becomes a record of several turns (G2/G3 P):
// |turns| = ceil(|sweep| / 2 pi).
CanonRecord turns_record(double cx, double cy, double ra, double a0, double sweep, double z0, double z1) {
  CanonRecord r = arc_record(cx, cy, ra, a0, sweep, z0, z1);
  const int32_t n = static_cast<int32_t>(std::ceil(std::fabs(sweep) / (2 * M_PI) - 1e-12));
  r.arc.turns = sweep > 0 ? n : -n;
  return r;
}

int check_arc(const Tool& tool, const char* name, double cx, double cy, double ra, double a0, double sweep, double z0,
              double z1, double slack_nm) {
  ArcGrid ag;
  SweepTool swt;
  sweep_tool_prepare(tool_profile(tool), 500, &swt);
  CutStats st;
  sweep_arc(&ag.g, swt, turns_record(cx, cy, ra, a0, sweep, z0, z1), &st);
  int bad = 0;
  for (int32_t j = 0; j < 64; ++j) {
    for (int32_t i = 0; i < 64; ++i) {
      const double px = i * 250000.0, py = j * 250000.0;
      const double got = ag.top[ag.g.index(i, j)];
      // Far from the circle: untouched. Otherwise the oracle at the column,
      // and only when that disagrees, at the displaced columns too.
      const double R = double(tool.diameter_nm / 2), rho = std::hypot(px - cx, py - cy);
      if (std::fabs(rho - ra) > R + 2 * slack_nm) {
        if (got != 60000 && ++bad <= 3) std::printf("  arc %s: dexel (%d,%d) out of reach but cut\n", name, i, j);
        continue;
      }
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (auto& o : oracle::kNeighbours) {
        if (&o != &oracle::kNeighbours[0] && lo - 1.0 <= got && got <= hi + 1.0) break;
        double h = oracle_arc(tool, cx, cy, ra, a0, sweep, z0, z1, px + o[0] * slack_nm, py + o[1] * slack_nm);
        double l = h == HUGE_VAL ? 60000.0 : std::min(60000.0, h / 500.0);
        lo = std::min(lo, l);
        hi = std::max(hi, l);
      }
      if ((got < lo - 1.0 || got > hi + 1.0) && ++bad <= 3)
        std::printf("  arc %s: dexel (%d,%d) top %.0f oracle [%.3f, %.3f] (ra %.0f a0 %.3f sweep %.3f z %.0f z1 %.0f)\n", name, i,
                    j, got, lo, hi, ra, a0, sweep, z0, z1);
    }
  }
  return bad;
}

}  // namespace

TEST(sweep_arc_level_exact_against_oracle) {
  std::mt19937_64 rng(77);
  const Tool tools[] = {tool_of(ToolKind::kBall, mm(6)), tool_of(ToolKind::kFlat, mm(4)),
                        tool_of(ToolKind::kBall, 3175000)};
  const char* names[] = {"ball6", "flat4", "ball3.175"};
  int bad = 0;
  for (int t = 0; t < 3; ++t) {
    for (int it = 0; it < 6; ++it) {
      const double ra = 1e6 + double(rng() % 5000000), a0 = double(rng() % 6283) / 1000.0;
      const double sweep = (it % 2 ? -1.0 : 1.0) * (0.3 + double(rng() % 5000) / 1000.0);
      const double z = 5e6 + double(rng() % 10000000);
      bad += check_arc(tools[t], names[t], 8e6, 8e6, ra, a0, sweep, z, z, 1.0);
    }
  }
  CHECK_EQ(bad, 0);
}

TEST(sweep_arc_helix_exact_against_oracle) {
  // Helices of a ball or flat end wider than the tool's radius are exact per
  // column too: the backward bound (1 LSB for the column moved by 1-2 nm),
  // not the chords' 1 um. A helical bore
  // (radius below the tool's) is chorded: the 1 um bound.
  std::mt19937_64 rng(78);
  const Tool tools[] = {tool_of(ToolKind::kBall, mm(6)), tool_of(ToolKind::kFlat, mm(4)),
                        tool_of(ToolKind::kBall, 3175000), tool_of(ToolKind::kFlat, mm(8))};
  const char* names[] = {"ball6-helix", "flat4-helix", "ball3.175-helix", "flat8-helix-bore (chords)"};
  int bad = 0;
  for (int t = 0; t < 4; ++t) {
    for (int it = 0; it < 4; ++it) {
      const double ra = (t == 3 ? 1e6 : 3.6e6) + double(rng() % 3000000), a0 = double(rng() % 6283) / 1000.0;
      const double sweep = (it % 2 ? -1.0 : 1.0) * (0.5 + double(rng() % 5500) / 1000.0);
      const double z0 = 8e6 + double(rng() % 6000000), z1 = z0 + (it < 2 ? -1.0 : 1.0) * double(rng() % 4000000);
      bad += check_arc(tools[t], names[t], 8e6, 8e6, ra, a0, sweep, z0, z1, t == 3 ? 1500.0 : 2.0);
    }
  }
  CHECK_EQ(bad, 0);
}

TEST(sweep_arc_helix_of_many_turns_cuts_its_dominant_turn) {
  // A helix of several turns about Z cuts what its last turn
  // (descending; ascending: its first) cuts, every other position having
  // a twin one turn away, lower: exact against the oracle over the whole
  // path, descending, ascending and level, ending on the start's angle or
  // not; and its cost is one turn's, whatever the turns.
  std::mt19937_64 rng(79);
  const Tool tools[] = {tool_of(ToolKind::kBall, mm(6)), tool_of(ToolKind::kFlat, mm(4))};
  int bad = 0;
  for (int t = 0; t < 2; ++t)
    for (int it = 0; it < 6; ++it) {
      const double ra = 3.6e6 + double(rng() % 3000000), a0 = double(rng() % 6283) / 1000.0;
      const double turns = 2 + it / 2 + (it % 2 ? 0.0 : double(rng() % 900) / 1000.0);
      const double sweep = (it % 3 == 1 ? -1.0 : 1.0) * 2 * M_PI * turns;
      const double z0 = 12e6 + double(rng() % 4000000);
      const double z1 = it % 3 == 2 ? z0 : z0 + (it % 2 ? 1.0 : -1.0) * (1e6 + double(rng() % 5000000));
      bad += check_arc(tools[t], t ? "flat4-turns" : "ball6-turns", 8e6, 8e6, ra, a0, sweep, z0, z1, 2.0);
    }
  CHECK_EQ(bad, 0);
  // The cost: a thousand turns visit what two do.
  uint64_t visits[2];
  for (int k = 0; k < 2; ++k) {
    ArcGrid ag;
    SweepTool swt;
    sweep_tool_prepare(tool_profile(tools[0]), 500, &swt);
    CutStats st;
    sweep_arc(&ag.g, swt, turns_record(8e6, 8e6, 5e6, 0, 2 * M_PI * (k ? 1000 : 2), 20e6, 10e6), &st);
    visits[k] = st.dexel_updates + st.instances;
  }
  CHECK_EQ(visits[0], visits[1]);
}

TEST(sweep_arc_visits_only_the_ring_within_reach) {
  // A piece visits the columns within reach, not the box around
  // it. Here the quarter turns' boxes held 2.6 times the columns within
  // reach (a helix piece took the whole circle's box: 7.3 times). A piece
  // now visits its box's part of the ring [ra - R, ra + R]: the box reaches
  // R past each end, an angle of about R / ra, so a quarter turn visits
  // 1 + 4 R / (pi ra) = 1.38 times its share (1.43 measured on this grid).
  // Every column within reach must be visited.
  const Tool ball = tool_of(ToolKind::kBall, mm(6));
  const double cx = 16e6, cy = 16e6, ra = 10e6, R = 3e6, sweep = 6.2;
  struct Case {
    const char* name;
    double z0, z1;
  };
  const Case cases[] = {{"level", 20e6, 20e6}, {"helix", 24e6, 16e6}};
  for (const Case& c : cases) {
    fixtures::TestGrid<uint16_t> tg(128, 128, 250000, 500);
    tg.fill(mm(30));
    SweepTool swt;
    sweep_tool_prepare(tool_profile(ball), 500, &swt);
    std::vector<DexelSpan> spans(1 << 14);
    SpanLog log;
    log.spans = spans.data();
    log.capacity = spans.size();
    CutStats st;
    st.log = &log;
    sweep_arc(&tg.g, swt, arc_record(cx, cy, ra, 0.3, sweep, c.z0, c.z1), &st);
    CHECK_EQ(log.dropped, uint64_t{0});
    std::vector<int> seen(128 * 128, 0);
    for (size_t k = 0; k < log.count; ++k)
      for (int32_t i = spans[k].i0; i <= spans[k].i1; ++i) ++seen[static_cast<size_t>(spans[k].j) * 128 + i];
    // Columns within reach of the arc (double oracle: the nearest point of
    // the sector, else the nearer end).
    uint64_t in_reach = 0;
    int missed = 0;
    for (int32_t j = 0; j < 128; ++j) {
      for (int32_t i = 0; i < 128; ++i) {
        const double px = i * 250000.0 - cx, py = j * 250000.0 - cy;
        double a = std::atan2(py, px) - 0.3;
        while (a < 0) a += 2 * kPi;
        const double rho = std::hypot(px, py);
        double d = std::fabs(rho - ra);
        if (a > sweep) {
          const double d0 = std::hypot(px - ra * std::cos(0.3), py - ra * std::sin(0.3));
          const double d1 = std::hypot(px - ra * std::cos(0.3 + sweep), py - ra * std::sin(0.3 + sweep));
          d = std::min(d0, d1);
        }
        if (d > R) continue;
        ++in_reach;
        if (seen[static_cast<size_t>(j) * 128 + i] == 0 && ++missed <= 3)
          std::printf("  %s: column (%d,%d) within reach (%.0f nm) but not visited\n", c.name, i, j, d);
      }
    }
    CHECK_EQ(missed, 0);
    const double ratio = double(st.dexel_updates) / double(in_reach);
    std::printf("  %s: %llu visits for %llu columns within reach (%.2fx)\n", c.name,
                static_cast<unsigned long long>(st.dexel_updates), static_cast<unsigned long long>(in_reach), ratio);
    CHECK(ratio >= 1.0);
    CHECK(ratio < 1.5);
  }
}

TEST(sweep_arc_helix_buried_shaft_cuts_to_its_highest_top) {
  // A 10 mm tool spiralling down from 5 mm to 15 mm below the floor of 8 mm
  // of stock: its shaft top passes the stock's top and its floor, and each
  // column's interval reaches the shaft top of the highest position over it
  // (core/cut/sweep_arc.cpp), not of the helix's lower end. Exact helices (ball,
  // flat): quarter-turn pieces, each cut as one union. The stock is thinner
  // than the tool is long, so no piece's tool is buried inside a dexel
  // (figure 2's case d, which leaves it as it was): then the pieces' cuts
  // add up to the union of the whole helix (core/cut/sweep.h). Chords (other
  // shapes) are pieces too, but their cuts are figure 2 applied chord by
  // chord, like stamping's instances, and at the rim they do not add up to
  // this oracle's single interval. Under 3/4 of a turn, so that no column
  // is reached twice (the oracle's one interval a column).
  const double cx = 8e6, cy = 8e6, ra = 5e6, a0 = 0.3, len = 10e6;
  int bad = 0, cases[4] = {0, 0, 0, 0};
  for (ToolKind k : {ToolKind::kBall, ToolKind::kFlat}) {
    for (double sweep : {4.5, -4.5}) {
      const Tool tool = fixtures::test_tool(k, mm(6), 0, 90000, int64_t(len));
      ArcGrid ag;
      ag.fill(mm(8));
      SweepTool swt;
      CHECK_EQ(sweep_tool_prepare(tool_profile(tool), 500, &swt), Status::kOk);
      CutStats st;
      const double z0 = 5e6, z1 = -15e6;
      sweep_arc(&ag.g, swt, arc_record(cx, cy, ra, a0, sweep, z0, z1), &st);
      // The oracle only near the circle (the band of reach), and not within
      // 10 nm of its rim, where sampling misses the tool's grazing touch.
      bad += oracle::check_figure2_grid(
          64, 64, 250000.0, 500.0, ag.top.data(), ag.bottom.data(), oracle::Dexel{double(ag.stock_lsb), 0}, len,
          2.0, [&](double x, double y) {
            const double d = std::fabs(std::hypot(x - cx, y - cy) - ra) - mm(3);
            if (std::fabs(d) < 10) return std::nan("");
            return d < 0 ? oracle_arc(tool, cx, cy, ra, a0, sweep, z0, z1, x, y) : HUGE_VAL;
          },
          [&](double x, double y) { return oracle_arc_highest(tool, cx, cy, ra, a0, sweep, z0, z1, x, y); }, cases,
          k == ToolKind::kBall ? "buried helix ball" : "buried helix flat");
    }
  }
  CHECK_EQ(bad, 0);
  CHECK_GT(cases[1], 100);
  CHECK_GT(cases[2], 100);
  CHECK_GT(cases[3], 100);
}

TEST(sweep_arc_chorded_cases_within_bound) {
  // Bull nose and V-bit arcs, and helices of a ball no wider than the ball,
  // go through 1 um chords: within 1 LSB for a column displaced by up to
  // 1 um. (The first and last cases here are exact helices, which meet the
  // wider bound too.)
  const Tool tools[] = {tool_of(ToolKind::kBall, mm(6)), tool_of(ToolKind::kBullNose, mm(6), mm(1)),
                        tool_of(ToolKind::kVBit, mm(6), 0, 90000), tool_of(ToolKind::kFlat, mm(4))};
  const char* names[] = {"ball6-helix", "bull-helix", "vbit-arc", "flat-helix"};
  int bad = 0;
  // The oracle's offsets are along x and y; 1.5 um covers 1 um radially.
  bad += check_arc(tools[0], names[0], 8e6, 8e6, 4e6, 0.2, 4.0, 12e6, 9e6, 1500.0);
  bad += check_arc(tools[1], names[1], 8e6, 8e6, 3e6, 1.0, -3.0, 11e6, 8e6, 1500.0);
  bad += check_arc(tools[2], names[2], 8e6, 8e6, 5e6, 2.0, 2.5, 12e6, 12e6, 1500.0);
  bad += check_arc(tools[3], names[3], 8e6, 8e6, 2e6, 0.0, 2 * kPi - 0.01, 12e6, 10e6, 1500.0);
  CHECK_EQ(bad, 0);
}

namespace {

const char kGoldenProgram[] =
    "G21 G90 G17 G94\n"
    "G0 Z25\n"
    "G0 X5 Y5\n"
    "G1 Z14 F300\n"                    // plunge
    "G1 X35 Y5 F800\n"                 // level line
    "G1 X35 Y25 Z12\n"                 // ramp
    "G2 X25 Y15 I-10 J0\n"             // level arc, IJK
    "G3 X15 Y25 R10\n"                 // level arc, R
    "G2 X15 Y25 I0 J-5 Z9\n"           // full helical turn
    "G1 X5 Y5 Z13\n"                   // diagonal ramp
    "G2 X5 Y5 I3 J3 Z11 P2\n"          // two-turn helix
    "G0 Z25\n"
    "G0 X30 Y10\n"
    "G1 Z-1 F200\n"                    // through the stock: a hole
    "G0 Z25\n"
    "M2\n";

class OneTool : public ToolLibrary {
 public:
  explicit OneTool(const Tool& t) : t_(t) {}
  bool tool(int32_t, Tool* out) const override { *out = t_; return true; }
 private:
  Tool t_;
};

template <class H>
uint64_t run_golden(CutMode mode, const Tool& tool, CutStats* st, uint64_t* news) {
  const int64_t lsb = lsb_for_range(mm(25), int(sizeof(H) * 8));
  std::vector<H> top(82 * 62), bottom(82 * 62);
  DexelGrid<H> g;
  GridGeometry geo{82, 62, 0, 0, 500000, 0, lsb};
  grid_init(&g, geo, top.data(), bottom.data(), top.size());
  std::vector<int32_t> words(cutter_storage_words(64));
  OneTool lib(tool);
  const uint64_t before = t::heap_allocations();
  grid_block_stock(&g, grid_height_of_z(g, mm(20)));
  Mill<H> mill(&g, mode, &lib, words.data(), words.size());
  mill.set_tool(tool);
  InterpOptions opt;
  Interp interp(&mill, opt);
  CHECK_EQ(interp_run_text(&interp, kGoldenProgram, std::strlen(kGoldenProgram), nullptr), 0u);
  mill.flush();
  *news = t::heap_allocations() - before;
  *st = mill.stats();
  return grid_hash(g);
}

}  // namespace

TEST(mill_golden_program_hashes) {
  // Pinned in tests/golden/hashes.txt as mill-MODE-mBITS: change only with
  // make bless and a commit that says why the new grid is right.
  struct Want { CutMode mode; int bits; };
  const Want want[] = {{CutMode::kSweep, 8}, {CutMode::kSweep, 16}, {CutMode::kSweep, 32},
                       {CutMode::kStamp, 8}, {CutMode::kStamp, 16}, {CutMode::kStamp, 32}};
  const Tool ball = tool_of(ToolKind::kBall, mm(6));
  for (const Want& w : want) {
    CutStats st;
    uint64_t news = 1, h = 0;
    if (w.bits == 8) h = run_golden<uint8_t>(w.mode, ball, &st, &news);
    if (w.bits == 16) h = run_golden<uint16_t>(w.mode, ball, &st, &news);
    if (w.bits == 32) h = run_golden<uint32_t>(w.mode, ball, &st, &news);
    std::printf("golden mill: %s m=%d %016llx updates %llu\n", w.mode == CutMode::kSweep ? "sweep" : "stamp", w.bits,
                static_cast<unsigned long long>(h), static_cast<unsigned long long>(st.dexel_updates));
    CHECK_GOLDEN_HASH(std::string("mill-") + (w.mode == CutMode::kSweep ? "sweep" : "stamp") + "-m" + std::to_string(w.bits), h);
    CHECK_EQ(news, 0u);  // no heap while cutting, interpreter included
  }
}
