// One run of a program on a stock: the engine every front end drives
// (`dexmill run`, `check --simulate`, `optimize`, the demos, the panel
// firmware, the embedding API display/api/dexmill.h). It owns the
// interpreter, the cut and the observers, all in one block of caller
// memory whose size sim_required_bytes gives up front; nothing is allocated
// and nothing grows while it cuts.
//
//   G-code text --> GcodeRunner --> Interp --> record queue --> Mill --> grid
//   (LineInput or fed pieces)                      |   observers: safety, gouges,
//                                                  |   process rules, provenance,
//                                                  |   time; SimObserver (frames)
//
// step(budget) reads lines and cuts their records until the budget is
// spent, and always returns at a record boundary: the grid, the status and
// every observer agree there, so a GUI or a controller's idle loop can read
// them (or draw a frame) between slices. A line's records wait in a queue
// of job.queue_records when the budget runs out inside it; a line that
// makes more (a deep peck cycle) is cut past the budget, never dropped.
//
// What the observers charge to a line: a record's removals to its line,
// except a move's deferred end cap (the Mill cuts the tool standing at a
// move's end with the next record, core/cut/mill.h), which is charged to
// the move that brought the tool there, as core/safety/safety.h and
// core/assess/gouge_watch.h describe. "The line before" is the last line
// that moved the tool: a record that does not move (S, M3, T) never
// takes a cap that is not its own.
#ifndef DEXMILL_CORE_SIM_SIMULATION_H
#define DEXMILL_CORE_SIM_SIMULATION_H

#include <stddef.h>
#include <stdint.h>

#include "core/assess/gouge_watch.h"
#include "core/safety/body.h"
#include "core/safety/material_limits.h"
#include "core/safety/safety.h"
#include "core/config.h"
#include "core/cut/mill.h"
#include "core/engage/engage_band.h"
#include "core/engage/engage_load.h"
#include "core/engage/engage_target.h"
#include "core/engage/load_watch.h"
#include "core/gcode/messages.h"
#include "core/grid/grid.h"
#include "core/interp/interp.h"
#include "core/canon/summary.h"
#include "core/sim/chunk_input.h"
#include "core/sim/gcode_runner.h"
#include "core/sim/job.h"
#include "core/safety/travel_watch.h"
#include "core/sim/peck_fold.h"
#include "core/sim/provenance.h"

namespace dexmill {

// Why a simulation could not be set up (sim_required_bytes, sim_create).
enum class SimError : uint8_t {
  kOk = 0,
  kBufferTooSmall,     // the memory given is smaller than sim_required_bytes
  kGrid,               // the plan's geometry is not a grid (core/grid/grid.h)
  kToolInvalid,        // a tool fails tool_check
  kToolTooWideStamp,   // stamp mode: a tool spans more than 2 kCutterMaxReach + 1 dexels
  kToolTooLargeSweep,  // sweep mode: a tool's radius is above 268 mm
  kToolCannotCut,      // the Mill refused the tool in the spindle
  kFixturesOutside,    // the fixtures hold no column of the stock's lattice, or span more than 65535
  kFixturesTooLarge,   // the fixtures span more than 64 M columns
  kDesignGeometry,     // the design's grid is not the plan's
};

struct SimSetup {
  SimError error = SimError::kOk;
  int tool = -1;  // the tool it is about: -1 job.tool, k job.tools[k]
};

// What a step may spend before it returns (each count is a most; the first
// one reached ends the step, at a record boundary).
struct SimBudget {
  uint64_t moves = UINT64_MAX;          // motion records (G0, G1, arcs)
  uint32_t lines = UINT32_MAX;          // program lines read
  uint64_t dexel_updates = UINT64_MAX;  // the cut's work (core/cut/stats.h)
  // Asked after every record: true ends the step (a deadline on the
  // caller's clock). Null: never.
  bool (*yield)(void* ctx) = nullptr;
  void* yield_ctx = nullptr;
};

enum class SimState : uint8_t {
  kReady = 0,   // more to do: call step again
  kNeedInput,   // fed text is used up (Simulation::feed more, or close_input)
  kDone,        // the program was read to its end (finished)
  kStopped,     // stopped early (stop_reason; finished)
  kIoError,     // the input could not be read (finished)
};

enum class SimStop : uint8_t {
  kNone = 0,
  kInputError,  // a record at or past job.stop_line, or the first input error of a single pass
  kGouge,       // job.stop_at_gouge
  kCollision,   // job.stop_at_collision
  kToolFailed,  // a T the library lacks, or one the Mill cannot cut (Mill::failed_tool)
  kCaller,      // Simulation::stop
};

// Where the tool is and what the machine is doing, at the last record cut.
struct SimStatus {
  uint32_t line = 0;             // the record's program line
  PointNm pos{0, 0, 0};          // the tool tip (machine, nm)
  int64_t feed_nm_per_min = 0;   // the last feed move's rate
  int32_t tool = 0;              // in the spindle (0 before any M6)
  int64_t sim_us = 0;            // estimated machine time so far
  uint64_t moves = 0;            // motion records cut
  uint64_t records = 0;          // records cut
};

// Hooks for a front end (frames, a backplot, printing as findings come):
// called from inside step, in this order per record: tool_loaded (a tool
// change loaded one), record, changed (the grid's change, which the
// simulation then clears), moved (after a motion record, with the count).
class SimObserver {
 public:
  virtual void tool_loaded(const Tool& t) { (void)t; }
  virtual void record(const CanonRecord& r) { (void)r; }
  virtual void changed(const GridRect& r) { (void)r; }
  virtual void moved(uint64_t moves) { (void)moves; }

