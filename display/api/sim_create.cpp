// The embedding API: a dm_job into the engine's job (core/sim/job.h), its
// memory, creation and end (dexmill.h).
#include <new>

#include "core/material/material_preset.h"
#include "core/sim/carver.h"
#include "core/tool/spec.h"
#include "display/api/handles.h"

using namespace dexmill;
using namespace dexmill::api;

static_assert(DM_TOOL_FLAT == static_cast<int>(ToolKind::kFlat) && DM_TOOL_BALL == static_cast<int>(ToolKind::kBall) &&
                  DM_TOOL_BULL == static_cast<int>(ToolKind::kBullNose) &&
                  DM_TOOL_VBIT == static_cast<int>(ToolKind::kVBit),
              "DM_TOOL_* are the ToolKind numbers");

namespace dexmill {
namespace api {

int32_t NumberedTools::find(int32_t number) const {
  for (int32_t k = 0; k < n; ++k)
    if (numbers[k] == number) return k;
  return -1;
}

bool NumberedTools::tool(int32_t number, Tool* out) const {
  const int32_t k = find(number);
  if (k >= 0) *out = tools[k];
  return k >= 0;
}

bool NumberedTools::tool_length_nm(int32_t number, int64_t* z_nm) const {
  const int32_t k = find(number);
  if (k >= 0) *z_nm = lengths[k];
  return k >= 0;
}

bool NumberedTools::tool_radius_nm(int32_t number, int64_t* r_nm) const {
  const int32_t k = find(number);
  if (k >= 0) *r_nm = tools[k].diameter_nm / 2;
  return k >= 0;
}

dm_status status_of(SimError e) {
  switch (e) {
    case SimError::kOk: return DM_OK;
    case SimError::kBufferTooSmall: return DM_E_MEMORY;
    case SimError::kGrid: return DM_E_GRID;
    case SimError::kFixturesOutside:
    case SimError::kFixturesTooLarge: return DM_E_FIXTURES;
    case SimError::kDesignGeometry: return DM_E_DESIGN;
    default: return DM_E_TOOL;  // invalid, too wide, too large, cannot cut
  }
}

}  // namespace api
}  // namespace dexmill

namespace {

// Coordinates the API takes: within 1 km of the origin (the grid's own
// bound, core/grid/grid.h), so that differences never overflow.
constexpr int64_t kCoordinateMaxNm = 1000LL * 1000 * kNmPerMm;
bool coordinate_ok(int64_t v) { return v >= -kCoordinateMaxNm && v <= kCoordinateMaxNm; }

// A C string's length, counting no further than `most`.
size_t text_length(const char* s, size_t most) {
  size_t n = 0;
  while (n < most && s[n]) ++n;
  return n;
}

dm_status tool_of(const dm_tool& d, Tool* out) {
  if (d.spec) {
    const size_t n = text_length(d.spec, 4 * kToolSpecTextMax);
    if (n == 4 * kToolSpecTextMax) return DM_E_TOOL_SPEC;
    const ToolSpecError e = tool_spec_parse(d.spec, n, out);
    if (e == ToolSpecError::kOk) return DM_OK;
    return e == ToolSpecError::kOutOfRange ? DM_E_TOOL : DM_E_TOOL_SPEC;
  }
  if (d.shape < DM_TOOL_FLAT || d.shape > DM_TOOL_VBIT) return DM_E_ARGUMENT;
  Tool t;
  t.kind = static_cast<ToolKind>(d.shape);
  t.diameter_nm = d.diameter_nm;
  t.corner_radius_nm = d.corner_radius_nm;
  t.tip_angle_mdeg = d.tip_angle_mdeg;
  t.flute_length_nm = d.flute_length_nm;
  t.stick_out_nm = d.stick_out_nm;
  t.shank_diameter_nm = d.shank_diameter_nm;
  t.centre_cutting = d.not_centre_cutting == 0;
  if (tool_spec_complete(&t) != ToolSpecError::kOk) return DM_E_TOOL;
  *out = t;
  return DM_OK;
}

// The job's numbers in their ranges (what the parts below do not check),
// then its stock box (not read by a scan).
dm_status check_values(const dm_job& in) {
  if (in.api_version != DEXMILL_API_VERSION) return DM_E_VERSION;
  if (in.ntools < 0 || in.ntools > DM_TOOLS_MAX) return DM_E_TOOL_NUMBER;
  if (in.nfixtures < 0 || in.nfixtures > DM_FIXTURES_MAX) return DM_E_FIXTURES;
  if ((in.mode != DM_MODE_SWEEP && in.mode != DM_MODE_STAMP) || (in.units != DM_UNITS_MM && in.units != DM_UNITS_INCH) ||
      (in.checks & ~static_cast<uint32_t>(DM_CHECK_ALL)) ||
      (in.stop_at & ~static_cast<uint32_t>(DM_STOP_AT_GOUGE | DM_STOP_AT_COLLISION)) || in.default_feed_nm_per_min < 0 ||
      in.pitch_nm < 0 || in.grid_nx < 0 || in.grid_ny < 0 || in.tolerance_nm < 0 || !coordinate_ok(in.tolerance_nm) ||
      (in.ndesign > 0 && !in.design) || (in.has_table && !coordinate_ok(in.table_z_nm)) ||
      (in.input_buffer_bytes != 0 && in.input_buffer_bytes < DM_INPUT_MIN_BYTES) || in.queue_records > (1u << 16))
    return DM_E_ARGUMENT;
  return DM_OK;
}

dm_status check_stock(const dm_job& in) {
  for (int k = 0; k < 3; ++k)
    if (!coordinate_ok(in.stock.lo_nm[k]) || !coordinate_ok(in.stock.hi_nm[k]) || in.stock.lo_nm[k] >= in.stock.hi_nm[k])
      return DM_E_STOCK;
  return DM_OK;
}

}  // namespace

