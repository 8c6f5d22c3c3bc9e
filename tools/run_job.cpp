// The passes and outputs of `dexmill run`; see run_job.h.
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

#include "core/cut/mill.h"
#include "core/cut/sweep.h"
#include "core/grid/volume.h"
#include "core/math/trig.h"
#include "core/motion/interp.h"
#include "core/motion/summary.h"
#include "core/tool/cutter.h"
#include "core/tool/spec.h"
#include "platform/output_file.h"
#include "platform/clock.h"
#include "platform/gcode_file.h"
#include "platform/frame_files.h"
#include "platform/image_file.h"
#include "platform/program_input.h"
#include "platform/progress.h"
#include "platform/report_json.h"
#include "platform/report_summary.h"
#include "platform/stl.h"
#include "platform/tool_table.h"
#include "tools/cli.h"
#include "tools/demo_program.h"
#include "tools/run_assess.h"
#include "tools/run_colours.h"
#include "tools/run_live.h"
#include "tools/run_outputs.h"
#include "tools/run_path.h"
#include "tools/run_render.h"
#include "display/material_colours.h"
#include "tools/run_material.h"
#include "tools/run_safety.h"
#include "tools/run_stock.h"
#include "tools/run_tool_table.h"

namespace dexmill {
namespace cli {
namespace {

constexpr size_t kMaxReportedWarnings = 100;

// Prints diagnostics (when asked) and keeps them for the report.
class RunMessages final : public GcodeMessages {
 public:
  RunMessages(const std::string& file, bool print) : file_(file), print_(print) {}
  void set_file(const char* name) override { file_ = name; }
  void error(const GcodeDiag& d) override { add(d, true); }
  void warning(const GcodeDiag& d) override { add(d, false); }
  // An error found outside the interpreter (a tool the table lacks).
  void error_text(uint32_t line, uint32_t col, const std::string& msg) {
    ++errors_;
    if (print_) std::fprintf(stderr, "%s:%u:%u: error: %s\n", file_.c_str(), line, col, msg.c_str());
    error_list.push_back(ReportDiag{line, col, msg});
  }
  std::vector<ReportDiag> error_list, warning_list;

 private:
  void add(const GcodeDiag& d, bool is_error) {
    char msg[400];
    gcode_format_message(d, msg, sizeof msg);
    if (is_error) ++errors_;
    else ++warnings_;
    if (print_) {
      char line[700];
      gcode_format_diag(file_.c_str(), d, is_error, line, sizeof line);
      std::fprintf(stderr, "%s\n", line);
    }
    if (is_error) error_list.push_back(ReportDiag{d.line, d.col, msg});
    else if (warning_list.size() < kMaxReportedWarnings) warning_list.push_back(ReportDiag{d.line, d.col, msg});
  }
  std::string file_;
  bool print_;
};

// The scan pass: the summary, and the tools the program changes to.
class ScanSink final : public CanonSink {
 public:
  ScanSink(const ToolLibrary* lib, const Tool& initial, const MotionTimeModel& model)
      : summary(model), max_radius_nm(initial.diameter_nm / 2), lib_(lib) {
    tools_seen.push_back(initial);
  }
  void emit(const CanonRecord& r) override {
    summary.emit(r);
    if (interp && (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc))
      (interp->state().inch ? inch_moves : mm_moves) = true;
    if (path) append_path(r, path);
    if (r.kind != CanonKind::kToolChange) return;
    Tool t;
    if (!lib_->tool(r.tool, &t)) {
      if (!bad_tool_line) { bad_tool_line = r.line; bad_tool = r.tool; }
      return;
    }
    max_radius_nm = max_of(max_radius_nm, t.diameter_nm / 2);
    tools_seen.push_back(t);
    for (const ReportToolUse& u : used)
      if (u.number == r.tool) return;
    char spec[kToolSpecTextMax];
    tool_spec_format(t, spec, sizeof spec);
    used.push_back(ReportToolUse{r.tool, spec});
  }
  MotionSummary summary;
  const Interp* interp = nullptr;     // for the units each move was written in
  std::vector<PathSegment>* path = nullptr;  // the backplot's pieces, when wanted
  bool inch_moves = false, mm_moves = false;
  std::vector<ReportToolUse> used;
  std::vector<Tool> tools_seen;
  int64_t max_radius_nm;
  uint32_t bad_tool_line = 0;
  int32_t bad_tool = 0;