 protected:
  ~SimObserver() = default;
};

// The first errors a run met (a front end that prints them as they come
// gives a GcodeMessages of its own: Simulation::forward_messages).
constexpr int kSimDiagsMax = 16;

// A simulation of m-bit heights H (core/grid/grid.h); Simulation is the
// build's (core/config.h H).
template <class H>
class SimulationT final : public CanonSink, public ProbeSensor {
 public:
  // Bytes of memory a simulation of `job` needs (0 with *why set when the
  // job cannot be simulated: a tool too large, fixtures off the lattice...).
  // It reads the job's values, its tools and fixtures and the design's
  // geometry; of its other inputs (library, offsets, material, sinks) only
  // whether they are given, so a front end may size a job before it has
  // built them (the embedding API's dm_required_bytes).
  static size_t required_bytes(const SimJob& job, SimSetup* why = nullptr);
  // Sets a simulation up in mem (8-byte aligned, `bytes` of it): the stock
  // is filled (fill_stock), nothing is read yet. Null with *why on failure.
  // The simulation lives in mem: nothing to free; destroy ends it.
  static SimulationT* create(const SimJob& job, void* mem, size_t bytes, SimSetup* why = nullptr);
  static void destroy(SimulationT* s) {
    if (s) s->~SimulationT();
  }

  SimulationT(const SimulationT&) = delete;
  SimulationT& operator=(const SimulationT&) = delete;

  // -- before the first step
  // Carves the stock to a blank's shape (core/sim/stock_plan.h carve_stock).
  void carve(const DesignGrid& blank);
  // Lines from a caller's input (a file on the host); else the pieces fed.
  void read_from(LineInput* in);
  void set_observer(SimObserver* o) { observer_ = o; }
  // Off: every vertical move is cut by itself (the reference
  // tests/test_peck_fold.cpp compares the fold with). Before start().
  void set_fold(bool on) { fold_allowed_ = on; }
  // Off: the shank and holder looks read every column over the body's
  // lowest point (SafetyWatch::body_fast; the reference
  // tests/test_safety_body_fast.cpp compares the fast look with).
  void set_body_fast(bool on) { safety_.body_fast = on; }
  // Errors also go to m as they come (the host prints them).
  void forward_messages(GcodeMessages* m) { msgs_.forward = m; }
  // Takes the stock as it is now as the untouched one (the watches'
  // shadows, provenance): called by the first step when not before.
  void start();

  // -- program text in pieces (job.input_buffer_bytes > 0)
  // Lends text (chunk_input.h: it must stay until input_taken()).
  void feed(const char* text, size_t n) { chunks_.feed(text, n); }
  void close_input() { chunks_.close(); }
  bool input_taken() const { return chunks_.taken(); }
  void set_rereader(ChunkReReader fn, void* ctx) { chunks_.set_rereader(fn, ctx); }
  void set_input_name(const char* name) { chunks_.set_name(name); }
  uint64_t input_bytes_read() const { return chunks_.bytes_read(); }

  // -- running
  SimState step(const SimBudget& budget);
  // Stops here (SimStop::kCaller) and finishes.
  void stop() { stop_with(SimStop::kCaller, status_.line); }
  // Shows the cut so far (the Mill defers a move's end cap) and passes its
  // change to the observer: before anything draws the grid.
  void sync();
  // The end of the cut: the deferred end cap cut for good, watched (step
  // calls it when the program ends or stops; once).
  void finish();

