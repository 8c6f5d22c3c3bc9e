// The first pass of `dexmill run`; see run_scan.h.
#include "tools/run/run_scan.h"

#include <cstdio>
#include <memory>

#include "core/tool/spec.h"
#include "tools/cli/cli.h"
#include "tools/run/run_path.h"
#include "tools/run/run_tools_report.h"

namespace dexmill {
namespace cli {
namespace {

// The backplot's pieces, as the scan reads them.
class PathSink final : public CanonSink {
 public:
  explicit PathSink(std::vector<PathSegment>* p) : path_(p) {}
  void emit(const CanonRecord& r) override { append_path(r, path_); }

 private:
  std::vector<PathSegment>* path_;
};

}  // namespace

void RunMessages::error_text(uint32_t line, uint32_t col, const std::string& msg) {
  ++errors_;
  if (print_) {
    fold_.flush();  // the warnings before it, before it
    std::fprintf(stderr, "%s:%u:%u: error: %s\n", file_.c_str(), line, col, msg.c_str());
  }
  error_list.push_back(ReportDiag{line, col, msg});
}

void RunMessages::warning_text(uint32_t line, uint32_t col, const std::string& msg) {
  ++warnings_;
  if (print_) fold_.add(file_, line, col, msg);
  (void)kept_.add(file_, line, col, msg);  // past the first 100 distinct, only counted
}

void RunMessages::error(const GcodeDiag& d) {
  ++errors_;
  char msg[400];
  gcode_format_message(d, msg, sizeof msg);
  if (print_) {
    fold_.flush();
    char line[700];
    gcode_format_diag(file_.c_str(), d, true, line, sizeof line);
    std::fprintf(stderr, "%s\n", line);
  }
  error_list.push_back(ReportDiag{d.line, d.col, msg});
}

std::vector<ReportDiag> RunMessages::warning_list() const {
  std::vector<ReportDiag> v;
  for (const FoldedWarning& w : kept_.entries()) v.push_back(ReportDiag{w.line, w.column, w.message, w.count, w.last_line});
  return v;
}

int scan_pass(const ScanInput& in, ProgramScan* scan, const GcodeNotes& notes, std::vector<PathSegment>* path,
              RunMessages* msgs, RunReport* rep) {
  ProgramScan& s = *scan;
  {
    GcodeFile file;
    if (!file.open(in.read_path.c_str(), in.shown_name.c_str())) return fail(kExitIo, "%s", file.error());
    file.set_subroutine_path(in.read->subroutine_path);
    file.set_guard(in.guard);
    const std::unique_ptr<ProgramMemory> mem(new ProgramMemory());
    PathSink sink(path);
    s.run(&file, msgs, mem.get(), path ? &sink : nullptr);
    if (s.io_error) return fail(file.refused() ? kExitUsage : kExitIo, "%s", file.error());
  }
  if (s.bad_tool_line) {
    char m[200];
    const char* table = in.table ? in.table->name().c_str() : "";
    if (in.table && in.table->has(s.bad_tool))
      std::snprintf(m, sizeof m, "tool T%d has diameter 0 in the tool table '%s': it cannot cut",
                    static_cast<int>(s.bad_tool), table);
    else
      std::snprintf(m, sizeof m, "tool T%d is not in the tool table '%s'", static_cast<int>(s.bad_tool), table);
    msgs->error_text(s.bad_tool_line, 1, m);
  }
  if (in.choice) report_tools(s, *in.choice, in.shown_name, msgs, rep);
  rep->lines = s.lines;
  if (s.inch_moves || s.mm_moves) rep->units = s.inch_moves ? (s.mm_moves ? "mixed" : "inch") : "mm";
  motion_to_report(s.summary, rep);
  tool_times_to_report(s, rep);
  rep->errors = msgs->error_list;
  msgs->finish();
  rep->warnings = msgs->warning_list();
  for (const GcodeNotes::Note& n : notes.kept)
    if (rep->messages.size() < 100) rep->messages.push_back(RunReport::Message{n.line, n.kind, n.text});
  rep->warnings_total = msgs->warnings();
  if (!in.choice)
    for (int k = 1; k < s.ntools; ++k) {
      char spec[kToolSpecTextMax];
      tool_spec_format(s.tools[k], spec, sizeof spec);
      rep->tools_used.push_back(ReportToolUse{s.numbers[k], spec, "", 0, "", s.tools[k].length_nm,
                                                s.first_lines[k], s.last_lines[k]});
    }
  return kExitOk;
}

void motion_to_report(const MotionSummary& sum, RunReport* rep) {
  rep->rapid = sum.count(CanonKind::kTraverse);
  rep->feed = sum.count(CanonKind::kFeed);
  rep->arc = sum.count(CanonKind::kArc);
  rep->dwell = sum.count(CanonKind::kDwell);
  rep->tool_change = sum.count(CanonKind::kToolChange);
  // The headline is the best estimate the pass made: blended where it had
  // an acceleration and the look-ahead, else the model's.
  rep->estimated_us = sum.blended_time_us();
  rep->feed_us = sum.blended_feed_us();
  rep->rapid_us = sum.blended_rapid_us();
  rep->dwell_us = sum.dwell_time_us();
  rep->no_accel_us = sum.no_accel_time_us();
  rep->stop_us = sum.stop_time_us();
  rep->blended_us = sum.blended_time_us();
  rep->blended = sum.blending();
  rep->have_bounds = sum.motion_box().valid;
  rep->bounds_lo = sum.motion_box().lo;
  rep->bounds_hi = sum.motion_box().hi;
}

void tool_times_to_report(const ProgramScan& s, RunReport* rep) {
  rep->time_by_tool.clear();
  rep->path_tolerance_nm = s.path_tolerance_max_nm;
  for (int k = 0; k < s.ntools; ++k) {
    const ScanToolTime& t = s.tool_time[k];
    if (k == 0 && t.moves == 0 && t.dwell_us == 0) continue;  // nothing before the first M6
    rep->time_by_tool.push_back(ReportToolTime{s.numbers[k], t.estimated_us, t.feed_us, t.rapid_us, t.moves});
  }
}

}  // namespace cli
}  // namespace dexmill
