// One run of a program on a stock; see simulation.h.
#include "core/sim/simulation.h"
#include "core/sim/simulation_impl.h"

#include <string.h>

#include "core/grid/volume.h"

namespace dexmill {

void sim_checks_for_tools(SimChecks* c, const Tool* tools, int ntools) {
  for (int k = 0; k < ntools; ++k) {
    const Tool& t = tools[k];
    c->shank = c->shank || t.flute_length_nm > 0;
    c->holder = c->holder || t.holder_segments > 0;
    c->plunge = c->plunge || !t.centre_cutting;
  }
}

InterpOptions sim_interp_options(const SimJob& job, const ToolTable* fallback, ProgramMemory* mem) {
  InterpOptions o;
  o.inch = job.inch;
  o.units_given = job.units_given;
  o.feed_in_line_units = job.feed_in_line_units;
  o.tools = job.offsets ? job.offsets : fallback;
  o.warnings = job.warnings;
  o.messages = job.notes;
  o.default_feed_nm_per_min = job.default_feed_nm_per_min;
  o.max_blocks = job.max_blocks;
  o.work_offsets = job.work_offsets;
  o.start_coord_system = job.start_coord_system;
  o.start_g92 = job.start_g92;
  o.start_tlo_nm = job.start_tlo_nm;
  if (job.resume && job.resume->have_position) {
    o.start_given = true;
    o.start_pos = job.resume->position;
    o.start_tool = job.resume->tool;
  }
  if (mem) {
    memset(static_cast<void*>(mem), 0, sizeof *mem);  // as a fresh one: every default is zero (params.h, oword_store.h)
    o.params = &mem->params;
    o.control = &mem->control;
  }
  return o;
}

// The build's heights (simulation_impl.h says why only those).
template class SimulationT<height_t>;

}  // namespace dexmill
