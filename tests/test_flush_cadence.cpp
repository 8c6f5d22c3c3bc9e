// The grid after a program is a function of the program and
// the cutting options only. Mill::flush (core/cut/mill.h) makes the grid show
// the cut so far for a frame or a live view, which flush at --every N moves
// or at wall-clock ticks; where it is called must not change what is finally
// cut. Each program here runs through the Mill with no flush, a flush after
// every record and random flush patterns, and every grid must be the same to
// the bit, for each tool shape, both modes and each height type.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/cut/mill.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/tool/cutter.h"
#include "core/tool/tool.h"
#include "tests/cut_fixtures.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using fixtures::mm;

// The records of a program, as the interpreter gives them to a run.
class Recorder : public CanonSink {
 public:
  void emit(const CanonRecord& r) override { records.push_back(r); }
  std::vector<CanonRecord> records;
};

std::vector<CanonRecord> records_of(const std::string& text) {
  Recorder rec;
  InterpOptions opt;
  Interp interp(&rec, opt);
  GcodeDiag first{};
  const uint32_t errors = interp_run_text(&interp, text.data(), text.size(), &first);
  CHECK_EQ(errors, 0u);
  return rec.records;
}

// T1..T4 of every program: a short ball whose shaft dips under the stock top
// on deep moves (then figure 2's cases other than a min() come in), a flat
// end, a bull nose and a V-bit; the default tool is given per program.
Tool tool_number(int32_t n) {
  switch (n) {
    case 1: {
      Tool t = fixtures::test_tool(ToolKind::kBall, mm(4), 0, 0, mm(5));
      t.flute_length_nm = mm(4);
      return t;
    }
    case 2: return fixtures::test_tool(ToolKind::kFlat, mm(5), 0, 0, mm(40));
    case 3: return fixtures::test_tool(ToolKind::kBullNose, mm(6), mm(1), 0, mm(40));
    default: return fixtures::test_tool(ToolKind::kVBit, mm(6), 0, 90000, mm(40));
  }
}

class Library : public ToolLibrary {
 public:
  bool tool(int32_t number, Tool* out) const override {
    if (number < 1 || number > 4) return false;
    *out = tool_number(number);
    return true;
  }
};

// Where a program cuts: a block of stock from z = -10 mm to 0 over the
// grid, whose origin and pitch each program chooses (odd ones: joints fall
// anywhere between dexels).
struct Setup {
  int64_t x0_nm, y0_nm, pitch_nm;
  int32_t nx, ny;
};

template <class H>
struct Run {
  std::vector<H> top, bottom;
  DexelGrid<H> g;
  CutStats stats;
};

// Flush patterns: none, after every record, or after each record with
// probability 1/4 or 1/2 (seeded).
enum class Pattern { kNone, kEvery, kRandom };

template <class H>
void run_program(const Setup& s, const Tool& initial, CutMode mode, const std::vector<CanonRecord>& recs,
                 Pattern pattern, uint64_t seed, Run<H>* out, bool skip_covered = true) {
  const size_t n = static_cast<size_t>(s.nx) * static_cast<size_t>(s.ny);
  out->top.assign(n, 0);
  out->bottom.assign(n, 0);
  const GridGeometry geo{s.nx, s.ny, s.x0_nm, s.y0_nm, s.pitch_nm, -mm(10), lsb_for_range(mm(10), int(sizeof(H) * 8))};
  CHECK_EQ(grid_init(&out->g, geo, out->top.data(), out->bottom.data(), n), Status::kOk);
  grid_block_stock(&out->g, grid_height_of_z(out->g, 0));
  Library lib;
  size_t words = 0;
  for (int32_t k = 0; k <= 4; ++k) {
    const Tool t = k ? tool_number(k) : initial;
    words = std::max(words, mill_words<H>(mode, tool_profile(t), out->g));
  }
  std::vector<int32_t> memory(words);
  Mill<H> mill(&out->g, mode, &lib, memory.data(), memory.size());
  mill.set_skip_covered(skip_covered);
  CHECK_EQ(mill.set_tool(initial), Status::kOk);
  std::mt19937_64 rng(seed);
  const unsigned odds = seed % 2 ? 4 : 2;
  // What a display keeps: the tops, updated only within the grid's dirty
  // rectangle after each step (a flush's cap put back must be marked too).
  // Sweep mode only: stamping defers nothing.
  std::vector<H> shown = out->top;
  auto redraw = [&] {
    const GridRect d = mode == CutMode::kSweep ? out->g.dirty : GridRect::none();
    for (int32_t j = d.j0; j < d.j1; ++j)
      for (int32_t i = d.i0; i < d.i1; ++i) shown[out->g.index(i, j)] = out->top[out->g.index(i, j)];
    out->g.dirty = GridRect::none();
  };
  for (const CanonRecord& r : recs) {
    mill.emit(r);
    redraw();
    if (pattern == Pattern::kEvery || (pattern == Pattern::kRandom && rng() % odds == 0)) {
      mill.flush();
      redraw();
    }
  }
  mill.flush();  // a program may end without M2
  redraw();
  if (mode == CutMode::kSweep) CHECK(shown == out->top);
  CHECK_EQ(mill.status(), Status::kOk);
  out->stats = mill.stats();
}