 private:
  const ToolLibrary* lib_;
};

// Everything that watches the cut pass.
struct Watchers {
  std::vector<RenderOutput*> outputs;  // fed the grid's changes
  RenderOutput* frames_out = nullptr;
  FrameFiles* frames = nullptr;
  uint64_t every = 0;
  RenderOutput* live_out = nullptr;
};

// The cut pass: records into the Mill, then frames.
class CutSink final : public CanonSink {
 public:
  CutSink(Mill<height_t>* mill, DexelGrid<height_t>* g, Watchers* w, const ToolLibrary* lib, RunDesign* design,
          RunSafety* safety, const Tool& initial, const MotionTimeModel& model)
      : time(model), mill_(mill), g_(g), w_(w), lib_(lib), design_(design), safety_(safety),
        profile_(tool_profile(initial)) {
    tool_body_build(initial, &body_);
    if (safety_) safety_watch_set_tool(&safety_->watch, profile_);
  }
  void emit(const CanonRecord& r) override {
    if (stop_line && r.line >= stop_line) {  // a partial run: nothing of the bad block or after it
      stopped_at_error = true;
      return;
    }
    // Where the line before left the tool: a deferred end cap cut now is its.
    const bool move = r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
    if (move && r.line != last_line_) {
      origin_ = GougeOrigin{last_line_, mill_->position(), &profile_};
      safety_origin_ = SafetyOrigin{last_move_, mill_->position(), &profile_};
      process_origin_ = ProcessOrigin{last_process_, mill_->position(), &profile_};
      have_origin_ = last_line_ != 0;
    }
    mill_->emit(r);
    if (tool_colours) run_colours_record(tool_colours, g_->dirty);
    if (count_path) path_done += path_pieces(r);
    last_line_ = r.line;
    watch();
    if (safety_) {
      // M3/M4 in effect (the interpreter's state: a record's rpm is 0 both
      // after M5 and for M3 with no S word, which a controller runs at its
      // default speed).
      const bool spindle_on = interp && interp->state().spindle_dir != 0;
      SafetyMove m{r.line, r.kind == CanonKind::kTraverse, spindle_on, moved_};
      m.plunge = safety_is_plunge(r);
      m.end = r.end;
      m.body = &body_;
      check_safety(r, m, have_origin_ ? &safety_origin_ : nullptr);
      if (move) {
        last_move_ = m;
        moved_ = true;
      }
    }
    const int64_t t_before = time.estimated_time_us();
    time.emit(r);
    if (material) check_process(r, move, time.estimated_time_us() - t_before);
    status.line = r.line;
    status.pos = mill_->position();
    if (r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc) status.feed_nm_per_min = r.feed_nm_per_min;
    if (r.kind == CanonKind::kToolChange) {
      status.tool = r.tool;
      Tool t;
      if (lib_->tool(r.tool, &t)) {
        profile_ = tool_profile(t);
        tool_body_build(t, &body_);
        if (safety_) safety_watch_set_tool(&safety_->watch, profile_);
        if (tool_colours) run_colours_tool_change(tool_colours, r.tool);
        char spec[kToolSpecTextMax];
        tool_spec_format(t, spec, sizeof spec);
        status.tool_spec = spec;
        for (RenderOutput* o : w_->outputs) o->set_tool(t);
      }
    }
    status.sim_us = time.estimated_time_us();
    fan_out_dirty(g_, w_->outputs.data(), static_cast<int>(w_->outputs.size()));
    if (r.kind != CanonKind::kTraverse && r.kind != CanonKind::kFeed && r.kind != CanonKind::kArc) return;
    ++moves;
    if (w_->frames && moves % w_->every == 0) write_frame();
  }
  // Shows the cut so far (the Mill defers a move's end cap) and passes its
  // dirty rectangle on: before anything reads the grid. The gouge watch
  // skips what flush shows: the records after it cut that cap for good
  // (core/cut/mill.h), so the watch's events do not depend on when frames
  // are drawn either.
  void sync() {
    mill_->flush();
    if (tool_colours) run_colours_note(tool_colours, g_->dirty);
    fan_out_dirty(g_, w_->outputs.data(), static_cast<int>(w_->outputs.size()));
  }
  // The end of the cut pass: the deferred cap for good, watched.
  void finish() {
    mill_->finish();
    if (tool_colours) run_colours_record(tool_colours, g_->dirty);
    watch();
    if (safety_) {  // the deferred end cap, now cut for good, is the last move's
      CanonRecord cap{};
      cap.kind = CanonKind::kDwell;
      cap.line = last_move_.line;
      check_safety(cap, last_move_, nullptr);
    }
    if (material) {  // and to the process rules, in the last move's state
      ProcessState last = last_process_;
      last.time_us = 0;
      process_watch_record(&material->watch, *g_, g_->dirty, last, nullptr);
    }
    fan_out_dirty(g_, w_->outputs.data(), static_cast<int>(w_->outputs.size()));
  }
  // One frame of the sequence; false (and frame_error set) on failure.
  bool write_frame() {
    if (!frame_error.empty()) return false;
    sync();
    const double t0 = clock_now_s();
    const RenderResult res = w_->frames_out->draw(g_, pose());
    const double t1 = clock_now_s();
    if (!w_->frames->present(res.rects, res.nrects)) frame_error = w_->frames->error();
    render_s += t1 - t0;
    write_s += clock_now_s() - t1;
    last_frame_moves = moves;
    return frame_error.empty();
  }
  CutterPose pose() const { return CutterPose{true, mill_->position()}; }