  // -- what it knows
  SimState state() const { return state_; }
  SimStop stop_reason() const { return stop_; }
  uint32_t stop_line() const { return stop_line_; }
  int32_t failed_tool() const { return mill_.failed_tool(); }
  const SimStatus& status() const { return status_; }
  const SimJob& job() const { return job_; }
  DexelGrid<H>& grid() { return grid_; }
  const DexelGrid<H>& grid() const { return grid_; }
  const Mill<H>& mill() const { return mill_; }
  const Interp& interp() const { return interp_; }
  const ToolProfile& profile() const { return profile_; }  // the tool in the spindle
  const MotionSummary& time() const { return time_; }
  uint64_t removed_lsb() const { return material_before_ - grid_material_now(); }
  uint32_t lines_read() const { return runner_.lines(); }
  bool io_error() const { return runner_.io_error(); }
  uint32_t errors() const { return msgs_.errors(); }
  uint32_t warnings() const { return msgs_.warnings(); }
  const GcodeDiag* diags(int* n) const {
    *n = msgs_.nkept;
    return msgs_.kept;
  }
  // The stock's columns, to read a saved stock into (job.resume, before
  // start()) or to save it from: the layers of `layers` (StockLayer bits)
  // this simulation keeps (provenance's), null for the others.
  StockColumns stock_columns(uint8_t layers) {
    StockColumns c;
    c.top = grid_.top;
    c.bottom = grid_.bottom;
    if (job_.provenance && (layers & kStockLayerClass)) c.cls = prov_cls_;
    if (layers & kStockLayerLine) c.line = prov_lines_;
    if (c.line && (layers & kStockLayerProgram)) c.program = prov_programs_;
    return c;
  }
  // The observers (null when off).
  const SafetyWatch* safety() const { return safety_on_ ? &safety_ : nullptr; }
  const GougeWatch* gouges() const { return job_.design ? &gouges_ : nullptr; }
  const ProcessWatch* process() const { return job_.material ? &process_ : nullptr; }
  const EngageSummary* engagement() const { return job_.engagement ? &engage_sum_ : nullptr; }
  const LoadWatch* load() const { return job_.engagement && job_.load_check ? &load_ : nullptr; }
  const TravelWatch* travel() const { return travel_on_ ? &travel_ : nullptr; }
  // engage_colours: each column's load band, nx * ny (null when off).
  uint8_t* engage_classes() const { return engage_cls_; }
  // Whether its bands are by the load limits (the spindle's power, a
  // material's largest chip), else by the engagement angle (engage_band.h).
  bool engage_by_limits() const {
    bool chip = false;
    for (int32_t k = 0; job_.material && k < job_.material->material_count; ++k)
      chip = chip || job_.material->materials[k].process.max_chip_nm > 0;
    return job_.spindle_power_mw > 0 || chip;
  }
  // engage_target's feed for each line (null without one).
  const EngageLineFeeds* target_feeds() const { return target_lines_.n ? &target_lines_ : nullptr; }
  // And the moves split where it changes along them (null when not splitting).
  const EngageSplits* target_splits() const { return split_trace_ ? &splits_ : nullptr; }
  const ToolProvenance<H>* provenance() const { return job_.provenance ? &prov_ : nullptr; }
  bool gouged() const { return gouged_; }
  // Records (and the finish) whose gouge check found a gouge: a front end
  // that marks them redraws its marks when this moves.
  uint64_t gouge_finds() const { return gouge_finds_; }
  bool collided() const { return collided_; }

  // CanonSink: the interpreter's records (queued, cut in order).
  void emit(const CanonRecord& r) override;
  // ProbeSensor: where a probe move trips on the stock as cut so far (the
  // one place the interpreter waits for the cut: the records before the
  // probe are cut, the deferred end cap shown, in the memory the run has;
  // nothing is kept).
  ProbeSense sense(const PointNm& from, const PointNm& to, int motion, PointNm* stop) override;

  // The layout's (sim_create.cpp): where each part lives in the block, and
  // a record queued with the interpreter's state when it was made.
  struct Memory;
  struct Queued {
    CanonRecord r;
    int8_t spindle_dir;
    int32_t spindle_rpm;
    uint8_t coolant;
  };