struct Tally {
  int runs = 0, differ = 0;
};

// Runs recs with every pattern and compares each grid with the unflushed one.
template <class H>
void check_patterns(const char* name, const Setup& s, const Tool& initial, CutMode mode,
                    const std::vector<CanonRecord>& recs, Tally* tally) {
  Run<H> base;
  run_program<H>(s, initial, mode, recs, Pattern::kNone, 0, &base);
  struct P { Pattern p; uint64_t seed; };
  const P patterns[] = {{Pattern::kEvery, 0}, {Pattern::kRandom, 1}, {Pattern::kRandom, 2}, {Pattern::kRandom, 3},
                        {Pattern::kRandom, 4}};
  for (const P& p : patterns) {
    Run<H> other;
    run_program<H>(s, initial, mode, recs, p.p, p.seed, &other);
    ++tally->runs;
    // The counts too (dexel_updates goes into the run's report).
    CHECK_EQ(other.stats.instances, base.stats.instances);
    CHECK_EQ(other.stats.dexel_updates, base.stats.dexel_updates);
    size_t diffs = 0, first = 0;
    for (size_t k = 0; k < base.top.size(); ++k) {
      if (base.top[k] == other.top[k] && base.bottom[k] == other.bottom[k]) continue;
      if (!diffs++) first = k;
    }
    if (!diffs) continue;
    ++tally->differ;
    if (tally->differ <= 8)
      std::printf("  %s %s m=%d pattern %d/%llu: %zu dexels differ, first (%d,%d): %llu/%llu vs %llu/%llu\n", name,
                  mode == CutMode::kSweep ? "sweep" : "stamp", int(sizeof(H) * 8), int(p.p),
                  static_cast<unsigned long long>(p.seed), diffs, int(first % size_t(s.nx)), int(first / size_t(s.nx)),
                  static_cast<unsigned long long>(base.top[first]), static_cast<unsigned long long>(base.bottom[first]),
                  static_cast<unsigned long long>(other.top[first]), static_cast<unsigned long long>(other.bottom[first]));
  }
}

