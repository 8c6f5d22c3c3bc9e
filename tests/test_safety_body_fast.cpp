// The shank and holder's fast look (core/safety/safety.cpp, body_contacts:
// columns under every ring reaching them, tiles and blocks of tiles under
// the body, passed over) against the reference that reads every column
// over the body's lowest point (Simulation::set_body_fast(false)): programs
// that scrape the holder and the shank, plunge, ramp and cut arcs (helices
// of many batches of chords, an upright arc), with tools of every shape and
// holders of cylinders and cones, give the same findings to the last field
// (line, depth, point, columns, volume, the stretch's last line, the
// order) and leave the same tile bounds. A tool whose body clears the stock finds nothing either way (no
// false alarm), and one whose holder face ends exactly at the stock's top
// finds nothing while 0.2 mm deeper does (no miss).
#include <cmath>
#include <cstdio>
#include <string>

#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;
using sim_test::Run;
using sim_test::same_events;

namespace {

const char* const kPrograms[] = {
    // Pockets stepping down, each level a loop around the last.
    ("G21 G90 G17\nG0 X5 Y5 Z2\nM3 S10000\nG1 Z-3 F300\nG1 X35\nG1 Y15\nG1 X5\nG1 Z-6\nG1 X35 Y25\nG1 X5\n"
     "G1 Y35 Z-9\nG1 X35\nG1 Y5\nG0 Z5\nM2\n"),
    // Plunges and a peck drill.
    ("G21 G90\nG0 X20 Y20 Z3\nM3 S9000\nG1 Z-10 F100\nG0 Z3\nG0 X10 Y30\nG1 Z-4\nG1 Z-8\nG0 Z3\n"
     "G98 G83 X30 Y10 Z-9 R1 Q2 F150\nG80\nG0 Z5\nM2\n"),
    // Ramps across the block and back.
    "G21 G90\nG0 X2 Y2 Z1\nM3 S9000\nG1 X38 Y20 Z-9 F300\nG1 X2 Y38 Z-3\nG1 X20 Y2 Z-11\nG0 Z5\nM2\n",
    // A helix of one turn and a half, then an upright arc (G18).
    ("G21 G90 G17\nG0 X20 Y10 Z1\nM3 S9000\nG1 Z-2 F300\nG2 X20 Y30 I0 J10 Z-5\nG2 X30 Y20 I0 J-10 Z-8\n"
     "G18 G2 X20 Z-8 I-5 K0\nG17 G3 X20 Y20 I0 J0.01\nG0 Z5\nM2\n"),
};

const char* const kTools[] = {
    "flat:6,len=4,stick=8,holder=20x10",
    "ball:4,len=3,stick=6,shank=6,holder=12-30x8,30x5",
    "bull:5:1,len=2,stick=5,holder=8x2,8-24x6,nocentre",
    "vbit:8:90,len=5,stick=9,holder=16x20",
};

// Runs `program` with `tool` fast or by the reference (with `framed`, the
// cut shown after every move, as frames do); true when it ran watched.
bool cut(Run* r, const char* tool, const char* program, bool fast, bool framed = false) {
  r->stock("0,0,-12,40,40,0").tool(tool).pitch("0.2");
  r->body_fast = fast;
  SimBudget b;
  if (framed) b.moves = 1;
  return r->check_all().text("body_fast.ngc", program, b, framed) && r->sim().safety();
}

// The tiles' bounds the looks left (what ends a stretch of contact): the
// fast look tightens the same tiles to the same tops.
bool same_bounds(const SafetyWatch& a, const SafetyWatch& b) {
  if (!a.tile_max || !b.tile_max || a.tiles_x != b.tiles_x || a.tiles_y != b.tiles_y) return false;
  for (size_t k = 0; k < static_cast<size_t>(a.tiles_x) * static_cast<size_t>(a.tiles_y); ++k)
    if (a.tile_max[k] != b.tile_max[k]) return false;
  return true;
}

size_t body_events(Run& r) { return r.events(SafetyKind::kShank).size() + r.events(SafetyKind::kHolder).size(); }

}  // namespace

