// The embedding API (display/api/dexmill.h) from C++: a run through it cuts
// the bits the engine cuts, fed in any pieces or by line, with any budget;
// nothing allocates after dm_create; findings and input errors come with
// their lines; bad input is a status, never a crash; a view redrawn bit by
// bit equals one drawn once.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/sim/simulation.h"
#include "core/tool/spec.h"
#include "display/api/dexmill.h"
#include "display/api/handles.h"
#include "tests/alloc_count.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

constexpr int64_t mm = DM_NM_PER_MM;

void set_box(dm_box* b, int64_t x0, int64_t y0, int64_t z0, int64_t x1, int64_t y1, int64_t z1) {
  b->lo_nm[0] = x0;
  b->lo_nm[1] = y0;
  b->lo_nm[2] = z0;
  b->hi_nm[0] = x1;
  b->hi_nm[1] = y1;
  b->hi_nm[2] = z1;
}

// The test programs' stock: 0..33 x 0..23 x -10..0 mm at 0.1 mm, flat:6.
dm_job pocket_job() {
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION), DM_OK);
  set_box(&j.stock, 0, 0, -10 * mm, 33 * mm, 23 * mm, 0);
  j.pitch_nm = 100000;
  j.tool.spec = "flat:6";
  return j;
}

// A simulation with its memory.
struct Api {
  std::vector<uint64_t> mem;
  dm_sim* sim = nullptr;
  explicit Api(const dm_job& j) {
    size_t n = 0;
    CHECK_EQ(dm_required_bytes(&j, &n), DM_OK);
    mem.assign(n / 8 + 1, 0);
    CHECK_EQ(dm_create(&j, mem.data(), n, &sim), DM_OK);
  }
  ~Api() { dm_destroy(sim); }
  // Feeds text in pieces of `piece` bytes, stepping with b between; the
  // final state.
  int32_t run(const std::string& text, size_t piece, const dm_budget* b = nullptr) {
    size_t at = 0;
    int32_t state = DM_READY;
    for (int guard = 0; guard < 10000000; ++guard) {
      CHECK_EQ(dm_step(sim, b, &state), DM_OK);
      if (state == DM_NEED_INPUT) {
        if (at >= text.size()) {
          CHECK_EQ(dm_end_input(sim), DM_OK);
        } else {
          const size_t n = std::min(piece, text.size() - at);
          CHECK_EQ(dm_feed(sim, text.data() + at, n), DM_OK);
          at += n;
        }
        continue;
      }
      if (state != DM_READY) break;
    }
    return state;
  }
  uint64_t grid_hash() const { return dexmill::grid_hash(sim->sim->grid()); }
};

std::string pocket_text() { return run_cli::slurp(std::string(t::tests_dir()) + "/run/pocket.ngc"); }

// The same job for the engine directly.
SimJob engine_job() {
  SimJob j;
  const StockBox box{PointNm{0, 0, -10 * mm}, PointNm{33 * mm, 23 * mm, 0}};
  CHECK(plan_grid(box, 0, 0, 100000, &j.plan) == PlanError::kOk);
  CHECK(tool_spec_parse("flat:6", 6, &j.tool) == ToolSpecError::kOk);
  j.input_buffer_bytes = LineReader::kStartBytes;
  return j;
}

uint64_t engine_hash(const std::string& text) {
  const SimJob j = engine_job();
  std::vector<uint64_t> mem(sim_required_bytes(j) / 8 + 1);
  Simulation* s = sim_create(j, mem.data(), mem.size() * 8);
  CHECK(s != nullptr);
  if (!s) return 0;
  s->feed(text.data(), text.size());
  s->close_input();
  while (s->step(SimBudget()) == SimState::kReady) {
  }
  const uint64_t h = grid_hash(s->grid());
  sim_destroy(s);
  return h;
}

}  // namespace