// A random program over a 60 x 45 mm block: short and long moves at any
// angle, runs along an axis (collinear joints, reversals), ramps and level
// moves, plunges and retracts, steep ramps, level arcs and helices, and
// tool changes; depths down to 7 mm (the short T1's shaft dips under the
// stock top).
std::string random_program(std::mt19937_64* rng, bool changes) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * u01(*rng); };
  std::string p = "G21 G90 G17\nG0 Z5\n";
  double x = rnd(10, 50), y = rnd(10, 35), z = rnd(-3, -0.5);
  char b[200];
  std::snprintf(b, sizeof b, "G0 X%.4f Y%.4f\nG1 Z%.4f F400\n", x, y, z);
  p += b;
  double dir = rnd(0, 6.2832);
  for (int k = 0; k < 48; ++k) {
    const double c = u01(*rng);
    double nx = x, ny = y, nz = z;
    if (c < 0.3) {  // any angle, short or long
      dir = u01(*rng) < 0.3 ? dir + rnd(-0.2, 0.2) : rnd(0, 6.2832);
      const double len = std::exp(rnd(std::log(0.02), std::log(12.0)));
      nx = x + len * std::cos(dir);
      ny = y + len * std::sin(dir);
    } else if (c < 0.5) {  // along an axis: on, back or across
      const double len = std::exp(rnd(std::log(0.05), std::log(10.0)));
      const int axis = static_cast<int>(rnd(0, 4));
      nx = x + (axis == 0 ? len : axis == 1 ? -len : 0);
      ny = y + (axis == 2 ? len : axis == 3 ? -len : 0);
    } else if (c < 0.6) {  // plunge or retract
      nz = rnd(-7, 0.5);
    } else if (c < 0.68) {  // steep ramp
      nx = x + rnd(-0.05, 0.05);
      ny = y + rnd(-0.05, 0.05);
      nz = rnd(-7, 0.5);
    } else if (c < 0.85) {  // arc or helix
      const double ra = std::exp(rnd(std::log(0.3), std::log(8.0))), a = rnd(0, 6.2832);
      const double cx = x - ra * std::cos(a), cy = y - ra * std::sin(a), sweep = rnd(0.1, 4.0);
      const bool ccw = u01(*rng) < 0.5;
      const double e = ccw ? a + sweep : a - sweep;
      nx = cx + ra * std::cos(e);
      ny = cy + ra * std::sin(e);
      nz = u01(*rng) < 0.5 ? z : std::min(0.5, std::max(-7.0, z + rnd(-2, 2)));
      std::snprintf(b, sizeof b, "G%d X%.4f Y%.4f Z%.4f I%.4f J%.4f\n", ccw ? 3 : 2, nx, ny, nz, cx - x, cy - y);
      p += b;
      x = nx, y = ny, z = nz;
      continue;
    } else if (c < 0.9 && changes) {  // a tool change
      std::snprintf(b, sizeof b, "T%d M6\n", 1 + static_cast<int>(rnd(0, 4)));
      p += b;
      continue;
    } else {  // a rapid somewhere else, through the air or not
      nx = rnd(5, 55);
      ny = rnd(5, 40);
      nz = u01(*rng) < 0.5 ? 2.0 : rnd(-4, 0);
      std::snprintf(b, sizeof b, "G0 X%.4f Y%.4f Z%.4f\nG1 F400\n", nx, ny, nz);
      p += b;
      x = nx, y = ny, z = nz;
      continue;
    }
    if (c >= 0.5 && c < 0.6) {
    } else if (u01(*rng) < 0.4) {
      nz = std::min(0.5, std::max(-7.0, z + rnd(-1.5, 1.5)));  // a ramp
    }
    nx = std::min(58.0, std::max(2.0, nx));
    ny = std::min(43.0, std::max(2.0, ny));
    std::snprintf(b, sizeof b, "G1 X%.4f Y%.4f Z%.4f\n", nx, ny, nz);
    p += b;
    x = nx, y = ny, z = nz;
  }
  if (u01(*rng) < 0.5) p += "M2\n";
  return p;
}

// The program where the flushes showed (dexmill run --tool ball:3 --stock
// -2.5628,-2.9064,-6.875,145.6294,118.9275,0 --pitch 0.58574): before the
// fix, --frames --every 1 left one dexel 1 LSB lower.
const char kEveryOneProgram[] =
    "G1 F300.0 Z-2.0\n"
    "G1 X14.9484 Y104.1733\n"
    "G1 X69.9772\n"
    "G1 Y103.8451\n"
    "G1 X69.5458 Y103.7156\n";

// Hand-made joints: a square with a 1 um step, a U-turn, a zig-zag of short
// collinear ramps, a spiral of chords, a plunge in the middle of a line,
// and an arc between two lines.
const char kHandProgram[] =
    "G21 G90 G17\nG0 X10 Y10 Z2\nG1 Z-2 F300\n"
    "G1 X30\nG1 Y30\nG1 X10\nG1 Y10.001\nG1 X10.001 Y10\n"
    "G1 X40 Y12 Z-2.5\nG1 X12 Y12.3 Z-2.4\n"
    "G1 X14 Z-2.3\nG1 X16 Z-2.6\nG1 X18 Z-2.2\nG1 X20 Z-2.2\nG1 X22 Z-3\n"
    "G1 X25 Y20 Z-1\nG1 Z-4\nG1 Z-1.5\nG1 X30 Y25\n"
    "G2 X40 Y25 I5 J0\nG1 X45 Y30\nG3 X45 Y30 I-3 J-3 Z-3\nG1 X50 Y20 Z-1\n";

}  // namespace

