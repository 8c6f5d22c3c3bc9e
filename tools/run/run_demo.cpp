// `dexmill run --demo NAME`; see run_demo.h.
#include "tools/run/run_demo.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/design/builtin.h"
#include "platform/live/frame_files.h"
#include "platform/report/report_json.h"
#include "tools/cli/cli.h"
#include "tools/run/demo_program.h"
#include "tools/run/run_job.h"
#include "tools/run/zig_job.h"

namespace dexmill {
namespace cli {

int demo_defaults(RunOptions* o) {
  if (o->out.image.empty()) o->out.image = "out/final.ppm";
  if (o->job.design.empty()) {  // the demo's own part: its report has an assessment, and out/error.ppm
    o->job.design = "(the demo's part)";
    o->job.demo_design = true;
    if (o->out.error_image.empty()) o->out.error_image = "out/error.ppm";
  }
  if (o->out.frames_dir.empty()) o->out.frames_dir = "out/frames";
  if (o->job.material.empty()) {
    o->job.material = demo_material();
    if (!o->view.have_color) o->view.color = ViewOptions::Color::kMaterial;
  }
  std::string err;
  if (!make_dirs("out", &err)) return fail(kExitIo, "%s", err.c_str());
  o->job.made_program = demo_program();
  return kExitOk;
}

StockBox demo_stock_box() {
  int64_t v[6];
  const char* s = demo_stock();
  for (int k = 0; k < 6; ++k) {
    v[k] = std::strtol(s, const_cast<char**>(&s), 10) * kNmPerMm;
    if (*s == ',') ++s;
  }
  return StockBox{PointNm{v[0], v[1], v[2]}, PointNm{v[3], v[4], v[5]}};
}

int run_demo(RunOptions o, FileGuard* guard) {
  if (o.job.demo == "list") {
    std::printf("%-9s the built-in demo (run with no FILE on a terminal): a 100 x 70 x 20 mm block of %s, "
                "three tools, writes out/\n", kBuiltinDemoName, demo_material());
    for (int32_t k = 0; k < builtin_design_count(); ++k) {
      const BuiltinDesign& b = builtin_design_at(k);
      std::printf("%-9s %3d x %-3d dexels of %s mm, %d-dexel ball, %-10s %s\n", b.name, b.nx, b.ny,
                  nm_to_mm_text(b.pitch_nm, 3).c_str(), b.ball_dexels, b.material, b.about);
    }
    return kExitOk;
  }
  const BuiltinDesign* b = builtin_design_find(o.job.demo.c_str());
  if (!b) return fail(kExitUsage, "no built-in part '%s' (dexmill run --demo list)", o.job.demo.c_str());
  if (const int code = builtin_setup(*b, o.job.tool_given, &o.job)) return code;
  o.job.tool_given = true;  // the part's own tool (or --tool's), no guess: the program's comment names it too
  const std::string dir = "out/" + o.job.demo;
  std::string err;
  if (!make_dirs(dir, &err)) return fail(kExitIo, "%s", err.c_str());
  // The paper's path: stripes one dexel apart, a position on every dexel,
  // the tool lifted at the end of each and returned at rapid.
  ZigJob job;
  zig_fit_to_material(o.job, &job.prog);
  std::string text;
  ZigProgramStats st;
  GridPlan plan;
  const int code = zig_generate(o.job, &job, &text, &st, &plan);
  if (code != kExitOk) return code;
  if (!o.view.quiet) zig_print_stats(plan, st);
  o.job.file = dir + "/" + o.job.demo + ".ngc";
  o.job.made_program = text;  // written once the guard has seen every file
  if (o.out.image.empty()) o.out.image = dir + "/final.png";
  if (o.out.error_image.empty()) o.out.error_image = dir + "/error.png";
  if (o.out.frames_dir.empty()) o.out.frames_dir = dir + "/frames";
  if (o.out.report.empty()) o.out.report = dir + "/report.json";
  if (!o.view.have_color) o.view.color = ViewOptions::Color::kMaterial;
  const int rc = run_job(o, guard);
  if (rc == kExitOk && !o.view.quiet)
    std::fprintf(stderr, "dexmill: demo %s written to %s/ (%s.ngc, final.png, error.png, frames/, report.json)\n",
                 o.job.demo.c_str(), dir.c_str(), o.job.demo.c_str());
  return rc;
}

}  // namespace cli
}  // namespace dexmill
