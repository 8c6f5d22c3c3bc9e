// The cutting stage: canonical records to stamp or sweep calls.
//
// Ranges: a tool's diameter <= 1 m and a grid's pitch <= 1 m, origins within
// 1 km and 65535 dexels a side (core/tool/tool.h, core/grid/grid.h): the
// stamp's chord margin D + pitch <= 2^31 nm, the grid's reach rectangle
// within 2^46.1 nm; mill_words' sides <= 65535 and their product times 8
// bytes < 2^35.
#include "core/cut/mill.h"

#include <string.h>

#include "core/cut/arc_walk.h"
#include "core/cut/stamp.h"
#include "core/cut/sweep_cut.h"
#include "core/math/fixed.h"
#include "core/tool/cutter.h"

namespace dexmill {

template <class H>
Mill<H>::Mill(DexelGrid<H>* grid, CutMode mode, const ToolLibrary* tools, int32_t* words, size_t nwords)
    : grid_(grid), mode_(mode), tools_(tools), words_(words), nwords_(nwords) {}

template <class H>
Status Mill<H>::set_tool(const Tool& t) {
  Status s = tool_check(t);
  if (!ok(s)) return s;
  finish();  // the pending cap belongs to the tool in the spindle
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
void Mill<H>::end_chain() {
  if (have_tool_ && mode_ == CutMode::kSweep) sweep_chain_end(grid_, sweep_, &stats_, &chain_);
}

template <class H>
void Mill<H>::finish() {
  unshow();
  end_chain();
}

template <class H>
void Mill<H>::flush() {
  if (!have_tool_ || mode_ != CutMode::kSweep || shown_ || chain_.state != SweepChain::State::kPending) return;
  // The dexels the tool standing at the joint may change: sweep_piece's
  // columns for that point.
  SweepColumns c;
  GridRect box = GridRect::none();
  if (sweep_columns(*grid_, sweep_, chain_.end.x_nm, chain_.end.x_nm, chain_.end.y_nm, chain_.end.y_nm, &c))
    box = GridRect{static_cast<int32_t>(c.i_first), static_cast<int32_t>(c.j_first), static_cast<int32_t>(c.i_last + 1),
                   static_cast<int32_t>(c.j_last + 1)};
  const size_t row = box.empty() ? 0 : static_cast<size_t>(box.i1 - box.i0) * sizeof(H);
  const size_t rows = box.empty() ? 0 : static_cast<size_t>(box.j1 - box.j0);
  if (rows && (!words_ || 2 * row * rows > nwords_ * sizeof(int32_t))) {
    end_chain();  // no room to put the dexels back: for good
    return;
  }
  unsigned char* save = reinterpret_cast<unsigned char*>(words_);
  for (int32_t j = box.j0; j < box.j1; ++j) {
    const size_t k = grid_->index(box.i0, j);
    memcpy(save, grid_->top + k, row);
    memcpy(save + row, grid_->bottom + k, row);
    save += 2 * row;
  }
  shown_box_ = box;
  shown_stats_ = stats_;
  shown_bottoms_zero_ = grid_->bottoms_zero;
  sweep_chain_end(grid_, sweep_, &stats_, &chain_);
  // Still pending: the next move cuts its wedge of the cap over the dexels
  // put back, as without this flush.
  chain_.state = SweepChain::State::kPending;
  shown_ = true;
}

template <class H>
void Mill<H>::unshow() {
  if (!shown_) return;
  shown_ = false;
  const GridRect box = shown_box_;
  const size_t row = box.empty() ? 0 : static_cast<size_t>(box.i1 - box.i0) * sizeof(H);
  const unsigned char* save = reinterpret_cast<const unsigned char*>(words_);
  for (int32_t j = box.j0; j < box.j1 && row; ++j) {
    const size_t k = grid_->index(box.i0, j);
    memcpy(grid_->top + k, save, row);
    memcpy(grid_->bottom + k, save + row, row);
    save += 2 * row;
  }
  stats_ = shown_stats_;
  grid_->bottoms_zero = shown_bottoms_zero_;
  grid_->dirty.include(box);  // changed back: readers of the changes redraw it
}

template <class H>
void Mill<H>::cut_line(PointNm a, PointNm b) {
  // A move that continues from the last one's end need not redo the tool
  // standing at that joint (stamp: the instance; sweep: the start cap).
  const bool first = !(chained_ && a == last_);
  // A vertical move from the last one's end that stays within the span the
  // tool has swept at this X and Y (a peck cycle's retracts and its rapids
  // back down, a repeated point: a move of no length) cuts nothing new: a
  // cutter's radius never shrinks upwards, so the tool standing anywhere in
  // that span lies inside what the moves there swept, and each dexel's cut
  // is a min over them (core/cut/sweep.h). It costs nothing and leaves the
  // grid as cutting it would (tests/test_flush_cadence.cpp).
  const bool vertical = a.x_nm == b.x_nm && a.y_nm == b.y_nm;
  const int64_t lo = min_of(a.z_nm, b.z_nm), hi = max_of(a.z_nm, b.z_nm);
  if (!first && vertical && skip_covered_ && lo >= covered_z_lo_nm_ && hi <= covered_z_hi_nm_) {
    last_ = b;
    return;
  }
  if (have_tool_) {
    if (mode_ == CutMode::kStamp) stamp_line(grid_, cutter_, a, b, &stats_, first);
    else sweep_chain_line(grid_, sweep_, a, b, &stats_, &chain_);
  }
  if (!first && vertical) {
    covered_z_lo_nm_ = min_of(covered_z_lo_nm_, lo);
    covered_z_hi_nm_ = max_of(covered_z_hi_nm_, hi);
  } else {
    covered_z_lo_nm_ = vertical ? lo : b.z_nm;
    covered_z_hi_nm_ = vertical ? hi : b.z_nm;
  }
  last_ = b;
  chained_ = true;
}

template <class H>
void Mill<H>::emit(const CanonRecord& r) {
  // A record that cuts or ends the chain starts from the grid as it was
  // before any flush (what flush shows does not change the cut).
  if (r.kind == CanonKind::kTraverse || r.kind == CanonKind::kFeed || r.kind == CanonKind::kArc ||
      r.kind == CanonKind::kToolChange || r.kind == CanonKind::kEnd)
    unshow();
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
        covered_z_lo_nm_ = covered_z_hi_nm_ = r.end.z_nm;
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
      end_chain();
      break;
    default:
      break;
  }
}

template <class H>
size_t mill_words(CutMode mode, const ToolProfile& p, const DexelGrid<H>& g) {
  if (g.pitch_nm <= 0) return 0;  // not a grid (grid_init refuses it)
  if (mode == CutMode::kStamp) return cutter_storage_words(min_of(cutter_reach_dex(p, g.pitch_nm), kCutterMaxReach));
  // The columns sweep_columns finds for one point: axes within R + 1 nm of
  // it, at most floor(2 (R + 1) / pitch) + 1 a side, and no more than the
  // grid's; a top and a bottom each.
  const uint64_t side = static_cast<uint64_t>(2 * (p.radius_nm + 1) / g.pitch_nm + 1);
  const uint64_t w = min_of<uint64_t>(side, static_cast<uint64_t>(g.nx));
  const uint64_t h = min_of<uint64_t>(side, static_cast<uint64_t>(g.ny));
  return static_cast<size_t>((w * h * 2 * sizeof(H) + sizeof(int32_t) - 1) / sizeof(int32_t));
}

template size_t mill_words<uint8_t>(CutMode, const ToolProfile&, const DexelGrid<uint8_t>&);
template size_t mill_words<uint16_t>(CutMode, const ToolProfile&, const DexelGrid<uint16_t>&);
template size_t mill_words<uint32_t>(CutMode, const ToolProfile&, const DexelGrid<uint32_t>&);

template class Mill<uint8_t>;
template class Mill<uint16_t>;
template class Mill<uint32_t>;

}  // namespace dexmill
