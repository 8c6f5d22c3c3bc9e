// The engine (core/sim/simulation.h) driven directly, as every front end
// drives it: budgets that stop at any record give the same bits as one
// run, text fed in pieces of any size reads as the file does, a line longer
// than the record queue is cut whole, no heap while it runs, and what the
// observers charge to a line does not depend on records that do not move.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/grid/volume.h"
#include "core/sim/chunk_input.h"
#include "core/sim/simulation.h"
#include "core/tool/spec.h"
#include "platform/input/gcode_file.h"
#include "platform/report/report_json.h"
#include "tests/alloc_count.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"
#include "tests/sim_util.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = kNmPerMm;

using sim_test::box_job;
using sim_test::Engine;

const char kRapidIntoStock[] =
    "G21 G90\nG0 X0 Y0 Z5\nM3 S1000\nG0 Z-1\nG0 X10\nG1 X20 F100\nM30\n";
const char kRapidIntoStockS[] =
    "G21 G90\nG0 X0 Y0 Z5\nM3 S1000\nG0 Z-1\nG0 X10\nS2000 G1 X20 F100\nM30\n";

}  // namespace

// The bug this engine ended (one copy of the run's steps left): the CLI's
// sink took a record that does not move (the S word) as the line a
// deferred end cap belongs to, so the rapid's cap went to the feed.
TEST(sim_rapid_removal_does_not_depend_on_an_s_word) {
  uint64_t removed[2] = {0, 0}, hash[2] = {0, 0};
  const char* programs[2] = {kRapidIntoStock, kRapidIntoStockS};
  for (int k = 0; k < 2; ++k) {
    SimJob j = box_job(-5 * mm, -5 * mm, -5 * mm, 30 * mm, 10 * mm, 100000, "flat:6");
    j.checks.rapid = true;
    Engine e(j);
    CHECK(e.run(programs[k], 4096) == SimState::kDone);
    CHECK(e.sim->safety() != nullptr);
    removed[k] = e.sim->safety()->rapid_removed_lsb;
    hash[k] = e.grid_hash();
  }
  CHECK_EQ(hash[0], hash[1]);
  CHECK(removed[0] > 0);
  CHECK_EQ(removed[0], removed[1]);
}

// The same set up as `dexmill run` sets it up (the program read from a
// file, a line a step): the report's rapid_removed_mm3 is the same for both.
TEST(sim_run_rapid_removal_does_not_depend_on_an_s_word) {
  std::string vol[2];
  const char* programs[2] = {kRapidIntoStock, kRapidIntoStockS};
  dexmill::SimBudget line;
  line.lines = 1;
  for (int k = 0; k < 2; ++k) {
    sim_test::Run r;
    r.stock("-5,-5,-5,30,10,0").tool("flat:6").pitch("0.1");
    r.o.job.checks.rapid = true;
    CHECK(r.text(k ? "s_word.ngc" : "no_s_word.ngc", programs[k], line));
    const DexelGrid<height_t>& g = r.sim().grid();
    vol[k] = volume_mm3_text(r.sim().safety()->rapid_removed_lsb, g.lsb_nm, g.pitch_nm);
  }
  CHECK(vol[0] != "0.000");
  CHECK(vol[0] == vol[1]);
  if (vol[0] != vol[1]) std::printf("  %s against %s\n", vol[0].c_str(), vol[1].c_str());
}

namespace {

// A program with lines of every kind of record: arcs, a canned cycle of
// many pecks (more records than a small queue holds), tool changes.
std::string busy_program() {
  std::string s = "G21 G90 G17\nT1 M6\nM3 S8000\nG0 X2 Y2 Z3\nG1 Z-1 F300\n";
  for (int k = 0; k < 12; ++k) {
    char b[120];
    std::snprintf(b, sizeof b, "G1 X%d Y%d Z-%d.%d F600\nG2 X%d Y%d I2 J0\n", 4 + 2 * k, 3 + k % 5, 1 + k % 3, k % 10,
                  8 + 2 * k, 3 + k % 5);
    s += b;
  }
  s += "G0 Z3\nT2 M6\nG0 X20 Y12\nG83 X20 Y12 Z-4 R1 Q0.05 F200\nG80\nG0 Z5\nM30\n";
  return s;
}

class TwoTools final : public ToolLibrary {
 public:
  bool tool(int32_t n, Tool* out) const override {
    const char* spec = n == 2 ? "ball:3" : "flat:4";
    return tool_spec_parse(spec, std::strlen(spec), out) == ToolSpecError::kOk;
  }
};

}  // namespace