  MotionSummary time;
  LiveStatus status;
  uint32_t stop_line = 0;        // the first bad block of a partial run (0: none)
  const Interp* interp = nullptr;  // the cut pass's, for the spindle's state
  RunMaterial* material = nullptr;  // the process rules (null: no --material)
  RunColours* tool_colours = nullptr;  // --color tool: told what each record lowered (null: off)
  bool count_path = false;       // keep path_done: the backplot's pieces cut so far
  uint32_t path_done = 0;
  bool stopped_at_error = false;
  bool gouged = false;  // a gouge was found (the watch's warnings are printed)
  bool collided = false;  // a safety check found something
  uint64_t moves = 0, last_frame_moves = 0;
  std::string frame_error;
  double render_s = 0, write_s = 0;

 private:
  Mill<height_t>* mill_;
  DexelGrid<height_t>* g_;
  Watchers* w_;
  const ToolLibrary* lib_;
  RunDesign* design_;  // null: no gouge watch
  RunSafety* safety_;  // null: no safety checks
  bool moved_ = false;       // a move has run: the tool's position is the program's, not assumed
  SafetyMove last_move_{};   // the last motion record's line and state
  SafetyOrigin safety_origin_{SafetyMove{}, PointNm{0, 0, 0}, nullptr};
  ProcessState last_process_{};  // the last motion record's, for the process rules
  ProcessOrigin process_origin_{ProcessState{}, PointNm{0, 0, 0}, nullptr};
  uint32_t last_line_ = 0;
  ToolProfile profile_{};  // the tool in the spindle
  ToolBody body_{};        // its shank and holder (core/check/body.h)
  GougeOrigin origin_{0, PointNm{0, 0, 0}, nullptr};
  bool have_origin_ = false;

  // The process rules on what record r removed, in the interpreter's state.
  void check_process(const CanonRecord& r, bool move, int64_t time_us) {
    ProcessState s;
    s.line = r.line;
    s.feed_move = r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc;
    s.feed_nm_per_min = r.feed_nm_per_min;
    if (interp) {
      s.spindle_rpm = interp->state().spindle_rpm;
      s.spindle_on = interp->state().spindle_dir != 0;
      s.coolant = interp->state().coolant;
    }
    s.time_us = time_us;
    process_watch_record(&material->watch, *g_, g_->dirty, s, have_origin_ ? &process_origin_ : nullptr);
    if (move) last_process_ = s;
  }

  void check_safety(const CanonRecord& r, const SafetyMove& m, const SafetyOrigin* prev) {
    if (!safety_watch_record(&safety_->watch, *g_, g_->dirty, r, m, prev)) return;
    collided = true;
    safety_mark_new(safety_);
  }

