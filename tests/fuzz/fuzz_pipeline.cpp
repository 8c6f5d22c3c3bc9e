// libFuzzer target: the whole pipeline, its set-up taken from the input.
// Bytes -> tool spec and tool table readers -> the simulation
// (core/sim/simulation.h: G-code reader, interpreter, cutting by sweep or
// stamp into a grid of the input's size, pitch and height type, the gouge
// watch, the time estimate) -> drawing step by step, render_update against
// render_full (tests/fuzz/fuzz_render.h), with backplot, error colours and
// the assessment when asked for. Any crash, sanitizer report, broken
// grid invariant or frame that differs from a full redraw is a bug.
// `make fuzz SECONDS=N`.
//
// Input: kHeaderBytes of set-up (PipelineHeader below), then text:
//   line 1        a tool spec (core/tool/spec.h: "ball:6", "bull:10:1.5,len=20");
//                 the tool in the spindle at the start (flat:3 if it does not parse)
//   lines 2..     with the header's table flag: a LinuxCNC tool table
//                 (platform/format/tool_table.h), up to the first empty line; T
//                 words and G43 H then use it (a table that does not
//                 parse: every T is the line-1 tool)
//   the rest      the G-code program
// tools/scripts/fuzz_seeds.py makes inputs of this form from the project's
// programs (tests/fuzz/seeds/pipeline).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/assess/assess.h"
#include "core/assess/gouge_watch.h"
#include "core/cut/mill.h"
#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/canon/summary.h"
#include "core/sim/simulation.h"
#include "core/sim/simulation_impl.h"  // the 8- and 32-bit engines
#include "core/tool/cutter.h"
#include "core/tool/spec.h"
#include "core/tool/tool.h"
#include "platform/format/tool_table.h"
#include "tests/fuzz/fuzz_entry.h"
#include "tests/fuzz/fuzz_render.h"
#include "tests/fuzz/fuzz_spec.h"
#include "tools/run/run_path.h"

namespace fuzz_pipeline {

using namespace dexmill;

constexpr size_t kHeaderBytes = 12;
// Bounds that keep one execution in milliseconds: records past the cap
// are still interpreted (and timed) but not cut or drawn.
constexpr int32_t kMaxSide = 64;
constexpr uint64_t kMaxCutRecords = 1024;
constexpr uint64_t kMaxSteps = 32;
constexpr size_t kMaxPathPieces = 4096;
constexpr int32_t kMaxStampReach = 16;  // stamp cutter: (2K+1)^2 rays per instance

// The header, byte by byte.
struct PipelineHeader {
  // [0] bit 0 stamp (else sweep), 1 inch, 2-3 height bits (0: 16, 1: 8,
  //     2: 32, 3: 16), 4 tool table, 5 design (error colours, gouge watch,
  //     assessment), 6 backplot, 7 RGB565 (else XRGB8888)
  // [1] [2] nx, ny: 4 + b % 61
  // [3] pitch: (1 + b % 32) times 1 um, 10 um, 100 um, 1 mm, 1 nm, 10 nm,
  //     100 nm, 10 mm (b / 32)
  // [4] grid origin: x0 = -span (b % 16) / 16, y0 = -span (b / 16) / 16
  // [5] stock: depth (1 + b % 32) mm below Z0, the top of the stock; bits
  //     5-6 headroom above it (0, 1, 2, 7 depths) in the height range; bit 7
  //     the time model accelerates (500 mm/s^2)
  // [6] view: bits 0-1 preset, 2 perspective, 3 16-bit depth, 4-5 frame
  //     (64x48, 48x64, 96x72, 37x23), 6-7 zoom (1, 4x in, 2x out, 64x in)
  // [7] steps: bits 0-3 moves per step - 1, 4 no drawing, 5-6 cutter (shown,
  //     hidden, every other step, shown off by a pitch), 7 padded rows
  // [8] [9] camera: azimuth b8 * 2^24 bam and elevation (int8) b9 * 2^23
  //     bam, unless both are 0 (then the preset's)
  // [10] [11] design: a 2x2 height image, four samples of 4 bits over the
  //     stock (0 at the stock's bottom, 15 at its top); render options:
  //     b11 bit 0 no table, bit 1 no gradient
  uint8_t b[kHeaderBytes];
};

class NoWarnings final : public GcodeDiagSink {
 public:
  void warning(const GcodeDiag&) override { ++count; }
  uint64_t count = 0;
};

// The backplot's pieces (tools/run/run_path.h), with a cap.
class PathSink final : public CanonSink {
 public:
  explicit PathSink(std::vector<PathSegment>* path, int64_t sagitta_nm) : path_(path), sagitta_nm_(sagitta_nm) {}
  void emit(const CanonRecord& r) override { cli::append_path(r, path_, sagitta_nm_, kMaxPathPieces); }

