#include "core/interp/modal_context.h"

#include "core/interp/interp.h"

namespace dexmill {

ModalContext modal_context_save(const InterpState& s, bool auto_restore) {
  ModalContext c{};
  c.valid = true;
  c.auto_restore = auto_restore;
  c.inch = s.inch;
  c.incremental = s.incremental;
  c.arc_absolute = s.arc_absolute;
  c.inverse_time = s.inverse_time;
  c.per_rev = s.per_rev;
  c.retract_to_r = s.retract_to_r;
  c.diameter_x = s.diameter_x;
  c.plane = s.plane;
  c.comp_side = s.comp.side;
  c.coord_system = s.coord_system;
  c.coolant = s.coolant;
  c.spindle_dir = s.spindle_dir;
  c.path_mode = s.path_mode;
  c.path_tolerance_nm = s.path_tolerance_nm;
  c.spindle_rpm = s.spindle_rpm;
  c.feed_nm_per_min = s.feed_nm_per_min;
  c.tlo_nm = s.tlo_nm;
  return c;
}

void modal_context_apply(const ModalContext& c, InterpState* s) {
  s->inch = c.inch;
  s->incremental = c.incremental;
  s->arc_absolute = c.arc_absolute;
  s->inverse_time = c.inverse_time;
  s->per_rev = c.per_rev;
  s->retract_to_r = c.retract_to_r;
  s->diameter_x = c.diameter_x;
  s->plane = c.plane;
  s->coord_system = c.coord_system;
  s->coolant = c.coolant;
  s->spindle_dir = c.spindle_dir;
  s->path_mode = c.path_mode;
  s->path_tolerance_nm = c.path_tolerance_nm;
  s->spindle_rpm = c.spindle_rpm;
  s->feed_nm_per_min = c.feed_nm_per_min;
  s->tlo_nm = c.tlo_nm;
}

}  // namespace dexmill
