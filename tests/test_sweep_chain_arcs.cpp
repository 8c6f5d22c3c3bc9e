// core/cut/sweep_arc.cpp, sweep_chain_arc: an arc swept as chords (out of
// the XY plane, a bull nose or V-bit, a helix tighter than the tool) puts its
// chords on the chain as straight moves (deferred end caps, wedge-only start
// caps) instead of cutting each chord's caps in full. In exact arithmetic
// the grids are equal (core/cut/sweep.h, SweepChain); in integers a band and
// a cap may round apart by an LSB, so a dexel may differ from cutting every
// chord with its caps (sweep_arc), rarely, and always within one LSB of the
// exact sweep of the same chords (the double oracle of tests/sweep_oracle.h).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/cut/arc_walk.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/tool/tool.h"
#include "tests/cut_fixtures.h"
#include "tests/gcode_test_util.h"
#include "tests/runner.h"
#include "tests/sweep_oracle.h"

using namespace dexmill;

namespace {

using fixtures::mm;

// The program's moves (lines and arcs), as the interpreter gives them.
std::vector<CanonRecord> records_of(const char* text) {
  t::Recorder rec;
  InterpOptions opt;
  Interp interp(&rec, opt);
  CHECK_EQ(interp_run_text(&interp, text, std::strlen(text), nullptr), 0u);
  std::vector<CanonRecord> moves;
  for (const CanonRecord& r : rec.records)
    if (r.kind == CanonKind::kFeed || r.kind == CanonKind::kTraverse || r.kind == CanonKind::kArc) moves.push_back(r);
  return moves;
}

// Profiles in XZ and YZ of arcs and lines (as a CAM's lathe-like finish
// writes them), XY arcs and a tight helix: every way an arc goes to chords.
const char* const kPrograms[] = {
    ("G21 G90 G18\nG0 X4 Y9.3 Z30\nG1 Z24 F500\nG3 X8 Z20.5 R4\nG1 X14.2\nG2 X20 Z23.1 R5\nG1 X26 Z21.7\n"
    "G3 X31.5 Z18 R4.5\nG1 Y12.1\nG2 X24 Z22 R5.5\nG1 X9\nM2\n"),
    ("G21 G90 G19\nG0 X20.5 Y3 Z30\nG1 Z22 F500\nG2 Y9 Z19 R4\nG1 Y15 Z20\nG3 Y23.7 Z24 R6\nG1 X25.1\n"
    "G2 Y14 Z18.2 R7.9\nM2\n"),
    ("G21 G90 G17\nG0 X10 Y10 Z30\nG1 Z22 F500\nG2 X22 Y14 I6 J2\nG3 X30 Y20 R7\nG1 X18 Y22\n"
    "G2 X18 Y22 I-3 J-2.5 Z19\nM2\n"),
    "G21 G90 G17\nG0 X15.5 Y15 Z30\nG1 Z24 F500\nG2 X15.5 Y15 I2 J0 Z21\nG1 X25 Z23\nM2\n",
};

const Tool kTools[] = {fixtures::test_tool(ToolKind::kBall, mm(6), 0, 0, mm(60)),
                       fixtures::test_tool(ToolKind::kFlat, mm(5), 0, 0, mm(60)),
                       fixtures::test_tool(ToolKind::kBullNose, mm(8), mm(2), 0, mm(60)),
                       fixtures::test_tool(ToolKind::kVBit, mm(6), 0, 90000, mm(60)),
                       fixtures::test_tool(ToolKind::kBall, 3175000, 0, 0, mm(60))};

// The straight pieces the sweep cuts for the records: lines as they are,
// chorded arcs as the chords sweep_arc takes, and exact arcs as chords of 2
// nm sagitta (within 4 nm of the arc, core/canon/arc_chords.h).
std::vector<std::pair<PointNm, PointNm>> pieces_of(const SweepTool& t, const std::vector<CanonRecord>& recs) {
  std::vector<std::pair<PointNm, PointNm>> out;
  const RectNm all{-mm(100), -mm(100), mm(100), mm(100)};
  for (const CanonRecord& r : recs) {
    if (r.kind != CanonKind::kArc) out.emplace_back(r.start, r.end);
    else arc_walk(r, sweep_arc_exact(t, r) ? 2 : kArcChordSagittaNm, all, [&](PointNm a, PointNm b) { out.emplace_back(a, b); });
  }
  return out;
}

// What a chained top may lie beyond the sweep's 1 LSB (core/cut/sweep.h,
// SweepChain): a band and a cap round apart by a few of the sweep's units on
// chords a tenth of a millimetre long, which shows only where an LSB is a
// nanometre (m = 32 here; measured: 2 nm).
constexpr double kChainSlackNm = 4;

struct Diff {
  int64_t dexels = 0, differ = 0, worst = 0, outside = 0;
  double excess_nm = 0;  // the most a differing top lies beyond 1 LSB of the oracle
  uint64_t full_updates = 0, chain_updates = 0;
};

template <class H>
void compare(const Tool& tool, const std::vector<CanonRecord>& recs, int64_t lsb, Diff* d) {
  fixtures::TestGrid<H> full(84, 64, 500000, lsb), chain(84, 64, 500000, lsb);
  full.fill(mm(26));
  chain.fill(mm(26));
  SweepTool t;
  if (!CHECK_EQ(sweep_tool_prepare(tool_profile(tool), lsb, &t), Status::kOk)) return;
  CutStats s1, s2;
  SweepChain c;
  for (const CanonRecord& r : recs) {
    if (r.kind == CanonKind::kArc) {
      sweep_arc(&full.g, t, r, &s1);
      sweep_chain_arc(&chain.g, t, r, &s2, &c);
    } else {
      sweep_line(&full.g, t, r.start, r.end, &s1);
      sweep_chain_line(&chain.g, t, r.start, r.end, &s2, &c);
    }
  }
  sweep_chain_end(&chain.g, t, &s2, &c);
  d->full_updates += s1.dexel_updates;
  d->chain_updates += s2.dexel_updates;
  const std::vector<std::pair<PointNm, PointNm>> pieces = pieces_of(t, recs);
  for (int32_t j = 0; j < full.g.ny; ++j) {
    for (int32_t i = 0; i < full.g.nx; ++i) {
      const size_t k = full.g.index(i, j);
      ++d->dexels;
      const int64_t dt = int64_t(chain.top[k]) - int64_t(full.top[k]);
      if (!dt && chain.bottom[k] == full.bottom[k]) continue;
      ++d->differ;
      d->worst = std::max(d->worst, dt < 0 ? -dt : dt);
      // The exact sweep of the same pieces at the column and 1 nm around it.
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (auto& o : oracle::kNeighbours) {
        double h = HUGE_VAL;
        for (const auto& p : pieces)
          h = std::min(h, oracle::lowest_on_line(tool, oracle::P3{double(p.first.x_nm), double(p.first.y_nm), double(p.first.z_nm)},
                                                 oracle::P3{double(p.second.x_nm), double(p.second.y_nm), double(p.second.z_nm)},
                                                 double(i) * full.g.pitch_nm + o[0], double(j) * full.g.pitch_nm + o[1]));
        const double lsbs = std::max(0.0, h == HUGE_VAL ? double(full.stock_lsb) : std::min(double(full.stock_lsb), h / double(lsb)));
        lo = std::min(lo, lsbs);
        hi = std::max(hi, lsbs);
      }
      const double got = chain.top[k];
      const double beyond_lsb = std::max(0.0, std::max(lo - 1.0 - got, got - hi - 1.0));
      d->excess_nm = std::max(d->excess_nm, beyond_lsb * double(lsb));
      if (chain.bottom[k] != full.bottom[k] || beyond_lsb * double(lsb) > kChainSlackNm) {
        if (++d->outside <= 5)
          std::printf("  m=%d dexel (%d,%d): chain %lld, full %lld, oracle [%.3f, %.3f]\n", int(sizeof(H) * 8), i, j,
                      (long long)chain.top[k], (long long)full.top[k], lo, hi);
      }
    }
  }
}

}  // namespace

TEST(sweep_chain_arcs_equal_full_caps_within_an_lsb) {
  Diff d;
  for (const char* program : kPrograms) {
    const std::vector<CanonRecord> recs = records_of(program);
    CHECK(recs.size() >= 4);
    for (const Tool& tool : kTools) {
      compare<uint8_t>(tool, recs, 120000, &d);
      compare<uint16_t>(tool, recs, 1000, &d);
      compare<uint32_t>(tool, recs, 1, &d);
    }
  }
  std::printf("sweep chain arcs vs full caps: %lld of %lld dexels differ (worst %lld LSB), %.0f nm past 1 LSB of the "
              "oracle at most, %lld outside the bound; updates %llu chained against %llu\n",
              static_cast<long long>(d.differ), static_cast<long long>(d.dexels), static_cast<long long>(d.worst),
              d.excess_nm, static_cast<long long>(d.outside), static_cast<unsigned long long>(d.chain_updates),
              static_cast<unsigned long long>(d.full_updates));
  CHECK_EQ(d.outside, 0);
  CHECK(d.differ * 200 <= d.dexels);  // rare, as for lines (tests/test_sweep_chain.cpp)
  // The point of it: fewer caps.
  CHECK(d.chain_updates < d.full_updates);
}
