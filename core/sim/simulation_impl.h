// The member definitions of SimulationT<H> (simulation.h): core/sim/simulation.cpp
// instantiates them for the build's heights (core/config.h height_t), the
// one the library and the panel carry; a program that wants another m
// (the pipeline fuzz target cuts 8-, 16- and 32-bit grids) includes this
// header, and the compiler makes what it uses.
#ifndef DEXMILL_CORE_SIM_SIMULATION_IMPL_H
#define DEXMILL_CORE_SIM_SIMULATION_IMPL_H

#include <new>
#include <string.h>

#include "core/cut/sweep.h"
#include "core/grid/volume.h"
#include "core/math/wide.h"
#include "core/sim/carver.h"
#include "core/sim/simulation.h"
#include "core/cut/probe.h"
#include "core/tool/cutter.h"

namespace dexmill {

namespace sim_detail {

inline bool is_move(const CanonRecord& r) {
  return r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
}

}  // namespace sim_detail

// Where each part of a simulation lives in its block.
template <class H>
struct SimulationT<H>::Memory {
  H* top = nullptr;
  H* bottom = nullptr;
  int32_t* words = nullptr;       // the Mill's (core/cut/mill.h mill_words)
  size_t nwords = 0;
  ProgramMemory* program = nullptr;  // the program's parameters and o-word flow
  Queued* queue = nullptr;
  char* input = nullptr;          // the fed text's reader buffer
  uint32_t* safety_shadow = nullptr;
  uint32_t* tiles = nullptr;
  size_t tile_words = 0;
  DexelGrid<uint32_t> fixtures;   // sized (fixture_grid_size); tops and bottoms below
  uint32_t* fixture_top = nullptr;
  uint32_t* fixture_bottom = nullptr;
  uint32_t* process_shadow = nullptr;
  uint32_t* engage_shadow = nullptr;
  uint8_t* engage_cls = nullptr;
  int64_t* line_feed = nullptr;
  int64_t* target_feed = nullptr;  // engage_target: each line's feed
  EngageSample* split_trace = nullptr;  // split_rule: a move's samples
  EngageSplitPiece* split_pieces = nullptr;
  uint8_t* target_kept = nullptr;
  uint8_t* process_seen = nullptr;  // the findings counted per line (core/safety/material_limits.h)
  uint8_t* seen = nullptr;
  size_t seen_bytes = 0;
  uint8_t* prov_cls = nullptr;
  uint32_t* prov_shadow = nullptr;
  uint32_t* prov_lines = nullptr;
  uint8_t* prov_programs = nullptr;
};

namespace sim_detail {

template <class H>
DexelGrid<H> plan_grid_view(const GridPlan& plan) {
  DexelGrid<H> g;
  g.nx = plan.geo.nx;
  g.ny = plan.geo.ny;
  g.x0_nm = plan.geo.x0_nm;
  g.y0_nm = plan.geo.y0_nm;
  g.pitch_nm = plan.geo.pitch_nm;
  g.z0_nm = plan.geo.z0_nm;
  g.lsb_nm = plan.geo.lsb_nm;
  return g;
}

// The tools' checks and the Mill's words for the largest (core/cut/mill.h).
template <class H>
bool size_tools(const SimJob& job, const DexelGrid<H>& g, size_t* words, SimSetup* why) {
  *words = 0;
  for (int k = -1; k < job.ntools; ++k) {
    const Tool& t = k < 0 ? job.tool : job.tools[k];
    why->tool = k;
    if (!ok(tool_check(t))) {
      why->error = SimError::kToolInvalid;
      return false;
    }
    const ToolProfile p = tool_profile(t);
    if (job.mode == CutMode::kStamp) {
      if (cutter_reach_dex(p, g.pitch_nm) > kCutterMaxReach) {
        why->error = SimError::kToolTooWideStamp;
        return false;
      }
    } else {
      SweepTool st;
      if (!ok(sweep_tool_prepare(p, g.lsb_nm, &st))) {
        why->error = SimError::kToolTooLargeSweep;
        return false;
      }
    }
    *words = max_of(*words, mill_words(job.mode, p, g));
  }
  why->tool = -1;
  return true;
}

// Lays the block out for job: into *m when base is not null. The size, or 0
// with *why set.
template <class H>
size_t layout(const SimJob& job, char* base, typename SimulationT<H>::Memory* m, SimSetup* why, size_t self_bytes) {
  if (!ok(grid_check_geometry(job.plan.geo))) {
    why->error = SimError::kGrid;
    return 0;
  }
  if (job.plan.top_lsb < 0 || job.plan.top_lsb > height_max<H>()) {  // the stock's height in m bits
    why->error = SimError::kGrid;
    return 0;
  }
  const DexelGrid<H> g = plan_grid_view<H>(job.plan);
  const size_t cells = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  size_t words = 0;
  if (!size_tools(job, g, &words, why)) return 0;
  if (job.design && (job.design->geo.nx != g.nx || job.design->geo.ny != g.ny ||
                     job.design->geo.pitch_nm != g.pitch_nm || job.design->geo.lsb_nm != g.lsb_nm)) {
    why->error = SimError::kDesignGeometry;
    return 0;
  }
  DexelGrid<uint32_t> fixtures;
  size_t fixture_cells = 0;
  if (job.checks.nfixtures > 0) {
    if (!fixture_grid_size(g, job.checks.fixtures, job.checks.nfixtures, &fixtures)) {
      why->error = SimError::kFixturesOutside;
      return 0;
    }
    fixture_cells = static_cast<size_t>(fixtures.nx) * static_cast<size_t>(fixtures.ny);
    if (fixture_cells > (size_t{1} << 26)) {
      why->error = SimError::kFixturesTooLarge;
      return 0;
    }
  }
  Carver c(base);
  (void)c.take<char>(self_bytes);
  typename SimulationT<H>::Memory mem;
  mem.top = c.take<H>(cells);
  mem.bottom = c.take<H>(cells);
  mem.nwords = words;
  mem.words = c.take<int32_t>(words);
  mem.program = c.take<ProgramMemory>(1);
  mem.queue = c.take<typename SimulationT<H>::Queued>(job.queue_records > 0 ? job.queue_records : 1);
  mem.input = c.take<char>(job.input_buffer_bytes);
  if (job.checks.any()) {
    mem.safety_shadow = c.take<uint32_t>(cells);
    mem.tile_words = safety_tile_words(g);
    mem.tiles = c.take<uint32_t>(mem.tile_words);
    if (fixture_cells) {
      mem.fixtures = fixtures;
      mem.fixture_top = c.take<uint32_t>(fixture_cells);
      mem.fixture_bottom = c.take<uint32_t>(fixture_cells);
    }
  }
  if (job.material) {
    mem.process_shadow = c.take<uint32_t>(cells);
    mem.line_feed = c.take<int64_t>(job.line_feed_lines);
    mem.process_seen = c.take<uint8_t>(process_seen_bytes(job.process_lines));
  }
  if (job.engagement) mem.engage_shadow = c.take<uint32_t>(cells);
  if (job.engagement && job.engage_colours) mem.engage_cls = c.take<uint8_t>(cells);
  if (job.engagement && job.engage_target) {
    mem.target_feed = c.take<int64_t>(job.target_lines);
    mem.target_kept = c.take<uint8_t>(job.target_lines);
    if (job.split_rule.max_segments > 1 && job.split_pieces) {
      mem.split_trace = c.take<EngageSample>(kEngageMaxSamples);
      mem.split_pieces = c.take<EngageSplitPiece>(job.split_pieces);
    }
  }
  if (job.design) {
    mem.seen_bytes = gouge_watch_seen_bytes(g.nx, g.ny);
    mem.seen = c.take<uint8_t>(mem.seen_bytes);
  }
  if (job.provenance) {
    mem.prov_cls = c.take<uint8_t>(cells);
    mem.prov_shadow = c.take<uint32_t>(cells);
    if (job.provenance_lines) mem.prov_lines = c.take<uint32_t>(cells);
    if (job.provenance_lines && job.provenance_programs) mem.prov_programs = c.take<uint8_t>(cells);
  }
  if (m) *m = mem;
  return c.used();
}

}  // namespace sim_detail

template <class H>
size_t SimulationT<H>::required_bytes(const SimJob& job, SimSetup* why) {
  SimSetup dummy;
  SimSetup* w = why ? why : &dummy;
  *w = SimSetup{};
  return sim_detail::layout<H>(job, nullptr, nullptr, w, sizeof(SimulationT));
}

template <class H>
SimulationT<H>* SimulationT<H>::create(const SimJob& job, void* mem, size_t bytes, SimSetup* why) {
  SimSetup dummy;
  SimSetup* w = why ? why : &dummy;
  *w = SimSetup{};
  const size_t need = sim_detail::layout<H>(job, nullptr, nullptr, w, sizeof(SimulationT));
  if (need == 0) return nullptr;
  if (!mem || bytes < need || (reinterpret_cast<uintptr_t>(mem) & 7) != 0) {
    w->error = SimError::kBufferTooSmall;
    return nullptr;
  }
  char* base = static_cast<char*>(mem);
  Memory m;
  (void)sim_detail::layout<H>(job, base, &m, w, sizeof(SimulationT));
  SimulationT* s = new (base) SimulationT(job, m);
  if (!ok(s->mill_.set_tool(job.tool))) {
    w->error = SimError::kToolCannotCut;
    s->~SimulationT();
    return nullptr;
  }
  return s;
}

template <class H>
SimulationT<H>::SimulationT(const SimJob& job, const Memory& m)
    : job_(job),
      single_(job.tool),
      library_(job.library ? job.library : &single_),
      grid_(sim_detail::plan_grid_view<H>(job.plan)),
      mill_(&grid_, job.mode, library_, m.words, m.nwords),
      chunks_(m.input, job.input_buffer_bytes),
      interp_(this,
              [&]() {
                InterpOptions o = sim_interp_options(job, &single_, m.program);
                o.warnings = &msgs_;  // counted, then the job's
                o.probe = this;       // probe moves stop on the stock
                return o;
              }()),
      runner_(&chunks_, &interp_, &msgs_, true),
      queue_(m.queue),
      queue_cap_(job.queue_records > 0 ? job.queue_records : 1),
      time_(job.time),
      safety_on_(job.checks.any()),
      fixture_grid_(m.fixtures),
      safety_shadow_(m.safety_shadow),
      safety_tiles_(m.tiles),
      safety_tile_words_(m.tile_words),
      gouge_seen_(m.seen),
      process_shadow_(m.process_shadow),
      line_feed_limits_(m.line_feed),
      process_seen_(m.process_seen),
      engage_shadow_(m.engage_shadow),
      engage_cls_(m.engage_cls),
      target_lines_{m.target_feed, m.target_kept, job.engage_target ? job.target_lines : 0},
      splits_{m.split_pieces, m.split_pieces ? job.split_pieces : 0, 0, 0, 0},
      split_trace_(m.split_trace),
      prov_cls_(m.prov_cls),
      prov_shadow_(m.prov_shadow),
      prov_lines_(m.prov_lines),
      prov_programs_(m.prov_programs) {
  msgs_.warn_to = job.warnings;
  const size_t cells = static_cast<size_t>(grid_.nx) * static_cast<size_t>(grid_.ny);
  (void)grid_init(&grid_, job.plan.geo, m.top, m.bottom, cells);  // the geometry was checked
  if (!job.resume) fill_stock(&grid_, job.plan);  // else the front end reads a saved one in (stock_columns)
  if (m.fixture_top) {
    fixture_grid_.top = m.fixture_top;
    fixture_grid_.bottom = m.fixture_bottom;
  }
  load_tool(job.tool);
  status_.tool = 0;
}

template <class H>
void SimulationT<H>::Messages::error(const GcodeDiag& d) {
  ++errors_;
  if (nkept < kSimDiagsMax) kept[nkept++] = d;
  if (forward) forward->error(d);
}

template <class H>
void SimulationT<H>::Messages::warning(const GcodeDiag& d) {
  ++warnings_;
  if (warn_to) warn_to->warning(d);
}

template <class H>
void SimulationT<H>::carve(const DesignGrid& blank) { carve_stock(&grid_, job_.plan, blank); }

template <class H>
void SimulationT<H>::read_from(LineInput* in) { runner_ = GcodeRunner(in, &interp_, &msgs_, true); }

template <class H>
uint64_t SimulationT<H>::grid_material_now() const { return grid_material_lsb(grid_); }

template <class H>
void SimulationT<H>::start() {
  if (started_) return;
  started_ = true;
  if (const StockMeta* r = job_.resume) {  // what the cut's shortcuts rely on, as the stock file holds it
    grid_.bottoms_zero = r->bottoms_zero;
    grid_.top_bound_lsb = r->top_bound_lsb;
    grid_.dirty = grid_.bounds();
  }
  const size_t cells = static_cast<size_t>(grid_.nx) * static_cast<size_t>(grid_.ny);
  material_before_ = grid_material_lsb(grid_);
  if (job_.design) (void)gouge_watch_init(&gouges_, job_.design, job_.assess, gouge_seen_, gouge_watch_seen_bytes(grid_.nx, grid_.ny));
  if (job_.material) {
    (void)process_watch_init(&process_, grid_, job_.material, process_shadow_, cells);
    if (job_.line_feed_lines) process_watch_track_lines(&process_, line_feed_limits_, job_.line_feed_lines);
    if (job_.process_lines) process_watch_track_findings(&process_, process_seen_, job_.process_lines);
  }
  if (job_.engagement) (void)engage_meter_init(&engage_, grid_, engage_shadow_, cells);
  for (size_t k = 0; engage_cls_ && k < cells; ++k) engage_cls_[k] = 0;  // uncut
  engage_band_ = 0;
  load_.spindle_power_mw = job_.spindle_power_mw;
  travel_on_ = job_.travel_check && job_.machine;
  if (travel_on_) travel_watch_init(&travel_, *job_.machine);
  if (target_lines_.n) engage_line_feeds_clear(&target_lines_);
  splits_.n = 0;
  splits_.moves = splits_.left = 0;
  engage_.trace = split_trace_;
  if (safety_on_) {
    (void)safety_watch_init(&safety_, grid_, safety_shadow_, cells, safety_tiles_, safety_tile_words_);
    const SimChecks& c = job_.checks;
    safety_.check_rapid = c.rapid;
    safety_.check_spindle = c.spindle;
    safety_.check_below = c.below;
    safety_.check_shank = c.shank;
    safety_.check_holder = c.holder;
    safety_.check_plunge = c.plunge;
    safety_.bottom_nm = grid_.z0_nm;
    safety_.check_table = c.has_table;
    safety_.table_nm = c.table_nm;
    if (c.nfixtures > 0) {
      fixture_grid_fill(&fixture_grid_, c.fixtures, c.nfixtures);
      safety_.fixtures = &fixture_grid_;
      safety_.fixture_boxes = c.fixtures;
      safety_.nfixture_boxes = c.nfixtures;
    }
  }
  if (job_.provenance) {
    const StockMeta* r = job_.resume;
    const bool classes = r && (r->layers & kStockLayerClass), lines = r && (r->layers & kStockLayerLine);
    const bool programs = lines && (r->layers & kStockLayerProgram);
    // A stock's lines without their programs are its first program's.
    if (prov_programs_ && lines && !programs) memset(prov_programs_, 0, cells);
    provenance_resume(&prov_, grid_, classes ? r->prov_current : job_.provenance_first_tool,
                      classes ? r->prov_slots : job_.provenance_slots, prov_cls_, prov_shadow_, prov_lines_,
                      prov_programs_, classes, lines, r ? r->prov_tool : nullptr, classes ? r->prov_ntools : 0,
                      classes ? r->prov_unlisted : 0, static_cast<uint8_t>(r ? r->nprograms : 0));
  }
  fold_on_ = fold_allowed_ && !safety_on_ && !job_.engagement && !job_.material && !job_.design;
  load_tool(job_.tool);
}

template <class H>
void SimulationT<H>::load_tool(const Tool& t) {
  profile_ = tool_profile(t);
  tool_body_build(t, &body_);
  if (safety_on_ && started_) safety_watch_set_tool(&safety_, profile_);
  if (job_.engagement) engage_meter_set_tool(&engage_, t, grid_.pitch_nm);
}

template <class H>
void SimulationT<H>::emit(const CanonRecord& r) {
  if (queue_n_ == queue_cap_) {  // a line longer than the queue: its head is cut now
    process(queue_[queue_head_]);
    queue_head_ = (queue_head_ + 1) % queue_cap_;
    --queue_n_;
  }
  const InterpState& st = interp_.state();
  queue_[(queue_head_ + queue_n_) % queue_cap_] = Queued{r, st.spindle_dir, st.spindle_rpm, st.coolant};
  ++queue_n_;
}

// A measured move's tool, and with materials its load and limits: the
// material its edge met (at its largest cross-section, else its widest
// arc), that material's coefficients and chip limit. Returns that limit
// (0: none).
template <class H>
int64_t SimulationT<H>::measure_load(EngageMove* mv) {
  mv->tool = status_.tool;
  if (!mv->feed) return 0;
  int64_t max_chip_nm = 0;
  if (job_.material && job_.material->material_count > 0) {
    const PointNm at = mv->section.area_um2 > 0 ? mv->area_at : mv->worst_at;
    mv->material = composition_material_at(*job_.material, at.x_nm, at.y_nm, at.z_nm);
    const MaterialProcess& p = job_.material->materials[mv->material].process;
    CuttingCoefficients c;
    c.kc11_n_per_mm2 = p.kc11_n_per_mm2;
    c.mc_ppm = p.mc_ppm;
    engage_load(engage_.tool, c, mv);
    max_chip_nm = p.max_chip_nm;
    if (target_lines_.n) {
      EngageFeedWhy why;
      const int64_t f = engage_target_feed(*job_.engage_target, *mv, c, max_chip_nm, p.max_feed_nm_per_min, &why);
      engage_line_feeds_add(&target_lines_, mv->line, f, why);
      if (split_trace_ && engage_.ntrace > 1 && why == EngageFeedWhy::kTarget)
        split_move(*mv, c, max_chip_nm, p.max_feed_nm_per_min, f);
    }
  }
  if (job_.load_check) load_watch_check(&load_, *mv, max_chip_nm);
  return max_chip_nm;
}

// A straight move's pieces at its load's changes (core/engage/engage_split.h):
// each sample's feed for the target on the move's material.
template <class H>
void SimulationT<H>::split_move(const EngageMove& mv, const CuttingCoefficients& c, int64_t max_chip_nm,
                                int64_t max_feed_nm_per_min, int64_t move_feed_nm_per_min) {
  int64_t s[kEngageMaxSamples], f[kEngageMaxSamples];
  const int32_t n = static_cast<int32_t>(engage_.ntrace);
  for (int32_t k = 0; k < n; ++k) {
    s[k] = split_trace_[k].s_nm;
    f[k] = engage_sample_feed(*job_.engage_target, engage_.tool, mv, split_trace_[k].at, c, max_chip_nm,
                              max_feed_nm_per_min, move_feed_nm_per_min);
  }
  const CanonRecord& r = engage_.record;
  const int64_t len = hypot_floor(r.end.x_nm - r.start.x_nm, r.end.y_nm - r.start.y_nm);
  EngageSegment seg[kEngageMaxSegments];
  int32_t count = engage_split(s, f, n, len, job_.split_rule, seg);
  if (count > 1) count = engage_split_snap(r.start, r.end, seg, count);
  (void)engage_splits_add(&splits_, mv.line, seg, count);
}

template <class H>
void SimulationT<H>::process(const Queued& q) {
  const CanonRecord& r = q.r;
  if (job_.stop_line && r.line >= job_.stop_line) {  // a partial run: nothing of the bad block or after it
    stopped_at_error_ = true;
    return;
  }
  const bool move = sim_detail::is_move(r);
  const bool held = peck_fold_add(&fold_, r);  // false when nothing is held
  if (!held) settle_fold();
  // Where the line before left the tool: a deferred end cap cut now is its.
  if (move && r.line != last_move_line_) {
    const PointNm at = mill_.position();
    origin_ = GougeOrigin{last_move_line_, at, &profile_};
    safety_origin_ = SafetyOrigin{last_move_, at, &profile_};
    process_origin_ = ProcessOrigin{last_process_, at, &profile_};
    have_origin_ = last_move_line_ != 0;
  }
  const Status before = mill_.status();
  // Engagement: the stock before this record cuts it (M4 turns the other way).
  if (job_.engagement) {
    const int32_t rpm = q.spindle_rpm > 0 ? q.spindle_rpm : job_.default_spindle_rpm;
    engage_meter_before(&engage_, grid_, r, q.spindle_dir >= 0, rpm);
  }
  if (!held && !(fold_on_ && peck_fold_begin(&fold_, r, mill_.position()))) {
    mill_.emit(r);
    charge_cut(r.line);
  }
  if (travel_on_) (void)travel_watch_check(&travel_, r);
  const bool spindle_on = q.spindle_dir != 0;
  SafetyMove m{r.line, r.kind == CanonKind::kTraverse, spindle_on, moved_};
  if (safety_on_) {
    // M3/M4 in effect (the interpreter's state: a record's rpm is 0 both
    // after M5 and for M3 with no S word, which a controller runs at its
    // default speed).
    m.plunge = safety_is_plunge(r);
    m.end = r.end;
    m.body = &body_;
    if (safety_watch_record(&safety_, grid_, grid_.dirty, r, m, have_origin_ ? &safety_origin_ : nullptr))
      collided_ = true;
  }
  if (move) {
    last_move_ = m;
    moved_ = true;
    last_move_line_ = r.line;
  }
  const int64_t t_before = time_.estimated_time_us();
  if (job_.time_estimate || job_.material || job_.engagement) time_.emit(r);
  if (job_.material) check_process(q, move, time_.estimated_time_us() - t_before);
  if (job_.engagement) {
    EngageMove mv;
    engage_meter_measure(&engage_, grid_, grid_.dirty, &mv);
    mv.time_us = time_.estimated_time_us() - t_before;
    mv.end_us = time_.estimated_time_us();
    const int64_t max_chip_nm = measure_load(&mv);
    if (engage_cls_) {
      const uint8_t band = engage_band(mv, engage_by_limits(), job_.spindle_power_mw, max_chip_nm);
      if (band) engage_band_ = band;
    }
    engage_meter_commit(&engage_, grid_, grid_.dirty, engage_cls_, engage_band_);
    engage_summary_add(&engage_sum_, mv);
    if (mv.feed && job_.engage_sink) job_.engage_sink->move(mv);
  }
  status_.line = r.line;
  status_.pos = fold_.active ? fold_.at : mill_.position();
  if (r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc) status_.feed_nm_per_min = r.feed_nm_per_min;
  if (r.kind == CanonKind::kToolChange) {
    status_.tool = r.tool;
    Tool t;
    if (library_->tool(r.tool, &t)) {
      load_tool(t);
      if (job_.provenance) provenance_set_tool(&prov_, r.tool);
      if (observer_) observer_->tool_loaded(t);
    }
    if (ok(before) && !ok(mill_.status())) stop_with(SimStop::kToolFailed, r.line);
  }
  status_.sim_us = time_.estimated_time_us();
  ++status_.records;
  if (observer_) {
    observer_->record(r);
    observer_->changed(grid_.dirty);
  }
  grid_.dirty = GridRect::none();
  if (!move) return;
  ++status_.moves;
  if (observer_) observer_->moved(status_.moves);
}

// What the cut of a record of `line` changed, to the watchers that charge it
// to a line: provenance and gouges.
template <class H>
void SimulationT<H>::charge_cut(uint32_t line) {
  if (job_.provenance) {
    const ProvenanceOrigin po{origin_.line, origin_.end, origin_.tool};
    provenance_record(&prov_, grid_.dirty, line, have_origin_ ? &po : nullptr);
  }
  if (job_.design &&
      gouge_watch_check(&gouges_, grid_, grid_.dirty, line, mill_.position(), have_origin_ ? &origin_ : nullptr)) {
    gouged_ = true;
    ++gouge_finds_;
  }
}

// Cuts the held vertical moves as one (core/sim/peck_fold.h), charged to
// their line, and shows it to the observer: every reader of the grid and
// every step's return see the cut as if each move had been cut.
template <class H>
void SimulationT<H>::settle_fold() {
  if (!fold_.active) return;
  fold_.active = false;
  CanonRecord moves[3];
  const int n = peck_fold_moves(fold_, moves);
  for (int k = 0; k < n; ++k) mill_.emit(moves[k]);
  charge_cut(fold_.line);
  if (observer_) observer_->changed(grid_.dirty);
  grid_.dirty = GridRect::none();
}

// The process rules on what the record removed, in the state it ran in.
template <class H>
void SimulationT<H>::check_process(const Queued& q, bool move, int64_t time_us) {
  ProcessState s;
  s.line = q.r.line;
  s.feed_move = q.r.kind == CanonKind::kFeed || q.r.kind == CanonKind::kArc;
  s.feed_nm_per_min = q.r.feed_nm_per_min;
  s.spindle_rpm = q.spindle_rpm;
  s.spindle_on = q.spindle_dir != 0;
  s.coolant = q.coolant;
  s.time_us = time_us;
  process_watch_record(&process_, grid_, grid_.dirty, s, have_origin_ ? &process_origin_ : nullptr);
  if (move) last_process_ = s;
}

template <class H>
void SimulationT<H>::stop_with(SimStop why, uint32_t line) {
  if (finished_) return;
  stop_ = why;
  stop_line_ = line;
  state_ = SimState::kStopped;
  finish();
}

// The checks made when a line's records are all cut.
template <class H>
bool SimulationT<H>::line_end_stops() {
  if (stopped_at_error_) {
    stop_with(SimStop::kInputError, job_.stop_line);
    return true;
  }
  if (job_.stop_at_gouge && gouged_) {
    stop_with(SimStop::kGouge, status_.line);
    return true;
  }
  if (job_.stop_at_collision && collided_) {
    stop_with(SimStop::kCollision, status_.line);
    return true;
  }
  return false;
}

template <class H>
SimState SimulationT<H>::step(const SimBudget& budget) {
  if (finished_) return state_;
  start();
  const uint64_t moves0 = status_.moves, work0 = mill_.stats().dexel_updates;
  uint32_t lines = 0;
  for (;;) {
    if (queue_n_ > 0) {
      const Queued q = queue_[queue_head_];
      queue_head_ = (queue_head_ + 1) % queue_cap_;
      --queue_n_;
      process(q);
      if (finished_) return state_;
      if (queue_n_ == 0) settle_fold();  // the line is cut: what it held too
      if (queue_n_ == 0 && !runner_.done() && line_end_stops()) return state_;
      if (status_.moves - moves0 >= budget.moves || mill_.stats().dexel_updates - work0 >= budget.dexel_updates ||
          (budget.yield && budget.yield(budget.yield_ctx))) {
        settle_fold();  // a step returns with the grid showing every record
        return state_ = SimState::kReady;
      }
      continue;
    }
    if (lines >= budget.lines) return state_ = SimState::kReady;
    if (!runner_.step()) {
      if (runner_.waiting()) return state_ = SimState::kNeedInput;
      if (queue_n_ > 0) continue;  // what the end of the input made (a compensation queue's last moves)
      if (finished_) return state_;
      // A single pass stops at its first input error, as the scan does.
      if (!job_.stop_line && msgs_.errors() > 0) {
        stop_with(SimStop::kInputError, msgs_.kept[0].line);
        return state_;
      }
      state_ = runner_.io_error() ? SimState::kIoError : SimState::kDone;
      finish();
      return state_;
    }
    ++lines;
    if (queue_n_ == 0 && line_end_stops()) return state_;
  }
}

template <class H>
ProbeSense SimulationT<H>::sense(const PointNm& from, const PointNm& to, int motion, PointNm* stop) {
  // Every record before the probe is cut: step reads a line only with the
  // queue empty, and the probe's own records come when its block commits.
  // What is left is the last move's deferred end cap, shown as sync shows it.
  sync();
  ToolProfile tip = profile_;
  if (job_.probe_tip_nm > 0) {
    tip.kind = ToolKind::kBall;
    tip.radius_nm = job_.probe_tip_nm / 2;
    tip.corner_nm = tip.radius_nm;
  }
  switch (probe_move(grid_, tip, from, to, motion == 382 || motion == 383, stop)) {
    case ProbeResult::kTripped: return ProbeSense::kTripped;
    case ProbeResult::kAlreadyTripped: return ProbeSense::kAlreadyTripped;
    default: return ProbeSense::kNoContact;
  }
}

template <class H>
void SimulationT<H>::sync() {
  settle_fold();
  mill_.flush();
  if (job_.provenance) provenance_note(&prov_, grid_.dirty);
  if (job_.engagement) engage_meter_note(&engage_, grid_.dirty);
  if (observer_) observer_->changed(grid_.dirty);
  grid_.dirty = GridRect::none();
}

template <class H>
void SimulationT<H>::finish() {
  if (finished_) return;
  start();
  finished_ = true;
  if (state_ == SimState::kReady || state_ == SimState::kNeedInput) state_ = SimState::kDone;
  settle_fold();
  mill_.finish();
  if (job_.provenance) provenance_record(&prov_, grid_.dirty, last_move_line_, nullptr);
  if (job_.engagement) engage_meter_commit(&engage_, grid_, grid_.dirty, engage_cls_, engage_band_);  // the last end cap
  if (job_.design &&
      gouge_watch_check(&gouges_, grid_, grid_.dirty, last_move_line_, mill_.position(), have_origin_ ? &origin_ : nullptr)) {
    gouged_ = true;
    ++gouge_finds_;
  }
  if (safety_on_) {  // the deferred end cap, now cut for good, is the last move's
    CanonRecord cap{};
    cap.kind = CanonKind::kDwell;
    cap.line = last_move_.line;
    if (safety_watch_record(&safety_, grid_, grid_.dirty, cap, last_move_, nullptr)) collided_ = true;
  }
  if (job_.material) {  // and to the process rules, in the last move's state
    ProcessState last = last_process_;
    last.time_us = 0;
    process_watch_record(&process_, grid_, grid_.dirty, last, nullptr);
  }
  if (observer_) observer_->changed(grid_.dirty);
  grid_.dirty = GridRect::none();
}

}  // namespace dexmill

#endif