TEST(flush_cadence_leaves_the_same_grid) {
  Tally tally;
  // That program on its own grid (the run's: origin a pitch outside
  // the stock, 16-bit heights over its 6.875 mm).
  {
    const Setup s{-2562800 - 585740, -2906400 - 585740, 585740, 258, 210};
    std::string text = kEveryOneProgram;
    const std::vector<CanonRecord> recs = records_of(text);
    // Its stock is 6.875 mm deep; this block is 10 mm, which
    // moves the LSB (lsb_for_range) but keeps the joints where they were.
    for (CutMode mode : {CutMode::kSweep, CutMode::kStamp})
      check_patterns<uint16_t>("every-1", s, fixtures::test_tool(ToolKind::kBall, mm(3), 0, 0, mm(40)), mode, recs,
                               &tally);
  }
  const Tool defaults[] = {fixtures::test_tool(ToolKind::kBall, mm(3), 0, 0, mm(40)),
                           fixtures::test_tool(ToolKind::kBall, 6350000, 0, 0, mm(40)), tool_number(1), tool_number(2),
                           tool_number(3), tool_number(4)};
  std::mt19937_64 rng(25);
  int program = 0;
  for (const Tool& tool : defaults) {
    for (int rep = 0; rep < 3; ++rep, ++program) {
      std::uniform_int_distribution<int64_t> pitch(170000, 620000), off(0, 1000000);
      const int64_t p = pitch(rng);
      const Setup s{-off(rng), -off(rng), p, static_cast<int32_t>(mm(62) / p) + 2, static_cast<int32_t>(mm(47) / p) + 2};
      const std::string text = rep == 0 ? std::string(kHandProgram) : random_program(&rng, rep == 2);
      const std::vector<CanonRecord> recs = records_of(text);
      char name[32];
      std::snprintf(name, sizeof name, "program %d", program);
      for (CutMode mode : {CutMode::kSweep, CutMode::kStamp}) {
        check_patterns<uint16_t>(name, s, tool, mode, recs, &tally);
        if (rep == 1) {
          check_patterns<uint8_t>(name, s, tool, mode, recs, &tally);
          check_patterns<uint32_t>(name, s, tool, mode, recs, &tally);
        }
      }
    }
  }
  std::printf("flush cadence: %d of %d flushed runs differ from the unflushed one\n", tally.differ, tally.runs);
  CHECK_EQ(tally.differ, 0);
}

TEST(flush_shows_what_finish_cuts) {
  // A frame after flush shows the pending end cap: the grid is the one that
  // ending the chain for good there leaves (Mill::finish), with the memory
  // to put the dexels back and without it (then flush cuts for good).
  std::mt19937_64 rng(2502);
  const Setup s{-300000, -200000, 310000, 202, 152};
  int compared = 0;
  for (int32_t number = 1; number <= 4; ++number) {
    const std::vector<CanonRecord> recs = records_of(random_program(&rng, false));
    for (int pick = 0; pick < 4; ++pick) {
      const size_t cut = 3 + rng() % (recs.size() - 3);
      std::vector<uint16_t> a[2], b[2];
      for (int way = 0; way < 3; ++way) {
        const size_t n = static_cast<size_t>(s.nx) * static_cast<size_t>(s.ny);
        std::vector<uint16_t> top(n), bottom(n);
        DexelGrid<uint16_t> g;
        const GridGeometry geo{s.nx, s.ny, s.x0_nm, s.y0_nm, s.pitch_nm, -mm(10), lsb_for_range(mm(10), 16)};
        CHECK_EQ(grid_init(&g, geo, top.data(), bottom.data(), n), Status::kOk);
        grid_block_stock(&g, grid_height_of_z(g, 0));
        Library lib;
        const Tool t = tool_number(number);
        std::vector<int32_t> memory(way == 2 ? 0 : mill_words<uint16_t>(CutMode::kSweep, tool_profile(t), g));
        Mill<uint16_t> mill(&g, CutMode::kSweep, &lib, memory.empty() ? nullptr : memory.data(), memory.size());
        CHECK_EQ(mill.set_tool(t), Status::kOk);
        for (size_t k = 0; k < cut; ++k) mill.emit(recs[k]);
        if (way == 0) mill.finish();
        else mill.flush();
        a[way == 0 ? 0 : 1] = top;
        b[way == 0 ? 0 : 1] = bottom;
        if (way == 0) continue;
        CHECK(a[0] == a[1]);
        CHECK(b[0] == b[1]);
        ++compared;
      }
    }
  }
  CHECK(compared > 20);
}