// Pieces of any size, by line, and budgets down to one move cut what the
// engine cuts in one go.
TEST(api_runs_cut_as_the_engine_does) {
  const std::string prog = pocket_text();
  CHECK(prog.size() > 200);
  const uint64_t want = engine_hash(prog);
  dm_budget one{};
  one.moves = 1;
  dm_budget few{};
  few.dexel_updates = 500;
  few.lines = 2;
  const dm_budget* budgets[3] = {nullptr, &one, &few};
  const size_t pieces[3] = {4096, 7, 1};
  for (int k = 0; k < 3; ++k) {
    Api a(pocket_job());
    CHECK_EQ(a.run(prog, pieces[k], budgets[k]), DM_DONE);
    CHECK_EQ(a.grid_hash(), want);
    dm_progress p;
    CHECK_EQ(dm_get_progress(a.sim, &p), DM_OK);
    CHECK_EQ(p.state, DM_DONE);
    CHECK_EQ(p.errors, 0u);
    CHECK(p.moves > 15);
    CHECK(p.removed_um3 > 0);
  }
  // By line: each copied, a line end added.
  Api a(pocket_job());
  size_t at = 0;
  int32_t state = DM_READY;
  for (int guard = 0; guard < 100000 && state != DM_DONE; ++guard) {
    CHECK_EQ(dm_step(a.sim, &one, &state), DM_OK);
    if (state != DM_NEED_INPUT) continue;
    if (at >= prog.size()) {
      CHECK_EQ(dm_end_input(a.sim), DM_OK);
      continue;
    }
    const size_t end = prog.find('\n', at);
    CHECK_EQ(dm_feed_line(a.sim, prog.data() + at, end - at), DM_OK);
    at = end + 1;
  }
  CHECK_EQ(state, DM_DONE);
  CHECK_EQ(a.grid_hash(), want);
}

namespace {

// A deadline that has passed after `left` records.
struct Deadline {
  int left = 0;
  int asked = 0;
};
int32_t deadline_passed(void* ctx) {
  Deadline* d = static_cast<Deadline*>(ctx);
  ++d->asked;
  return d->left-- <= 0 ? 1 : 0;
}

}  // namespace

// The yield callback ends a step after the record it answers 1 to; the cut
// is the same.
TEST(api_yield_ends_a_step) {
  const std::string prog = pocket_text();
  Api a(pocket_job());
  CHECK_EQ(dm_feed(a.sim, prog.data(), prog.size()), DM_OK);
  CHECK_EQ(dm_end_input(a.sim), DM_OK);
  Deadline d;
  dm_budget b{};
  b.yield = deadline_passed;
  b.yield_ctx = &d;
  int32_t state = DM_READY;
  int steps = 0;
  uint64_t most = 0, last = 0;
  while (state == DM_READY && steps < 100000) {
    d.left = 1;  // two records a step
    CHECK_EQ(dm_step(a.sim, &b, &state), DM_OK);
    dm_progress p;
    CHECK_EQ(dm_get_progress(a.sim, &p), DM_OK);
    most = std::max<uint64_t>(most, p.records - last);
    last = p.records;
    ++steps;
  }
  CHECK_EQ(state, DM_DONE);
  CHECK_EQ(most, uint64_t{2});
  CHECK(steps > 10);
  CHECK(d.asked >= 2 * (steps - 1));
  CHECK_EQ(a.grid_hash(), engine_hash(prog));
}