// Budgets end a step at a record; what is cut does not depend on where.
TEST(sim_budgets_and_pieces_give_the_same_bits) {
  const TwoTools lib;
  Tool tools[2];
  CHECK(lib.tool(1, &tools[0]) && lib.tool(2, &tools[1]));
  const std::string prog = busy_program();
  uint64_t ref = 0, ref_updates = 0, ref_moves = 0;
  struct Way {
    size_t piece;
    uint64_t moves, updates;
    uint32_t queue;
  };
  const Way ways[] = {{1 << 20, UINT64_MAX, UINT64_MAX, 64}, {1, 1, UINT64_MAX, 64}, {7, 3, UINT64_MAX, 4},
                      {4096, UINT64_MAX, 500, 2},           {13, 1, 1, 1}};
  for (const Way& w : ways) {
    SimJob j = box_job(0, 0, -8 * mm, 40 * mm, 20 * mm, 100000, "flat:4");
    j.library = &lib;
    j.tools = tools;
    j.ntools = 2;
    j.queue_records = w.queue;
    j.checks.rapid = j.checks.spindle = true;
    j.provenance = j.provenance_lines = true;
    Engine e(j);
    SimBudget b;
    b.moves = w.moves;
    b.dexel_updates = w.updates;
    CHECK(e.run(prog, w.piece, b) == SimState::kDone);
    CHECK_EQ(e.sim->errors(), 0u);
    const uint64_t h = e.grid_hash();
    if (!ref) {
      ref = h;
      ref_updates = e.sim->mill().stats().dexel_updates;
      ref_moves = e.sim->status().moves;
      CHECK(ref_moves > 200);  // the pecks are there
      continue;
    }
    CHECK_EQ(h, ref);
    CHECK_EQ(e.sim->mill().stats().dexel_updates, ref_updates);
    CHECK_EQ(e.sim->status().moves, ref_moves);
  }
}

// A budget of one move returns after one motion record; a line with more
// records than the queue holds is the one exception (its head is cut as
// the interpreter makes it).
TEST(sim_one_move_budget_returns_after_each_move) {
  for (uint32_t queue : {1024u, 4u}) {
    SimJob j = box_job(0, 0, -8 * mm, 40 * mm, 20 * mm, 200000, "flat:4");
    j.queue_records = queue;
    Engine e(j);
    const std::string prog = busy_program();
    e.sim->feed(prog.data(), prog.size());
    e.sim->close_input();
    SimBudget one;
    one.moves = 1;
    uint64_t last = 0, steps = 0, most = 0;
    for (SimState s = SimState::kReady; s == SimState::kReady; ++steps) {
      s = e.sim->step(one);
      const uint64_t now = e.sim->status().moves;
      most = std::max(most, now - last);
      last = now;
    }
    CHECK(e.sim->state() == SimState::kDone);
    CHECK(last > 300);
    if (queue > last) {
      CHECK_EQ(most, uint64_t{1});
      CHECK(steps >= last);
    } else {
      CHECK(most > 1);  // the peck cycle's line
    }
  }
}

// Text in pieces reads as the file: the same lines, the same errors, for
// the inputs the reader treats specially.
TEST(sim_pieces_read_as_the_file_does) {
  const std::string inputs[] = {
      std::string("\xef\xbb\xbfG0 X1\r\nG1 X2 F100\r\n(comment)\r\nG1 X3"),
      std::string("G0 X1\rG1 X2 F100\rG1 Y2\r"),  // an old Mac file
      std::string("G0 X1\n") + std::string(300, 'X') + "\nG1 X2 F100\n",
      std::string("G0\x01\x02\x03\x04 X1\n\x05\x06\x07"),  // not text
      std::string("G0 X1\nG1 X2 F100\nG1 Q\nG1 X3\n"),   // an error on line 3
  };
  int n = 0;
  for (const std::string& text : inputs) {
    const std::string path = run_cli::write_tmp("pieces.ngc", text.c_str());
    // The file, through a GcodeFile.
    std::vector<std::string> want;
    {
      GcodeFile f;
      CHECK(f.open(path.c_str()));
      for (;;) {
        const char* t = nullptr;
        size_t len = 0;
        uint32_t line = 0;
        const LineReader::Read r = f.next(&t, &len, &line);
        if (r == LineReader::Read::kEof || r == LineReader::Read::kIoError) break;
        want.push_back(std::to_string(line) + ":" + std::to_string(int(r)) + ":" +
                       (r == LineReader::Read::kLine ? std::string(t, len) : ""));
        if (r == LineReader::Read::kNotText || r == LineReader::Read::kEndless) break;
      }
    }
    for (size_t piece : {size_t(1), size_t(2), size_t(3), size_t(5), size_t(4096)}) {
      std::vector<char> buf(LineReader::kStartBytes);
      ChunkInput in(buf.data(), buf.size());
      std::vector<std::string> got;
      size_t at = 0;
      for (int guard = 0; guard < 100000; ++guard) {
        const char* t = nullptr;
        size_t len = 0;
        uint32_t line = 0;
        const LineReader::Read r = in.next(&t, &len, &line);
        if (r == LineReader::Read::kWait) {
          if (at >= text.size()) in.close();
          else {
            const size_t k = std::min(piece, text.size() - at);
            in.feed(text.data() + at, k);
            at += k;
          }
          continue;
        }
        if (r == LineReader::Read::kEof || r == LineReader::Read::kIoError) break;
        got.push_back(std::to_string(line) + ":" + std::to_string(int(r)) + ":" +
                      (r == LineReader::Read::kLine ? std::string(t, len) : ""));
        if (r == LineReader::Read::kNotText || r == LineReader::Read::kEndless) break;
      }
      CHECK(got == want);
      if (got != want) std::printf("  input %d in pieces of %zu: %zu lines against %zu\n", n, piece, got.size(), want.size());
    }
    ++n;
  }
}

