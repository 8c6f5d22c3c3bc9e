// The cutting stage: canonical records to stamp or sweep calls.
#include "core/cut/mill.h"

#include "core/cut/arc_walk.h"
#include "core/cut/stamp.h"

namespace dexmill {

template <class H>
Mill<H>::Mill(DexelGrid<H>* grid, CutMode mode, const ToolLibrary* tools, int32_t* words, size_t nwords)
    : grid_(grid), mode_(mode), tools_(tools), words_(words), nwords_(nwords) {}

template <class H>
Status Mill<H>::set_tool(const Tool& t) {
  Status s = tool_check(t);
  if (!ok(s)) return s;
  flush();  // the pending cap belongs to the tool in the spindle
  const ToolProfile p = tool_profile(t);
  if (mode_ == CutMode::kStamp) {
    s = cutter_build(p, grid_->pitch_nm, grid_->lsb_nm, words_, nwords_, &cutter_);
  } else {
    s = sweep_tool_prepare(p, grid_->lsb_nm, &sweep_);
  }
  if (!ok(s)) return s;
  tool_ = t;
  have_tool_ = true;
  chained_ = false;  // a joint cut by another tool does not cover this one
  chain_ = SweepChain{};
  return Status::kOk;
}

template <class H>
void Mill<H>::flush() {
  if (have_tool_ && mode_ == CutMode::kSweep) sweep_chain_end(grid_, sweep_, &stats_, &chain_);
}

template <class H>
void Mill<H>::cut_line(PointNm a, PointNm b) {
  // A move that continues from the last one's end need not redo the tool
  // standing at that joint (stamp: the instance; sweep: the start cap).
  const bool first = !(chained_ && a == last_);
  if (have_tool_) {
    if (mode_ == CutMode::kStamp) stamp_line(grid_, cutter_, a, b, &stats_, first);
    else sweep_chain_line(grid_, sweep_, a, b, &stats_, &chain_);
  }
  last_ = b;
  chained_ = true;
}

template <class H>
void Mill<H>::emit(const CanonRecord& r) {
  switch (r.kind) {
    case CanonKind::kTraverse:
    case CanonKind::kFeed:
      cut_line(r.start, r.end);
      break;
    case CanonKind::kArc: {
      if (mode_ == CutMode::kSweep) {
        if (have_tool_) sweep_chain_arc(grid_, sweep_, r, &stats_, &chain_);
        last_ = r.end;
        chained_ = true;
        break;
      }
      // Chords near the grid only; the tool tip still ends at r.end.
      const int64_t margin = tool_.diameter_nm + grid_->pitch_nm;
      const RectNm reach{grid_->x0_nm - margin, grid_->y0_nm - margin,
                         grid_->x0_nm + (grid_->nx - 1) * grid_->pitch_nm + margin,
                         grid_->y0_nm + (grid_->ny - 1) * grid_->pitch_nm + margin};
      arc_walk(r, kArcChordSagittaNm, reach, [this](PointNm a, PointNm b) { cut_line(a, b); });
      last_ = r.end;
      break;
    }
    case CanonKind::kToolChange: {
      Tool t;
      if (!tools_ || !tools_->tool(r.tool, &t)) {
        if (ok(status_)) { status_ = Status::kBadArgument; failed_tool_ = r.tool; }
        break;
      }
      const Status s = set_tool(t);
      if (!ok(s) && ok(status_)) { status_ = s; failed_tool_ = r.tool; }
      break;
    }
    case CanonKind::kEnd:
      flush();
      break;
    default:
      break;
  }
}

template class Mill<uint8_t>;
template class Mill<uint16_t>;
template class Mill<uint32_t>;

}  // namespace dexmill
