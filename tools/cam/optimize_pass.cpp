#include "tools/cam/optimize_pass.h"

#include <cstdio>
#include <memory>

#include "core/safety/material_limits.h"
#include "core/gcode/block.h"
#include "core/math/fixed.h"
#include "core/interp/interp.h"
#include "platform/input/gcode_file.h"
#include "tools/cli/cli.h"
#include "tools/cam/feed_rewrite.h"
#include "tools/cam/feed_word.h"
#include "tools/cam/move_split.h"

namespace dexmill {
namespace cli {
namespace {

// The records of the line being interpreted.
class LineRecords final : public CanonSink {
 public:
  void emit(const CanonRecord& r) override { records.push_back(r); }
  std::vector<CanonRecord> records;
};

bool is_feed(const CanonRecord& r) { return r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc; }

std::string mm_per_min(int64_t nm_per_min) { return feed_number(nm_per_min, false, 0).text; }

// Where e's F goes in the line; an F written with a parameter or an
// expression has no number to change: the line stays as written (said, and
// counted when it was to be lowered), *e and the rewriter's modal feed
// are the program's.
FeedSplice placed_splice(const OptimizeInput& in, uint32_t line, const char* text, std::size_t len, const FeedLine& fl,
                         FeedEdit* e, FeedRewriter* rewriter, OptimizeResult* out) {
  if (e->kind == FeedEdit::Kind::kNone) return FeedSplice();
  const FeedSplice s = feed_splice(text, len, *e);
  if (!s.text.empty()) return s;
  std::fprintf(stderr, "%s:%u:1: warning: F here is not a number this rewrite can change: left as written (%s mm/min "
               "where %s mm/min was wanted%s)\n", in.shown_name.c_str(), line, mm_per_min(fl.programmed_nm_per_min).c_str(),
               mm_per_min(e->feed_nm_per_min).c_str(), e->lowered ? ", a limit" : "");
  if (e->lowered) ++out->left_over;
  *e = FeedEdit();
  e->feed_nm_per_min = fl.programmed_nm_per_min;
  rewriter->modal_changed(fl.feed_after_nm_per_min);
  return s;
}

// Each split line's pieces: where they begin in the splits, and how many.
using SplitIndex = std::map<uint32_t, std::pair<std::size_t, int32_t>>;
SplitIndex split_index(const std::vector<EngageSplitPiece>* splits) {
  SplitIndex at;
  for (std::size_t k = 0, first = 0; splits && k < splits->size(); ++k)
    if ((*splits)[k].last) {
      at[(*splits)[k].line] = {first, static_cast<int32_t>(k + 1 - first)};
      first = k + 1;
    }
  return at;
}

// The pieces of the line's move r (in.splits[first, first + count)), put
// before the line, which starts at byte line_at.
MoveSplit split_line(const OptimizeInput& in, std::pair<std::size_t, int32_t> pieces, const CanonRecord& r, bool inch,
                     uint32_t line, uint64_t line_at, OptimizeResult* out) {
  std::vector<EngageSegment> seg;
  for (int32_t k = 0; k < pieces.second; ++k) seg.push_back((*in.splits)[pieces.first + static_cast<std::size_t>(k)].segment);
  MoveSplit split = move_split(r, seg.data(), static_cast<int32_t>(seg.size()), inch, in.crlf ? "\r\n" : "\n");
  out->splices.push_back(ProgramSplice{line_at, 0, split.text});
  ++out->moves_split;
  out->split_moves.emplace_back(line, r);
  out->lines_added += static_cast<uint32_t>(seg.size());
  return split;
}

// The program's time before or after the rewrite; with --accel blended
// (core/canon/motion_plan.h), each copy with its own look-ahead.
struct PlannedSummary {
  explicit PlannedSummary(const MotionTimeModel& model) : summary(model), planner(new MotionPlanner()) {
    summary.set_planner(planner.get());
  }
  int64_t finish_us() {
    summary.finish();
    return summary.blended_time_us();
  }
  MotionSummary summary;
  std::unique_ptr<MotionPlanner> planner;
};

}  // namespace

int optimize_pass(const OptimizeInput& in, OptimizeResult* out) {
  GcodeFile file;
  if (!file.open(in.read_path.c_str())) return fail(kExitIo, "%s", file.error());
  const std::unique_ptr<GcodeMemory> memory = gcode_memory();
  InterpOptions opt;
  opt.inch = in.inch;
  opt.feed_in_line_units = in.feed_in_line_units;
  opt.default_feed_nm_per_min = in.default_feed_nm_per_min;
  opt.tools = in.tools;  // warnings were printed by the cut's reading
  memory->attach(&opt);
  LineRecords sink;
  Interp interp(&sink, opt);
  PlannedSummary before(in.time_model), after(in.time_model);
  FeedRewriter rewriter;
  const SplitIndex split_at = split_index(in.splits);
  const char* text = nullptr;
  std::size_t len = 0;
  uint32_t line = 0;
  for (;;) {
    const GcodeFile::Read rd = file.next(&text, &len, &line);
    if (rd == GcodeFile::Read::kEof) break;
    if (rd == GcodeFile::Read::kIoError) return fail(kExitIo, "%s", file.error());
    GcodeDiag diag{};
    sink.records.clear();
    const InterpState state_before = interp.state();
    const GcodeError ge =
        rd == GcodeFile::Read::kLine ? interp.execute_line(text, len, line, &diag) : GcodeError::kLineTooLong;
    // A line a loop runs twice would want two feeds: the rewrite is per line.
    if (ge == GcodeError::kOwordNoSource)
      return fail(kExitInput, "%s:%u: dexmill optimize rewrites programs without o-word loops and calls only",
                  in.shown_name.c_str(), line);
    if (ge != GcodeError::kOk)
      return fail(kExitInput, "%s:%u: the program no longer reads as it did when it was cut", in.shown_name.c_str(), line);
    FeedLine fl;
    int64_t hi = 0;  // G94: the moves of a line share its F; G93: a line makes one move
    for (const CanonRecord& r : sink.records)
      if (is_feed(r)) {
        fl.feeds = true;
        hi = max_of(hi, r.feed_nm_per_min);
      }
    const InterpState& st = interp.state();
    // A feed tied to the spindle (G95's F, G33/G33.1's K) is no F per
    // minute this pass could rewrite: left as written, said when too fast.
    if (fl.feeds && (st.per_rev || st.motion == 330 || st.motion == 331)) {
      fl.feeds = false;
      if (line < in.limits->size() && (*in.limits)[line] < hi) {
        std::fprintf(stderr, "%s:%u:1: warning: feed per spindle revolution (G95, G33, G33.1) left as written: %s mm/min "
                     "where a material's limit is %s mm/min\n", in.shown_name.c_str(), line, mm_per_min(hi).c_str(),
                     mm_per_min((*in.limits)[line]).c_str());
        ++out->left_over;
      }
    }
    // A block's feed mode and units are those its own moves and F word use.
    fl.inverse_time = st.inverse_time;
    fl.programmed_nm_per_min = hi;
    fl.limit_nm_per_min = line < in.limits->size() ? (*in.limits)[line] : kNoFeedLimit;
    if (in.targets && line < in.targets->size() && (*in.targets)[line] != INT64_MAX) {
      fl.retarget = true;
      fl.limit_nm_per_min = min_of(fl.limit_nm_per_min, (*in.targets)[line]);
    }
    fl.feed_after_nm_per_min = st.feed_nm_per_min;
    // An F word on a line that changes the units is read in the units
    // before it (core/interp/interp_modes.cpp), a G95 or grbl's in the line's.
    fl.inch = st.per_rev || in.feed_in_line_units ? st.inch : state_before.inch;
    GcodeBlock b;
    GcodeLineKind kind;
    const bool block = gcode_read_block(text, len, line, &b, &kind, &diag) == GcodeError::kOk && kind == GcodeLineKind::kBlock;
    if (block) {
      fl.has_f = b.has_word('F');
      if (fl.has_f) fl.inverse_f = b.val('F');
      fl.sets_feed = fl.has_f || b.g[kGFeedMode] >= 0;
      fl.block_delete = b.block_delete;
    }
    // A long move with pieces: the lines before it, the line itself the last piece.
    MoveSplit split;
    const auto sp = split_at.find(line);
    if (sp != split_at.end() && fl.feeds && fl.retarget) {
      if (block && move_splittable(b, text, len, state_before, st, sink.records)) {
        split = split_line(in, sp->second, sink.records[0], st.inch, line, file.line_offset(), out);
        rewriter.modal_changed(split.last_inserted_nm_per_min);
        fl.limit_nm_per_min = split.last_feed_nm_per_min;
      } else {
        ++out->splits_kept_whole;
      }
    }
    FeedEdit e = rewriter.line(fl);
    const FeedSplice s = placed_splice(in, line, text, len, fl, &e, &rewriter, out);
    if (fl.feeds && fl.inverse_time && fl.limit_nm_per_min < hi && e.kind == FeedEdit::Kind::kNone) {
      std::fprintf(stderr, "%s:%u:1: warning: inverse-time feed (G93) left as written: %s mm/min where a material's limit is %s mm/min, "
                   "and F would be below 0.000001\n", in.shown_name.c_str(), line, mm_per_min(hi).c_str(),
                   mm_per_min(fl.limit_nm_per_min).c_str());
      ++out->left_over;
    }
    for (CanonRecord r : sink.records) {
      before.summary.emit(r);
      if (is_feed(r)) r.feed_nm_per_min = e.feed_nm_per_min;
      if (split.pieces.empty()) after.summary.emit(r);
    }
    for (std::size_t k = 0; k < split.pieces.size(); ++k) {  // the pieces, the last at the line's own feed
      CanonRecord r = split.pieces[k];
      if (k + 1 == split.pieces.size()) r.feed_nm_per_min = e.feed_nm_per_min;
      after.summary.emit(r);
    }
    if (e.kind == FeedEdit::Kind::kNone) continue;
    out->splices.push_back(ProgramSplice{file.line_offset() + s.at, s.erase, s.text});
    ++out->lines_changed;
    if (e.raised) {
      ++out->lines_raised;
    } else if (e.lowered) {
      ++out->lines_lowered;
      if (!fl.retarget) ++out->lowered_to[fl.limit_nm_per_min];
    } else {
      ++out->lines_restored;
    }
  }
  out->before_us = before.finish_us();
  out->after_us = after.finish_us();
  return kExitOk;
}

std::string apply_splices(const std::string& program, const std::vector<ProgramSplice>& splices) {
  std::string o;
  o.reserve(program.size() + 16 * splices.size());
  uint64_t from = 0;
  for (const ProgramSplice& s : splices) {
    o.append(program, from, s.at - from);
    o += s.text;
    from = s.at + s.erase;
  }
  o.append(program, from, std::string::npos);
  return o;
}

}  // namespace cli
}  // namespace dexmill
