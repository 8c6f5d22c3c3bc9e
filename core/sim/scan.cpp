// The first pass over a program; see scan.h.
#include "core/sim/scan.h"

#include "core/math/fixed.h"

namespace dexmill {

ProgramScan::ProgramScan(const SimJob& job)
    : summary(job.time), job_(job), single_(job.tool), lib_(job.library ? job.library : &single_) {
  tools[0] = job.tool;
  numbers[0] = -1;
  ntools = 1;
  max_radius_nm = job.tool.diameter_nm / 2;
  summary.set_move_sink(this);
}

void ProgramScan::move_time(const MoveTimes& t) {
  if (in_spindle_ < 0) return;
  ScanToolTime& s = tool_time[in_spindle_];
  s.estimated_us = sat_add_i64(s.estimated_us, t.blended_us);
  if (t.kind == kMoveDwell) {
    s.dwell_us = sat_add_i64(s.dwell_us, t.blended_us);
    return;
  }
  int64_t& part = t.kind == kMoveFeed ? s.feed_us : s.rapid_us;
  part = sat_add_i64(part, t.blended_us);
  ++s.moves;
}

void ProgramScan::run(LineInput* in, GcodeMessages* messages, ProgramMemory* mem, CanonSink* also) {
  ScanPass pass(this, in, messages, mem, also);
  while (pass.step(0) != ScanPass::State::kDone) {
  }
}

namespace {

InterpOptions scan_interp_options(const SimJob& job, const ToolTable* single, ProgramMemory* mem,
                                  GcodeMessages* messages) {
  InterpOptions opt = sim_interp_options(job, single, mem);
  if (!job.warnings) opt.warnings = messages;
  return opt;
}

}  // namespace

ScanPass::ScanPass(ProgramScan* scan, LineInput* in, GcodeMessages* messages, ProgramMemory* mem, CanonSink* also)
    : scan_(scan),
      interp_(scan, scan_interp_options(scan->job_, &scan->single_, mem, messages)),
      tap_(in, scan->choice_ ? &scan->choice_->comments() : nullptr, scan),
      runner_(&tap_, &interp_, messages, true) {
  scan->also_ = also;
  scan->interp_ = &interp_;
}

ScanPass::State ScanPass::step(uint32_t lines) {
  if (done_) return State::kDone;
  for (uint32_t k = 0; lines == 0 || k < lines; ++k) {
    if (scan_->bad_tool_line || !runner_.step()) {
      if (runner_.waiting() && !scan_->bad_tool_line) return State::kWaiting;
      done_ = true;
      scan_->finish(runner_, interp_);
      return State::kDone;
    }
  }
  return State::kReading;
}

void ProgramScan::finish(const GcodeRunner& runner, const Interp& interp) {
  summary.finish();  // a program without M2: the look-ahead's last moves
  lines = runner.lines();
  probes = interp.probe_moves();
  io_error = runner.io_error();
  table_inch = interp.tool_named() && interp.units_set_at_tool() ? interp.inch_at_tool() : job_.inch;
  interp_ = nullptr;
  also_ = nullptr;
  if (!choice_) return;
  // The tools as the whole program's comments chose them (a comment after
  // its M6 binds only later).
  choice_->comments().finish();
  tools[0] = choice_->initial();
  max_radius_nm = tools[0].diameter_nm / 2;
  for (int k = 1; k < ntools; ++k) {
    (void)choice_->tool(numbers[k], &tools[k]);
    max_radius_nm = max_of(max_radius_nm, tools[k].diameter_nm / 2);
  }
}

void ProgramScan::line(const char* text, size_t n, uint32_t line_no) {
  WorkpieceBox b;
  const char* why = nullptr;
  const InterpState& s = interp_->state();
  bool blk = false;
  if (!workpiece_comment(text, n, s.inch, &b, &why)) {
    const bool workpiece_form = why != nullptr;
    if (!why) blk = blk_form_comment(text, n, s.inch, &blk_, &b, &why);
    if (why && !workpiece_bad) {
      workpiece_bad = why;
      workpiece_bad_line = line_no;
      workpiece_bad_form = workpiece_form ? "(WORKPIECE,...)" : "(BLK FORM ...)";
    }
    if (!blk) return;
  }
  // In the coordinate system where it stands (as LinuxCNC's preview draws it).
  const PointNm& o = s.work_offset[s.coord_system];
  const PointNm lo{b.lo.x_nm + o.x_nm + s.g92.x_nm, b.lo.y_nm + o.y_nm + s.g92.y_nm, b.lo.z_nm + o.z_nm + s.g92.z_nm};
  const PointNm hi{b.hi.x_nm + o.x_nm + s.g92.x_nm, b.hi.y_nm + o.y_nm + s.g92.y_nm, b.hi.z_nm + o.z_nm + s.g92.z_nm};
  if (!have_workpiece) {
    workpiece = StockBox{lo, hi};
    workpiece_kind = b.kind;
    workpiece_line = line_no;
    blk_form = blk;
    have_workpiece = true;
    return;
  }
  workpiece.lo = PointNm{min_of(workpiece.lo.x_nm, lo.x_nm), min_of(workpiece.lo.y_nm, lo.y_nm), min_of(workpiece.lo.z_nm, lo.z_nm)};
  workpiece.hi = PointNm{max_of(workpiece.hi.x_nm, hi.x_nm), max_of(workpiece.hi.y_nm, hi.y_nm), max_of(workpiece.hi.z_nm, hi.z_nm)};
}

void ProgramScan::emit(const CanonRecord& r) {
  summary.emit(r);  // first: a tool change's flush still finds the old tool in the spindle
  if ((r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc || r.kind == CanonKind::kTraverse) &&
      r.path_mode == 640 && r.path_tolerance_nm > 0)
    path_tolerance_max_nm = max_of(path_tolerance_max_nm, r.path_tolerance_nm);
  if (interp_ && (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc))
    (interp_->state().inch ? inch_moves : mm_moves) = true;
  if (choice_ && interp_) choice_->comments().record(r, interp_->state().inch, interp_->state().selected_tool);
  if (also_) also_->emit(r);
  const bool moves = r.kind == CanonKind::kArc || (r.kind == CanonKind::kFeed && !(r.start == r.end));
  if (moves && in_spindle_ >= 0 && !cuts[in_spindle_]) {
    cuts[in_spindle_] = true;
    if (in_spindle_ == 0) first_lines[0] = r.line;
  }
  if (moves && in_spindle_ >= 0) last_lines[in_spindle_] = r.line;
  if (r.kind != CanonKind::kToolChange) return;
  in_spindle_ = -1;
  Tool t;
  if (!lib_->tool(r.tool, &t)) {
    if (!bad_tool_line) {
      bad_tool_line = r.line;
      bad_tool = r.tool;
    }
    return;
  }
  max_radius_nm = max_of(max_radius_nm, t.diameter_nm / 2);
  for (int k = 1; k < ntools; ++k)
    if (numbers[k] == r.tool) {
      in_spindle_ = k;
      return;
    }
  if (ntools == kScanToolsMax) {
    ++unlisted;
    return;
  }
  tools[ntools] = t;
  numbers[ntools] = r.tool;
  first_lines[ntools] = r.line;
  in_spindle_ = ntools;
  ++ntools;
}

int64_t ProgramScan::smallest_diameter_nm() const {
  int64_t smallest = 0;
  for (int k = 0; k < ntools; ++k) smallest = smallest ? min_of(smallest, tools[k].diameter_nm) : tools[k].diameter_nm;
  return smallest;
}

}  // namespace dexmill
