// `dexmill run`'s settings once parsed; see run_options.h.
#include "tools/run/run_options.h"

#include "core/tool/spec.h"
#include "tools/cli/cli.h"
#include "tools/run/run_demo.h"

namespace dexmill {
namespace cli {

JobOptions::JobOptions() { (void)tool_spec_parse(tool_text.data(), tool_text.size(), &tool); }

namespace {

// The options that contradict each other or want another.
int check_pairs(const RunOptions& o) {
  const JobOptions& j = o.job;
  if (j.grid_nx && j.pitch_nm) return fail(kExitUsage, "give --grid or --pitch, not both");
  if (o.view.have_preset && (o.view.have_azimuth || o.view.have_elevation))
    return fail(kExitUsage, "give --view or --azimuth/--elevation, not both");
  if (o.out.every && o.out.frames_dir.empty()) return fail(kExitUsage, "--every needs --frames DIR");
  if (o.out.have_stl_tolerance && o.out.stl.empty()) return fail(kExitUsage, "--stl-tolerance needs --stl FILE.stl");
  if (o.view.window && !o.view.fbdev.empty()) return fail(kExitUsage, "give --window or --fbdev, not both");
  if (!j.demo.empty() && (!j.file.empty() || !j.design.empty()))
    return fail(kExitUsage, "--demo cuts its own program from its own design: give no FILE and no --design");
  if (j.design.empty() && (j.have_design_z || !j.tolerance_boxes.empty()))
    return fail(kExitUsage, "%s needs --design", j.have_design_z ? "--design-z" : "--tolerance-box");
  if (!o.out.error_image.empty() && j.design.empty() && !j.file.empty())
    return fail(kExitUsage, "--error-image needs --design (the part to compare the cut with)");
  if (o.view.overlay != ViewOptions::Overlay::kNone && j.design.empty())
    return fail(kExitUsage, "--overlay needs --design (the part to draw with the cut)");
  return kExitOk;
}

// The verdict: --stop-at any is at a safety finding, and at a gouge when
// there is a design; asking to stop or fail on a collision without naming
// checks runs them all.
int settle_verdict(JobOptions* j) {
  if (j->stop_at_any) {
    j->stop_at_collision = true;
    j->stop_at_gouge = j->stop_at_gouge || !j->design.empty();
  }
  if ((j->stop_at_collision || j->fail_on_collision) && !j->checks.any()) j->checks.all();
  if (j->check_travel && j->machine_file.empty())
    return fail(kExitUsage, "--check travel and --fail-on-travel need --machine FILE (the machine's soft limits)");
  if (!j->machine_file.empty()) j->check_travel = true;  // on with a machine
  if (j->check_load && j->material.empty())
    return fail(kExitUsage, "--check load needs --material (the chip limit and the cutting coefficients are the "
                            "material's)");
  if ((j->stop_at_gouge || j->fail_on_gouge) && j->design.empty())
    return fail(kExitUsage, "%s needs --design (the part a gouge goes into)",
                j->stop_at_gouge ? "--stop-at gouge" : "--fail-on-gouge");
  return kExitOk;
}

// The colour mode: --thin says which mode it is for (alone it is that
// mode, with another an error); --material alone means material.
int settle_colours(const JobOptions& j, ViewOptions* v) {
  if (v->have_thin && v->have_color && v->color != ViewOptions::Color::kThin)
    return fail(kExitUsage, "--thin is the limit of --color thin; it does not go with another --color");
  if (v->have_thin && !v->have_color) {
    v->color = ViewOptions::Color::kThin;
    v->have_color = true;
  }
  if (!j.material.empty() && !v->have_color) v->color = ViewOptions::Color::kMaterial;
  if (v->color == ViewOptions::Color::kMaterial && j.material.empty())
    return fail(kExitUsage, "--color material needs --material (what the stock is made of)");
  if (v->color == ViewOptions::Color::kError && j.design.empty())
    return fail(kExitUsage, "--color error needs --design (the part to compare the cut with)");
  return kExitOk;
}

}  // namespace

int choose_program(RunOptions* o, bool stdin_terminal) {
  JobOptions& j = o->job;
  if (j.demo == kBuiltinDemoName) {
    if (!j.file.empty())
      return fail(kExitUsage, "--demo %s runs the built-in demo's own program: give no FILE", kBuiltinDemoName);
    j.demo.clear();
    return kExitOk;
  }
  if (!j.file.empty() || !j.demo.empty() || stdin_terminal) return kExitOk;
  j.file = "-";
  j.stdin_implied = true;
  return kExitOk;
}

int finish_run_options(RunOptions* o) {
  JobOptions& j = o->job;
  if (const int code = check_pairs(*o)) return code;
  if (const int code = settle_verdict(&j)) return code;
  if (const int code = settle_colours(j, &o->view)) return code;
  if (j.design_pgm && !j.have_design_z)
    return fail(kExitUsage, "a PGM design needs --design-z ZLOW,ZHIGH (the heights of black and white)");
  if (!j.design.empty() && !j.design_pgm && j.have_design_z)
    return fail(kExitUsage, "--design-z is for PGM designs; place an STL design with --design-offset");
  return kExitOk;
}

bool run_draws(const RunOptions& o) {
  const OutputOptions& f = o.out;
  return !f.image.empty() || !f.error_image.empty() || !f.frames_dir.empty() || !f.heightmap.empty() ||
         !f.stl.empty() || !f.save_stock.empty() || !f.engagement_csv.empty() || !f.load_plot.empty() || !f.sheet.empty() || o.view.window || !o.view.fbdev.empty();
}

bool run_prints_summary(const RunOptions& o) { return o.out.print_summary && !run_draws(o) && o.out.report.empty(); }

}  // namespace cli
}  // namespace dexmill
