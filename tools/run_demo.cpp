// `dexmill run --demo NAME`; see run_demo.h.
#include "tools/run_demo.h"

#include <cstdio>
#include <string>

#include "core/design/builtin.h"
#include "core/material/material_preset.h"
#include "core/math/fixed.h"
#include "platform/frame_files.h"
#include "platform/output_file.h"
#include "platform/report_json.h"
#include "tools/cli.h"
#include "tools/run_job.h"
#include "tools/zig_job.h"

namespace dexmill {
namespace cli {
namespace {

// Feeds and spindle speed within every limit of the demo's material preset
// (paper §2.6: the process rules then pass): the lowest max feed (at most
// 1000 mm/min), a third of it to plunge, a speed inside every range.
void fit_to_material(const RunOptions& o, ZigProgramOptions* p) {
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

}  // namespace

int run_demo(RunOptions o) {
  if (o.demo == "list") {
    for (int32_t k = 0; k < builtin_design_count(); ++k) {
      const BuiltinDesign& b = builtin_design_at(k);
      std::printf("%-9s %3d x %-3d dexels of %s mm, %d-dexel ball, %-10s %s\n", b.name, b.nx, b.ny,
                  nm_to_mm_text(b.pitch_nm, 3).c_str(), b.ball_dexels, b.material, b.about);
    }
    return kExitOk;
  }
  const BuiltinDesign* b = builtin_design_find(o.demo.c_str());
  if (!b) return fail(kExitUsage, "no built-in part '%s' (dexmill run --demo list)", o.demo.c_str());
  builtin_setup(*b, o.tool_given, &o);
  const std::string dir = "out/" + o.demo;
  std::string err;
  if (!make_dirs(dir, &err)) return fail(kExitIo, "%s", err.c_str());
  // The paper's path: stripes one dexel apart, a position on every dexel,
  // the tool lifted at the end of each and returned at rapid.
  ZigJob job;
  fit_to_material(o, &job.prog);
  std::string text;
  ZigProgramStats st;
  GridPlan plan;
  const int code = zig_generate(o, &job, &text, &st, &plan);
  if (code != kExitOk) return code;
  if (!o.quiet) zig_print_stats(plan, st);
  o.file = dir + "/" + o.demo + ".ngc";
  char e[1300];
  if (!write_output(o.file.c_str(), text.data(), text.size(), e, sizeof e)) return fail(kExitIo, "%s", e);
  if (o.image.empty()) o.image = dir + "/final.png";
  if (o.error_image.empty()) o.error_image = dir + "/error.png";
  if (o.frames_dir.empty()) o.frames_dir = dir + "/frames";
  if (o.report.empty()) o.report = dir + "/report.json";
  if (!o.have_color) o.color = RunOptions::Color::kMaterial;
  const int rc = run_job(o);
  if (rc == kExitOk && !o.quiet)
    std::fprintf(stderr, "dexmill: demo %s written to %s/ (%s.ngc, final.png, error.png, frames/, report.json)\n",
                 o.demo.c_str(), dir.c_str(), o.demo.c_str());
  return rc;
}

}  // namespace cli
}  // namespace dexmill
