// The interpreter's own parameters, read as LinuxCNC 2.9 gives
// them: lengths in the program's current units, positions in the current
// coordinate system. Numbered: #5061-#5069 the last probe's end (a G38.x
// move is simulated to its end point: the contact point cannot be known)
// and #5070 1 after one, #5161-#5169 G28 home, #5181-#5189 G30 home,
// #5210 G92 in force, #5211-#5219 G92 offsets, #5220 the coordinate system
// (1 = G54 ... 9 = G59.3), #5221 + 20 (k - 1) + axis its offsets (#5230 +
// 20 (k - 1): rotation, 0), #5400 the tool, #5403 its length offset,
// #5420-#5428 the position. Named (predefined, read-only): _x _y _z (and
// a b c u v w: 0), _metric _imperial _absolute _incremental _inverse_time
// _units_per_minute _feed _rpm _current_tool _current_pocket
// _selected_tool _selected_pocket _coord_system _motion_mode _plane
// _spindle_on _spindle_cw _flood _mist _ccomp _tool_offset _retract_r_plane
// _retract_old_z, and _value and _value_returned (what the last endsub or
// return gave; oword_store.h).
#include <string.h>

#include "core/math/fixed.h"
#include "core/interp/interp.h"

namespace dexmill {
namespace {

int64_t axis_nm(const PointNm& p, int axis) { return axis == 0 ? p.x_nm : axis == 1 ? p.y_nm : axis == 2 ? p.z_nm : 0; }

// A length in the program's units, e9.
int64_t length(const InterpState& s, int64_t nm) { return s.inch ? muldiv_round(nm, 10000, 254) : nm * 1000; }

// The position in the current coordinate system, axis 0..8 (x y z a b c u v w).
int64_t position(const InterpState& s, int axis) {
  if (axis > 2) return 0;
  return length(s, axis_nm(s.pos, axis) - axis_nm(s.work_offset[s.coord_system], axis) - axis_nm(s.g92, axis));
}

bool numbered(const InterpState& s, int32_t n, int64_t* e9) {
  auto axis_of = [](int32_t first, int32_t n2, int* axis) {
    *axis = n2 - first;
    return *axis >= 0 && *axis < 9;
  };
  int axis;
  if (axis_of(5161, n, &axis)) return *e9 = length(s, axis_nm(s.g28_home, axis)), true;
  if (axis_of(5181, n, &axis)) return *e9 = length(s, axis_nm(s.g30_home, axis)), true;
  if (n == 5210) return *e9 = (s.g92.x_nm || s.g92.y_nm || s.g92.z_nm) ? kGValueOne : 0, true;
  if (axis_of(5211, n, &axis)) return *e9 = length(s, axis_nm(s.g92, axis)), true;
  if (n == 5220) return *e9 = (s.coord_system + 1) * kGValueOne, true;
  if (n >= 5221 && n <= 5390) {
    const int32_t k = (n - 5221) / 20, a = (n - 5221) % 20;
    if (a > 9) return false;
    *e9 = a == 9 ? s.rotation_deg_e9[k] : length(s, axis_nm(s.work_offset[k], a));
    return true;
  }
  if (axis_of(5061, n, &axis)) return *e9 = length(s, axis_nm(s.probe_prog, axis)), true;
  if (n == 5070) return *e9 = s.probed ? kGValueOne : 0, true;
  if (n == 5400) return *e9 = s.tool * kGValueOne, true;
  if (axis_of(5401, n, &axis)) return *e9 = axis == 2 ? length(s, s.tlo_nm) : 0, true;
  if (axis_of(5420, n, &axis)) return *e9 = position(s, axis), true;
  return false;
}

bool named(const InterpState& s, const char* name, int64_t* e9) {
  static const char* const kAxes[9] = {"_x", "_y", "_z", "_a", "_b", "_c", "_u", "_v", "_w"};
  for (int a = 0; a < 9; ++a)
    if (!strcmp(name, kAxes[a])) return *e9 = position(s, a), true;
  struct Flag {
    const char* name;
    int64_t value;
  };
  const int64_t one = kGValueOne;
  const Flag flags[] = {
      {"_metric", s.inch ? 0 : one},
      {"_imperial", s.inch ? one : 0},
      {"_absolute", s.incremental ? 0 : one},
      {"_incremental", s.incremental ? one : 0},
      {"_inverse_time", s.inverse_time ? one : 0},
      {"_units_per_minute", s.inverse_time || s.per_rev ? 0 : one},
      {"_units_per_rev", s.per_rev ? one : 0},
      {"_feed", length(s, s.feed_nm_per_min)},
      {"_rpm", static_cast<int64_t>(s.spindle_rpm) * one},
      {"_current_tool", static_cast<int64_t>(s.tool) * one},
      {"_current_pocket", static_cast<int64_t>(s.tool) * one},
      {"_selected_tool", static_cast<int64_t>(s.selected_tool) * one},
      {"_selected_pocket", static_cast<int64_t>(s.selected_tool) * one},
      // G54 540 ... G59 590, G59.1 591, G59.2 592, G59.3 593 (LinuxCNC).
      {"_coord_system", (s.coord_system < 6 ? 540 + 10 * s.coord_system : 591 + (s.coord_system - 6)) * one},
      {"_motion_mode", static_cast<int64_t>(s.motion) * one},
      {"_plane", (s.plane == Plane::kXY ? 170 : s.plane == Plane::kZX ? 180 : 190) * one},
      {"_spindle_on", s.spindle_dir != 0 ? one : 0},
      {"_spindle_cw", s.spindle_dir > 0 ? one : 0},
      {"_flood", (s.coolant & 2) ? one : 0},
      {"_mist", (s.coolant & 1) ? one : 0},
      {"_ccomp", 400 * one},
      {"_tool_offset", (s.tlo_nm != 0 ? 430 : 490) * one},
      {"_retract_r_plane", s.retract_to_r ? one : 0},
      {"_retract_old_z", s.retract_to_r ? 0 : one},
  };
  for (const Flag& f : flags)
    if (!strcmp(name, f.name)) return *e9 = f.value, true;
  return false;
}

}  // namespace

bool Interp::read_param(const void* ctx, int32_t n, const char* name, GValue* out) {
  const Interp* in = static_cast<const Interp*>(ctx);
  const InterpState& s = in->state_;
  if (name && !strcmp(name, "_value")) {
    const OwordStore* c = in->options_.control;
    return out->e9 = c ? c->return_value.e9 : 0, true;
  }
  if (name && !strcmp(name, "_value_returned")) {
    const OwordStore* c = in->options_.control;
    return out->e9 = c && c->value_returned ? kGValueOne : 0, true;
  }
  return name ? named(s, name, &out->e9) : numbered(s, n, &out->e9);
}

}  // namespace dexmill
