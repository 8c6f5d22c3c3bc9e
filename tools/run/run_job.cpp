// `dexmill run`: the options into a job for the engine (core/sim/simulation.h),
// its files and views around it; see run_job.h.
#include "tools/run/run_job.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "core/sim/simulation.h"
#include "core/sim/stock_state.h"
#include "platform/format/stock_io.h"
#include "platform/os/clock.h"
#include "platform/input/gcode_file.h"
#include "platform/format/heightmap.h"
#include "platform/format/image_file.h"
#include "platform/os/memory.h"
#include "platform/os/output_file.h"
#include "platform/os/output_set.h"
#include "platform/os/process.h"
#include "platform/live/progress.h"
#include "platform/report/report_json.h"
#include "platform/report/report_summary.h"
#include "platform/format/stl.h"
#include "tools/cli/cli.h"
#include "tools/run/run_assess.h"
#include "tools/run/run_material.h"
#include "tools/run/run_safety.h"
#include "tools/run/run_scan.h"
#include "tools/run/run_setup.h"
#include "tools/run/run_sheet.h"
#include "tools/run/run_views.h"
#include "tools/run/setup_text.h"

namespace dexmill {
namespace cli {
namespace {

// The errors only the cut finds, in a program that probes: a probe that
// trips where it starts or reaches its end untripped (G38.2, G38.4), as
// LinuxCNC's motion controller ends the program there. The others the
// first pass reported already.
class ProbeErrors final : public GcodeMessages {
 public:
  ProbeErrors(const std::string& file, bool print, std::vector<ReportDiag>* out) : msgs_(file, print), out_(out) {}
  void error(const GcodeDiag& d) override {
    if (d.code != GcodeError::kProbeNoContact && d.code != GcodeError::kProbeAlreadyTripped &&
        d.code != GcodeError::kProbeNotTripped)
      return;
    msgs_.error(d);
    out_->push_back(msgs_.error_list.back());
  }
  void warning(const GcodeDiag&) override {}
  void set_file(const char* name) override { msgs_.set_file(name); }

