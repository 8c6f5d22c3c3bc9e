// `dexmill run --save-stock` and `--stock FILE.dxstock` (core/stock/stock_file.h,
// core/sim/stock_state.h): a program split in two at a move, its second
// part run on the first part's saved stock, gives the whole run's
// heightmap, bottoms, tool classes, error view and totals, for every tool
// shape in both modes at every move; and a bad stock file is an
// error with its place, never a stock.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "core/stock/stock_file.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/stock_util.h"

namespace {

using namespace run_cli;
using namespace dexmill;

// The program the splits cut: its own F on every feed, so each part reads
// as the whole does. Lines 3.. are moves of every kind: plunges, ramps,
// lines in x, y and at an angle, arcs, a drilled hole.
const char* const kLines[] = {
    "G21 G90 G17 G94",
    "G0 Z5",
    "G0 X4 Y4",
    "G1 Z-1.5 F300",
    "G1 X26 F900",
    "G1 X20 Y16 Z-2.5 F900",
    "G1 X5 F900",
    "G1 Y5 Z-1 F900",
    "G2 X15 Y5 I5 J0 F600",
    "G1 X25 Y12 Z-3 F800",
    "G3 X10 Y12 I-7.5 J0 F600",
    "G0 Z5",
    "G0 X15 Y10",
    "G1 Z-4 F200",
    "G1 X22 Y17 F700",
    "G0 Z5",
    "G81 X27 Y3 Z-8 R2 F200",
    "G80",
    "G0 Z10",
};
constexpr int kNLines = static_cast<int>(sizeof kLines / sizeof kLines[0]);

std::string lines(int from, int to) {  // 1-based, inclusive
  std::string s;
  for (int k = from; k <= to; ++k) s += std::string(kLines[k - 1]) + "\n";
  return s;
}

// A JSON number after "key": in text (the first one).
std::string json_value(const std::string& text, const std::string& key) {
  const size_t at = text.find("\"" + key + "\": ");
  if (at == std::string::npos) return "?";
  const size_t from = at + key.size() + 4;
  return text.substr(from, text.find_first_of(",}", from) - from);
}
std::string chain_of(const std::string& report) {
  const size_t at = report.find("\"chain\": ");
  // to its totals' line: "  ], \"removed_mm3\": ...}"
  const size_t end = at == std::string::npos ? at : report.find("\n  ], ", at);
  return at == std::string::npos ? std::string() : report.substr(at, report.find('\n', end + 1) - at);
}

}  // namespace