// What the API says about the cut: heights where the pocket was cut, the
// volume it removed, where the tool ended.
TEST(api_heights_volume_and_position) {
  Api a(pocket_job());
  CHECK_EQ(a.run(pocket_text(), 4096), DM_DONE);
  int64_t z = 0;
  CHECK_EQ(dm_height_nm(a.sim, 15 * mm, 7 * mm, &z), DM_OK);  // the pocket's floor, 3 mm deep
  CHECK_EQ(z, -3 * mm);
  CHECK_EQ(dm_height_nm(a.sim, 31 * mm, 2 * mm, &z), DM_OK);  // uncut
  CHECK_EQ(z, 0);
  CHECK_EQ(dm_height_nm(a.sim, 100 * mm, 2 * mm, &z), DM_E_OUTSIDE);
  CHECK_EQ(dm_height_nm(a.sim, 0, -5 * mm, &z), DM_E_OUTSIDE);
  dm_column c;
  CHECK_EQ(dm_column_at(a.sim, 28 * mm, 18 * mm, &c), DM_OK);  // the drilled hole's axis, 8 mm deep
  CHECK_EQ(c.top_nm, -8 * mm);
  CHECK_EQ(c.last_tool, -2);  // no provenance asked for
  dm_progress p;
  CHECK_EQ(dm_get_progress(a.sim, &p), DM_OK);
  CHECK_EQ(p.position_nm[2], 10 * mm);  // the last move, G0 Z10
  CHECK_EQ(p.line, 23u);                // the last record, M30
  dm_grid_info g;
  CHECK_EQ(dm_get_grid(a.sim, &g), DM_OK);
  CHECK_EQ(g.pitch_nm, int64_t{100000});
  // The volume, exactly: LSB dexels times the dexel's column.
  const long double um3 = static_cast<long double>(p.removed_lsb_dexels) * g.lsb_nm * g.pitch_nm * g.pitch_nm / 1e9L;
  CHECK_NEAR(static_cast<long double>(p.removed_um3), um3, 0.5L);
  // A pocket of 26 x 16 mm (the 6 mm tool around 20 x 10) 3 mm deep at least.
  CHECK(p.removed_um3 > 26ull * 16 * 3 * 1000000000ull);
}

// Findings with their lines: a rapid into the stock, a gouge under a
// design, which tool cut a column.
TEST(api_findings) {
  {
    dm_job j = pocket_job();
    j.checks = DM_CHECK_RAPID;
    Api a(j);
    CHECK_EQ(a.run("G21 G90\nG0 X5 Y5 Z5\nM3 S1000\nG0 Z-1\nG0 X15\nG1 X20 F100\nM30\n", 4096), DM_DONE);
    CHECK(dm_finding_count(a.sim) >= 1);
    CHECK_EQ(dm_finding_total(a.sim), uint64_t{dm_finding_count(a.sim)});
    dm_finding f;
    CHECK_EQ(dm_finding_get(a.sim, 0, &f), DM_OK);
    CHECK_EQ(f.kind, DM_FIND_RAPID);
    CHECK(f.line == 4u || f.line == 5u);
    CHECK(std::strcmp(dm_finding_name(f.kind), "rapid") == 0);
    CHECK_EQ(dm_finding_get(a.sim, dm_finding_count(a.sim), &f), DM_E_INDEX);
  }
  {
    // A design 2 mm under the top over the whole stock; the pocket goes 3 mm.
    dm_job j = pocket_job();
    const dm_triangle tris[2] = {{{{-5 * mm, -5 * mm, -2 * mm}, {40 * mm, -5 * mm, -2 * mm}, {40 * mm, 30 * mm, -2 * mm}}},
                                 {{{-5 * mm, -5 * mm, -2 * mm}, {40 * mm, 30 * mm, -2 * mm}, {-5 * mm, 30 * mm, -2 * mm}}}};
    j.design = tris;
    j.ndesign = 2;
    j.provenance = 1;
    Api a(j);
    CHECK_EQ(a.run(pocket_text(), 4096), DM_DONE);
    CHECK(dm_finding_count(a.sim) >= 1);
    dm_finding f;
    CHECK_EQ(dm_finding_get(a.sim, 0, &f), DM_OK);
    CHECK_EQ(f.kind, DM_FIND_GOUGE);
    CHECK_EQ(f.line, 10u);  // the second pass, at Z-3
    CHECK_EQ(f.depth_nm, 1 * mm);
    CHECK_EQ(f.at_nm[2], -2 * mm);
    dm_column c;
    CHECK_EQ(dm_column_at(a.sim, 15 * mm, 7 * mm, &c), DM_OK);
    CHECK_EQ(c.last_tool, -1);  // the job's tool, no M6
    CHECK(c.last_line >= 10u && c.last_line <= 13u);
    CHECK_EQ(dm_column_at(a.sim, 31 * mm, 2 * mm, &c), DM_OK);
    CHECK_EQ(c.last_tool, -2);  // uncut
  }
  {
    // The job stops at the end of the line that gouged.
    dm_job j = pocket_job();
    const dm_triangle tri = {{{-5 * mm, -5 * mm, -2 * mm}, {80 * mm, -5 * mm, -2 * mm}, {-5 * mm, 80 * mm, -2 * mm}}};
    j.design = &tri;
    j.ndesign = 1;
    j.stop_at = DM_STOP_AT_GOUGE;
    Api a(j);
    CHECK_EQ(a.run(pocket_text(), 4096), DM_STOPPED);
    dm_progress p;
    CHECK_EQ(dm_get_progress(a.sim, &p), DM_OK);
    CHECK_EQ(p.stop_reason, DM_STOPPED_GOUGE);
    CHECK_EQ(p.stop_line, 10u);
  }
}

