// `dexmill zig`'s job; see zig_job.h.
#include "tools/run/zig_job.h"

#include <cstdio>

#include "core/material/material_preset.h"
#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "platform/report/report_json.h"
#include "tools/cli/cli.h"
#include "tools/run/run_assess.h"

namespace dexmill {
namespace cli {

int builtin_setup(const BuiltinDesign& b, bool tool_given, JobOptions* o) {
  if (!o->stock_stl.empty())
    return fail(kExitUsage, "the built-in part %s takes --stock as a box X0,Y0,Z0,X1,Y1,Z1, not an STL blank ('%s')",
                b.name, o->stock_stl.c_str());
  o->builtin = &b;
  o->design = std::string("(built-in part ") + b.name + ")";
  o->design_pgm = false;
  if (!o->have_stock) {
    // The block's top at Z0, as CAM programs set it (the machine starts at
    // 0, 0, 0: on the top, not inside the block). A --stock given is the
    // block instead, the part where it always is (load_design).
    o->have_stock = true;
    const int64_t s[6] = {0, 0, -b.stock_height_nm, (b.nx - 1) * b.pitch_nm, (b.ny - 1) * b.pitch_nm, 0};
    for (int k = 0; k < 6; ++k) o->stock_nm[k] = s[k];
  }
  if (!o->pitch_nm && !o->grid_nx) o->pitch_nm = b.pitch_nm;
  if (!tool_given) {  // the paper's ball
    o->tool = Tool{};
    o->tool.kind = ToolKind::kBall;
    o->tool.diameter_nm = b.ball_dexels * b.pitch_nm;
    o->tool.flute_length_nm = b.stock_height_nm;
    o->tool.length_nm = b.stock_height_nm + 20 * kNmPerMm;
    char spec[kToolSpecTextMax];
    tool_spec_format(o->tool, spec, sizeof spec);
    o->tool_text = spec;
  }
  if (o->material.empty()) o->material = b.material;
  return kExitOk;
}

void zig_fit_to_material(const JobOptions& o, ZigProgramOptions* p) {
  static StockComposition comp;
  const BoxNm box{PointNm{o.stock_nm[0], o.stock_nm[1], o.stock_nm[2]}, PointNm{o.stock_nm[3], o.stock_nm[4], o.stock_nm[5]}};
  if (!material_preset(o.material.c_str(), box, &comp)) return;  // a file: its own business
  int64_t feed = p->feed_nm_per_min;
  int32_t lo = 0, hi = INT32_MAX;
  for (int32_t k = 0; k < comp.material_count; ++k) {
    const MaterialProcess& m = comp.materials[k].process;
    feed = min_of(feed, m.max_feed_nm_per_min);
    lo = max_of(lo, m.spindle_min_rpm);
    hi = min_of(hi, m.spindle_max_rpm);
  }
  p->feed_nm_per_min = feed;
  p->plunge_nm_per_min = feed / 3;
  if (lo <= hi) p->spindle_rpm = clamp(p->spindle_rpm, lo, hi);
}

int zig_generate(const JobOptions& o, ZigJob* z, std::string* text, ZigProgramStats* st, GridPlan* plan_out) {
  // The grid `run` would use for this stock and tool.
  const StockBox stock{PointNm{o.stock_nm[0], o.stock_nm[1], o.stock_nm[2]}, PointNm{o.stock_nm[3], o.stock_nm[4], o.stock_nm[5]}};
  const int64_t pitch_nm = o.pitch_nm || o.grid_nx ? o.pitch_nm : default_pitch_nm(stock, o.tool.diameter_nm);
  GridPlan& plan = *plan_out;
  std::string err;
  if (!plan_grid(stock, o.grid_nx, o.grid_ny, pitch_nm, run_grid_budget(o.max_memory_bytes), &plan, &err))
    return fail(kExitUsage, "%s", err.c_str());
  RunDesign d;
  const int dcode = load_design(o, plan, "", &d);
  if (dcode != kExitOk) return dcode;
  if (!design_columns(d.grid)) return fail(kExitInput, "%s: the design covers no dexel of the stock", o.design.c_str());
  const int64_t p = plan.geo.pitch_nm;
  z->prog.zig.stepover_dex = static_cast<int32_t>(max_of<int64_t>(1, z->stepover_nm ? div_round(z->stepover_nm, p) : 1));
  z->prog.zig.step_dex = static_cast<int32_t>(max_of<int64_t>(1, z->step_nm ? div_round(z->step_nm, p) : 1));
  z->prog.safe_z_nm = z->have_safe ? z->safe_z_nm : stock.hi.z_nm + 5 * kNmPerMm;
  if (z->prog.safe_z_nm <= stock.hi.z_nm) return fail(kExitUsage, "--safe-z must be above the stock's top");
  // The lowest the tool goes where no design is under it: the design's
  // lowest top.
  int64_t lowest = INT64_MAX;
  for (int32_t t : d.tops)
    if (t != kNoDesign) lowest = min_of<int64_t>(lowest, t);
  const int64_t floor_nm = plan.geo.z0_nm + lowest * plan.geo.lsb_nm;
  char spec[kToolSpecTextMax];
  tool_spec_format(o.tool, spec, sizeof spec);
  z->prog.header = "dexmill zig: " + (o.builtin ? "built-in part " + std::string(o.builtin->name) : o.design) + ", tool " + spec + ", stripes along " + (z->prog.zig.along_y ? "y" : "x") +
                  " every " + nm_to_mm_text(z->prog.zig.stepover_dex * p, 4) + " mm, a position every " +
                  nm_to_mm_text(z->prog.zig.step_dex * p, 4) + " mm, " + (z->prog.zigzag ? "zigzag" : "lifted returns") +
                  (z->prog.zig.allowance_nm ? ", allowance " + nm_to_mm_text(z->prog.zig.allowance_nm, 4) + " mm" : "") +
                  "\nsimulate with: dexmill run PROGRAM --stock " + nm_to_mm_text(o.stock_nm[0], 3) + "," +
                  nm_to_mm_text(o.stock_nm[1], 3) + "," + nm_to_mm_text(o.stock_nm[2], 3) + "," +
                  nm_to_mm_text(o.stock_nm[3], 3) + "," + nm_to_mm_text(o.stock_nm[4], 3) + "," +
                  nm_to_mm_text(o.stock_nm[5], 3) + " --pitch " + nm_to_mm_text(p, 4) + " --tool " + spec + " --design " + (o.builtin ? std::string(o.builtin->name) : o.design);
  if (o.design_pgm)
    z->prog.header += " --design-z " + nm_to_mm_text(o.design_z_nm[0], 3) + "," + nm_to_mm_text(o.design_z_nm[1], 3);
  else if (o.design_offset_nm[0] || o.design_offset_nm[1] || o.design_offset_nm[2])
    z->prog.header += " --design-offset " + nm_to_mm_text(o.design_offset_nm[0], 3) + "," +
                     nm_to_mm_text(o.design_offset_nm[1], 3) + "," + nm_to_mm_text(o.design_offset_nm[2], 3);
  if (!zig_program(d.grid, tool_profile(o.tool), z->prog, floor_nm, text, st, &err)) return fail(kExitUsage, "%s", err.c_str());
  return kExitOk;
}

void zig_print_stats(const GridPlan& plan, const ZigProgramStats& st) {
  std::fprintf(stderr, "dexmill zig: grid %d x %d at %s mm, %u stripes, %llu positions, %llu moves, %.3f s (%.0f positions/s)\n",
               plan.geo.nx, plan.geo.ny, nm_to_mm_text(plan.geo.pitch_nm, 4).c_str(), st.stripes,
               static_cast<unsigned long long>(st.positions), static_cast<unsigned long long>(st.moves), st.seconds,
               st.seconds > 0 ? static_cast<double>(st.positions) / st.seconds : 0.0);
}

}  // namespace cli
}  // namespace dexmill