TEST(zero_length_moves_cut_nothing) {
  // A move of no length from where the last one ended (a post's repeated
  // point, a dwell written as G1 to the same place) cuts nothing the moves
  // around it do not (core/cut/mill.cpp, cut_line): with one or three of
  // them after every move, the grid is the one of the program without them
  // to the bit, and the cutting loop visits no more dexels; each tool
  // shape, both modes, flushed or not.
  std::mt19937_64 rng(4107);
  const Setup s{-300000, -200000, 310000, 202, 152};
  int compared = 0;
  for (int program = 0; program < 3; ++program) {
    const std::string text = program == 0 ? std::string(kHandProgram) : random_program(&rng, program == 2);
    const std::vector<CanonRecord> recs = records_of(text);
    for (int repeats : {1, 3}) {
      std::vector<CanonRecord> padded;
      for (const CanonRecord& r : recs) {
        padded.push_back(r);
        if (r.kind != CanonKind::kFeed && r.kind != CanonKind::kTraverse && r.kind != CanonKind::kArc) continue;
        CanonRecord z = r;
        z.kind = CanonKind::kFeed;
        z.start = z.end = r.end;
        for (int k = 0; k < repeats; ++k) padded.push_back(z);
      }
      for (int32_t number = 1; number <= 4; ++number)
        for (CutMode mode : {CutMode::kSweep, CutMode::kStamp})
          for (Pattern pattern : {Pattern::kNone, Pattern::kRandom}) {
            Run<uint16_t> plain, zero;
            run_program<uint16_t>(s, tool_number(number), mode, recs, pattern, 7, &plain);
            run_program<uint16_t>(s, tool_number(number), mode, padded, pattern, 7, &zero);
            CHECK(plain.top == zero.top);
            CHECK(plain.bottom == zero.bottom);
            CHECK_EQ(plain.stats.dexel_updates, zero.stats.dexel_updates);
            ++compared;
          }
    }
  }
  CHECK_EQ(compared, 3 * 2 * 4 * 2 * 2);
}

// Peck drilling (G83, G73: each peck retracts and comes back down) and a
// program's own pecks, retracts and repeated points, at holes placed
// anywhere between dexels, then a move on.
std::string peck_program(std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto rnd = [&](double lo, double hi) { return lo + (hi - lo) * u01(*rng); };
  std::string p = "G21 G90 G17 G98\nG0 Z5\n";
  char b[200];
  for (int h = 0; h < 4; ++h) {
    const double x = rnd(8, 52), y = rnd(8, 37), z = rnd(-6, -1), q = rnd(0.05, 1.5);
    std::snprintf(b, sizeof b, "G%d X%.4f Y%.4f Z%.4f R1 Q%.4f F300\nG80\n", h % 2 ? 73 : 83, x, y, z, q);
    p += b;
    std::snprintf(b, sizeof b, "G0 X%.4f Y%.4f\nG1 Z%.4f\nZ%.4f\nZ%.4f\nZ%.4f\nZ%.4f\nG1 X%.4f\nX%.4f\nZ%.4f\n", x + 3,
                  y, z * 0.5, z * 0.2, z * 0.4, z * 0.8, z, x + 3, x + 5, z * 0.3);
    p += b;
  }
  return p + "G0 Z5\nM2\n";
}

TEST(covered_vertical_moves_cut_nothing) {
  // The moves cut_line skips (core/cut/mill.cpp: vertical ones within the
  // span swept at their X and Y) leave the grid the reference, cutting
  // every move, leaves, to the bit, with fewer dexels visited: peck
  // cycles, retracts and repeated points, and random programs; each tool
  // shape, both modes, flushed or not.
  std::mt19937_64 rng(4109);
  const Setup s{-300000, -200000, 310000, 202, 152};
  int compared = 0;
  uint64_t visited = 0, reference = 0;
  for (int program = 0; program < 5; ++program) {
    const std::string text = program < 3 ? peck_program(&rng) : random_program(&rng, program == 4);
    const std::vector<CanonRecord> recs = records_of(text);
    for (int32_t number = 1; number <= 4; ++number)
      for (CutMode mode : {CutMode::kSweep, CutMode::kStamp})
        for (Pattern pattern : {Pattern::kNone, Pattern::kRandom}) {
          Run<uint16_t> ref, skip;
          run_program<uint16_t>(s, tool_number(number), mode, recs, pattern, 7, &ref, false);
          run_program<uint16_t>(s, tool_number(number), mode, recs, pattern, 7, &skip, true);
          CHECK(ref.top == skip.top);
          CHECK(ref.bottom == skip.bottom);
          CHECK(skip.stats.dexel_updates <= ref.stats.dexel_updates);
          visited += skip.stats.dexel_updates;
          reference += ref.stats.dexel_updates;
          ++compared;
        }
  }
  std::printf("covered moves: %d runs, %llu dexel visits against the reference's %llu\n", compared,
              static_cast<unsigned long long>(visited), static_cast<unsigned long long>(reference));
  CHECK_EQ(compared, 5 * 4 * 2 * 2);
  CHECK(visited < reference);
}