TEST(run_split_at_a_move_equals_the_whole_run) {
  if (skip()) return;
  write_tmp("whole.ngc", (lines(1, kNLines) + "M30\n").c_str());
  write_file(tmp_dir() + "/floor.pgm", std::string("P5\n2 2\n255\n") + std::string(4, '\0'));
  const char* const tools[] = {"ball:3", "flat:3", "bull:4:1", "vbit:6:90"};
  const char* const modes[] = {"sweep", "stamp"};
  // The last line of part one: after every move of the program (lines 3
  // to 18: rapids, plunges, ramps, lines, arcs, a drill cycle).
  std::vector<int> splits;
  for (int k = 3; k < kNLines; ++k) splits.push_back(k);
  int compared = 0;
  for (const char* tool : tools)
    for (const char* mode : modes) {
      const std::string base = std::string("-q --tool ") + tool + " --mode " + mode + " ";
      // The error view against a design below every cut (a flat PGM at Z-10):
      // its colours are the heights' own. (Gouge marks are each run's own
      // findings, not carried by a stock file yet.)
      const std::string design = " --design %/floor.pgm --design-z -10,-9.5";
      CHECK_EQ(run("%/whole.ngc " + base + "--stock 0,0,-10,30,20,0 --pitch 0.25 --heightmap %/whole.pgm --report "
                    "%/whole.json --save-stock %/whole.dxstock --error-image %/whole_err.ppm" + design).code,
               0);
      const std::string whole = slurp(tmp_dir() + "/whole.json");
      const t::StockFileColumns w = t::read_stock_file(tmp_dir() + "/whole.dxstock");
      CHECK(w.ok);
      for (int k : splits) {
        write_tmp("a.ngc", lines(1, k).c_str());
        // Part two: the units and modes again (a program of its own), then the rest.
        write_tmp("b.ngc", (std::string("G21 G90 G17 G94\n") + lines(k + 1, kNLines) + "M30\n").c_str());
        CHECK_EQ(run("%/a.ngc " + base + "--stock 0,0,-10,30,20,0 --pitch 0.25 --save-stock %/a.dxstock").code, 0);
        const Result b = run("%/b.ngc " + base + "--stock %/a.dxstock --heightmap %/b.pgm --report %/b.json "
                             "--save-stock %/b.dxstock --error-image %/b_err.ppm" + design);
        CHECK_EQ(b.code, 0);
        CHECK(slurp(tmp_dir() + "/whole_err.ppm") == slurp(tmp_dir() + "/b_err.ppm"));
        // Every top is the whole run's, the bull nose's rim included: a
        // cap's distance is the grid frame's exact one, as the tool
        // standing at the joint has it (core/cut/sweep_piece.h
        // general_row), so the split's standing tool and the whole run's
        // next move agree even where the torus stands vertical.
        const std::string part2 = slurp(tmp_dir() + "/b.json");
        const std::string chain = chain_of(part2);
        // The chain's totals are the whole run's (the last "removed_mm3" of
        // the chain line is its total).
        const size_t total_at = chain.rfind("\"removed_mm3\": ");
        CHECK(total_at != std::string::npos);
        if (total_at != std::string::npos) {
          CHECK_EQ(json_value(chain.substr(total_at), "removed_mm3"), json_value(whole, "removed_mm3"));
          CHECK_EQ(json_value(chain.substr(total_at), "estimated_time_s"), json_value(whole, "estimated_time_s"));
          CHECK_EQ(json_value(chain.substr(total_at), "moves"), json_value(chain_of(whole), "moves"));
        }
        CHECK(has(chain, "/a.ngc\", \"setup\": \"none\", \"removed_mm3\""));
        CHECK(has(chain, "/b.ngc\", \"setup\": \"none\", \"removed_mm3\""));
        // Bottoms and tool classes too; each line names the same block of
        // the whole program (part two's lines are k - 1 further on there).
        const t::StockFileColumns s = t::read_stock_file(tmp_dir() + "/b.dxstock");
        CHECK(s.ok);
        if (!s.ok || !w.ok) continue;
        int differ = 0, worst = 0;
        for (size_t c = 0; c < s.top.size(); ++c)
          if (s.top[c] != w.top[c]) {
            ++differ;
            worst = std::max(worst, std::abs(static_cast<int>(s.top[c]) - static_cast<int>(w.top[c])));
          }
        CHECK_EQ(differ, 0);
        CHECK_EQ(worst, 0);
        CHECK(slurp(tmp_dir() + "/whole.pgm") == slurp(tmp_dir() + "/b.pgm"));
        CHECK(s.bottom == w.bottom);
        CHECK(s.cls == w.cls);
        CHECK_EQ(s.meta.nprograms, 2);
        size_t mismatched = 0;
        for (size_t c = 0; c < s.line.size(); ++c) {
          const uint32_t whole_line = s.program[c] == 1 ? s.line[c] + static_cast<uint32_t>(k) - 1 : s.line[c];
          if (s.line[c] == 0 ? w.line[c] != 0 : whole_line != w.line[c]) ++mismatched;
        }
        CHECK_EQ(mismatched, 0u);
        ++compared;
      }
    }
  CHECK_EQ(compared, 4 * 2 * (kNLines - 3));
}

TEST(run_saved_stock_carries_the_tool_position) {
  if (skip()) return;
  // Part one leaves the tool at X20 Y10 Z-2 in the stock; part two's first
  // move goes up from there: the stock is cut only where part one cut it.
  write_tmp("p1.ngc", "G21 G90\nG0 X5 Y10 Z5\nG1 Z-2 F300\nG1 X20 F600\n");
  write_tmp("p2.ngc", "G21 G90\nG1 Z5 F300\nM30\n");
  write_tmp("p12.ngc", "G21 G90\nG0 X5 Y10 Z5\nG1 Z-2 F300\nG1 X20 F600\nG1 Z5 F300\nM30\n");
  const std::string base = "-q --tool flat:4 --stock 0,0,-10,30,20,0 --pitch 0.25 ";
  CHECK_EQ(run("%/p12.ngc " + base + "--heightmap %/p12.pgm").code, 0);
  CHECK_EQ(run("%/p1.ngc " + base + "--save-stock %/p1.dxstock").code, 0);
  CHECK_EQ(run("%/p2.ngc -q --tool flat:4 --stock %/p1.dxstock --heightmap %/p2.pgm").code, 0);
  CHECK(slurp(tmp_dir() + "/p12.pgm") == slurp(tmp_dir() + "/p2.pgm"));
}