TEST(safety_body_fast_look_matches_the_full_scan) {
  size_t shank = 0, holder = 0;
  for (const char* tool : kTools)
    for (const char* program : kPrograms) {
      // The fast look framed: the tiles' tops it keeps do not depend on
      // when the cut is shown.
      Run fast, full;
      if (!CHECK(cut(&fast, tool, program, true, true)) || !CHECK(cut(&full, tool, program, false))) continue;
      if (!CHECK(same_events(*fast.sim().safety(), *full.sim().safety()))) std::printf("  %s\n%s", tool, program);
      CHECK(same_bounds(*fast.sim().safety(), *full.sim().safety()));
      shank += fast.events(SafetyKind::kShank).size();
      holder += fast.events(SafetyKind::kHolder).size();
    }
  // Both kinds found (what is compared is not nothing against nothing).
  CHECK(shank > 0);
  CHECK(holder > 0);
}

TEST(safety_body_fast_look_no_false_alarm_and_no_miss) {
  // Long flutes and a long stick-out: the body clears every program.
  for (const char* program : kPrograms) {
    Run fast, full;
    if (!CHECK(cut(&fast, "flat:6,len=20,stick=40,holder=20x10", program, true)) ||
        !CHECK(cut(&full, "flat:6,len=20,stick=40,holder=20x10", program, false)))
      continue;
    CHECK_EQ(body_events(fast), size_t{0});
    CHECK(same_events(*fast.sim().safety(), *full.sim().safety()));
  }
  // The holder face 8 mm over the tip: a slot 8 mm deep puts it at the
  // stock's top (no contact), 8.2 mm deep 0.2 mm into the walls beside it.
  const char* tool = "flat:6,stick=8,holder=20x10";
  const std::string at_top = "G21 G90\nG0 X-5 Y20 Z2\nM3 S9000\nG1 Z-8 F300\nG1 X45\nG0 Z5\nM2\n";
  const std::string below = "G21 G90\nG0 X-5 Y20 Z2\nM3 S9000\nG1 Z-8.2 F300\nG1 X45\nG0 Z5\nM2\n";
  for (bool fast : {true, false}) {
    Run a, b;
    if (!CHECK(cut(&a, tool, at_top.c_str(), fast)) || !CHECK(cut(&b, tool, below.c_str(), fast))) continue;
    CHECK_EQ(a.events(SafetyKind::kHolder).size(), size_t{0});
    const std::vector<SafetyEvent> e = b.events(SafetyKind::kHolder);
    CHECK(!e.empty());
    if (!e.empty()) CHECK(e[0].depth_nm > 0 && e[0].depth_nm <= 200000 + b.sim().grid().lsb_nm);
  }
}

TEST(safety_body_fast_look_matches_the_full_scan_on_a_relief) {
  // safety-deep-1k in small (tools/bench/bench_cut.cpp): a zig-zag finish
  // of a wavy relief with a 40 mm holder 6 mm over the tip, the stock
  // scraped on most moves, over many blocks of tiles.
  std::string program = "G21 G90\nG0 X0 Y1 Z5\nM3 S9000\n";
  char line[96];
  for (int row = 0; row < 12; ++row) {
    const double y = 1 + row * 2.5;
    for (int k = 0; k <= 20; ++k) {
      const double x = (row % 2 ? 20 - k : k) * 2.0;
      std::snprintf(line, sizeof line, "G1 X%.3f Y%.3f Z%.3f F600\n", x, y, -4 + 2 * std::sin(x / 6) * std::cos(y / 9));
      program += line;
    }
  }
  program += "G0 Z5\nM2\n";
  for (const char* tool : {"ball:3,len=3,stick=6,holder=40x20", "flat:4,len=2,stick=5,holder=10-40x8"}) {
    Run fast, full;
    if (!CHECK(cut(&fast, tool, program.c_str(), true)) || !CHECK(cut(&full, tool, program.c_str(), false))) continue;
    CHECK(same_events(*fast.sim().safety(), *full.sim().safety()));
    CHECK(same_bounds(*fast.sim().safety(), *full.sim().safety()));
    CHECK(body_events(fast) > 0);
  }
}