// Input errors: code, line, column and message.
TEST(api_input_errors) {
  Api a(pocket_job());
  CHECK_EQ(a.run("G21\nG1 X1 Q F100\nG0 Z1\n", 4096), DM_STOPPED);
  CHECK_EQ(dm_error_count(a.sim), 1u);
  dm_input_error e;
  CHECK_EQ(dm_error_get(a.sim, 0, &e), DM_OK);
  CHECK_EQ(e.line, 2u);
  CHECK_EQ(e.col, 7u);
  CHECK_EQ(e.code, gcode_error_number(GcodeError::kMissingNumber));
  char msg[128];
  CHECK(dm_error_message(a.sim, 0, msg, sizeof msg) > 5);
  CHECK(std::strstr(msg, "'Q'") != nullptr);
  CHECK_EQ(dm_error_get(a.sim, 1, &e), DM_E_INDEX);
  CHECK_EQ(dm_error_message(a.sim, 1, msg, sizeof msg), size_t{0});
  dm_progress p;
  CHECK_EQ(dm_get_progress(a.sim, &p), DM_OK);
  CHECK_EQ(p.stop_reason, DM_STOPPED_INPUT_ERROR);
}

// Bad input is a status with a message, never a crash.
TEST(api_bad_input_is_a_status) {
  for (int32_t s = DM_OK; s <= DM_E_IO; ++s) CHECK(std::strcmp(dm_status_message(s), "unknown status") != 0);
  CHECK(std::strcmp(dm_status_message(99), "unknown status") == 0);
  dm_job j;
  CHECK_EQ(dm_job_init(&j, DEXMILL_API_VERSION + 1), DM_E_VERSION);
  CHECK_EQ(dm_job_init(nullptr, DEXMILL_API_VERSION), DM_E_ARGUMENT);
  CHECK_EQ(dm_version(), uint32_t{DEXMILL_API_VERSION});
  size_t n = 0;
  CHECK_EQ(dm_required_bytes(nullptr, &n), DM_E_ARGUMENT);
  struct Case {
    void (*change)(dm_job*);
    dm_status want;
  };
  const Case cases[] = {
      {[](dm_job* x) { x->api_version = 0; }, DM_E_VERSION},
      {[](dm_job* x) { x->stock.hi_nm[0] = x->stock.lo_nm[0]; }, DM_E_STOCK},
      {[](dm_job* x) { x->stock.lo_nm[1] = INT64_MIN; }, DM_E_STOCK},
      {[](dm_job* x) { x->tool.spec = "spoon:6"; }, DM_E_TOOL_SPEC},
      {[](dm_job* x) { x->tool.spec = "bull:6:4"; }, DM_E_TOOL},
      {[](dm_job* x) {
         x->tool.spec = nullptr;
         x->tool.shape = 9;
       },
       DM_E_ARGUMENT},
      {[](dm_job* x) {
         x->tool.spec = nullptr;
         x->tool.shape = DM_TOOL_BALL;
         x->tool.diameter_nm = 0;
       },
       DM_E_TOOL},
      {[](dm_job* x) {
         x->pitch_nm = 0;
         x->grid_nx = 3;
         x->grid_ny = 3;
       },
       DM_E_GRID},
      {[](dm_job* x) { x->pitch_nm = 10; }, DM_E_GRID},
      {[](dm_job* x) { x->mode = 7; }, DM_E_ARGUMENT},
      {[](dm_job* x) { x->ntools = DM_TOOLS_MAX + 1; }, DM_E_TOOL_NUMBER},
      {[](dm_job* x) {
         x->ntools = 2;
         x->tools[0].spec = x->tools[1].spec = "ball:3";
         x->tools[0].number = x->tools[1].number = 4;
       },
       DM_E_TOOL_NUMBER},
      {[](dm_job* x) { x->nfixtures = -1; }, DM_E_FIXTURES},
      {[](dm_job* x) {
         x->nfixtures = 1;
         set_box(&x->fixtures[0], 10010000, 10010000, 0, 10050000, 10050000, 5 * mm);  // between dexel axes
       },
       DM_E_FIXTURES},
      {[](dm_job* x) { x->material = "cheese"; }, DM_E_MATERIAL},
      {[](dm_job* x) { x->ndesign = 3; }, DM_E_ARGUMENT},
      {[](dm_job* x) { x->input_buffer_bytes = 10; }, DM_E_ARGUMENT},
      {[](dm_job* x) { x->checks = 1u << 20; }, DM_E_ARGUMENT},
  };
  for (const Case& c : cases) {
    dm_job bad = pocket_job();
    c.change(&bad);
    if (!CHECK_EQ(dm_required_bytes(&bad, &n), c.want)) std::printf("  case %d\n", static_cast<int>(&c - cases));
    std::vector<uint64_t> mem(1 << 17);
    dm_sim* s = reinterpret_cast<dm_sim*>(1);
    CHECK_EQ(dm_create(&bad, mem.data(), mem.size() * 8, &s), c.want);
    CHECK(s == nullptr);
  }
  // A design that lies off the grid, found when the memory is set up.
  dm_job off = pocket_job();
  const dm_triangle far = {{{0, 0, 0}, {1, 0, 0}, {0, 2000 * mm, 0}}};
  off.design = &far;
  off.ndesign = 1;
  CHECK_EQ(dm_required_bytes(&off, &n), DM_OK);
  std::vector<uint64_t> mem(n / 8 + 1);
  dm_sim* s = nullptr;
  CHECK_EQ(dm_create(&off, mem.data(), n, &s), DM_E_DESIGN);
  // Memory: short, misaligned, null.
  const dm_job good = pocket_job();
  CHECK_EQ(dm_required_bytes(&good, &n), DM_OK);
  mem.assign(n / 8 + 2, 0);
  CHECK_EQ(dm_create(&good, mem.data(), n - 1, &s), DM_E_MEMORY);
  CHECK_EQ(dm_create(&good, reinterpret_cast<char*>(mem.data()) + 4, n, &s), DM_E_MEMORY);
  CHECK_EQ(dm_create(&good, nullptr, n, &s), DM_E_MEMORY);
  CHECK_EQ(dm_create(&good, mem.data(), n, &s), DM_OK);
  // Calls out of turn.
  CHECK_EQ(dm_feed(s, "G0 X1\n", 6), DM_OK);
  CHECK_EQ(dm_feed(s, "G0 X2\n", 6), DM_E_BUSY);  // the reader waits for 64 KiB or the end
  CHECK_EQ(dm_feed(s, nullptr, 3), DM_E_ARGUMENT);
  char longer[DM_LINE_MAX + 2] = {};
  CHECK_EQ(dm_feed_line(s, longer, sizeof longer), DM_E_LINE);
  int32_t state = -1;
  CHECK_EQ(dm_step(s, nullptr, nullptr), DM_E_ARGUMENT);
  CHECK_EQ(dm_step(s, nullptr, &state), DM_OK);
  CHECK_EQ(state, DM_NEED_INPUT);
  CHECK_EQ(dm_input_taken(s), 1);
  CHECK_EQ(dm_end_input(s), DM_OK);
  CHECK_EQ(dm_feed(s, "G0 X3\n", 6), DM_E_STATE);
  CHECK_EQ(dm_step(s, nullptr, &state), DM_OK);
  CHECK_EQ(state, DM_DONE);
  dm_view* v = nullptr;
  dm_frame f{nullptr, 64, 48, 256, DM_XRGB8888};
  CHECK_EQ(dm_view_bytes(s, 64, 0, &n), DM_E_FRAME);
  CHECK_EQ(dm_view_create(s, &f, nullptr, mem.data(), mem.size() * 8, &v), DM_E_FRAME);  // no pixels
  std::vector<uint32_t> px(64 * 48);
  f.pixels = px.data();
  f.format = 5;
  CHECK_EQ(dm_view_create(s, &f, nullptr, mem.data(), mem.size() * 8, &v), DM_E_FRAME);
  f.format = DM_XRGB8888;
  const dm_camera steep{DM_VIEW_ISO, 1, 0, 95000};
  CHECK_EQ(dm_view_create(s, &f, &steep, mem.data(), mem.size() * 8, &v), DM_E_ARGUMENT);
  dm_destroy(s);
  CHECK_EQ(dm_step(s, nullptr, &state), DM_E_ARGUMENT);  // destroyed
  CHECK_EQ(dm_get_progress(nullptr, nullptr), DM_E_ARGUMENT);
  dm_destroy(nullptr);
  dm_view_destroy(nullptr);
}