namespace dexmill {
namespace api {

dm_status tools_of(const dm_job& in, NumberedTools* lib, SimJob* j) {
  if (const dm_status s = tool_of(in.tool, &j->tool)) return s;
  lib->n = 0;
  for (int32_t k = 0; k < in.ntools; ++k) {
    const dm_tool& d = in.tools[k];
    if (d.number < 0 || lib->has(d.number)) return DM_E_TOOL_NUMBER;
    if (!coordinate_ok(d.length_offset_nm)) return DM_E_ARGUMENT;
    if (const dm_status s = tool_of(d, &lib->tools[k])) return s;
    lib->numbers[k] = d.number;
    lib->lengths[k] = d.length_offset_nm;
    lib->n = k + 1;
  }
  if (lib->n > 0) {
    j->library = lib;
    j->offsets = lib;
    j->tools = lib->tools;
    j->ntools = lib->n;
  }
  return DM_OK;
}

// What a scan reads of a job (handles.h).
dm_status scan_job_of(const dm_job& in, NumberedTools* lib, SimJob* j) {
  if (const dm_status s = check_values(in)) return s;
  if (const dm_status s = tools_of(in, lib, j)) return s;
  j->inch = in.units == DM_UNITS_INCH;
  if (in.max_blocks) j->max_blocks = in.max_blocks;
  j->input_buffer_bytes = in.input_buffer_bytes ? in.input_buffer_bytes : LineReader::kStartBytes;
  return DM_OK;
}

}  // namespace api
}  // namespace dexmill

