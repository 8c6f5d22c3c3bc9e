// A simulation's memory: one block of the caller's, laid out here once for
// sim_required_bytes (counting) and sim_create (carving); see simulation.h.
#include <new>

#include "core/cut/sweep.h"
#include "core/grid/volume.h"
#include "core/sim/carver.h"
#include "core/sim/simulation.h"
#include "core/tool/cutter.h"

namespace dexmill {

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
  int64_t* line_feed = nullptr;
  uint8_t* seen = nullptr;
  size_t seen_bytes = 0;
  uint8_t* prov_cls = nullptr;
  uint32_t* prov_shadow = nullptr;
  uint32_t* prov_lines = nullptr;
};

namespace {

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
  }
  if (job.design) {
    mem.seen_bytes = gouge_watch_seen_bytes(g.nx, g.ny);
    mem.seen = c.take<uint8_t>(mem.seen_bytes);
  }
  if (job.provenance) {
    mem.prov_cls = c.take<uint8_t>(cells);
    mem.prov_shadow = c.take<uint32_t>(cells);
    if (job.provenance_lines) mem.prov_lines = c.take<uint32_t>(cells);
  }
  if (m) *m = mem;
  return c.used();
}

}  // namespace

template <class H>
size_t SimulationT<H>::required_bytes(const SimJob& job, SimSetup* why) {
  SimSetup dummy;
  SimSetup* w = why ? why : &dummy;
  *w = SimSetup{};
  return layout<H>(job, nullptr, nullptr, w, sizeof(SimulationT));
}

template <class H>
SimulationT<H>* SimulationT<H>::create(const SimJob& job, void* mem, size_t bytes, SimSetup* why) {
  SimSetup dummy;
  SimSetup* w = why ? why : &dummy;
  *w = SimSetup{};
  const size_t need = layout<H>(job, nullptr, nullptr, w, sizeof(SimulationT));
  if (need == 0) return nullptr;
  if (!mem || bytes < need || (reinterpret_cast<uintptr_t>(mem) & 7) != 0) {
    w->error = SimError::kBufferTooSmall;
    return nullptr;
  }
  char* base = static_cast<char*>(mem);
  Memory m;
  (void)layout<H>(job, base, &m, w, sizeof(SimulationT));
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
      grid_(plan_grid_view<H>(job.plan)),
      mill_(&grid_, job.mode, library_, m.words, m.nwords),
      chunks_(m.input, job.input_buffer_bytes),
      interp_(this,
              [&]() {
                InterpOptions o = sim_interp_options(job, &single_, m.program);
                o.warnings = &msgs_;  // counted, then the job's
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
      prov_cls_(m.prov_cls),
      prov_shadow_(m.prov_shadow),
      prov_lines_(m.prov_lines) {
  msgs_.warn_to = job.warnings;
  const size_t cells = static_cast<size_t>(grid_.nx) * static_cast<size_t>(grid_.ny);
  (void)grid_init(&grid_, job.plan.geo, m.top, m.bottom, cells);  // the geometry was checked
  fill_stock(&grid_, job.plan);
  if (m.fixture_top) {
    fixture_grid_.top = m.fixture_top;
    fixture_grid_.bottom = m.fixture_bottom;
  }
  load_tool(job.tool);
  status_.tool = 0;
}

// The members defined here (the class's others: simulation.cpp).
#define DEXMILL_SIM_CREATE_INSTANTIATE(H)                                                              \
  template size_t SimulationT<H>::required_bytes(const SimJob&, SimSetup*);                          \
  template SimulationT<H>* SimulationT<H>::create(const SimJob&, void*, size_t, SimSetup*);          \
  template SimulationT<H>::SimulationT(const SimJob&, const Memory&);
DEXMILL_SIM_CREATE_INSTANTIATE(uint8_t)
DEXMILL_SIM_CREATE_INSTANTIATE(uint16_t)
DEXMILL_SIM_CREATE_INSTANTIATE(uint32_t)
#undef DEXMILL_SIM_CREATE_INSTANTIATE

}  // namespace dexmill