namespace {

// A view's frame with its memory.
struct Frame {
  std::vector<uint8_t> pixels;
  std::vector<uint64_t> mem;
  dm_view* view = nullptr;
  Frame(dm_sim* s, int32_t w, int32_t h, int32_t format, int32_t pad, uint32_t flags = 0) {
    const int32_t stride = w * (format == DM_RGB565 ? 2 : 4) + pad;
    pixels.assign(static_cast<size_t>(stride) * h, 0);
    size_t n = 0;
    CHECK_EQ(dm_view_bytes_flags(s, w, h, format, flags, &n), DM_OK);
    mem.assign(n / 8 + 1, 0);
    const dm_frame f{pixels.data(), w, h, stride, format};
    CHECK_EQ(dm_view_create_flags(s, &f, nullptr, flags, mem.data(), n, &view), DM_OK);
  }
  ~Frame() { dm_view_destroy(view); }
};

}  // namespace

namespace {

// A view drawn after every few moves (incremental redraw) ends with the
// pixels of one drawn once at the end, in both formats and with padded
// rows; nothing allocates once the simulation and views are made.
void check_incremental_redraw(uint32_t flags) {
  for (int32_t format : {DM_XRGB8888, DM_RGB565}) {
    Api a(pocket_job());
    Frame often(a.sim, 160, 120, format, 12, flags), once(a.sim, 160, 120, format, 12, flags);
    const std::string prog = pocket_text();
    const uint64_t before = t::heap_allocations();
    dm_budget b{};
    b.moves = 3;
    size_t at = 0;
    int32_t state = DM_READY;
    int renders = 0, partial = 0;
    for (int guard = 0; guard < 100000; ++guard) {
      CHECK_EQ(dm_step(a.sim, &b, &state), DM_OK);
      if (state == DM_NEED_INPUT) {
        if (at < prog.size()) {
          CHECK_EQ(dm_feed(a.sim, prog.data() + at, std::min<size_t>(64, prog.size() - at)), DM_OK);
          at += 64;
        } else {
          CHECK_EQ(dm_end_input(a.sim), DM_OK);
        }
        continue;
      }
      dm_rect rects[DM_RECTS_MAX];
      int32_t n = 0;
      CHECK_EQ(dm_render(often.view, rects, DM_RECTS_MAX, &n), DM_OK);
      ++renders;
      if (n > 0 && rects[0].x1 - rects[0].x0 < 160) ++partial;
      if (state != DM_READY) break;
    }
    dm_rect all;
    int32_t n = 0;
    CHECK_EQ(dm_render(once.view, &all, 1, &n), DM_OK);  // its rectangles merged into one
    dm_progress p;
    CHECK_EQ(dm_get_progress(a.sim, &p), DM_OK);
    CHECK_EQ(t::heap_allocations(), before);
    CHECK_EQ(state, DM_DONE);
    CHECK_EQ(n, 1);
    CHECK(all.x0 == 0 && all.y0 == 0 && all.x1 == 160 && all.y1 == 120);
    CHECK(renders > 5);
    CHECK(partial > 0);  // some redraws were not whole frames
    CHECK(often.pixels == once.pixels);
    // The pixels are a picture: the stock's grey and the background differ.
    size_t distinct = 0;
    for (size_t k = 4; k < once.pixels.size(); k += 4)
      if (std::memcmp(&once.pixels[k], &once.pixels[0], 2) != 0) ++distinct;
    CHECK(distinct > 1000);
    // A second render with nothing changed repaints nothing.
    dm_rect r[4];
    CHECK_EQ(dm_render(once.view, r, 4, &n), DM_OK);
    CHECK_EQ(n, 0);
    // After the simulation ends, its views refuse to draw.
    dm_destroy(a.sim);
    CHECK_EQ(dm_render(once.view, r, 4, &n), DM_E_STATE);
    a.sim = nullptr;
  }
}

}  // namespace