  // The columns the last record changed (the grid's dirty rectangle, which
  // fan_out_dirty clears after every record) against the design.
  void watch() {
    if (design_ && watch_gouges(*g_, g_->dirty, last_line_, mill_->position(), have_origin_ ? &origin_ : nullptr, design_))
      gouged = true;
  }
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

}  // namespace

int run_job(RunOptions o) {
  const double t_start = clock_now_s();
  RunReport rep;
  const bool demo = o.file.empty();
  std::string read_path = o.file, shown_name = o.file;
  ProgramInput input;
  std::string err;

  // -- inputs and output folders, before anything long happens
  if (demo) {
    if (o.image.empty()) o.image = "out/final.ppm";
    if (o.design.empty()) {  // the demo's own part: its report has an assessment, and out/error.ppm
      o.design = "(the demo's part)";
      o.demo_design = true;
      if (o.error_image.empty()) o.error_image = "out/error.ppm";
    }
    if (o.frames_dir.empty()) o.frames_dir = "out/frames";
    if (o.material.empty()) {
      o.material = demo_material();
      if (!o.have_color) o.color = RunOptions::Color::kMaterial;
    }
    if (!make_dirs("out", &err)) return fail(kExitIo, "%s", err.c_str());
    read_path = shown_name = "out/demo.ngc";
    const std::string text = demo_program();
    char e[1300];
    if (!write_output(read_path.c_str(), text.data(), text.size(), e, sizeof e)) return fail(kExitIo, "%s", e);
  }
  OutputFormats formats;
  {
    const int code = check_outputs(o, {o.file, o.read.tools_file, o.design, o.stock_stl}, &formats);
    if (code != kExitOk) return code;
  }
  if (!demo) {
    if (o.file == "-") shown_name = "<stdin>";
    if (!o.shown_name.empty()) shown_name = o.shown_name;
    if (!input.open(o.file, &err)) return fail(kExitIo, "%s", err.c_str());
    read_path = input.read_path();
  }
  if (!o.frames_dir.empty()) {
    uint32_t removed = 0;
    if (!make_dirs(o.frames_dir, &err)) return fail(kExitIo, "%s", err.c_str());
    if (access(o.frames_dir.c_str(), W_OK) != 0)
      return fail(kExitIo, "cannot write frames into '%s': %s", o.frames_dir.c_str(), std::strerror(errno));
    if (!remove_old_frames(o.frames_dir, &removed, &err)) return fail(kExitIo, "%s", err.c_str());
    if (removed && !o.quiet && !demo)
      std::fprintf(stderr, "dexmill: removed %u frames of an earlier run from '%s'\n", removed, o.frames_dir.c_str());
  }

  // -- tools
  ToolTableFile table;
  const bool have_table = !o.read.tools_file.empty() || demo;
  if (!o.read.tools_file.empty()) {
    const int code = load_tool_table(o.read.tools_file, o.read.inch, &table);
    if (code != kExitOk) return code;
  } else if (demo) {
    const char* t = demo_tool_table();
    if (table.parse("demo tool table", t, std::strlen(t), false) != ToolTableFile::Load::kOk)
      return fail(kExitInput, "%s", table.message().c_str());
  }
  for (const std::string& w : table.warnings()) std::fprintf(stderr, "%s\n", w.c_str());
  SingleToolLibrary single(o.tool);
  const ToolLibrary* lib = have_table ? static_cast<const ToolLibrary*>(&table) : &single;

  rep.file = shown_name;
  rep.units = o.read.inch ? "inch" : "mm";
  rep.mode = o.mode == CutMode::kSweep ? "sweep" : "stamp";
  rep.default_tool = o.tool_text;
  rep.tool_table = demo && o.read.tools_file.empty() ? "(built-in demo table)" : o.read.tools_file;
  rep.height_bits = DEXMILL_HEIGHT_BITS;
  rep.rapid_nm_per_min = o.rapid_nm_per_min;
  auto write_report = [&]() -> bool {
    if (o.report.empty()) return true;
    rep.timing.emplace_back("total", clock_now_s() - t_start);
    char e[1300];
    if (write_report_json(o.report.c_str(), rep, e, sizeof e)) return true;
    fail(kExitIo, "%s", e);
    return false;
  };

  // -- scan pass
  RunMessages scan_msgs(shown_name, true);
  GcodeNotes notes(shown_name.c_str());  // a program's messages, printed once (this pass)
  MotionTimeModel time_model;
  time_model.rapid_nm_per_min = o.rapid_nm_per_min;
  time_model.accel_nm_per_s2 = o.accel_nm_per_s2;
  rep.accel_nm_per_s2 = o.accel_nm_per_s2;
  ScanSink scan(lib, o.tool, time_model);
  // The backplot's path: for --path-overlay, and for a live view (its p key).
  const bool want_path = o.path_overlay || o.window || !o.fbdev.empty();
  std::vector<PathSegment> path;
  if (want_path) scan.path = &path;
  {
    const double t0 = clock_now_s();
    GcodeFile in;
    if (!in.open(read_path.c_str(), shown_name.c_str())) return fail(kExitIo, "%s", in.error());
    ReadSetup setup;
    InterpOptions opt;
    setup.apply(o.read, &opt, &in);
    opt.warnings = &scan_msgs;
    opt.tools = have_table ? static_cast<const ToolTable*>(&table) : &single;  // G41/G42: the --tool radius
    opt.messages = &notes;
    Interp interp(&scan, opt);
    scan.interp = &interp;
    GcodeRunner runner(&in, &interp, &scan_msgs, true);
    while (runner.step()) {
      if (scan.bad_tool_line) {
        char m[200];
        if (table.has(scan.bad_tool))
          std::snprintf(m, sizeof m, "tool T%d has diameter 0 in the tool table '%s': it cannot cut",
                        static_cast<int>(scan.bad_tool), table.name().c_str());
        else
          std::snprintf(m, sizeof m, "tool T%d is not in the tool table '%s'", static_cast<int>(scan.bad_tool),
                        table.name().c_str());
        scan_msgs.error_text(scan.bad_tool_line, 1, m);
        break;
      }
    }
    if (runner.io_error()) return fail(kExitIo, "%s", in.error());
    rep.lines = runner.lines();
    scan.interp = nullptr;
    if (scan.inch_moves || scan.mm_moves) rep.units = scan.inch_moves ? (scan.mm_moves ? "mixed" : "inch") : "mm";
    rep.timing.emplace_back("scan", clock_now_s() - t0);
  }
  const MotionSummary& sum = scan.summary;
  rep.rapid = sum.count(CanonKind::kTraverse);
  rep.feed = sum.count(CanonKind::kFeed);
  rep.arc = sum.count(CanonKind::kArc);
  rep.dwell = sum.count(CanonKind::kDwell);
  rep.tool_change = sum.count(CanonKind::kToolChange);
  rep.errors = scan_msgs.error_list;
  rep.warnings = scan_msgs.warning_list;
  for (const GcodeNotes::Note& n : notes.kept)
    if (rep.messages.size() < 100) rep.messages.push_back(RunReport::Message{n.line, n.kind, n.text});
  rep.warnings_total = scan_msgs.warnings();
  rep.tools_used = scan.used;
  rep.estimated_us = sum.estimated_time_us();
  rep.feed_us = sum.feed_time_us();
  rep.rapid_us = sum.rapid_time_us();
  rep.dwell_us = sum.dwell_time_us();
  rep.have_bounds = sum.motion_box().valid;
  rep.bounds_lo = sum.motion_box().lo;
  rep.bounds_hi = sum.motion_box().hi;
  // A program with an input error is cut up to its first bad block (as
  // LinuxCNC's preview draws the path up to it), unless --strict.
  uint32_t stop_line = 0;
  if (scan_msgs.errors()) {
    if (o.strict) {
      if (!write_report()) return kExitIo;
      return kExitInput;
    }
    stop_line = rep.errors.front().line;
    rep.stopped_reason = "error";
    rep.stopped_line = stop_line;
  }

  // -- stock and grid
  StockBox stock;
  std::vector<TriangleNm> blank;
  if (!o.stock_stl.empty()) {
    const int code = read_stock_stl(o.stock_stl, &blank, &stock);
    if (code != kExitOk) return code;
    rep.stock_source = "stl";
  } else if (o.have_stock) {
    stock = StockBox{PointNm{o.stock_nm[0], o.stock_nm[1], o.stock_nm[2]}, PointNm{o.stock_nm[3], o.stock_nm[4], o.stock_nm[5]}};
    rep.stock_source = "option";
  } else if (demo) {
    int64_t v[6];
    const char* s = demo_stock();
    for (int k = 0; k < 6; ++k) {
      v[k] = std::strtol(s, const_cast<char**>(&s), 10) * kNmPerMm;
      if (*s == ',') ++s;
    }
    stock = StockBox{PointNm{v[0], v[1], v[2]}, PointNm{v[3], v[4], v[5]}};
    rep.stock_source = "demo";
  } else {
    stock = default_stock(sum, scan.max_radius_nm);
    rep.stock_source = "program";
  }
  GridPlan plan;
  int64_t pitch_nm = o.pitch_nm;
  if (!pitch_nm && !o.grid_nx) {
    int64_t smallest = 0;
    for (const Tool& t : scan.tools_seen) smallest = smallest ? min_of(smallest, t.diameter_nm) : t.diameter_nm;
    pitch_nm = default_pitch_nm(stock, smallest);
  }
  if (!plan_grid(stock, o.grid_nx, o.grid_ny, pitch_nm, &plan, &err)) return fail(kExitUsage, "%s", err.c_str());
  // A tool narrower than the pitch may fall between the dexel axes and cut
  // nothing: say so rather than show an untouched block.
  for (const Tool& t : scan.tools_seen)
    if (t.diameter_nm < plan.geo.pitch_nm) {
      char spec[kToolSpecTextMax];
      tool_spec_format(t, spec, sizeof spec);
      std::fprintf(stderr, "dexmill: warning: the tool %s is narrower than the grid's pitch (%s mm) and may cut nothing; "
                   "give a finer --pitch\n", spec, nm_to_mm_text(plan.geo.pitch_nm, 4).c_str());
      break;
    }
  rep.have_stock = true;
  rep.stock_lo = plan.stock.lo;
  rep.stock_hi = plan.stock.hi;
  rep.nx = plan.geo.nx;
  rep.ny = plan.geo.ny;
  rep.pitch_nm = plan.geo.pitch_nm;
  rep.lsb_nm = plan.geo.lsb_nm;
  const size_t cells = static_cast<size_t>(plan.geo.nx) * static_cast<size_t>(plan.geo.ny);
  std::vector<height_t> top(cells), bottom(cells);
  DexelGrid<height_t> grid;
  if (!ok(grid_init(&grid, plan.geo, top.data(), bottom.data(), cells)))
    return fail(kExitUsage, "the stock and grid give a geometry the dexel grid cannot hold");
  fill_stock(&grid, plan);
  if (!blank.empty()) {
    const int code = carve_stock(&grid, plan, blank);
    if (code != kExitOk) return code;
  }
  const uint64_t material_before = grid_material_lsb(grid);
  // -- the design part, before the cut: a bad file costs no simulation
  RunDesign design;
  if (!o.design.empty()) {
    const int code = load_design(o, plan, shown_name, &design);
    if (code != kExitOk) return code;
  }

  // -- the safety checks, on the grid as stocked
  RunSafety safety;
  SafetyChoice checks = o.checks;
  for (const Tool& t : scan.tools_seen) {  // what a tool describes is checked
    checks.shank = checks.shank || t.flute_length_nm > 0;
    checks.holder = checks.holder || t.holder_segments > 0;
    checks.plunge = checks.plunge || !t.centre_cutting;
  }
  // -- the stock's materials and their process rules
  RunMaterial material;
  if (!o.material.empty()) {
    const int code = material_start(&material, o.material, BoxNm{plan.stock.lo, plan.stock.hi}, grid);
    if (code != kExitOk) return code;
    if (o.line_feed_limits) {  // `dexmill optimize`: lines 0 .. the last
      o.line_feed_limits->assign(static_cast<size_t>(rep.lines) + 1, kNoFeedLimit);
      process_watch_track_lines(&material.watch, o.line_feed_limits->data(), o.line_feed_limits->size());
    }
  }
  const bool safety_on = checks.any();
  if (safety_on) {
    std::string why;
    if (!safety_start(&safety, grid, checks, &why)) return fail(kExitUsage, "--fixture: %s", why.c_str());
  }

  // -- the Mill's memory for the largest tool used: the stamp set, or the
  // dexels under a deferred end cap that a frame shows (core/cut/mill.h)
  size_t words = 0;
  for (const Tool& t : scan.tools_seen) {
    const ToolProfile p = tool_profile(t);
    char spec[kToolSpecTextMax];
    tool_spec_format(t, spec, sizeof spec);
    if (o.mode == CutMode::kStamp) {
      const int32_t reach = cutter_reach_dex(p, grid.pitch_nm);
      if (reach > kCutterMaxReach)
        return fail(kExitUsage, "the tool %s spans more than %d dexels at this pitch; use a coarser --pitch or --mode sweep",
                    spec, 2 * kCutterMaxReach + 1);
    } else {
      SweepTool st;
      if (!ok(sweep_tool_prepare(p, grid.lsb_nm, &st)))
        return fail(kExitUsage, "the tool %s is too large for --mode sweep (radius above 268 mm)", spec);
    }
    words = max_of(words, mill_words(o.mode, p, grid));
  }
  std::vector<int32_t> cutter_words(words);
  Mill<height_t> mill(&grid, o.mode, lib, cutter_words.empty() ? nullptr : cutter_words.data(), cutter_words.size());
  if (!ok(mill.set_tool(o.tool))) return fail(kExitUsage, "the tool %s cannot cut this grid", o.tool_text.c_str());

  // -- outputs that watch the cut
  CameraChoice cam;
  cam.preset = o.view;
  if (o.have_azimuth || o.have_elevation) {
    const Camera iso = camera_preset(ViewPreset::kIso);
    cam.angles = true;
    cam.azimuth_bam = o.have_azimuth ? bam_from_mdeg(o.azimuth_mdeg) : iso.azimuth_bam;
    cam.elevation_bam = o.have_elevation ? static_cast<int32_t>(bam_from_mdeg(o.elevation_mdeg)) : iso.elevation_bam;
  }
  Watchers w;
  std::unique_ptr<FrameFiles> frames;
  std::unique_ptr<RenderOutput> frames_out, image_out;
  std::vector<uint32_t> image_pixels;
  LiveView live;
  const bool is_live = o.window || !o.fbdev.empty();
  const uint64_t motion_moves = rep.rapid + rep.feed + rep.arc;
  if (is_live) {
    const int code = live.open(o, grid, cam, sum.estimated_time_us(), &err);
    if (code != kExitOk) return fail(code, "%s", err.c_str());
    w.live_out = live.output();
    w.outputs.push_back(w.live_out);
  }
  if (!o.frames_dir.empty()) {
    frames.reset(new FrameFiles(o.frames_dir, o.frame_format, o.width, o.height));
    frames_out.reset(new RenderOutput());
    if (!frames_out->init(grid, frames->frame(), cam, &err)) return fail(kExitUsage, "%s", err.c_str());
    w.frames = frames.get();
    w.frames_out = frames_out.get();
    w.every = o.every ? static_cast<uint64_t>(o.every) : max_of<uint64_t>(1, (motion_moves + 99) / 100);
    w.outputs.push_back(frames_out.get());
  }
  // A still frame of its own at --size.
  auto still = [&](std::vector<uint32_t>* pixels, std::unique_ptr<RenderOutput>* out) -> bool {
    pixels->assign(static_cast<size_t>(o.width) * static_cast<size_t>(o.height), 0);
    FrameView fb;
    fb.pixels = pixels->data();
    fb.width = o.width;
    fb.height = o.height;
    fb.stride_bytes = o.width * 4;
    fb.format = PixelFormat::kXrgb8888;
    out->reset(new RenderOutput());
    return (*out)->init(grid, fb, cam, &err);
  };
  // The final image is the frame of the live view or of the sequence when
  // there is one (the same pixels), else a frame of its own.
  RenderOutput* image_src = is_live ? w.live_out : frames_out.get();
  if (!o.image.empty() && !image_src) {
    if (!still(&image_pixels, &image_out)) return fail(kExitUsage, "%s", err.c_str());
    w.outputs.push_back(image_out.get());
    image_src = image_out.get();
  }
  std::vector<uint32_t> error_pixels;
  std::unique_ptr<RenderOutput> error_out;
  if (!o.error_image.empty()) {
    if (!still(&error_pixels, &error_out)) return fail(kExitUsage, "%s", err.c_str());
    w.outputs.push_back(error_out.get());
  }
  for (RenderOutput* out : w.outputs) out->set_tool(o.tool);
  if (o.color == RunOptions::Color::kError || error_out) {
    error_view_init(grid, &design);
    for (RenderOutput* out : w.outputs) {
      if (out != error_out.get() && o.color != RunOptions::Color::kError) continue;
      out->set_colours(&design.colours.colours);
      out->set_legend(&design.legend);
    }
  }
  // The material under each top (--color material), in every output but the error view.
  MaterialColours<height_t> material_colours;
  std::vector<uint8_t> material_cls;
  std::vector<uint32_t> material_luts, material_texture;
  if (o.color == RunOptions::Color::kMaterial) {
    material_cls.assign(static_cast<size_t>(grid.nx) * static_cast<size_t>(grid.ny), 0);
    material_luts.assign(static_cast<size_t>(kMaxColourClasses) * kShadeLevels, 0);
    material_colours_init(&material_colours, grid, *material.comp, material_cls.data(), material_luts.data());
    // Textured; uncut tops tinted on a block stock (an STL blank's tops vary).
    material_texture.assign((material_texture_bytes(grid) + 3) / 4, 0);
    material_colours_texture(&material_colours, material_texture.data(),
                             o.stock_stl.empty() ? static_cast<uint32_t>(plan.top_lsb) : 0u);
    for (RenderOutput* out : w.outputs)
      if (out != error_out.get()) out->set_colours(&material_colours.colours);
  }
  // --color tool|slope|thin, in every output but the error view.
  RunColours colours;
  run_colours_start(&colours, o, grid, lib);
  if (const SurfaceColours* c = colours.colours())
    for (RenderOutput* out : w.outputs)
      if (out != error_out.get()) {
        out->set_colours(c);
        out->set_legend(&colours.legend);
      }
  // The gouges found so far, marked in every frame and live view.
  if (!o.design.empty())
    for (RenderOutput* out : w.outputs) out->add_marks(&design.marks, Rgb{255, 32, 24});
  if (safety_on)  // the safety findings so far, in magenta
    for (RenderOutput* out : w.outputs) out->add_marks(&safety.marks, Rgb{255, 40, 255});
  if (!o.checks.fixtures.empty()) {  // in every frame, the error view's too
    for (RenderOutput* out : w.outputs) out->set_fixtures(&o.checks.fixtures);
  }
  grid.dirty = grid.bounds();
  fan_out_dirty(&grid, w.outputs.data(), static_cast<int>(w.outputs.size()));

  // -- cut pass
  CutSink cut(&mill, &grid, &w, lib, o.design.empty() ? nullptr : &design, safety_on ? &safety : nullptr, o.tool,
              time_model);
  cut.stop_line = stop_line;
  if (o.color == RunOptions::Color::kTool) cut.tool_colours = &colours;
  cut.count_path = want_path;
  if (want_path)
    for (RenderOutput* out : w.outputs) {
      out->set_path(&path, &cut.path_done);
      out->set_path_visible(o.path_overlay);
    }
  if (is_live) live.set_before_draw([&cut] { cut.sync(); });
  cut.status.inch = o.read.inch;
  cut.status.tool_spec = o.tool_text;
  bool user_quit = false;
  std::vector<PointNm> error_mark, stop_mark;
  {
    const double t0 = clock_now_s();
    if (!input.unchanged(&err)) return fail(kExitIo, "%s", err.c_str());
    if (frames) cut.write_frame();  // the untouched stock
    GcodeFile in;
    if (!in.open(read_path.c_str(), shown_name.c_str())) return fail(kExitIo, "%s", in.error());
    RunMessages quiet(shown_name, false);
    ReadSetup setup;
    InterpOptions opt;
    setup.apply(o.read, &opt, &in);
    opt.tools = have_table ? static_cast<const ToolTable*>(&table) : &single;  // G41/G42: the --tool radius
    Interp interp(&cut, opt);
    cut.interp = &interp;
    if (!o.material.empty()) cut.material = &material;
    GcodeRunner runner(&in, &interp, &quiet, true);
    Progress progress(stderr, !o.quiet && !is_live);
    while (runner.step()) {
      progress.update(in.bytes_read(), in.total_bytes(), cut.moves);
      if (!cut.frame_error.empty() || cut.stopped_at_error) break;
      if (o.stop_at_gouge && cut.gouged) {
        rep.stopped_reason = "gouge";
        rep.stopped_line = cut.status.line;
        break;
      }
      if (o.stop_at_collision && cut.collided) {
        rep.stopped_reason = "collision";
        rep.stopped_line = cut.status.line;
        break;
      }
      if (is_live && !live.tick(&grid, cut.pose(), cut.status)) {
        user_quit = !live.failed();
        break;
      }
    }
    progress.finish();
    cut.finish();
    if (stop_line) {  // the bad block's place, in amber on the last frames
      error_mark.push_back(mill.position());
      for (RenderOutput* out : w.outputs) out->add_marks(&error_mark, Rgb{255, 190, 0});
    }
    if (rep.stopped_reason == "collision" && safety.watch.nevents > 0) {  // the finding it stopped at, in red
      stop_mark.push_back(safety.watch.events[safety.watch.nevents - 1].at);
      for (RenderOutput* out : w.outputs) out->add_marks(&stop_mark, Rgb{255, 32, 24});
    }
    if (!o.design.empty()) print_gouges(grid, &design);
    if (safety_on) {
      safety_print(safety, shown_name, grid);
      safety_to_report(safety, &rep);
    }
    if (!o.material.empty()) {
      if (!o.line_feed_limits) material_print(material, shown_name);
      material_to_report(material, grid, &rep);
    }
    if (runner.io_error()) return fail(kExitIo, "%s", in.error());
    if (!cut.frame_error.empty()) return fail(kExitIo, "%s", cut.frame_error.c_str());
    if (live.failed()) return fail(kExitIo, "%s", live.error().c_str());
    if (frames && (cut.last_frame_moves != cut.moves || stop_line) && !cut.write_frame())
      return fail(kExitIo, "%s", cut.frame_error.c_str());
    rep.timing.emplace_back("cut", clock_now_s() - t0 - cut.render_s - cut.write_s);
  }
  rep.instances = mill.stats().instances;
  rep.dexel_updates = mill.stats().dexel_updates;
  rep.removed_lsb_dexels = material_before - grid_material_lsb(grid);
  if (!o.design.empty()) {
    const double t0 = clock_now_s();
    assess_design(grid, &design);
    rep.have_assessment = true;
    rep.assessment = design.report;
    rep.timing.emplace_back("assess", clock_now_s() - t0);
  }

  // -- final frame and files
  double render_s = cut.render_s, write_s = cut.write_s;
  char e[1300];
  if (is_live && !user_quit && !live.last_frame(&grid, cut.pose(), cut.status))
    return fail(kExitIo, "%s", live.error().c_str());
  if (!o.image.empty()) {
    const double t0 = clock_now_s();
    if (image_src != w.live_out) image_src->draw(&grid, cut.pose());
    const FrameView* shown = &image_src->view();
    OverlayImage overlay;
    if (o.overlay != RunOptions::Overlay::kNone && image_src != w.live_out &&
        !overlay_image(o, plan, design, image_src, &overlay, &shown, &err))
      return fail(kExitUsage, "%s", err.c_str());
    const double t1 = clock_now_s();
    render_s += t1 - t0;
    if (!write_frame_image(o.image.c_str(), formats.image, *shown, e, sizeof e)) return fail(kExitIo, "%s", e);
    write_s += clock_now_s() - t1;
  }
  if (error_out) {
    const double t0 = clock_now_s();
    error_out->draw(&grid, cut.pose());
    const double t1 = clock_now_s();
    render_s += t1 - t0;
    if (!write_frame_image(o.error_image.c_str(), formats.error_image, error_out->view(), e, sizeof e)) return fail(kExitIo, "%s", e);
    write_s += clock_now_s() - t1;
  }
  const double t_files = clock_now_s();
  if (!o.heightmap.empty() && !write_heightmap(o.heightmap.c_str(), formats.heightmap, grid, e, sizeof e)) return fail(kExitIo, "%s", e);
  double stl_s = 0;
  if (!o.stl.empty()) {
    const double t_stl = clock_now_s();
    if (!write_stl(o.stl.c_str(), grid, e, sizeof e)) return fail(kExitIo, "%s", e);
    stl_s = clock_now_s() - t_stl;
  }
  write_s += clock_now_s() - t_files;
  rep.timing.emplace_back("render", render_s);
  rep.timing.emplace_back("write", write_s);
  if (!o.stl.empty()) rep.timing.emplace_back("stl", stl_s);  // a part of write
  if (!write_report()) return kExitIo;
  if (is_live && !user_quit && !live.wait_done(&grid, cut.pose(), cut.status))
    return fail(kExitIo, "%s", live.error().c_str());
  const bool no_output = o.image.empty() && o.error_image.empty() && o.frames_dir.empty() && o.heightmap.empty() &&
                         o.stl.empty() && o.report.empty() && !is_live;
  if (o.simulate_only) {
    const uint64_t found = safety_on ? safety.watch.total : 0;
    std::fprintf(stderr, "%s: %llu safety finding(s)%s\n", shown_name.c_str(), static_cast<unsigned long long>(found),
                 o.design.empty() ? "" : (cut.gouged ? ", gouged the design" : ", no gouge"));
  } else if (no_output && !o.line_feed_limits) {
    std::fputs(report_summary_text(rep).c_str(), stdout);
  }
  if (stop_line) return kExitInput;
  if (cut.gouged && (o.stop_at_gouge || o.fail_on_gouge)) return kExitCheck;
  if (cut.collided && (o.stop_at_collision || o.fail_on_collision)) return kExitCheck;
  if (!o.quiet && demo)
    std::fprintf(stderr, "dexmill: demo written to out/ (demo.ngc, final.ppm, error.ppm, frames/frame-*.%s)\n",
                 image_format_extension(o.frame_format));
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