 private:
  RunMessages msgs_;
  std::vector<ReportDiag>* out_;
};

// One run: the engine set up (tools/run/run_setup.h), and its views.
struct Run {
  RunSetup setup;
  RunViews views;
  double t_start = 0;
};

bool write_heightmap(const char* path, ImageFormat format, const DexelGrid<height_t>& g, char* err, size_t errn) {
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  ZeroedBlock block;
  if (!block.allocate(n * sizeof(uint16_t))) {
    std::snprintf(err, errn, "cannot allocate %s for the %dx%d heightmap", size_text(n * sizeof(uint16_t)).c_str(),
                  static_cast<int>(g.nx), static_cast<int>(g.ny));
    return false;
  }
  uint16_t* img = static_cast<uint16_t*>(block.data());
  heightmap_samples(g, img);
  return write_grey16_image(path, format, g.nx, g.ny, img, err, errn);
}

// The stock as the run leaves it, with the chain of programs on it, this
// run's last (a run that neither continues nor saves a stock has none):
// the report's chain and --save-stock's meta.
void chain_of_run(RunSetup* su) {
  const SimJob& j = su->sim->job();
  if (!j.resume && !j.provenance_programs) return;
  // A blended estimate is the program's time, as the report's; a run that
  // stopped early (a gouge, a collision) keeps the clock of what it cut.
  const bool whole = su->sim->stop_reason() == SimStop::kNone;
  const int64_t us = su->rep.blended && whole ? su->rep.estimated_us : -1;
  su->have_chain = sim_stock_meta(*su->sim, su->shown_name.c_str(), &su->chain, us) == StockStateError::kOk;
}

// The report's findings at their lines: its errors, warnings, gouges,
// safety findings and process rule breaks, the first kChainFindingsKept
// kept, and the count of all of them.
ProgramFindings findings_of(const RunReport& r) {
  ProgramFindings out;
  std::vector<ReportFinding>& f = out.kept;
  auto add = [&f](const char* kind, uint32_t line, const std::string& message) {
    if (f.size() < kChainFindingsKept) f.push_back(ReportFinding{kind, line, message});
  };
  for (const ReportDiag& d : r.errors) add("error", d.line, d.message);
  for (const ReportDiag& d : r.warnings) add("warning", d.line, d.message);
  out.total = r.errors.size() + r.warnings_total;
  if (r.have_assessment) {
    for (const ReportGouge& g : r.assessment.gouges)
      add("gouge", g.line, nm_to_mm_text(g.depth_nm, 4) + " mm into the design at X" + nm_to_mm_text(g.at.x_nm, 3) +
                               " Y" + nm_to_mm_text(g.at.y_nm, 3));
    out.total += r.assessment.gouges_total;
  }
  if (r.have_collisions) {
    for (const SafetyEvent& e : r.collisions)
      add("collision", e.line, std::string(safety_kind_name(e.kind)) + ", " + nm_to_mm_text(e.depth_nm, 4) + " mm");
    out.total += r.collisions_total;
  }
  if (r.have_materials) {
    for (const ReportViolation& v : r.material_violations) add("violation", v.line, v.rule + ": " + v.message);
    out.total += r.material_violations_total;
  }
  return out;
}

// The chain's programs, with the findings of those run before this one in
// the same `dexmill run` (the last ones before it: a saved stock may hold
// earlier programs, whose findings are not kept) and this one's.
void chain_to_report(const StockMeta& m, const JobOptions& j, RunReport* rep) {
  rep->have_chain = true;
  const int carried = static_cast<int>(j.chain_findings.size());
  for (int k = 0; k < m.nprograms; ++k) {
    const StockProgram& p = m.programs[k];
    RunReport::ChainProgram c;
    c.file = p.name;
    c.removed_lsb_dexels = p.removed_lsb_dexels;
    c.estimated_us = p.sim_us;
    c.moves = p.moves;
    c.setup = recorded_setup_text(p.setup, p.setup_offset_nm);
    const int before = k - (m.nprograms - 1 - carried);  // index into the carried findings
    if (k == m.nprograms - 1) {
      c.have_findings = true;
      const ProgramFindings f = findings_of(*rep);
      c.findings = f.kept;
      c.findings_total = f.total;
    } else if (before >= 0 && before < carried) {
      c.have_findings = true;
      c.findings = j.chain_findings[before].kept;
      c.findings_total = j.chain_findings[before].total;
    }
    rep->chain.push_back(c);
  }
  rep->chain_removed_lsb_dexels = m.removed_lsb_dexels;
  rep->chain_us = m.sim_us;
  rep->chain_moves = m.moves;
}

// The report, with the whole run's time (when asked for); false when it
// cannot be written (printed).
bool write_report(const RunOptions& o, Run* run) {
  if (o.out.report.empty()) return true;
  run->setup.rep.timing.emplace_back("total", clock_now_s() - run->t_start);
  char e[1300];
  if (write_report_json(o.out.report.c_str(), run->setup.rep, e, sizeof e)) return true;
  fail(kExitIo, "%s", e);
  return false;
}

// The views the options ask for, over the engine's grid (tools/run/run_views.h).
int open_views(const RunOptions& o, Run* run) {
  RunSetup& s = run->setup;
  RunViews::Inputs in;
  in.lib = s.lib;
  in.design = o.job.design.empty() ? nullptr : &s.design;
  in.material = o.job.material.empty() ? nullptr : &s.material;
  in.path = s.want_path ? &s.path : nullptr;
  in.motion_moves = s.rep.rapid + s.rep.feed + s.rep.arc;
  in.total_us = s.rep.estimated_us;
  in.top_lsb = o.job.stock_stl.empty() ? static_cast<uint32_t>(s.plan.top_lsb) : 0u;
  in.chain = s.stock_in ? &s.stock_meta : nullptr;
  in.program_name = s.shown_name;
  return run->views.open(o, s.sim, in);
}

// The cut: the program read again, a line a step, with the progress bar
// and the live view between lines. kExitOk or an exit code (printed).
int cut_pass(const RunOptions& o, Run* run, bool* user_quit) {
  RunSetup& su = run->setup;
  Simulation& sim = *su.sim;
  RunViews& v = run->views;
  std::string err;
  const double t0 = clock_now_s();
  if (!su.input.unchanged(&err)) return fail(kExitIo, "%s", err.c_str());
  if (v.has_frames()) v.write_frame();  // the untouched stock
  GcodeFile in;
  if (!in.open(su.read_path.c_str(), su.shown_name.c_str())) return fail(kExitIo, "%s", in.error());
  in.set_subroutine_path(o.job.read.subroutine_path);
  in.set_guard(su.guard);
  sim.read_from(&in);
  ProbeErrors probe_errors(su.shown_name, su.print, &su.probe_errors);
  if (su.cut_notes) sim.forward_messages(&probe_errors);
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
  v.after_cut(su.job.stop_line != 0);
  const SafetyWatch* safety = sim.safety();
  if (const GougeWatch* w = sim.gouges()) print_gouges(*w, sim.grid(), &su.design);
  if (safety) {
    safety_print(*safety, su.shown_name, sim.grid());
    safety_to_report(*safety, &su.rep);
  }
  if (const ProcessWatch* w = sim.process()) {
    if (o.view.material_warnings) material_print(su.material, *w, su.shown_name);
    material_to_report(su.material, *w, sim.grid(), &su.rep);
  }
  if (const EngageSummary* e = sim.engagement(); e && e->no_speed && o.view.material_warnings)
    std::fprintf(stderr, "%s: warning: %llu cutting moves ran with no spindle speed (no S word, or no M3): their chip per tooth, "
                 "force and power are not measured (give --default-spindle RPM)\n", su.shown_name.c_str(),
                 static_cast<unsigned long long>(e->no_speed));
  if (!o.job.machine_file.empty()) {
    if (const TravelWatch* w = sim.travel(); w && su.print) travel_print(*w, su.shown_name);
    machine_to_report(su.machine, o.job.machine_file, sim.travel(), &su.rep);
  }
  if (const LoadWatch* w = sim.load()) {
    if (o.view.material_warnings) load_print(*w, *su.material.comp, su.shown_name);
    load_to_report(*w, *su.material.comp, &su.rep);
  }
  if (sim.io_error()) return fail(in.refused() ? kExitUsage : kExitIo, "%s", in.error());
  if (!v.frame_error.empty()) return fail(kExitIo, "%s", v.frame_error.c_str());
  if (v.live_view().failed()) return fail(kExitIo, "%s", v.live_view().error().c_str());
  if (v.has_frames() && (v.last_frame_moves != sim.status().moves || su.job.stop_line) && !v.write_frame())
    return fail(kExitIo, "%s", v.frame_error.c_str());
  su.rep.timing.emplace_back("cut", clock_now_s() - t0 - v.render_s - v.write_s);
  return kExitOk;
}

// The final images, the heightmap and the STL, into the set (their
// renames wait for the report's: platform/os/output_set.h).
int write_files(const RunOptions& o, Run* run) {
  RunSetup& su = run->setup;
  RunViews& v = run->views;
  if (const int code = v.write_images(o, su.plan, su.formats.image, su.formats.error_image)) return code;
  char e[1300];
  const double t_files = clock_now_s();
  if (!o.out.heightmap.empty() && !write_heightmap(o.out.heightmap.c_str(), su.formats.heightmap, su.sim->grid(), e, sizeof e))
    return fail(kExitIo, "%s", e);
  if (su.engage && !su.engage->commit()) return fail(kExitIo, "%s", su.engage->error());
  if (!o.out.load_plot.empty()) {
    std::string err;
    if (!write_load_plot(o.out.load_plot, *su.engage, *su.sim->engagement(), su.shown_name, o.job.spindle_power_mw, &err))
      return fail(kExitIo, "%s", err.c_str());
  }
  if (!o.out.save_stock.empty()) {
    if (!su.have_chain)
      return fail(kExitUsage, "--save-stock: the stock already holds the %d programs a stock file remembers",
                  kStockMaxPrograms);
    StockMeta m = su.chain;
    // The stock's material and design, as the options name them (a later
    // run is told when it names others).
    if (!o.job.material.empty()) stock_name_set(m.material, o.job.material.c_str());
    if (!o.job.design.empty()) stock_name_set(m.design, o.job.design.c_str());
    std::string err;
    if (!write_stock_file(o.out.save_stock.c_str(), m, su.sim->stock_columns(m.layers), &err))
      return fail(kExitIo, "%s", err.c_str());
  }
  double stl_s = 0;
  if (!o.out.stl.empty()) {
    const double t_stl = clock_now_s();
    // The tolerance in whole LSB, rounded down so the surface stays within
    // the millimetres asked for; one LSB or less is the exact surface.
    const auto& g = su.sim->grid();
    if (!write_stl(o.out.stl.c_str(), g, o.out.stl_tolerance_nm / g.lsb_nm, e, sizeof e))
      return fail(kExitIo, "%s", e);
    stl_s = clock_now_s() - t_stl;
  }
  v.write_s += clock_now_s() - t_files;
  su.rep.timing.emplace_back("render", v.render_s);
  su.rep.timing.emplace_back("write", v.write_s);
  if (!o.out.stl.empty()) su.rep.timing.emplace_back("stl", stl_s);  // a part of write
  return kExitOk;
}

// The report's list of what the run wrote beside it.
void list_outputs(const RunOptions& o, const OutputSet& set, const RunViews& v, RunReport* rep) {
  if (!o.out.frames_dir.empty()) rep->outputs.push_back(ReportOutput{"--frames", o.out.frames_dir, -1, v.frames_written()});
  const std::pair<const char*, const std::string*> files[] = {{"--image", &o.out.image}, {"--error-image", &o.out.error_image},
                                                             {"--heightmap", &o.out.heightmap}, {"--stl", &o.out.stl},
                                                             {"--save-stock", &o.out.save_stock},
                                                             {"--engagement-csv", &o.out.engagement_csv},
                                                             {"--load-plot", &o.out.load_plot}};
  for (const auto& f : files)
    if (!f.second->empty()) rep->outputs.push_back(ReportOutput{f.first, *f.second, set.bytes_of(*f.second), 0});
}

// The report's results, the final frame and files, the report itself.
int write_results(const RunOptions& o, Run* run, bool user_quit) {
  RunSetup& su = run->setup;
  Simulation& sim = *su.sim;
  RunReport& rep = su.rep;
  RunViews& v = run->views;
  switch (sim.stop_reason()) {
    case SimStop::kGouge: rep.stopped_reason = "gouge"; rep.stopped_line = sim.stop_line(); break;
    case SimStop::kCollision: rep.stopped_reason = "collision"; rep.stopped_line = sim.stop_line(); break;
    default: break;
  }
  rep.instances = sim.mill().stats().instances;
  rep.dexel_updates = sim.mill().stats().dexel_updates;
  rep.removed_lsb_dexels = sim.removed_lsb();
  if (su.cut_notes) {  // a program that probes: the cut's messages, probe errors, moves and time
    motion_to_report(sim.time(), &rep);  // the engine's clock: not blended
    rep.time_by_tool.clear();               // the scan's, whose probes did not stop on the stock
    rep.messages.clear();
    for (const GcodeNotes::Note& n : su.cut_notes->kept)
      if (rep.messages.size() < 100) rep.messages.push_back(RunReport::Message{n.line, n.kind, n.text});
    for (const ReportDiag& d : su.probe_errors) rep.errors.push_back(d);
    if (!su.probe_errors.empty() && rep.stopped_reason.empty()) {
      rep.stopped_reason = "error";
      rep.stopped_line = su.probe_errors.front().line;
    }
  }
  if (const GougeWatch* w = sim.gouges()) {
    const double t0 = clock_now_s();
    assess_design(*w, sim.grid(), &su.design);
    rep.have_assessment = true;
    rep.assessment = su.design.report;
    rep.timing.emplace_back("assess", clock_now_s() - t0);
  }
  if (const EngageSummary* e = sim.engagement()) engage_to_report(*e, su.engage->tools(), &rep);
  chain_of_run(&su);
  if (su.have_chain) chain_to_report(su.chain, o.job, &rep);
  const CutterPose pose{true, sim.mill().position()};
  if (v.live() && !user_quit && !v.live_view().last_frame(&sim.grid(), pose, v.status))
    return fail(kExitIo, "%s", v.live_view().error().c_str());
  // Every file complete before any is renamed, the report last, so that a
  // report in place names the run each listed file is from.
  OutputSet set;
  if (const int code = write_files(o, run)) return code;
  list_outputs(o, set, v, &rep);
  if (!o.out.sheet.empty()) {  // drawn from the report as it stands, listed in it after
    if (const int code = write_sheet(o, &su, rep)) return code;
    rep.outputs.push_back(ReportOutput{"--sheet", o.out.sheet, set.bytes_of(o.out.sheet), 0});
  }
  if (!write_report(o, run)) return kExitIo;
  std::string err;
  if (!set.publish(&err)) return fail(kExitIo, "%s", err.c_str());
  if (v.live() && !user_quit && !v.live_view().wait_done(&sim.grid(), pose, v.status))
    return fail(kExitIo, "%s", v.live_view().error().c_str());
  return kExitOk;
}

// What goes to standard output when it was closed would be lost at the
// end: refused before the run, the I/O error the write would meet.
int check_standard_output(const RunOptions& o) {
  std::string err;
  if (standard_output_usable(&err)) return kExitOk;
  const std::pair<const char*, const std::string*> outs[] = {{"--image", &o.out.image}, {"--error-image", &o.out.error_image},
                                                            {"--heightmap", &o.out.heightmap}, {"--stl", &o.out.stl},
                                                            {"--save-stock", &o.out.save_stock},
                                                            {"--engagement-csv", &o.out.engagement_csv},
                                                            {"--load-plot", &o.out.load_plot},
                                                            {"--sheet", &o.out.sheet},
                                                            {"--report", &o.out.report}};
  for (const auto& out : outs)
    if (is_stdout_path(*out.second)) return fail(kExitIo, "cannot write %s -: %s", out.first, err.c_str());
  if (run_prints_summary(o)) return fail(kExitIo, "cannot print the summary: %s (write a --report instead)", err.c_str());
  return kExitOk;
}

}  // namespace

int run_job(RunOptions o, FileGuard* guard, RunResult* result) {
  if (const int code = check_standard_output(o)) return code;
  Run run;
  run.t_start = clock_now_s();
  RunSetup& su = run.setup;
  su.guard = guard;
  su.rep.run_started = clock_utc_text();
  su.rep.run_pid = static_cast<long>(getpid());
  su.print = !o.job.silent;
  if (const int code = run_setup(&o, &su)) {
    if (su.refused && !write_report(o, &run)) return kExitIo;  // --strict: the report of a program not cut
    return code;
  }
  if (const int code = open_views(o, &run)) return code;
  if (const int code = remove_earlier_frames(o, &su)) return code;
  bool user_quit = false;
  if (const int code = cut_pass(o, &run, &user_quit)) return code;
  if (const int code = write_results(o, &run, user_quit)) return code;
  Simulation& sim = *su.sim;
  if (result) {
    result->finished = true;
    result->shown_name = su.shown_name;
    result->safety_findings = sim.safety() ? sim.safety()->total : 0;
    result->gouged = sim.gouged();
    if (const ProcessWatch* w = sim.process())
      result->line_feed_limits.assign(w->line_feed_limit, w->line_feed_limit + w->line_feed_limits);
    if (const EngageLineFeeds* t = sim.target_feeds()) {
      result->line_target_feeds.assign(t->feed_nm_per_min, t->feed_nm_per_min + t->n);
      result->line_target_kept.assign(t->kept, t->kept + t->n);
    }
    if (o.job.keep_tops) {
      const DexelGrid<height_t>& g = sim.grid();
      result->tops.assign(g.top, g.top + static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny));
      result->grid = GridGeometry{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm};
      for (const Tool& t : su.tools) result->max_tool_radius_nm = max_of(result->max_tool_radius_nm, t.diameter_nm / 2);
    }
    if (const EngageSplits* t = sim.target_splits()) {
      result->target_splits.assign(t->pieces, t->pieces + t->n);
      result->splits_left = t->left;
    }
    if (const EngageSummary* e = sim.engagement()) {
      result->engagement = *e;
      result->have_engagement = true;
    }
    result->findings = findings_of(su.rep);
  }
  if (run_prints_summary(o)) {
    std::fputs(report_summary_text(su.rep).c_str(), stdout);
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
      return fail(kExitIo, "cannot print the summary on standard output: %s", std::strerror(errno));
  }
  if (su.job.stop_line || !su.probe_errors.empty()) return kExitInput;
  if (sim.gouged() && (o.job.stop_at_gouge || o.job.fail_on_gouge)) return kExitCheck;
  if (sim.collided() && (o.job.stop_at_collision || o.job.fail_on_collision)) return kExitCheck;
  if (o.job.fail_on_load && sim.load() && sim.load()->total > 0) return kExitCheck;
  if (o.job.fail_on_travel && sim.travel() && sim.travel()->total > 0) return kExitCheck;
  if (!o.view.quiet && su.demo)
    std::fprintf(stderr, "dexmill: demo written to out/ (demo.ngc, final.ppm, error.ppm, frames/frame-*.%s)\n",
                 image_format_extension(o.out.frame_format));
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