namespace {

dm_status plan_of(const dm_job& in, SimJob* j) {
  const StockBox box{PointNm{in.stock.lo_nm[0], in.stock.lo_nm[1], in.stock.lo_nm[2]},
                     PointNm{in.stock.hi_nm[0], in.stock.hi_nm[1], in.stock.hi_nm[2]}};
  int64_t pitch = in.pitch_nm;
  if (!pitch && !in.grid_nx && !in.grid_ny) {
    int64_t smallest = j->tool.diameter_nm;
    for (int k = 0; k < j->ntools; ++k) smallest = min_of(smallest, j->tools[k].diameter_nm);
    pitch = default_pitch_nm(box, smallest);
  }
  return plan_grid(box, in.grid_nx, in.grid_ny, pitch, &j->plan) == PlanError::kOk ? DM_OK : DM_E_GRID;
}

dm_status checks_of(const dm_job& in, BoxNm* fixtures, SimJob* j) {
  SimChecks& c = j->checks;
  c.rapid = (in.checks & DM_CHECK_RAPID) != 0;
  c.spindle = (in.checks & DM_CHECK_SPINDLE) != 0;
  c.below = (in.checks & DM_CHECK_BELOW) != 0;
  c.shank = (in.checks & DM_CHECK_SHANK) != 0;
  c.holder = (in.checks & DM_CHECK_HOLDER) != 0;
  c.plunge = (in.checks & DM_CHECK_PLUNGE) != 0;
  c.has_table = in.has_table != 0;
  c.table_nm = in.table_z_nm;
  for (int32_t k = 0; k < in.nfixtures; ++k) {
    const dm_box& b = in.fixtures[k];
    for (int a = 0; a < 3; ++a)
      if (!coordinate_ok(b.lo_nm[a]) || !coordinate_ok(b.hi_nm[a])) return DM_E_FIXTURES;
    fixtures[k] = BoxNm{PointNm{b.lo_nm[0], b.lo_nm[1], b.lo_nm[2]}, PointNm{b.hi_nm[0], b.hi_nm[1], b.hi_nm[2]}};
  }
  c.fixtures = in.nfixtures > 0 ? fixtures : nullptr;
  c.nfixtures = in.nfixtures;
  // What the tools describe is checked, as on the command line.
  sim_checks_for_tools(&c, &j->tool, 1);
  sim_checks_for_tools(&c, j->tools, j->ntools);
  return DM_OK;
}

// The engine's job for `in`, pointing into x and at `material` (where the
// composition is or will be: sizing reads only whether there is one,
// core/sim/simulation.h required_bytes).
dm_status job_of(const dm_job& in, JobInputs* x, const StockComposition* material, SimJob* j) {
  if (const dm_status s = check_values(in)) return s;
  if (const dm_status s = check_stock(in)) return s;  // before the tools, as ever: a bad stock is DM_E_STOCK
  if (const dm_status s = scan_job_of(in, &x->library, j)) return s;
  if (const dm_status s = plan_of(in, j)) return s;
  if (const dm_status s = checks_of(in, x->fixtures, j)) return s;
  j->mode = in.mode == DM_MODE_STAMP ? CutMode::kStamp : CutMode::kSweep;
  j->default_feed_nm_per_min = in.default_feed_nm_per_min;
  if (in.queue_records) j->queue_records = in.queue_records;
  if (in.material) {
    if (material_preset_index(in.material) < 0) return DM_E_MATERIAL;
    j->material = material;
  }
  if (in.design) {
    // Its tops come with the block (dm_create); only the stock's columns
    // count, not the grid's ring of holes around it.
    x->design.geo = j->plan.geo;
    j->design = &x->design;
    j->assess.region = GridRect{1, 1, j->plan.stock_nx + 1, j->plan.stock_ny + 1};
    j->assess.tol_nm = in.tolerance_nm;
  }
  // One class per tool (up to the engine's list), so a class names its tool.
  j->provenance = j->provenance_lines = in.provenance != 0;
  j->provenance_slots = kProvenanceMaxTools;
  j->provenance_first_tool = -1;
  j->stop_at_gouge = (in.stop_at & DM_STOP_AT_GOUGE) != 0;
  j->stop_at_collision = (in.stop_at & DM_STOP_AT_COLLISION) != 0;
  return DM_OK;
}

// The block for j: its size, and (base not null) where the design's tops
// and the engine go.
struct Block {
  size_t bytes = 0;
  int32_t* design_tops = nullptr;
  char* engine = nullptr;
  size_t engine_bytes = 0;
};

dm_status block_of(const SimJob& j, char* base, Block* b) {
  SimSetup why;
  b->engine_bytes = Simulation::required_bytes(j, &why);
  if (!b->engine_bytes) return status_of(why.error);
  Carver c(base);
  (void)c.take<dm_sim>(1);
  const size_t cells = static_cast<size_t>(j.plan.geo.nx) * static_cast<size_t>(j.plan.geo.ny);
  b->design_tops = j.design ? c.take<int32_t>(cells) : nullptr;
  b->engine = c.take<char>(b->engine_bytes);
  b->bytes = c.used();
  return DM_OK;
}

bool aligned(const void* p) { return (reinterpret_cast<uintptr_t>(p) & 7) == 0; }

// The design's triangles on the grid (dm_create).
dm_status design_of(const dm_job& in, const Block& b, DesignGrid* d) {
  const GridGeometry geo = d->geo;
  const size_t cells = static_cast<size_t>(geo.nx) * static_cast<size_t>(geo.ny);
  if (!ok(design_init(d, geo, b.design_tops, cells))) return DM_E_DESIGN;
  for (uint32_t k = 0; k < in.ndesign; ++k) {
    TriangleNm t;
    for (int v = 0; v < 3; ++v) {
      for (int a = 0; a < 3; ++a)
        if (!coordinate_ok(in.design[k].v_nm[v][a])) return DM_E_DESIGN;
      t.v[v] = PointNm{in.design[k].v_nm[v][0], in.design[k].v_nm[v][1], in.design[k].v_nm[v][2]};
    }
    if (!ok(design_add_triangle(d, t))) return DM_E_DESIGN;
  }
  return design_columns(*d) > 0 ? DM_OK : DM_E_DESIGN;
}

// dm_create after the dm_sim is in place.
dm_status set_up(const dm_job& in, dm_sim* s, size_t bytes) {
  SimJob j;
  if (const dm_status st = job_of(in, &s->in, &s->material, &j)) return st;
  Block b;
  if (const dm_status st = block_of(j, nullptr, &b)) return st;
  if (bytes < b.bytes) return DM_E_MEMORY;
  (void)block_of(j, reinterpret_cast<char*>(s), &b);
  if (j.material && !material_preset(in.material, BoxNm{j.plan.stock.lo, j.plan.stock.hi}, &s->material))
    return DM_E_MATERIAL;
  if (j.design)
    if (const dm_status st = design_of(in, b, &s->in.design)) return st;
  j.warnings = &s->warnings;
  SimSetup why;
  s->sim = Simulation::create(j, b.engine, b.engine_bytes, &why);
  if (!s->sim) return status_of(why.error);
  s->views.current = j.tool;
  s->views.sim = s->sim;  // the run's marks are kept from its records (display/api/run_marks.h)
  s->sim->set_observer(&s->views);
  s->sim->start();  // the stock as it is now is the untouched one
  return DM_OK;
}

}  // namespace