namespace {

const char kLoop[] =
    "G21 G90\n#1 = 0\no100 while [#1 LT 3]\nG0 X[#1 * 5] Y2 Z1\nG1 Z-1 F200\nG1 Y8\nG0 Z1\n#1 = [#1 + 1]\n"
    "o100 endwhile\nM30\n";

struct Whole {
  const std::string* text;
};
size_t reread_whole(void* ctx, uint64_t offset, char* buf, size_t n) {
  const std::string& s = *static_cast<Whole*>(ctx)->text;
  if (offset >= s.size()) return 0;
  const size_t k = std::min<size_t>(n, s.size() - offset);
  std::memcpy(buf, s.data() + offset, k);
  return k;
}

}  // namespace

// An o-word loop fed in pieces: back in the buffer, or through the
// caller's re-reader, or (neither) an error at the loop, never a wrong cut.
TEST(sim_loops_in_fed_text) {
  const std::string text = kLoop;
  uint64_t ref = 0;
  for (int way = 0; way < 3; ++way) {
    SimJob j = box_job(-5 * mm, -5 * mm, -3 * mm, 20 * mm, 12 * mm, 200000, "flat:2");
    // way 0: the whole text fits the buffer; 1 and 2: a 16-byte buffer,
    // with and without a re-reader.
    j.input_buffer_bytes = way == 0 ? LineReader::kStartBytes : 16;
    Engine e(j);
    Whole w{&text};
    if (way == 1) e.sim->set_rereader(reread_whole, &w);
    const SimState s = e.run(text, 5);
    if (way < 2) {
      CHECK(s == SimState::kDone);
      CHECK_EQ(e.sim->errors(), 0u);
      if (way == 0) ref = e.grid_hash();
      else CHECK_EQ(e.grid_hash(), ref);
    } else {
      CHECK(s == SimState::kStopped);
      CHECK(e.sim->stop_reason() == SimStop::kInputError);
      int n = 0;
      const GcodeDiag* d = e.sim->diags(&n);
      CHECK_EQ(n, 1);
      if (n) CHECK(d[0].code == GcodeError::kOwordSeek);
    }
  }
}

// After create, the engine takes nothing from the heap.
TEST(sim_no_heap_while_cutting) {
  const TwoTools lib;
  Tool tools[2];
  CHECK(lib.tool(1, &tools[0]) && lib.tool(2, &tools[1]));
  SimJob j = box_job(0, 0, -8 * mm, 40 * mm, 20 * mm, 100000, "flat:4");
  j.library = &lib;
  j.tools = tools;
  j.ntools = 2;
  j.checks.rapid = j.checks.spindle = j.checks.below = true;
  j.provenance = true;
  Engine e(j);
  const std::string prog = busy_program();
  const uint64_t before = t::heap_allocations();
  SimBudget b;
  b.moves = 3;
  CHECK(e.run(prog, 100, b) == SimState::kDone);
  CHECK_EQ(t::heap_allocations(), before);
}

// What cannot be simulated says why, before any memory is given.
TEST(sim_setup_errors) {
  SimJob j = box_job(0, 0, -8 * mm, 40 * mm, 20 * mm, 100000, "flat:4");
  SimSetup why;
  Tool huge = j.tool;
  huge.diameter_nm = 600 * mm;
  huge.length_nm = 700 * mm;
  j.tools = &huge;
  j.ntools = 1;
  CHECK_EQ(sim_required_bytes(j, &why), size_t{0});
  CHECK(why.error == SimError::kToolTooLargeSweep);
  CHECK_EQ(why.tool, 0);
  j.ntools = 0;
  const size_t n = sim_required_bytes(j, &why);
  CHECK(n > 0);
  std::vector<uint64_t> mem(n / 8);  // a little short
  CHECK(sim_create(j, mem.data(), n - 8, &why) == nullptr);
  CHECK(why.error == SimError::kBufferTooSmall);
}
