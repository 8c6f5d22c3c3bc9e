// The set-up of `dexmill run`; see run_setup.h.
#include "tools/run/run_setup.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/tool/spec.h"
#include "platform/os/clock.h"
#include "platform/live/frame_files.h"
#include "platform/os/memory.h"
#include "platform/os/output_file.h"
#include "platform/os/process.h"
#include "platform/live/window.h"
#include "platform/report/report_json.h"
#include "tools/cam/feed_word.h"
#include "tools/cli/cli.h"
#include "tools/run/demo_program.h"
#include "tools/run/guard_inputs.h"
#include "tools/run/run_colours.h"
#include "tools/run/run_demo.h"
#include "tools/run/run_safety.h"
#include "tools/run/run_scan.h"
#include "tools/run/run_stock.h"
#include "core/sim/scan_stock.h"
#include "core/sim/stock_state.h"
#include "tools/run/run_tool_table.h"

namespace dexmill {
namespace cli {
namespace {

// Every file the run reads, writes or removes, through the input guard
// (platform/input/file_guard.h) before any is touched: the demo's program (an
// output it then reads), the inputs, the outputs, the summary on standard
// output, the frames and the earlier frames their folder holds.
int guard_files(const RunOptions& o, RunSetup* run) {
  FileGuard& g = *run->guard;
  if (!o.job.made_program.empty())
    if (const int code = guard_status(g, g.check_output("the demo's program", run->read_path, FileGuard::kProgram)))
      return code;
  if (const int code = guard_job_inputs(o.job, run->read_path, &g)) return code;
  if (const int code = check_outputs(o.out, &g, &run->formats)) return code;
  if (run_prints_summary(o))
    if (const int code = guard_status(g, g.check_output("the summary", "-"))) return code;
  const std::string& dir = o.out.frames_dir;
  if (dir.empty()) return kExitOk;
  std::string err;
  if (!make_dirs(dir, &err)) return fail(kExitIo, "%s", err.c_str());
  if (access(dir.c_str(), W_OK) != 0)
    return fail(kExitIo, "cannot write frames into '%s': %s", dir.c_str(), std::strerror(errno));
  if (const int code = guard_status(g, g.check_frames("--frames", dir))) return code;
  if (!find_old_frames(dir, &run->old_frames, &err)) return fail(kExitIo, "%s", err.c_str());
  for (const std::string& old : run->old_frames)
    if (const int code = guard_status(g, g.check_removal("--frames", dir, old))) return code;
  return kExitOk;
}

// No FILE, and standard input (no terminal: choose_program read it) holds
// nothing: an empty program was surely not meant (a script, a CI job).
int no_program(const char* why) {
  return fail(kExitUsage, "no program: no FILE was given and standard input (not a terminal) %s; give a FILE, - to "
              "read standard input, or --demo %s for the built-in demo", why, kBuiltinDemoName);
}

// The demo's defaults, every file checked, the demo's program written, the
// program opened: before anything long happens.
int prepare(RunOptions* o, RunSetup* run) {
  std::string err;
  // A build without GLFW can never open the window: said before anything
  // is read, made or written (a display that is missing shows when the
  // window opens, still before any file is touched: remove_earlier_frames).
  if (o->view.window && !Window::available()) return fail(kExitUsage, "--window: %s", Window().error());
  run->demo = o->job.file.empty();
  run->read_path = run->shown_name = o->job.file;
  if (run->demo) {
    if (const int code = demo_defaults(o)) return code;
    run->read_path = run->shown_name = kDemoProgramPath;
  }
  if (const int code = guard_files(*o, run)) return code;
  const std::string& made = o->job.made_program;
  char e[1300];
  if (!made.empty() && !write_output(run->read_path.c_str(), made.data(), made.size(), e, sizeof e))
    return fail(kExitIo, "%s", e);
  if (!run->demo) {
    if (o->job.file == "-") run->shown_name = "<stdin>";
    if (!o->job.shown_name.empty()) run->shown_name = o->job.shown_name;
    run->input.set_copy_limit(o->job.max_input_bytes);
    if (o->job.stdin_implied && standard_input_closed()) return no_program("is closed");
    if (!run->input.open(o->job.file, &err)) return fail(run->input.too_large() ? kExitInput : kExitIo, "%s", err.c_str());
    if (o->job.stdin_implied && run->input.bytes() == 0) return no_program("is empty");
    run->read_path = run->input.read_path();
  }
  return kExitOk;
}

// The tool table (or the demo's) and the library T/M6 pick from.
int load_tools(const RunOptions& o, RunSetup* run) {
  run->have_table = !o.job.read.tools_file.empty() || run->demo;
  if (!o.job.read.tools_file.empty()) {
    bool inch = false;
    if (const int code = load_read_tool_table(o.job.read, run->read_path, &run->table, &inch)) return code;
    run->rep.tool_table_units = inch ? "inch" : "mm";
  } else if (run->demo) {
    const char* t = demo_tool_table();
    if (run->table.parse("demo tool table", t, std::strlen(t), false) != ToolTableFile::Load::kOk)
      return fail(kExitInput, "%s", run->table.message().c_str());
  }
  for (const std::string& w : run->table.warnings()) std::fprintf(stderr, "%s\n", w.c_str());
  // --tool, then the table, then the program's comments (read by the
  // first pass), then the default (core/sim/tool_choice.h).
  run->choice.reset(new ToolChoice(o.job.tool, o.job.tool_given, run->have_table ? &run->table : nullptr,
                                   run->have_table ? &run->table : nullptr));
  run->lib = run->choice.get();
  SimJob& j = run->job;
  j.mode = o.job.mode;
  j.tool = o.job.tool;
  j.library = run->lib;
  j.offsets = run->choice.get();
  j.inch = o.job.read.inch;
  j.units_given = o.job.read.units_given;
  j.feed_in_line_units = o.job.read.feed_in_line_units;
  j.default_feed_nm_per_min = o.job.read.default_feed_nm_per_min;
  j.max_blocks = o.job.read.max_blocks;
  j.time.rapid_nm_per_min = o.job.rapid_nm_per_min;
  j.time.accel_nm_per_s2 = o.job.accel_nm_per_s2;
  // With an acceleration the estimate blends (the scan's, which has the
  // look-ahead's memory; the engine's per-move clock stays the model's).
  j.time.axes = o.job.axes;
  j.time.blend = true;
  j.setups = o.job.setups.empty() ? nullptr : o.job.setups.data();
  j.nsetups = static_cast<int32_t>(o.job.setups.size());
  j.work_offsets = o.job.have_work_offsets ? o.job.work_offsets : nullptr;
  j.start_coord_system = o.job.start_coord_system;
  j.start_g92 = o.job.start_g92;
  j.start_tlo_nm = o.job.start_tlo_nm;
  return kExitOk;
}

// The report's stock and grid.
void report_plan(RunSetup* run) {
  const GridPlan& plan = run->plan;
  RunReport& rep = run->rep;
  rep.have_stock = true;
  rep.stock_lo = plan.stock.lo;
  rep.stock_hi = plan.stock.hi;
  rep.nx = plan.geo.nx;
  rep.ny = plan.geo.ny;
  rep.pitch_nm = plan.geo.pitch_nm;
  rep.lsb_nm = plan.geo.lsb_nm;
}

// --stock FILE.dxstock: the saved stock's header read, before the first
// pass (the program starts where the tool was left: job.resume); its
// columns are read into the engine once it exists (start_engine).
int open_saved_stock(const RunOptions& o, RunSetup* run) {
  if (o.job.stock_file.empty()) {
    if (!o.job.setups.empty())
      return fail(kExitUsage, "--setup turns a saved stock: give the stock with --stock FILE.dxstock");
    return kExitOk;
  }
  if (o.job.grid_nx || o.job.pitch_nm)
    return fail(kExitUsage, "--grid and --pitch cannot change a saved stock's grid: '%s' keeps the grid it was "
                "cut on", o.job.stock_file.c_str());
  run->stock_in.reset(new StockFileReader);
  std::string err;
  if (!run->stock_in->open(o.job.stock_file, &err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return run->stock_in->io_error() ? kExitIo : kExitInput;
  }
  run->stock_meta = run->stock_in->meta();
  const StockMeta& m = run->stock_meta;
  if (const int code = stock_heights_fit(m, o.job.stock_file)) return code;
  if (m.nprograms >= kStockMaxPrograms && !o.out.save_stock.empty())
    return fail(kExitUsage, "%s: the stock already holds the %d programs a stock file remembers; it cannot be "
                "saved again", o.job.stock_file.c_str(), kStockMaxPrograms);
  run->stock_file_meta = m;
  // The material and design the stock was cut with, against this run's.
  const std::pair<const char*, const std::string*> refs[] = {{"--material", &o.job.material}, {"--design", &o.job.design}};
  const char* const kept[] = {m.material, m.design};
  for (int k = 0; k < 2; ++k)
    if (kept[k][0] && !refs[k].second->empty() && *refs[k].second != kept[k] && run->print)
      std::fprintf(stderr, "dexmill: warning: %s '%s': the stock in '%s' was cut with %s '%s'\n", refs[k].first,
                   refs[k].second->c_str(), o.job.stock_file.c_str(), refs[k].first, kept[k]);
  for (size_t k = 0; k < o.job.setups.size(); ++k) {
    PointNm nearest{0, 0, 0};
    const StockSetupError e = stock_setup_meta(o.job.setups[k], &run->stock_meta, &nearest);
    if (e == StockSetupError::kOffsetNotExact)
      return fail(kExitUsage, "--setup '%s': %s; the nearest exact one is offset=%s,%s,%s", o.job.setup_texts[k].c_str(),
                  stock_setup_message(e), decimal_text(Decimal{nearest.x_nm, 6}).c_str(),
                  decimal_text(Decimal{nearest.y_nm, 6}).c_str(), decimal_text(Decimal{nearest.z_nm, 6}).c_str());
    if (e != StockSetupError::kOk)
      return fail(kExitUsage, "--setup '%s': %s", o.job.setup_texts[k].c_str(), stock_setup_message(e));
  }
  run->job.resume = &run->stock_meta;
  return kExitOk;
}

// The --setup turns on the columns read in the file's layout (the engine's
// grid is already the turned one's: same count of columns).
int turn_saved_stock(const RunOptions& o, RunSetup* run) {
  StockMeta m = run->stock_file_meta;
  const StockColumns cols = run->sim->stock_columns(m.layers);
  for (size_t k = 0; k < o.job.setups.size(); ++k) {
    std::vector<uint32_t> scratch(stock_setup_scratch_bytes(m, o.job.setups[k]) / 4 + 1);
    const StockSetupError e = stock_apply_setup(o.job.setups[k], &m, cols, scratch.data(), scratch.size() * 4);
    if (e != StockSetupError::kOk)
      return fail(kExitUsage, "--setup '%s': %s", o.job.setup_texts[k].c_str(), stock_setup_message(e));
  }
  return kExitOk;
}

int plan_saved_stock(const RunOptions& o, RunSetup* run) {
  run->plan = sim_plan_of_stock(run->stock_meta);
  std::string err;
  if (!plan_within_budget(run->plan, run_grid_budget(o.job.max_memory_bytes), &err))
    return fail(kExitUsage, "%s", err.c_str());
  run->rep.stock_source = "dxstock";
  report_plan(run);
  return kExitOk;
}

// --save-stock: a grid the stock file holds (its limit, not the budget's:
// said before the cut rather than after it).
int save_stock_fits(const RunOptions& o, const GridPlan& plan) {
  if (o.out.save_stock.empty() || static_cast<int64_t>(plan.geo.nx) * plan.geo.ny <= kStockMaxDexels) return kExitOk;
  return fail(kExitUsage, "--save-stock: the grid would be %dx%d dexels, more than the %lld a stock file holds (64 M); "
              "give a coarser --pitch or --grid", static_cast<int>(plan.geo.nx), static_cast<int>(plan.geo.ny),
              static_cast<long long>(kStockMaxDexels));
}

// The stock (an STL blank, the option's box, the demo's, or the program's
// extents) and the grid that holds it.
int plan_stock(const RunOptions& o, const ProgramScan& scan, RunSetup* run) {
  RunReport& rep = run->rep;
  StockBox stock;
  if (run->stock_in) return plan_saved_stock(o, run);
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
    rep.stock_source = scan_stock_source_name(scan_default_stock(scan, &stock));
  }
  if (scan.workpiece_bad && run->print)
    std::fprintf(stderr, "%s:%u: warning: a %s comment not read: %s\n", run->shown_name.c_str(),
                 scan.workpiece_bad_line, scan.workpiece_bad_form, scan.workpiece_bad);
  int64_t pitch_nm = o.job.pitch_nm;
  if (!pitch_nm && !o.job.grid_nx) pitch_nm = scan_default_pitch_nm(scan, stock);
  std::string err;
  if (!plan_grid(stock, o.job.grid_nx, o.job.grid_ny, pitch_nm, run_grid_budget(o.job.max_memory_bytes), &run->plan, &err))
    return fail(kExitUsage, "%s", err.c_str());
  if (const int code = save_stock_fits(o, run->plan)) return code;
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
  report_plan(run);
  return kExitOk;
}

// The engine's message for a job it cannot set up.
int setup_failed(const SimSetup& why, const RunOptions& o, const RunSetup& run) {
  char spec[kToolSpecTextMax];
  tool_spec_format(why.tool < 0 ? run.job.tool : run.job.tools[why.tool], spec, sizeof spec);
  switch (why.error) {
    case SimError::kToolTooWideStamp:
      return fail(kExitUsage, "the tool %s spans more than %d dexels at this pitch; use a coarser --pitch or --mode sweep",
                  spec, 2 * kCutterMaxReach + 1);
    case SimError::kToolTooLargeSweep:
      return fail(kExitUsage, "the tool %s is too large for --mode sweep (radius above 2^28 nm = 268.435 mm, a "
                  "diameter of 536.87 mm; --mode stamp takes up to 1000 mm)", spec);
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
int start_engine(const RunOptions& o, const ProgramScan& scan, RunSetup* run) {
  SimJob& j = run->job;
  j.plan = run->plan;
  run->tools.assign(scan.tools + 1, scan.tools + scan.ntools);
  // A saved stock's tool is still in the spindle: the table's, when it has it.
  Tool kept;
  if (j.resume && j.resume->have_position && j.resume->tool != 0 && run->lib && run->lib->tool(j.resume->tool, &kept)) {
    j.tool = kept;
    run->tools.push_back(kept);
  }
  j.tools = run->tools.data();
  j.ntools = static_cast<int>(run->tools.size());
  if (!o.job.design.empty()) {  // before the cut: a bad file costs no simulation
    if (const int code = load_design(o.job, run->plan, run->shown_name, &run->design,
                                     j.resume ? j.resume->frame : part_frame_identity()))
      return code;
    j.design = &run->design.grid;
    j.assess = run->design.opt;
  }
  j.checks = safety_checks(o.job.checks);
  sim_checks_for_tools(&j.checks, scan.tools, scan.ntools);
  if (!o.job.material.empty()) {
    // In the part's frame (a saved stock's: its setups turned the part),
    // over the part's box: the materials follow the part.
    const PartFrame frame = j.resume ? j.resume->frame : part_frame_identity();
    const PointNm a = part_frame_to_part(frame, run->plan.stock.lo), b = part_frame_to_part(frame, run->plan.stock.hi);
    const BoxNm box{PointNm{min_of(a.x_nm, b.x_nm), min_of(a.y_nm, b.y_nm), min_of(a.z_nm, b.z_nm)},
                    PointNm{max_of(a.x_nm, b.x_nm), max_of(a.y_nm, b.y_nm), max_of(a.z_nm, b.z_nm)}};
    if (const int code = material_start(&run->material, o.job.material, box)) return code;
    if (composition_set_frame(run->material.comp.get(), frame) != Status::kOk)
      return fail(kExitInput, "%s: the stock's part frame turns Z over into X or Y; its materials cannot follow it",
                  o.job.stock_file.c_str());
    j.material = run->material.comp.get();
    if (o.job.feed_limits) j.line_feed_lines = static_cast<size_t>(run->rep.lines) + 1;  // lines 0 .. the last
    j.process_lines = static_cast<size_t>(run->rep.lines) + 1;  // each finding once, lines 0 .. the last
  }
  const bool engage_colours = o.view.color == ViewOptions::Color::kEngagement;
  if (!o.out.engagement_csv.empty() || !o.out.load_plot.empty() || o.job.check_load || o.job.engage_target ||
      engage_colours) {  // each feed move's load, as the cut goes
    run->engage.reset(new EngageRecorder(run->plan.geo.lsb_nm, run->plan.geo.pitch_nm));
    if (!o.out.engagement_csv.empty() && !run->engage->open_csv(o.out.engagement_csv))
      return fail(kExitIo, "%s", run->engage->error());
    if (!o.out.load_plot.empty() || !o.out.sheet.empty()) run->engage->keep_plot();  // the sheet shows the plot
    j.engagement = true;
    j.engage_sink = run->engage.get();
    j.engage_colours = engage_colours;
    j.load_check = o.job.check_load;
    j.spindle_power_mw = o.job.spindle_power_mw;
    j.default_spindle_rpm = o.job.default_spindle_rpm;
    if (o.job.engage_target) {
      j.engage_target = o.job.engage_target;
      j.target_lines = static_cast<size_t>(run->rep.lines) + 1;  // lines 0 .. the last
      j.split_rule = o.job.split_rule;
      j.split_pieces = o.job.split_pieces;
    }
    for (int k = 0; k < scan.ntools && run->print; ++k)  // said once a tool: the chip per tooth rests on it
      if (scan.tools[k].flutes == 0 && (k == 0 ? scan.cuts[0] : true)) {
        char spec[kToolSpecTextMax];
        tool_spec_format(scan.tools[k], spec, sizeof spec);
        std::fprintf(stderr, "dexmill: warning: the chip per tooth takes %d flutes for %s, which does not say (give "
                     "flutes=N in its spec)\n", kToolFlutesAssumed, spec);
      }
  }
  if (!o.job.machine_file.empty()) {
    j.machine = &run->machine.file.spec;
    j.travel_check = o.job.check_travel;
  }
  j.provenance = o.view.color == ViewOptions::Color::kTool;
  j.provenance_first_tool = kInitialToolNumber;
  // A stock saved, or continued with its provenance: which tool, line and
  // program cut each column is carried.
  if (!o.out.save_stock.empty() || (j.resume && (j.resume->layers & kStockLayerClass))) {
    j.provenance = true;
    j.provenance_lines = j.provenance_programs = true;
  }
  // A click in the window says which line last cut the column clicked.
  if (o.view.window) j.provenance = j.provenance_lines = true;
  j.probe_tip_nm = o.job.probe_tip_nm;
  j.stop_at_gouge = o.job.stop_at_gouge;
  j.stop_at_collision = o.job.stop_at_collision;
  SimSetup why;
  const size_t bytes = sim_required_bytes(j, &why);
  if (!bytes) return setup_failed(why, o, *run);
  std::string over;
  if (!engine_within_budget(bytes, run->plan, run_grid_budget(o.job.max_memory_bytes), &over))
    return fail(kExitUsage, "%s", over.c_str());
  if (!run->memory.allocate(bytes))
    return fail(kExitIo, "cannot allocate %s for the %dx%d grid (and the engine that cuts it)", size_text(bytes).c_str(),
                static_cast<int>(run->plan.geo.nx), static_cast<int>(run->plan.geo.ny));
  run->sim = sim_create(j, run->memory.data(), bytes, &why);
  if (!run->sim) return setup_failed(why, o, *run);
  if (run->stock_in) {
    std::string err;
    if (!run->stock_in->read_columns(run->sim->stock_columns(run->stock_meta.layers), &err)) {
      std::fprintf(stderr, "%s\n", err.c_str());
      return run->stock_in->io_error() ? kExitIo : kExitInput;
    }
    run->stock_in.reset();
    if (const int code = turn_saved_stock(o, run)) return code;
  }
  if (!run->blank.empty()) {
    const int code = carve_stock(&run->sim->grid(), run->plan, run->blank);
    if (code != kExitOk) return code;
  }
  run->sim->start();
  return kExitOk;
}

// The first pass and its verdict on the program: the report's program
// part; a program with an input error is cut up to its first bad block (as
// LinuxCNC's preview draws the path up to it), unless --strict.
int first_pass(const RunOptions& o, RunSetup* run) {
  RunReport& rep = run->rep;
  rep.file = run->shown_name;
  rep.units = o.job.read.inch ? "inch" : "mm";
  rep.mode = o.job.mode == CutMode::kSweep ? "sweep" : "stamp";
  rep.default_tool = o.job.tool_text;
  rep.tool_table = run->demo && o.job.read.tools_file.empty() ? "(built-in demo table)" : o.job.read.tools_file;
  rep.height_bits = DEXMILL_HEIGHT_BITS;
  rep.rapid_nm_per_min = o.job.rapid_nm_per_min;
  rep.accel_nm_per_s2 = o.job.accel_nm_per_s2;
  RunMessages msgs(run->shown_name, run->print);
  // The program's messages are printed after the pass, from this one
  // unless it probes: then the cut's, where each probe stopped on the stock.
  GcodeNotes notes(run->shown_name.c_str(), false);
  SimJob scan_job = run->job;
  scan_job.notes = &notes;
  run->scan.reset(new ProgramScan(scan_job));
  run->scan->set_tool_choice(run->choice.get());
  run->planner.reset(new MotionPlanner());
  run->scan->set_planner(run->planner.get());
  run->want_path = o.view.path_overlay || o.view.window || !o.view.fbdev.empty();
  const double t0 = clock_now_s();
  const ScanInput in{run->read_path, run->shown_name, &o.job.read, &run->table, run->guard, run->choice.get()};
  if (const int code = scan_pass(in, run->scan.get(), notes, run->want_path ? &run->path : nullptr, &msgs, &rep))
    return code;
  rep.timing.emplace_back("scan", clock_now_s() - t0);
  if (run->scan->probes == 0) {
    if (run->print) notes.print_kept();
  } else {
    run->cut_notes.reset(new GcodeNotes(run->shown_name.c_str(), run->print));
    run->job.notes = run->cut_notes.get();
  }
  run->job.tool = run->scan->tools[0];  // a comment's, when it gives the tool before any M6
  run->scan_errors = msgs.errors();
  run->scan_warnings = msgs.warnings();
  if (!msgs.errors()) return kExitOk;
  if (o.job.strict) {
    run->refused = true;
    return kExitInput;
  }
  run->job.stop_line = rep.errors.front().line;
  rep.stopped_reason = "error";
  rep.stopped_line = run->job.stop_line;
  return kExitOk;
}

}  // namespace

int remove_earlier_frames(const RunOptions& o, RunSetup* s) {
  std::string err;
  if (!remove_old_frames(s->old_frames, &err)) return fail(kExitIo, "%s", err.c_str());
  if (!s->old_frames.empty() && !o.view.quiet && !s->demo)
    std::fprintf(stderr, "dexmill: removed %zu frames of an earlier run from '%s'\n", s->old_frames.size(),
                 o.out.frames_dir.c_str());
  s->old_frames.clear();
  return kExitOk;
}

int run_setup(RunOptions* o, RunSetup* s) {
  if (const int code = run_machine_load(o, &s->machine)) return code;  // its defaults before anything reads them
  if (const int code = prepare(o, s)) return code;
  if (const int code = load_tools(*o, s)) return code;
  if (const int code = open_saved_stock(*o, s)) return code;
  if (const int code = first_pass(*o, s)) return code;
  ToolSource initial = ToolSource::kDefault;
  (void)s->choice->initial(&initial);
  if (initial == ToolSource::kComment) {  // the views and messages show the tool the cut starts with
    char spec[kToolSpecTextMax];
    tool_spec_format(s->job.tool, spec, sizeof spec);
    o->job.tool = s->job.tool;
    o->job.tool_text = spec;
  }
  if (const int code = plan_stock(*o, *s->scan, s)) return code;
  return start_engine(*o, *s->scan, s);
}

}  // namespace cli
}  // namespace dexmill