TEST(run_bad_stock_files_are_errors_with_their_place) {
  if (skip()) return;
  write_tmp("one.ngc", "G21 G90\nG0 X5 Y5 Z5\nG1 Z-1 F300\nG1 X20 F600\nM30\n");
  CHECK_EQ(run("%/one.ngc -q --tool flat:3 --stock 0,0,-5,30,20,0 --pitch 0.5 --save-stock %/good.dxstock").code, 0);
  const std::string good = slurp(tmp_dir() + "/good.dxstock");
  CHECK(good.size() > kStockHeaderBytes);
  // Truncated in its columns.
  write_file(tmp_dir() + "/cut.dxstock", good.substr(0, good.size() / 2));
  Result r = run("%/one.ngc -q --tool flat:3 --stock %/cut.dxstock");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, ("cut.dxstock:1:" + std::to_string(good.size() / 2 + 1) + ": error: the stock file is truncated").c_str()));
  // A flipped byte in a tile.
  std::string bad = good;
  bad[kStockHeaderBytes + 10] = static_cast<char>(bad[kStockHeaderBytes + 10] ^ 4);
  write_file(tmp_dir() + "/flip.dxstock", bad);
  r = run("%/one.ngc -q --tool flat:3 --stock %/flip.dxstock");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "flip.dxstock:1:"));
  CHECK(has(r.err, "corrupt"));
  // Not a stock file at all.
  write_file(tmp_dir() + "/text.dxstock", "G0 X1\n");
  r = run("%/one.ngc -q --tool flat:3 --stock %/text.dxstock");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "text.dxstock:1:1: error: not a dexmill stock file"));
  // A grid that would resample it.
  r = run("%/one.ngc -q --tool flat:3 --stock %/good.dxstock --pitch 0.1");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "cannot change a saved stock's grid"));
  // Saving over the stock it reads: refused before anything is written; the file stays.
  r = run("%/one.ngc -q --tool flat:3 --stock %/good.dxstock --save-stock %/good.dxstock");
  CHECK_EQ(r.code, 2);
  CHECK(slurp(tmp_dir() + "/good.dxstock") == good);
  // Heights of another m: written by the core's writer as an 8-bit stock.
  StockMeta m;
  m.geo = GridGeometry{4, 4, 0, 0, 1000000, -5000000, 100000};
  m.height_bits = 8;
  m.top_bound_lsb = 50;
  m.top_lsb = 50;
  m.stock_nx = m.stock_ny = 2;
  m.stock_hi = PointNm{4000000, 4000000, 0};
  m.stock_lo = PointNm{0, 0, -5000000};
  std::vector<uint8_t> h(16, 50), z(16, 0);
  StockColumns c;
  c.top = h.data();
  c.bottom = z.data();
  std::string bytes;
  CHECK_EQ(stock_write(m, c, [](void* ctx, const uint8_t* p, size_t n) {
             static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(p), n);
             return true;
           }, &bytes),
           StockError::kOk);
  write_file(tmp_dir() + "/eight.dxstock", bytes);
  r = run("%/one.ngc -q --tool flat:3 --stock %/eight.dxstock");
  CHECK_EQ(r.code, 1);
  CHECK(has(r.err, "eight.dxstock:1:17: error: a stock of 8-bit heights"));
}