extern "C" {

dm_status dm_job_init(dm_job* job, uint32_t api_version) {
  if (!job) return DM_E_ARGUMENT;
  if (api_version != DEXMILL_API_VERSION) return DM_E_VERSION;
  *job = dm_job();
  job->api_version = api_version;
  job->tolerance_nm = AssessOptions().tol_nm;
  return DM_OK;
}

const char* dm_material_preset_name(int32_t index) {
  return index >= 0 && index < material_preset_count() ? material_preset_name(index) : nullptr;
}

dm_status dm_required_bytes(const dm_job* job, size_t* bytes) {
  if (!job || !bytes) return DM_E_ARGUMENT;
  *bytes = 0;
  JobInputs x;
  SimJob j;
  // Sizing: the composition's place is not known yet (job_of).
  if (const dm_status s = job_of(*job, &x, reinterpret_cast<const StockComposition*>(&x), &j)) return s;
  Block b;
  if (const dm_status s = block_of(j, nullptr, &b)) return s;
  *bytes = b.bytes;
  return DM_OK;
}

dm_status dm_create(const dm_job* job, void* mem, size_t bytes, dm_sim** out) {
  if (!job || !out) return DM_E_ARGUMENT;
  *out = nullptr;
  if (job->api_version != DEXMILL_API_VERSION) return DM_E_VERSION;
  if (!mem || !aligned(mem) || bytes < sizeof(dm_sim)) return DM_E_MEMORY;
  dm_sim* s = new (mem) dm_sim();
  s->tag = 0;
  s->ended = false;
  s->sim = nullptr;
  const dm_status st = set_up(*job, s, bytes);
  if (st != DM_OK) {
    Simulation::destroy(s->sim);
    return st;
  }
  s->tag = kSimTag;
  *out = s;
  return DM_OK;
}

void dm_destroy(dm_sim* sim) {
  if (!sim || sim->tag != kSimTag) return;
  for (dm_view* v = sim->views.first; v; v = v->next) v->sim = nullptr;
  Simulation::destroy(sim->sim);
  sim->tag = 0;  // a dm_sim has nothing else to end (handles.h)
}

}  // extern "C"
