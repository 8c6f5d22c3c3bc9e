// The embedding API: what a simulation knows between steps (dexmill.h).
#include "core/grid/volume.h"
#include "display/api/handles.h"

using namespace dexmill;
using namespace dexmill::api;

static_assert(DM_STOPPED_NOT == static_cast<int>(SimStop::kNone) &&
                  DM_STOPPED_INPUT_ERROR == static_cast<int>(SimStop::kInputError) &&
                  DM_STOPPED_GOUGE == static_cast<int>(SimStop::kGouge) &&
                  DM_STOPPED_COLLISION == static_cast<int>(SimStop::kCollision) &&
                  DM_STOPPED_TOOL == static_cast<int>(SimStop::kToolFailed) &&
                  DM_STOPPED_BY_CALLER == static_cast<int>(SimStop::kCaller),
              "DM_STOPPED_* are the engine's SimStop numbers");
static_assert(DM_FIND_PLUNGE - DM_FIND_RAPID == static_cast<int>(SafetyKind::kPlunge) &&
                  DM_FIND_FIXTURE - DM_FIND_RAPID == static_cast<int>(SafetyKind::kFixture) &&
                  DM_FIND_COOLANT - DM_FIND_FEED == static_cast<int>(ProcessRule::kCoolant),
              "the safety kinds and process rules follow DM_FIND_RAPID and DM_FIND_FEED in their order");

static_assert(DM_UNITS_VERDICT_SET == static_cast<int>(UnitsVerdict::kSet) &&
                  DM_UNITS_VERDICT_DEFAULT == static_cast<int>(UnitsVerdict::kDefault) &&
                  DM_UNITS_VERDICT_LOOK_INCH == static_cast<int>(UnitsVerdict::kLookInch),
              "DM_UNITS_VERDICT_* are the interpreter's UnitsVerdict numbers");

namespace {

void box_out(const StockBox& b, dm_box* out) {
  out->lo_nm[0] = b.lo.x_nm;
  out->lo_nm[1] = b.lo.y_nm;
  out->lo_nm[2] = b.lo.z_nm;
  out->hi_nm[0] = b.hi.x_nm;
  out->hi_nm[1] = b.hi.y_nm;
  out->hi_nm[2] = b.hi.z_nm;
}

void point_out(const PointNm& p, int64_t* out) {
  out[0] = p.x_nm;
  out[1] = p.y_nm;
  out[2] = p.z_nm;
}

size_t gouges_kept(const Simulation& s) { return s.gouges() ? s.gouges()->nevents : 0; }
size_t safety_kept(const Simulation& s) { return s.safety() ? s.safety()->nevents : 0; }
size_t rules_kept(const Simulation& s) { return s.process() ? s.process()->nkept : 0; }

}  // namespace

namespace {

// An input error's or a warning's fields and message (dm_error_get, dm_warning_get).
dm_status diag_out(const GcodeDiag* d, uint32_t kept, uint32_t index, dm_input_error* out) {
  if (index >= kept) return DM_E_INDEX;
  *out = dm_input_error();
  out->code = gcode_error_number(d[index].code);
  out->line = d[index].line;
  out->col = d[index].col;
  out->follow_on = d[index].follow_on ? 1 : 0;
  return DM_OK;
}

size_t diag_message(const GcodeDiag* d, uint32_t kept, uint32_t index, char* buf, size_t n) {
  return index < kept ? gcode_format_message(d[index], buf, n) : 0;
}

}  // namespace

extern "C" {

dm_status dm_get_progress(const dm_sim* sim, dm_progress* out) {
  if (!live(sim) || !out) return DM_E_ARGUMENT;
  const Simulation& s = *sim->sim;
  const SimStatus& st = s.status();
  const DexelGrid<height_t>& g = s.grid();
  *out = dm_progress();
  out->state = static_cast<int32_t>(s.state());
  out->stop_reason = static_cast<int32_t>(s.stop_reason());
  out->stop_line = s.stop_line();
  out->line = st.line;
  point_out(st.pos, out->position_nm);
  out->tool = st.tool;
  out->failed_tool = s.failed_tool();
  out->feed_nm_per_min = st.feed_nm_per_min;
  out->machine_time_us = st.sim_us;
  out->moves = st.moves;
  out->records = st.records;
  out->lines_read = s.lines_read();
  out->errors = s.errors();
  out->warnings = s.warnings();
  out->units_verdict = static_cast<uint32_t>(s.interp().units_verdict());
  out->removed_lsb_dexels = s.removed_lsb();
  out->removed_um3 = volume_um3(out->removed_lsb_dexels, g.lsb_nm, g.pitch_nm);
  out->dexel_updates = s.mill().stats().dexel_updates;
  return DM_OK;
}

dm_status dm_get_grid(const dm_sim* sim, dm_grid_info* out) {
  if (!live(sim) || !out) return DM_E_ARGUMENT;
  const DexelGrid<height_t>& g = sim->sim->grid();
  *out = dm_grid_info();
  out->nx = g.nx;
  out->ny = g.ny;
  out->x0_nm = g.x0_nm;
  out->y0_nm = g.y0_nm;
  out->pitch_nm = g.pitch_nm;
  out->z0_nm = g.z0_nm;
  out->lsb_nm = g.lsb_nm;
  box_out(sim->sim->job().plan.stock, &out->stock);
  return DM_OK;
}

dm_status dm_column_at(const dm_sim* sim, int64_t x_nm, int64_t y_nm, dm_column* out) {
  if (!live(sim) || !out) return DM_E_ARGUMENT;
  const DexelGrid<height_t>& g = sim->sim->grid();
  // Beyond 2^50 nm no column lies (the grid stays within 1 km of the origin).
  constexpr int64_t kFar = int64_t{1} << 50;
  if (x_nm < -kFar || x_nm > kFar || y_nm < -kFar || y_nm > kFar) return DM_E_OUTSIDE;
  const int64_t i = div_round(x_nm - g.x0_nm, g.pitch_nm), j = div_round(y_nm - g.y0_nm, g.pitch_nm);
  if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) return DM_E_OUTSIDE;
  *out = dm_column();
  out->i = static_cast<int32_t>(i);
  out->j = static_cast<int32_t>(j);
  const size_t k = g.index(out->i, out->j);
  out->has_material = g.is_hole(out->i, out->j) ? 0 : 1;
  out->top_nm = g.z0_nm + static_cast<int64_t>(g.top[k]) * g.lsb_nm;
  out->bottom_nm = g.z0_nm + static_cast<int64_t>(g.bottom[k]) * g.lsb_nm;
  out->last_tool = -2;
  if (const ToolProvenance<height_t>* p = sim->sim->provenance()) {
    // One class per listed tool (dm_create): class c is the c-th tool to cut.
    const uint8_t c = p->cls[k];
    if (c > 0 && c <= p->ntools) out->last_tool = p->tool[c - 1];
    if (p->line) out->last_line = p->line[k];
  }
  return DM_OK;
}

