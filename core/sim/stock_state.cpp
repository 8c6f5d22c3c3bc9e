// core/sim/stock_state.h: a saved stock into the next run's plan, a run's
// stock into the meta it is saved with.
#include "core/sim/stock_state.h"

#include "core/stock/stock_transform.h"

namespace dexmill {

GridPlan sim_plan_of_stock(const StockMeta& m) {
  GridPlan p{};
  p.geo = m.geo;
  p.stock_nx = m.stock_nx;
  p.stock_ny = m.stock_ny;
  p.top_lsb = m.top_lsb;
  p.stock = StockBox{m.stock_lo, m.stock_hi};
  return p;
}

template <class H>
StockStateError sim_stock_fits(const StockMeta& m) {
  return m.height_bits == static_cast<int>(8 * sizeof(H)) ? StockStateError::kOk : StockStateError::kHeightBits;
}

template <class H>
StockStateError sim_stock_meta(const SimulationT<H>& sim, const char* program, StockMeta* out, int64_t program_us) {
  const SimJob& job = sim.job();
  const StockMeta* was = job.resume;
  if (was && was->nprograms >= kStockMaxPrograms) return StockStateError::kTooManyPrograms;
  const DexelGrid<H>& g = sim.grid();
  StockMeta& m = *out;
  m = StockMeta{};
  m.geo = GridGeometry{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm};
  m.height_bits = static_cast<int>(8 * sizeof(H));
  m.bottoms_zero = g.bottoms_zero;
  m.top_bound_lsb = g.top_bound_lsb;
  m.stock_nx = job.plan.stock_nx;
  m.stock_ny = job.plan.stock_ny;
  m.top_lsb = job.plan.top_lsb;
  m.stock_lo = job.plan.stock.lo;
  m.stock_hi = job.plan.stock.hi;
  m.have_position = true;
  m.tool = sim.status().tool;
  m.position = sim.mill().position();
  const uint64_t removed = sim.removed_lsb();
  const int64_t us = program_us >= 0 ? program_us : sim.status().sim_us;
  const uint64_t moves = sim.status().moves;
  m.removed_lsb_dexels = (was ? was->removed_lsb_dexels : 0) + removed;
  m.sim_us = (was ? was->sim_us : 0) + us;
  m.moves = (was ? was->moves : 0) + moves;
  m.frame = was ? was->frame : stock_frame_identity();
  if (was) {
    stock_name_set(m.material, was->material);
    m.material_hash = was->material_hash;
    stock_name_set(m.design, was->design);
    m.design_hash = was->design_hash;
    m.nprograms = was->nprograms;
    for (int k = 0; k < was->nprograms; ++k) m.programs[k] = was->programs[k];
  }
  StockProgram& p = m.programs[m.nprograms++];
  for (int e = 0; e < 3; ++e) p.setup[4 * e] = 1;  // no setup: as it was
  for (int32_t k = 0; k < job.nsetups; ++k) stock_setup_record(job.setups[k], p.setup, p.setup_offset_nm);
  stock_name_set(p.name, program);
  p.removed_lsb_dexels = removed;
  p.sim_us = us;
  p.moves = moves;
  if (const ToolProvenance<H>* prov = sim.provenance()) {
    m.layers |= kStockLayerClass;
    if (prov->line) m.layers |= kStockLayerLine;
    if (prov->line && prov->program) m.layers |= kStockLayerProgram;
    m.prov_slots = prov->slots;
    m.prov_ntools = prov->ntools;
    m.prov_unlisted = prov->unlisted;
    m.prov_current = prov->current;
    for (int k = 0; k < prov->ntools && k < kStockMaxTools; ++k) m.prov_tool[k] = prov->tool[k];
  }
  return StockStateError::kOk;
}

#define DEXMILL_STOCK_STATE_INSTANTIATE(H)                         \
  template StockStateError sim_stock_fits<H>(const StockMeta&); \
  template StockStateError sim_stock_meta<H>(const SimulationT<H>&, const char*, StockMeta*, int64_t);
DEXMILL_STOCK_STATE_INSTANTIATE(height_t)
#undef DEXMILL_STOCK_STATE_INSTANTIATE

}  // namespace dexmill