 private:
  SimulationT(const SimJob& job, const Memory& m);
  ~SimulationT() = default;
  // Counts and keeps the first diagnostics; forwards them.
  struct Messages final : GcodeMessages {
    GcodeMessages* forward = nullptr;
    GcodeDiagSink* warn_to = nullptr;
    GcodeDiag kept[kSimDiagsMax];
    int nkept = 0;
    void error(const GcodeDiag& d) override;
    void warning(const GcodeDiag& d) override;
    void set_file(const char* name) override {
      if (forward) forward->set_file(name);
    }
  };

  void process(const Queued& q);
  void charge_cut(uint32_t line);
  void settle_fold();
  int64_t measure_load(EngageMove* mv);
  void split_move(const EngageMove& mv, const CuttingCoefficients& c, int64_t max_chip_nm, int64_t max_feed_nm_per_min,
                  int64_t move_feed_nm_per_min);
  void check_process(const Queued& q, bool move, int64_t time_us);
  void load_tool(const Tool& t);
  void stop_with(SimStop why, uint32_t line);
  bool line_end_stops();
  uint64_t grid_material_now() const;

  SimJob job_;
  SingleToolLibrary single_;   // the library and offsets when the job gives none
  const ToolLibrary* library_;
  DexelGrid<H> grid_;
  Mill<H> mill_;
  ChunkInput chunks_;
  Messages msgs_;
  Interp interp_;
  GcodeRunner runner_;
  Queued* queue_;
  uint32_t queue_cap_, queue_head_ = 0, queue_n_ = 0;
  MotionSummary time_;
  SimObserver* observer_ = nullptr;
  // Vertical moves held to be cut as one (core/sim/peck_fold.h): only with
  // no watcher that judges moves one by one.
  bool fold_allowed_ = true, fold_on_ = false;
  PeckFold fold_;
  // observers
  bool safety_on_;
  SafetyWatch safety_;
  DexelGrid<uint32_t> fixture_grid_;
  uint32_t* safety_shadow_;
  uint32_t* safety_tiles_;
  size_t safety_tile_words_;
  GougeWatch gouges_;
  uint8_t* gouge_seen_;
  ProcessWatch process_;
  uint32_t* process_shadow_;
  int64_t* line_feed_limits_;
  uint8_t* process_seen_;
  TravelWatch travel_;
  bool travel_on_ = false;
  EngageMeter engage_;
  EngageSummary engage_sum_;
  LoadWatch load_;
  uint32_t* engage_shadow_;
  uint8_t* engage_cls_;      // engage_colours: the bands
  uint8_t engage_band_ = 0;  // the band of the last measured move (a retract's deferred end cap takes it)
  EngageLineFeeds target_lines_;
  EngageSplits splits_;
  EngageSample* split_trace_;
  ToolProvenance<H> prov_;
  uint8_t* prov_cls_;
  uint32_t* prov_shadow_;
  uint32_t* prov_lines_;
  uint8_t* prov_programs_;
  // the cut's state
  bool started_ = false, finished_ = false;
  SimState state_ = SimState::kReady;
  SimStop stop_ = SimStop::kNone;
  uint32_t stop_line_ = 0;
  bool stopped_at_error_ = false;
  bool gouged_ = false, collided_ = false;
  uint64_t gouge_finds_ = 0;
  bool moved_ = false;        // a move has run: the tool's position is the program's, not assumed
  bool have_origin_ = false;
  uint32_t last_move_line_ = 0;  // the last motion record's line
  SafetyMove last_move_{};       // and its state
  ProcessState last_process_{};
  GougeOrigin origin_{0, PointNm{0, 0, 0}, nullptr};
  SafetyOrigin safety_origin_{SafetyMove{}, PointNm{0, 0, 0}, nullptr};
  ProcessOrigin process_origin_{ProcessState{}, PointNm{0, 0, 0}, nullptr};
  ToolProfile profile_{};  // the tool in the spindle
  ToolBody body_{};        // its shank and holder (core/safety/body.h)
  SimStatus status_{};
  uint64_t material_before_ = 0;
};

// Made for the build's heights in core/sim/simulation.cpp; for another m,
// include core/sim/simulation_impl.h.
extern template class SimulationT<height_t>;

using Simulation = SimulationT<height_t>;
inline size_t sim_required_bytes(const SimJob& job, SimSetup* why = nullptr) { return Simulation::required_bytes(job, why); }
inline Simulation* sim_create(const SimJob& job, void* mem, size_t bytes, SimSetup* why = nullptr) {
  return Simulation::create(job, mem, bytes, why);
}
inline void sim_destroy(Simulation* s) { Simulation::destroy(s); }

}  // namespace dexmill

#endif