dm_status dm_height_nm(const dm_sim* sim, int64_t x_nm, int64_t y_nm, int64_t* top_nm) {
  if (!top_nm) return DM_E_ARGUMENT;
  dm_column c;
  const dm_status s = dm_column_at(sim, x_nm, y_nm, &c);
  if (s != DM_OK) return s;
  if (!c.has_material) return DM_E_OUTSIDE;
  *top_nm = c.top_nm;
  return DM_OK;
}

uint32_t dm_finding_count(const dm_sim* sim) {
  if (!live(sim)) return 0;
  const Simulation& s = *sim->sim;
  return static_cast<uint32_t>(gouges_kept(s) + safety_kept(s) + rules_kept(s));
}

uint64_t dm_finding_total(const dm_sim* sim) {
  if (!live(sim)) return 0;
  const Simulation& s = *sim->sim;
  return (s.gouges() ? s.gouges()->total : 0) + (s.safety() ? s.safety()->total : 0) +
         (s.process() ? s.process()->total : 0);
}

dm_status dm_finding_get(const dm_sim* sim, uint32_t index, dm_finding* out) {
  if (!live(sim) || !out) return DM_E_ARGUMENT;
  const Simulation& s = *sim->sim;
  const DexelGrid<height_t>& g = s.grid();
  *out = dm_finding();
  out->material = -1;
  size_t k = index;
  if (k < gouges_kept(s)) {
    const GougeEvent& e = s.gouges()->events[k];
    out->kind = DM_FIND_GOUGE;
    out->line = out->last_line = e.line;
    // On the design's surface over the deepest column, where the CLI marks it.
    point_out(PointNm{g.x0_nm + e.i * g.pitch_nm, g.y0_nm + e.j * g.pitch_nm, g.z0_nm + e.design_lsb * g.lsb_nm},
              out->at_nm);
    out->depth_nm = e.depth_lsb * g.lsb_nm;
    out->columns = e.columns;
    return DM_OK;
  }
  k -= gouges_kept(s);
  if (k < safety_kept(s)) {
    const SafetyEvent& e = s.safety()->events[k];
    out->kind = DM_FIND_RAPID + static_cast<int32_t>(e.kind);
    out->line = e.line;
    out->last_line = e.last_line ? e.last_line : e.line;
    point_out(e.at, out->at_nm);
    out->depth_nm = e.depth_nm;
    out->columns = e.columns;
    return DM_OK;
  }
  k -= safety_kept(s);
  if (k < rules_kept(s)) {
    const ProcessViolation& v = s.process()->kept[k];
    out->kind = DM_FIND_FEED + static_cast<int32_t>(v.rule);
    out->line = out->last_line = v.line;
    out->material = v.material;
    point_out(v.at, out->at_nm);
    out->value = v.value;
    return DM_OK;
  }
  return DM_E_INDEX;
}

uint32_t dm_error_count(const dm_sim* sim) { return live(sim) ? sim->sim->errors() : 0; }

dm_status dm_error_get(const dm_sim* sim, uint32_t index, dm_input_error* out) {
  if (!live(sim) || !out) return DM_E_ARGUMENT;
  int n = 0;
  const GcodeDiag* d = sim->sim->diags(&n);
  return diag_out(d, static_cast<uint32_t>(n), index, out);
}

size_t dm_error_message(const dm_sim* sim, uint32_t index, char* buf, size_t n) {
  if (!live(sim) || !buf || n == 0) return 0;
  buf[0] = 0;
  int kept = 0;
  const GcodeDiag* d = sim->sim->diags(&kept);
  return diag_message(d, static_cast<uint32_t>(kept), index, buf, n);
}

uint32_t dm_warning_count(const dm_sim* sim) { return live(sim) ? sim->sim->warnings() : 0; }

dm_status dm_warning_get(const dm_sim* sim, uint32_t index, dm_input_error* out) {
  if (!live(sim) || !out) return DM_E_ARGUMENT;
  return diag_out(sim->warnings.kept, sim->warnings.n, index, out);
}

size_t dm_warning_message(const dm_sim* sim, uint32_t index, char* buf, size_t n) {
  if (!live(sim) || !buf || n == 0) return 0;
  buf[0] = 0;
  return diag_message(sim->warnings.kept, sim->warnings.n, index, buf, n);
}

}  // extern "C"