TEST(api_views_redraw_incrementally_without_heap) { check_incremental_redraw(0); }

// Anti-aliased (DM_VIEW_ANTIALIAS): a partial redraw resolves only what
// changed, on the renderer's tiles, and still equals a whole one.
TEST(api_antialiased_views_redraw_incrementally_without_heap) { check_incremental_redraw(DM_VIEW_ANTIALIAS); }

// DM_VIEW_ANTIALIAS against an aliased view of the same cut: its memory
// holds the frame at twice the size; inside regions of one colour the two
// pictures are the same, at the edges they differ; bad flags and frames too
// large to double are refused.
TEST(api_antialiased_view_memory_edges_and_refusals) {
  Api a(pocket_job());
  size_t plain_n = 0, aa_n = 0, aa565_n = 0, n = 0;
  CHECK_EQ(dm_view_bytes(a.sim, 320, 240, &plain_n), DM_OK);
  CHECK_EQ(dm_view_bytes_flags(a.sim, 320, 240, DM_XRGB8888, DM_VIEW_ANTIALIAS, &aa_n), DM_OK);
  CHECK_EQ(dm_view_bytes_flags(a.sim, 320, 240, DM_RGB565, DM_VIEW_ANTIALIAS, &aa565_n), DM_OK);
  std::printf("  view bytes 320x240: %zu aliased, %zu anti-aliased (XRGB8888), %zu (RGB565)\n", plain_n, aa_n, aa565_n);
  CHECK(aa_n > 4 * plain_n && aa_n < 6 * plain_n);  // 4x the scratch, and the doubled frame
  CHECK_EQ(aa_n - aa565_n, static_cast<size_t>(640 * 480 * 2));  // the doubled frame's pixels, 4 or 2 bytes
  CHECK_EQ(dm_view_bytes_flags(a.sim, 320, 240, DM_XRGB8888, 2, &n), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_bytes_flags(a.sim, 320, 240, 7, 0, &n), DM_E_FRAME);
  CHECK_EQ(dm_view_bytes_flags(a.sim, DM_FRAME_MAX_SIDE / 2 + 1, 240, DM_XRGB8888, DM_VIEW_ANTIALIAS, &n), DM_E_FRAME);
  CHECK_EQ(dm_view_bytes_flags(a.sim, DM_FRAME_MAX_SIDE / 2 + 1, 240, DM_XRGB8888, 0, &n), DM_OK);
  std::vector<uint64_t> mem(aa_n / 8 + 1, 0);
  std::vector<uint32_t> px(320 * 240, 0);
  const dm_frame f{px.data(), 320, 240, 320 * 4, DM_XRGB8888};
  dm_view* v = nullptr;
  CHECK_EQ(dm_view_create_flags(a.sim, &f, nullptr, 4, mem.data(), aa_n, &v), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_create_flags(a.sim, &f, nullptr, DM_VIEW_ANTIALIAS, mem.data(), aa_n - 8, &v), DM_E_MEMORY);
  CHECK(v == nullptr);
  Frame plain(a.sim, 320, 240, DM_XRGB8888, 0), aa(a.sim, 320, 240, DM_XRGB8888, 0, DM_VIEW_ANTIALIAS);
  CHECK_EQ(a.run(pocket_text(), 4096), DM_DONE);
  dm_rect r[DM_RECTS_MAX];
  int32_t nr = 0;
  CHECK_EQ(dm_render(plain.view, r, DM_RECTS_MAX, &nr), DM_OK);
  CHECK_EQ(dm_render(aa.view, r, DM_RECTS_MAX, &nr), DM_OK);
  auto at = [](const Frame& fr, int32_t x, int32_t y) {
    uint32_t p;
    std::memcpy(&p, &fr.pixels[(static_cast<size_t>(y) * 320 + x) * 4], 4);
    return p;
  };
  int flat = 0, flat_same = 0, differ = 0;
  for (int32_t y = 1; y < 239; ++y)
    for (int32_t x = 1; x < 319; ++x) {
      differ += at(plain, x, y) != at(aa, x, y);
      bool one = true;
      for (int32_t dy = -1; dy <= 1; ++dy)
        for (int32_t dx = -1; dx <= 1; ++dx) one = one && at(plain, x + dx, y + dy) == at(plain, x, y);
      if (!one) continue;
      ++flat;
      flat_same += at(aa, x, y) == at(plain, x, y);
    }
  std::printf("  %d of %d flat pixels equal, %d pixels differ\n", flat_same, flat, differ);
  CHECK_GT(flat, 20000);
  CHECK_EQ(flat_same, flat);
  CHECK_GT(differ, 300);
}