 private:
  std::vector<PathSegment>* path_;
  int64_t sagitta_nm_;
};

// The simulation's observer: a drawing step every few moves, with every
// change since the last (up to kMaxSteps).
template <class H>
class Steps final : public SimObserver {
 public:
  Steps(SimulationT<H>* sim, fuzz::RedrawCheck<H>* draw, uint32_t every, uint8_t cutter_mode, int64_t sagitta_nm)
      : sim_(sim), draw_(draw), every_(every), cutter_mode_(cutter_mode), sagitta_nm_(sagitta_nm) {}

  void tool_loaded(const Tool& t) override {
    profile_ = tool_profile(t);
    if (draw_) draw_->set_tool(&profile_);
  }
  void changed(const GridRect& r) override { pending_.include(r); }
  void record(const CanonRecord& r) override { path_done += path_pieces(r, sagitta_nm_); }
  void moved(uint64_t moves) override {
    if (moves % every_ == 0) step();
  }

  // The cut so far complete, then one drawing step.
  void step() {
    sim_->sync();
    DexelGrid<H>& g = sim_->grid();
    g.dirty = pending_;
    pending_ = GridRect::none();
    if (!draw_ || draw_->steps() >= kMaxSteps) return;
    CutterPose pose{true, sim_->mill().position()};
    switch (cutter_mode_) {
      case 1: pose.visible = false; break;
      case 2: pose.visible = (draw_->steps() & 1) != 0; break;
      case 3: pose.tip.x_nm += g.pitch_nm; break;
      default: break;
    }
    draw_->step(pose);
  }

  uint32_t path_done = 0;

