// `dexmill run`: the options into a job for the engine (core/sim/simulation.h),
// its files and views around it; see run_job.h.
#include "tools/run_job.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/sim/scan.h"
#include "core/sim/simulation.h"
#include "core/tool/spec.h"
#include "platform/clock.h"
#include "platform/frame_files.h"
#include "platform/gcode_file.h"
#include "platform/image_file.h"
#include "platform/output_file.h"
#include "platform/program_input.h"
#include "platform/progress.h"
#include "platform/report_json.h"
#include "platform/report_summary.h"
#include "platform/stl.h"
#include "platform/tool_table.h"
#include "tools/cli.h"
#include "tools/demo_program.h"
#include "tools/run_demo.h"
#include "tools/run_assess.h"
#include "tools/run_material.h"
#include "tools/run_outputs.h"
#include "tools/run_safety.h"
#include "tools/run_scan.h"
#include "tools/run_stock.h"
#include "tools/run_tool_table.h"
#include "tools/run_views.h"

namespace dexmill {
namespace cli {
namespace {

// Everything one run holds, in the order it is set up.
struct Run {
  bool demo = false;
  std::string read_path, shown_name;
  ProgramInput input;
  OutputFormats formats;
  ToolTableFile table;
  bool have_table = false;
  std::unique_ptr<SingleToolLibrary> single;
  const ToolLibrary* lib = nullptr;
  SimJob job;
  RunReport rep;
  std::vector<PathSegment> path;
  bool want_path = false;
  std::vector<Tool> tools;  // the scan's, for the job
  GridPlan plan{};
  std::vector<TriangleNm> blank;
  RunDesign design;
  RunMaterial material;
  std::vector<uint64_t> memory;
  Simulation* sim = nullptr;
  RunViews views;
  double t_start = 0;
  ~Run() { sim_destroy(sim); }
};

bool write_heightmap(const char* path, ImageFormat format, const DexelGrid<height_t>& g, char* err, size_t errn) {
  // Row 0 of the image is the grid's last row (north up); samples are the
  // top heights in LSB (the report gives the LSB), holes 0.
  std::vector<uint16_t> img(static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny));
  for (int32_t j = 0; j < g.ny; ++j)
    for (int32_t i = 0; i < g.nx; ++i) {
      const uint64_t h = g.top[g.index(i, j)];
      img[static_cast<size_t>(g.ny - 1 - j) * static_cast<size_t>(g.nx) + static_cast<size_t>(i)] =
          static_cast<uint16_t>(h > 65535 ? 65535 : h);
    }
  return write_grey16_image(path, format, g.nx, g.ny, img.data(), err, errn);
}

// The report, with the whole run's time (when asked for); false when it
// cannot be written (printed).
bool write_report(const RunOptions& o, Run* run) {
  if (o.out.report.empty()) return true;
  run->rep.timing.emplace_back("total", clock_now_s() - run->t_start);
  char e[1300];
  if (write_report_json(o.out.report.c_str(), run->rep, e, sizeof e)) return true;
  fail(kExitIo, "%s", e);
  return false;
}

// The demo's defaults, the outputs checked, the program opened, the frame
// folder made and emptied: before anything long happens.
int prepare(RunOptions* o, Run* run) {
  std::string err;
  run->demo = o->job.file.empty();
  run->read_path = run->shown_name = o->job.file;
  if (run->demo) {
    if (const int code = demo_defaults(o)) return code;
    run->read_path = run->shown_name = kDemoProgramPath;
  }
  if (const int code = check_outputs(o->out, {o->job.file, o->job.read.tools_file, o->job.design, o->job.stock_stl}, &run->formats))
    return code;
  if (!run->demo) {
    if (o->job.file == "-") run->shown_name = "<stdin>";
    if (!o->job.shown_name.empty()) run->shown_name = o->job.shown_name;
    if (!run->input.open(o->job.file, &err)) return fail(kExitIo, "%s", err.c_str());
    run->read_path = run->input.read_path();
  }
  if (o->out.frames_dir.empty()) return kExitOk;
  uint32_t removed = 0;
  if (!make_dirs(o->out.frames_dir, &err)) return fail(kExitIo, "%s", err.c_str());
  if (access(o->out.frames_dir.c_str(), W_OK) != 0)
    return fail(kExitIo, "cannot write frames into '%s': %s", o->out.frames_dir.c_str(), std::strerror(errno));
  if (!remove_old_frames(o->out.frames_dir, &removed, &err)) return fail(kExitIo, "%s", err.c_str());
  if (removed && !o->view.quiet && !run->demo)
    std::fprintf(stderr, "dexmill: removed %u frames of an earlier run from '%s'\n", removed, o->out.frames_dir.c_str());
  return kExitOk;
}

// The tool table (or the demo's) and the library T/M6 pick from.
int load_tools(const RunOptions& o, Run* run) {
  run->have_table = !o.job.read.tools_file.empty() || run->demo;
  if (!o.job.read.tools_file.empty()) {
    if (const int code = load_tool_table(o.job.read.tools_file, o.job.read.inch, &run->table)) return code;
  } else if (run->demo) {
    const char* t = demo_tool_table();
    if (run->table.parse("demo tool table", t, std::strlen(t), false) != ToolTableFile::Load::kOk)
      return fail(kExitInput, "%s", run->table.message().c_str());
  }
  for (const std::string& w : run->table.warnings()) std::fprintf(stderr, "%s\n", w.c_str());
  run->single.reset(new SingleToolLibrary(o.job.tool));
  run->lib = run->have_table ? static_cast<const ToolLibrary*>(&run->table) : run->single.get();
  SimJob& j = run->job;
  j.mode = o.job.mode;
  j.tool = o.job.tool;
  j.library = run->lib;
  j.offsets = run->have_table ? static_cast<const ToolTable*>(&run->table) : run->single.get();
  j.inch = o.job.read.inch;
  j.default_feed_nm_per_min = o.job.read.default_feed_nm_per_min;
  j.max_blocks = o.job.read.max_blocks;
  j.time.rapid_nm_per_min = o.job.rapid_nm_per_min;
  j.time.accel_nm_per_s2 = o.job.accel_nm_per_s2;
  return kExitOk;
}

// The stock (an STL blank, the option's box, the demo's, or the program's
// extents) and the grid that holds it.
int plan_stock(const RunOptions& o, const ProgramScan& scan, Run* run) {
  RunReport& rep = run->rep;
  StockBox stock;
  if (!o.job.stock_stl.empty()) {
    if (const int code = read_stock_stl(o.job.stock_stl, &run->blank, &stock)) return code;
    rep.stock_source = "stl";
  } else if (o.job.have_stock) {
    stock = StockBox{PointNm{o.job.stock_nm[0], o.job.stock_nm[1], o.job.stock_nm[2]}, PointNm{o.job.stock_nm[3], o.job.stock_nm[4], o.job.stock_nm[5]}};
    rep.stock_source = "option";
  } else if (run->demo) {
    stock = demo_stock_box();
    rep.stock_source = "demo";
  } else {
    stock = default_stock(scan.summary, scan.max_radius_nm);
    rep.stock_source = "program";
  }
  int64_t pitch_nm = o.job.pitch_nm;
  if (!pitch_nm && !o.job.grid_nx) pitch_nm = default_pitch_nm(stock, scan.smallest_diameter_nm());
  std::string err;
  if (!plan_grid(stock, o.job.grid_nx, o.job.grid_ny, pitch_nm, &run->plan, &err)) return fail(kExitUsage, "%s", err.c_str());
  // A tool narrower than the pitch may fall between the dexel axes and cut
  // nothing: say so rather than show an untouched block.
  for (int k = 0; k < scan.ntools; ++k)
    if (scan.tools[k].diameter_nm < run->plan.geo.pitch_nm) {
      char spec[kToolSpecTextMax];
      tool_spec_format(scan.tools[k], spec, sizeof spec);
      std::fprintf(stderr, "dexmill: warning: the tool %s is narrower than the grid's pitch (%s mm) and may cut nothing; "
                   "give a finer --pitch\n", spec, nm_to_mm_text(run->plan.geo.pitch_nm, 4).c_str());
      break;
    }
  const GridPlan& plan = run->plan;
  rep.have_stock = true;
  rep.stock_lo = plan.stock.lo;
  rep.stock_hi = plan.stock.hi;
  rep.nx = plan.geo.nx;
  rep.ny = plan.geo.ny;
  rep.pitch_nm = plan.geo.pitch_nm;
  rep.lsb_nm = plan.geo.lsb_nm;
  return kExitOk;
}

// The engine's message for a job it cannot set up.
int setup_failed(const SimSetup& why, const RunOptions& o, const Run& run) {
  char spec[kToolSpecTextMax];
  tool_spec_format(why.tool < 0 ? run.job.tool : run.job.tools[why.tool], spec, sizeof spec);
  switch (why.error) {
    case SimError::kToolTooWideStamp:
      return fail(kExitUsage, "the tool %s spans more than %d dexels at this pitch; use a coarser --pitch or --mode sweep",
                  spec, 2 * kCutterMaxReach + 1);
    case SimError::kToolTooLargeSweep:
      return fail(kExitUsage, "the tool %s is too large for --mode sweep (radius above 268 mm)", spec);
    case SimError::kToolInvalid:
    case SimError::kToolCannotCut: return fail(kExitUsage, "the tool %s cannot cut this grid", o.job.tool_text.c_str());
    case SimError::kFixturesOutside:
      return fail(kExitUsage, "--fixture: the fixtures hold no dexel column of the stock's lattice, or span more than "
                  "65535 of them");
    case SimError::kFixturesTooLarge:
      return fail(kExitUsage, "--fixture: the fixtures span more than 64 M dexel columns at this pitch; use a coarser --pitch");
    default: return fail(kExitUsage, "the stock and grid give a geometry the dexel grid cannot hold");
  }
}

// The job's observers from the options, the engine made over its memory,
// the stock carved, the design and the views set up.
int start_engine(const RunOptions& o, const ProgramScan& scan, Run* run) {
  SimJob& j = run->job;
  j.plan = run->plan;
  run->tools.assign(scan.tools + 1, scan.tools + scan.ntools);
  j.tools = run->tools.data();
  j.ntools = static_cast<int>(run->tools.size());
  if (!o.job.design.empty()) {  // before the cut: a bad file costs no simulation
    if (const int code = load_design(o.job, run->plan, run->shown_name, &run->design)) return code;
    j.design = &run->design.grid;
    j.assess = run->design.opt;
  }
  j.checks = safety_checks(o.job.checks);
  sim_checks_for_tools(&j.checks, scan.tools, scan.ntools);
  if (!o.job.material.empty()) {
    const BoxNm box{run->plan.stock.lo, run->plan.stock.hi};
    if (const int code = material_start(&run->material, o.job.material, box)) return code;
    j.material = run->material.comp.get();
    if (o.job.feed_limits) j.line_feed_lines = static_cast<size_t>(run->rep.lines) + 1;  // lines 0 .. the last
  }
  j.provenance = o.view.color == ViewOptions::Color::kTool;
  j.provenance_first_tool = kInitialToolNumber;
  j.stop_at_gouge = o.job.stop_at_gouge;
  j.stop_at_collision = o.job.stop_at_collision;
  SimSetup why;
  const size_t bytes = sim_required_bytes(j, &why);
  if (!bytes) return setup_failed(why, o, *run);
  run->memory.assign((bytes + 7) / 8, 0);
  run->sim = sim_create(j, run->memory.data(), bytes, &why);
  if (!run->sim) return setup_failed(why, o, *run);
  if (!run->blank.empty()) {
    const int code = carve_stock(&run->sim->grid(), run->plan, run->blank);
    if (code != kExitOk) return code;
  }
  run->sim->start();
  RunViews::Inputs in;
  in.lib = run->lib;
  in.design = o.job.design.empty() ? nullptr : &run->design;
  in.material = o.job.material.empty() ? nullptr : &run->material;
  in.path = run->want_path ? &run->path : nullptr;
  in.motion_moves = run->rep.rapid + run->rep.feed + run->rep.arc;
  in.total_us = run->rep.estimated_us;
  in.top_lsb = o.job.stock_stl.empty() ? static_cast<uint32_t>(run->plan.top_lsb) : 0u;
  return run->views.open(o, run->sim, in);
}

// The cut: the program read again, a line a step, with the progress bar
// and the live view between lines. kExitOk or an exit code (printed).
int cut_pass(const RunOptions& o, Run* run, bool* user_quit) {
  Simulation& sim = *run->sim;
  RunViews& v = run->views;
  std::string err;
  const double t0 = clock_now_s();
  if (!run->input.unchanged(&err)) return fail(kExitIo, "%s", err.c_str());
  if (v.has_frames()) v.write_frame();  // the untouched stock
  GcodeFile in;
  if (!in.open(run->read_path.c_str(), run->shown_name.c_str())) return fail(kExitIo, "%s", in.error());
  in.set_subroutine_path(o.job.read.subroutine_path);
  sim.read_from(&in);
  SimBudget line;
  line.lines = 1;
  Progress progress(stderr, !o.view.quiet && !v.live());
  while (sim.step(line) == SimState::kReady) {
    progress.update(in.bytes_read(), in.total_bytes(), sim.status().moves);
    if (!v.frame_error.empty()) break;
    if (v.live() && !v.live_view().tick(&sim.grid(), CutterPose{true, sim.mill().position()}, v.status)) {
      *user_quit = !v.live_view().failed();
      break;
    }
  }
  progress.finish();
  sim.finish();
  std::vector<PointNm> error_at, stop_at;
  if (run->job.stop_line) error_at.push_back(sim.mill().position());  // the bad block's place, in amber
  const SafetyWatch* safety = sim.safety();
  if (sim.stop_reason() == SimStop::kCollision && safety && safety->nevents > 0)  // the finding it stopped at, in red
    stop_at.push_back(safety->events[safety->nevents - 1].at);
  v.after_cut(error_at, stop_at);
  if (const GougeWatch* w = sim.gouges()) print_gouges(*w, sim.grid(), &run->design);
  if (safety) {
    safety_print(*safety, run->shown_name, sim.grid());
    safety_to_report(*safety, &run->rep);
  }
  if (const ProcessWatch* w = sim.process()) {
    if (o.view.material_warnings) material_print(run->material, *w, run->shown_name);
    material_to_report(run->material, *w, sim.grid(), &run->rep);
  }
  if (sim.io_error()) return fail(kExitIo, "%s", in.error());
  if (!v.frame_error.empty()) return fail(kExitIo, "%s", v.frame_error.c_str());
  if (v.live_view().failed()) return fail(kExitIo, "%s", v.live_view().error().c_str());
  if (v.has_frames() && (v.last_frame_moves != sim.status().moves || run->job.stop_line) && !v.write_frame())
    return fail(kExitIo, "%s", v.frame_error.c_str());
  run->rep.timing.emplace_back("cut", clock_now_s() - t0 - v.render_s - v.write_s);
  return kExitOk;
}

// The report's results, the final frame and files, the report itself.
int write_results(const RunOptions& o, Run* run, bool user_quit) {
  Simulation& sim = *run->sim;
  RunReport& rep = run->rep;
  RunViews& v = run->views;
  switch (sim.stop_reason()) {
    case SimStop::kGouge: rep.stopped_reason = "gouge"; rep.stopped_line = sim.stop_line(); break;
    case SimStop::kCollision: rep.stopped_reason = "collision"; rep.stopped_line = sim.stop_line(); break;
    default: break;
  }
  rep.instances = sim.mill().stats().instances;
  rep.dexel_updates = sim.mill().stats().dexel_updates;
  rep.removed_lsb_dexels = sim.removed_lsb();
  if (const GougeWatch* w = sim.gouges()) {
    const double t0 = clock_now_s();
    assess_design(*w, sim.grid(), &run->design);
    rep.have_assessment = true;
    rep.assessment = run->design.report;
    rep.timing.emplace_back("assess", clock_now_s() - t0);
  }
  const CutterPose pose{true, sim.mill().position()};
  if (v.live() && !user_quit && !v.live_view().last_frame(&sim.grid(), pose, v.status))
    return fail(kExitIo, "%s", v.live_view().error().c_str());
  if (const int code = v.write_images(o, run->plan, run->formats.image, run->formats.error_image)) return code;
  char e[1300];
  const double t_files = clock_now_s();
  if (!o.out.heightmap.empty() && !write_heightmap(o.out.heightmap.c_str(), run->formats.heightmap, sim.grid(), e, sizeof e))
    return fail(kExitIo, "%s", e);
  double stl_s = 0;
  if (!o.out.stl.empty()) {
    const double t_stl = clock_now_s();
    if (!write_stl(o.out.stl.c_str(), sim.grid(), e, sizeof e)) return fail(kExitIo, "%s", e);
    stl_s = clock_now_s() - t_stl;
  }
  v.write_s += clock_now_s() - t_files;
  rep.timing.emplace_back("render", v.render_s);
  rep.timing.emplace_back("write", v.write_s);
  if (!o.out.stl.empty()) rep.timing.emplace_back("stl", stl_s);  // a part of write
  if (!write_report(o, run)) return kExitIo;
  if (v.live() && !user_quit && !v.live_view().wait_done(&sim.grid(), pose, v.status))
    return fail(kExitIo, "%s", v.live_view().error().c_str());
  return kExitOk;
}

}  // namespace

int run_job(RunOptions o, RunResult* result) {
  Run run;
  run.t_start = clock_now_s();
  if (const int code = prepare(&o, &run)) return code;
  if (const int code = load_tools(o, &run)) return code;
  RunReport& rep = run.rep;
  rep.file = run.shown_name;
  rep.units = o.job.read.inch ? "inch" : "mm";
  rep.mode = o.job.mode == CutMode::kSweep ? "sweep" : "stamp";
  rep.default_tool = o.job.tool_text;
  rep.tool_table = run.demo && o.job.read.tools_file.empty() ? "(built-in demo table)" : o.job.read.tools_file;
  rep.height_bits = DEXMILL_HEIGHT_BITS;
  rep.rapid_nm_per_min = o.job.rapid_nm_per_min;
  rep.accel_nm_per_s2 = o.job.accel_nm_per_s2;

  // -- the scan: what the program does, before anything is cut
  RunMessages msgs(run.shown_name, true);
  GcodeNotes notes(run.shown_name.c_str());
  SimJob scan_job = run.job;
  scan_job.notes = &notes;
  std::unique_ptr<ProgramScan> scan(new ProgramScan(scan_job));
  // The backplot's path: for --path-overlay, and for a live view (its p key).
  run.want_path = o.view.path_overlay || o.view.window || !o.view.fbdev.empty();
  {
    const double t0 = clock_now_s();
    const ScanInput in{run.read_path, run.shown_name, &o.job.read, &run.table};
    if (const int code = scan_pass(in, scan.get(), notes, run.want_path ? &run.path : nullptr, &msgs, &rep))
      return code;
    rep.timing.emplace_back("scan", clock_now_s() - t0);
  }
  // A program with an input error is cut up to its first bad block (as
  // LinuxCNC's preview draws the path up to it), unless --strict.
  if (msgs.errors()) {
    if (o.job.strict) return write_report(o, &run) ? kExitInput : kExitIo;
    run.job.stop_line = rep.errors.front().line;
    rep.stopped_reason = "error";
    rep.stopped_line = run.job.stop_line;
  }

  // -- the stock, the engine and its views; the cut; the results
  if (const int code = plan_stock(o, *scan, &run)) return code;
  if (const int code = start_engine(o, *scan, &run)) return code;
  bool user_quit = false;
  if (const int code = cut_pass(o, &run, &user_quit)) return code;
  if (const int code = write_results(o, &run, user_quit)) return code;
  Simulation& sim = *run.sim;
  if (result) {
    result->finished = true;
    result->shown_name = run.shown_name;
    result->safety_findings = sim.safety() ? sim.safety()->total : 0;
    result->gouged = sim.gouged();
    if (const ProcessWatch* w = sim.process())
      result->line_feed_limits.assign(w->line_feed_limit, w->line_feed_limit + w->line_feed_limits);
  }
  const bool no_output = o.out.image.empty() && o.out.error_image.empty() && o.out.frames_dir.empty() && o.out.heightmap.empty() &&
                         o.out.stl.empty() && o.out.report.empty() && !run.views.live();
  if (no_output && o.out.print_summary) std::fputs(report_summary_text(rep).c_str(), stdout);
  if (run.job.stop_line) return kExitInput;
  if (sim.gouged() && (o.job.stop_at_gouge || o.job.fail_on_gouge)) return kExitCheck;
  if (sim.collided() && (o.job.stop_at_collision || o.job.fail_on_collision)) return kExitCheck;
  if (!o.view.quiet && run.demo)
    std::fprintf(stderr, "dexmill: demo written to out/ (demo.ngc, final.ppm, error.ppm, frames/frame-*.%s)\n",
                 image_format_extension(o.out.frame_format));
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