// dm_view_set_decorations: the triad and scale bar in the bottom-left
// corner only (an iso view of this stock leaves the corner free, so the
// framing stays), and gone again when turned off.
TEST(api_view_decorations_in_their_corner) {
  Api a(pocket_job());
  Frame plain(a.sim, 320, 240, DM_XRGB8888, 0), deco(a.sim, 320, 240, DM_XRGB8888, 0);
  CHECK_EQ(dm_view_set_decorations(nullptr, 1), DM_E_ARGUMENT);
  CHECK_EQ(dm_view_set_decorations(deco.view, 1), DM_OK);
  CHECK_EQ(a.run(pocket_text(), 4096), DM_DONE);
  dm_rect r[DM_RECTS_MAX];
  int32_t n = 0;
  CHECK_EQ(dm_render(plain.view, r, DM_RECTS_MAX, &n), DM_OK);
  CHECK_EQ(dm_render(deco.view, r, DM_RECTS_MAX, &n), DM_OK);
  int differ = 0, outside = 0;
  for (int32_t y = 0; y < 240; ++y)
    for (int32_t x = 0; x < 320; ++x) {
      const bool d = std::memcmp(&plain.pixels[(y * 320 + x) * 4], &deco.pixels[(y * 320 + x) * 4], 4) != 0;
      differ += d;
      outside += d && !(x < 160 && y >= 170);
    }
  CHECK_GT(differ, 300);
  CHECK_EQ(outside, 0);
  CHECK_EQ(dm_view_set_decorations(deco.view, 0), DM_OK);
  CHECK_EQ(dm_render(deco.view, r, DM_RECTS_MAX, &n), DM_OK);
  CHECK(deco.pixels == plain.pixels);
}