 private:
  SimulationT<H>* sim_;
  fuzz::RedrawCheck<H>* draw_;
  uint32_t every_;
  uint8_t cutter_mode_;
  int64_t sagitta_nm_;
  ToolProfile profile_{};
  GridRect pending_ = GridRect::none();
};

// The step budget: records past kMaxCutRecords are not cut.
template <class H>
bool cut_enough(void* sim) {
  return static_cast<SimulationT<H>*>(sim)->status().records >= kMaxCutRecords;
}

int64_t pitch_of(uint8_t b) {
  static const int64_t unit[8] = {1000, 10000, 100000, 1000000, 1, 10, 100, 10000000};
  return (1 + (b & 31)) * unit[b >> 5];
}

// The next line of text[*pos, n) (no '\n'), *pos moved past it.
size_t next_line(const char* text, size_t n, size_t* pos, const char** line) {
  const size_t b = *pos;
  const char* nl = static_cast<const char*>(std::memchr(text + b, '\n', n - b));
  const size_t e = nl ? static_cast<size_t>(nl - text) : n;
  *line = text + b;
  *pos = nl ? e + 1 : n;
  return e - b;
}

template <class H>
void run(const PipelineHeader& h, const char* text, size_t n) {
  const uint8_t flags = h.b[0];
  const CutMode mode = (flags & 1) ? CutMode::kStamp : CutMode::kSweep;
  const bool inch = (flags & 2) != 0;
  const int bits = static_cast<int>(sizeof(H)) * 8;

  // Tool spec, then the tool table, then the program.
  size_t pos = 0;
  const char* line;
  size_t len = next_line(text, n, &pos, &line);
  Tool first;
  if (len && line[len - 1] == '\r') --len;
  if (tool_spec_parse(line, len, &first) != ToolSpecError::kOk) {
    FUZZ_REQUIRE(tool_spec_parse("flat:3", 6, &first) == ToolSpecError::kOk);
  } else {
    fuzz::check_spec_text(first);
  }
  ToolTableFile table;
  bool have_table = false;
  if (flags & 0x10) {
    const size_t b = pos;
    size_t table_end = n;
    while (pos < n) {
      const size_t l = next_line(text, n, &pos, &line);
      if (l == 0 || (l == 1 && line[0] == '\r')) {
        table_end = static_cast<size_t>(line - text);
        break;
      }
    }
    have_table = table.parse("fuzz.tbl", text + b, table_end - b, inch) == ToolTableFile::Load::kOk;
  }
  SingleToolLibrary single(first);
  const ToolLibrary* lib = have_table ? static_cast<const ToolLibrary*>(&table) : &single;

  // The grid: the whole of it stock, to depth below Z0.
  SimJob job;
  GridGeometry& geo = job.plan.geo;
  geo.nx = 4 + h.b[1] % 61;
  geo.ny = 4 + h.b[2] % 61;
  geo.pitch_nm = pitch_of(h.b[3]);
  geo.x0_nm = -(geo.nx - 1) * geo.pitch_nm * (h.b[4] & 15) / 16;
  geo.y0_nm = -(geo.ny - 1) * geo.pitch_nm * (h.b[4] >> 4) / 16;
  const int64_t depth_nm = (1 + (h.b[5] & 31)) * kNmPerMm;
  static const int64_t headroom[4] = {0, 1, 2, 7};
  geo.z0_nm = -depth_nm;
  geo.lsb_nm = lsb_for_range(depth_nm * (1 + headroom[(h.b[5] >> 5) & 3]), bits);
  job.plan.top_lsb = div_round(depth_nm, geo.lsb_nm);
  job.plan.stock_nx = geo.nx - 1;
  job.plan.stock_ny = geo.ny - 1;
  // Stamping: a bounded reach keeps one execution short (a tool wider
  // than that is swept).
  job.mode = mode == CutMode::kStamp && cutter_reach_dex(tool_profile(first), geo.pitch_nm) <= kMaxStampReach
                 ? CutMode::kStamp
                 : CutMode::kSweep;
  job.tool = first;
  job.library = lib;
  job.offsets = have_table ? &table : nullptr;
  job.inch = inch;
  job.max_blocks = 20000;  // a fuzzed endless loop stays short
  job.input_buffer_bytes = 4096;

  // The design: a 2x2 height image over the stock's columns.
  const bool with_design = (flags & 0x20) != 0;
  static std::vector<int32_t> design_tops(kMaxSide * kMaxSide);
  DesignGrid design;
  AssessOptions aopt;
  aopt.region = GridRect{1, 1, geo.nx - 1, geo.ny - 1};
  aopt.tol_nm = geo.lsb_nm * (1 + (h.b[10] & 7));
  // A grid wider than the design's range has none (kOutOfRange).
  if (with_design && ok(design_init(&design, geo, design_tops.data(), design_tops.size()))) {
    const uint16_t samples[4] = {static_cast<uint16_t>(h.b[10] & 15), static_cast<uint16_t>(h.b[10] >> 4),
                                 static_cast<uint16_t>(h.b[11] & 15), static_cast<uint16_t>(h.b[11] >> 4)};
    const HeightImage img{samples, 2, 2, 15};
    FUZZ_REQUIRE(ok(design_from_image(&design, img, geo.x0_nm + geo.pitch_nm, geo.y0_nm + geo.pitch_nm,
                                      geo.x0_nm + (geo.nx - 2) * geo.pitch_nm, geo.y0_nm + (geo.ny - 2) * geo.pitch_nm,
                                      geo.z0_nm, 0)));
    job.design = &design;
    job.assess = aopt;
  }
  const bool designed = design.top_lsb != nullptr;

  // The program, for the backplot: a scan pass first (as `run` does).
  const char* program = text + pos;
  const size_t program_n = n - pos;
  // Parameters, expressions and o-word flow are read too (the fuzzer feeds
  // them: gcode.dict's #, [ ], functions, sub, call, while ...).
  NoWarnings warnings;
  job.warnings = &warnings;
  static ProgramMemory memory;
  const InterpOptions iopt = sim_interp_options(job, nullptr, &memory);
  const int64_t sagitta_nm = max_of<int64_t>(geo.pitch_nm / 4, 1000);
  static std::vector<PathSegment> path;
  path.clear();
  const bool with_path = (flags & 0x40) != 0;
  if (with_path) {
    PathSink ps(&path, sagitta_nm);
    Interp scan(&ps, iopt);
    (void)interp_run_text(&scan, program, program_n, nullptr);
  }

  // Drawing.
  const bool draw = (h.b[7] & 0x10) == 0;
  static fuzz::RedrawCheck<H> check;
  fuzz::DrawSetup s;
  uint32_t done_zero = 0;
  if (draw) {
    static const int32_t size[4][2] = {{64, 48}, {48, 64}, {96, 72}, {37, 23}};
    s.width = size[(h.b[6] >> 4) & 3][0];
    s.height = size[(h.b[6] >> 4) & 3][1];
    s.format = (flags & 0x80) ? PixelFormat::kRgb565 : PixelFormat::kXrgb8888;
    s.pad_pixels = (h.b[7] & 0x80) ? 3 : 0;
    s.opt.zformat = (h.b[6] & 8) ? ZFormat::kZ16 : ZFormat::kZ32;
    s.opt.table = (h.b[11] & 1) == 0;
    s.opt.gradient = (h.b[11] & 2) == 0;
    s.camera = camera_preset(static_cast<ViewPreset>(h.b[6] & 3));
    if (h.b[8] || h.b[9]) {
      s.camera.azimuth_bam = static_cast<uint32_t>(h.b[8]) << 24;
      s.camera.elevation_bam = static_cast<int32_t>(static_cast<int8_t>(h.b[9])) * (1 << 23);
    }
    if (h.b[6] & 4) s.camera.projection = Projection::kPerspective;
    static const int32_t zoom[4] = {0, 2, -1, 6};
    s.zoom_shift = zoom[h.b[6] >> 6];
  }

  if (h.b[5] & 0x80) job.time.accel_nm_per_s2 = 500 * kNmPerMm;
  static std::vector<uint64_t> mem;
  mem.assign(SimulationT<H>::required_bytes(job) / 8 + 1, 0);
  SimulationT<H>* sim = SimulationT<H>::create(job, mem.data(), mem.size() * 8);
  if (!sim) return;  // a tool the grid cannot take
  const uint32_t every = 1 + (h.b[7] & 15);
  Steps<H> steps(sim, draw ? &check : nullptr, every, static_cast<uint8_t>((h.b[7] >> 5) & 3), sagitta_nm);
  sim->set_observer(&steps);
  DexelGrid<H>& g = sim->grid();
  if (draw) {
    check.init(&g, s, designed ? &design : nullptr, aopt, with_path ? &path : nullptr,
               with_path ? &steps.path_done : &done_zero);
    const ToolProfile p = tool_profile(first);
    check.set_tool(&p);
    CutterPose pose{true, sim->mill().position()};
    check.step(pose);  // the first frame is drawn whole
  }
  sim->feed(program, program_n);
  sim->close_input();
  SimBudget budget;
  budget.yield = cut_enough<H>;
  budget.yield_ctx = sim;
  while (sim->step(budget) == SimState::kReady && sim->status().records < kMaxCutRecords) {
  }
  sim->finish();
  steps.step();

  // Invariants of the dexel set: bottom <= top, the stock's height bound.
  for (int32_t k = 0; k < g.nx * g.ny; ++k) {
    FUZZ_REQUIRE(g.bottom[k] <= g.top[k]);
    FUZZ_REQUIRE(static_cast<int64_t>(g.top[k]) <= g.top_bound_lsb);
  }
  if (designed) {
    AssessResult res;
    FUZZ_REQUIRE(ok(assess(g, design, aopt, &res)));
    FUZZ_REQUIRE(res.gouge_columns + res.leftover_columns + res.within_tol_columns == res.design_columns);
    const GougeWatch& watch = *sim->gouges();
    FUZZ_REQUIRE(watch.nevents <= kGougeEventsMax && watch.nevents <= watch.total);
  }
  SimulationT<H>::destroy(sim);
}

int fuzz_pipeline(const uint8_t* data, size_t size) {
  if (size < kHeaderBytes) return 0;
  PipelineHeader h;
  std::memcpy(h.b, data, kHeaderBytes);
  const char* text = reinterpret_cast<const char*>(data + kHeaderBytes);
  const size_t n = size - kHeaderBytes;
  switch ((h.b[0] >> 2) & 3) {
    case 1: run<uint8_t>(h, text, n); break;
    case 2: run<uint32_t>(h, text, n); break;
    default: run<uint16_t>(h, text, n); break;
  }
  return 0;
}

}  // namespace fuzz_pipeline

DEXMILL_FUZZ_ENTRY(fuzz_pipeline::fuzz_pipeline)