TEST(run_setup_refuses_what_would_resample) {
  if (skip()) return;
  write_tmp("s1.ngc", "G21 G90\nG0 X5 Y5 Z5\nG1 Z-1 F300\nG1 X20 F600\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/s1.ngc -q --tool flat:3 --stock 0,0,-5,30,20,0 --pitch 0.5 --save-stock %/s1.dxstock").code, 0);
  Result r = run("%/s1.ngc -q --tool flat:3 --stock %/s1.dxstock --setup offset=0.3,0,0");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "the nearest exact one is offset=0.5,0,0"));
  r = run("%/s1.ngc -q --tool flat:3 --setup flip-x");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--setup turns a saved stock"));
  r = run("%/s1.ngc -q --tool flat:3 --stock %/s1.dxstock --setup flip-z");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "not 'flip-z'"));
  // A quarter turn of the 30 x 20 stock: the box keeps its centre and
  // swaps its extents; turned back, the same tops as before.
  write_tmp("none.ngc", "G21 G90\nM30\n");
  CHECK_EQ(run("%/none.ngc -q --tool flat:3 --stock %/s1.dxstock --setup rotate-90 --report %/r90.json --save-stock "
               "%/r90.dxstock").code,
           0);
  CHECK(has(slurp(tmp_dir() + "/r90.json"), "\"min_mm\": [5.0000, -5.0000, -5.0000], \"max_mm\": [25.0000, 25.0000, 0.0000]"));
  CHECK_EQ(run("%/none.ngc -q --tool flat:3 --stock %/r90.dxstock --setup rotate-270 --heightmap %/back.pgm").code, 0);
  CHECK_EQ(run("%/none.ngc -q --tool flat:3 --stock %/s1.dxstock --heightmap %/as_cut.pgm").code, 0);
  CHECK(slurp(tmp_dir() + "/back.pgm") == slurp(tmp_dir() + "/as_cut.pgm"));
}

TEST(run_programs_in_order_on_one_stock) {
  if (skip()) return;
  // Two programs and a flip in one command: the same as saving the stock
  // after the first and starting the second from it.
  write_tmp("c1.ngc", "G21 G90\nG0 X5 Y5 Z5\nG1 Z-2 F300\nG1 X25 F600\nG0 Z5\nG0 X10 Y15\nG1 Z-11 F200\nG0 Z5\nM30\n");
  write_tmp("c2.ngc", "G21 G90\nG0 X3 Y3 Z5\nG1 Z-1 F300\nG1 Y17 F600\nG0 Z5\nM30\n");
  const std::string stock = " --tool flat:3 --stock 0,0,-10,30,20,0 --pitch 0.25 -q";
  CHECK_EQ(run("%/c1.ngc" + stock + " --setup flip-x %/c2.ngc --heightmap %/chain.pgm --report %/chain.json").code, 0);
  CHECK_EQ(run("%/c1.ngc" + stock + " --save-stock %/c1.dxstock").code, 0);
  CHECK_EQ(run("%/c2.ngc -q --tool flat:3 --stock %/c1.dxstock --setup flip-x --heightmap %/steps.pgm").code, 0);
  CHECK(slurp(tmp_dir() + "/chain.pgm") == slurp(tmp_dir() + "/steps.pgm"));
  const std::string chain = chain_of(slurp(tmp_dir() + "/chain.json"));
  CHECK(has(chain, "c1.ngc\", \"setup\": \"none\", \"removed_mm3\""));
  CHECK(has(chain, "c2.ngc\", \"setup\": \"flip-x\", \"removed_mm3\""));
  // An output of the last program never replaces an earlier one.
  const std::string c1 = slurp(tmp_dir() + "/c1.ngc");
  CHECK_EQ(run("%/c1.ngc" + stock + " %/c2.ngc --report %/c1.ngc").code, 2);
  CHECK(slurp(tmp_dir() + "/c1.ngc") == c1);
  // A setup before the first program turns nothing saved: refused.
  const Result r = run("--setup flip-y %/c1.ngc" + stock + " %/c2.ngc");
  CHECK_EQ(r.code, 2);
  CHECK(has(r.err, "--setup turns a saved stock"));
}

TEST(run_saved_stock_says_when_its_material_changes) {
  if (skip()) return;
  write_tmp("m1.ngc", "G21 G90\nG0 X5 Y5 Z5\nG1 Z-1 F300\nG1 X20 F600\nG0 Z5\nM30\n");
  CHECK_EQ(run("%/m1.ngc -q --tool flat:3 --stock 0,0,-5,30,20,0 --material wood --save-stock %/wood.dxstock").code, 0);
  Result r = run("%/m1.ngc -q --tool flat:3 --stock %/wood.dxstock --material aluminium");
  CHECK(has(r.err, "--material 'aluminium': the stock in"));
  r = run("%/m1.ngc -q --tool flat:3 --stock %/wood.dxstock --material wood");
  CHECK(lacks(r.err, "was cut with"));
}
