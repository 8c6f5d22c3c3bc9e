// What a checked block will do when committed (Plan), and what cutter
// compensation does in it (CompOps). A part of the block runner
// (block_runner.h), for the interpreter's own files only.
#ifndef DEXMILL_CORE_INTERP_BLOCK_PLAN_H
#define DEXMILL_CORE_INTERP_BLOCK_PLAN_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/interp/cutter_comp.h"
#include "core/interp/cycles.h"
#include "core/interp/interp.h"
#include "core/interp/modal_context.h"
#include "core/interp/spline.h"
#include "core/math/decimal.h"
#include "core/point.h"

namespace dexmill {

// What cutter compensation does in a block (core/interp/interp_comp.cpp):
// done on a scratch queue while the block is checked, again when it commits.
// Only the two flags are set in a block that does not compensate.
struct CompOps {
  bool off_flush;  // G40 ended compensation: the held moves end where the tool is, and go
  bool motion;     // the block's move is compensated: the steps below replace it
  // 1. The held records go (kDequeue), after their moves end at flush_to (kMoveEnd).
  enum Flush : uint8_t { kKeep, kDequeue, kMoveEnd } flush;
  Vec2 flush_to;
  // 2. A move round the corner, made at once.
  bool corner;
  CanonKind corner_kind;
  PointNm corner_end, corner_centre;
  int32_t corner_turns;
  // 3. Where the held move starts (LinuxCNC's set_endpoint), if set.
  bool set_endpoint;
  Vec2 endpoint;
  // 4. The compensated move, held.
  CanonKind kind;
  PointNm end;
  CanonArc arc;
  int64_t dir_a, dir_b, sweep_bam;
  PointNm prog_start;  // the programmed move starts here (G93 feeds come from it)
};

// What a checked block will do when committed.
struct Plan {
  bool tool_change = false;
  bool spindle = false;
  bool coolant = false;
  bool dwell = false;
  int64_t dwell_ms = 0;
  enum Motion : uint8_t { kNone, kStraight, kArc, kCycle, kHome, kSpline, kTap, kNurbs } motion = kNone;
  CanonKind straight_kind = CanonKind::kTraverse;
  PointNm target{0, 0, 0};
  CanonArc arc{Plane::kXY, {0, 0, 0}, 1};
  bool inverse_time = false;
  Decimal inverse_f{0, 0};
  int64_t sync_feed_nm_per_min = 0;  // G33/G33.1: K times S (0: the modal feed)
  // G5.2: a control point to add (nurbs_add: 1 go on, 2 start anew from the
  // position); set whole when nurbs_add says so.
  uint8_t nurbs_add = 0;
  int32_t nurbs_order;
  bool nurbs_has_point;
  int64_t nurbs_first_weight, nurbs_x, nurbs_y, nurbs_weight;
  bool rest_skipped = false;  // M72 ran the saved modes in place of the rest of the line
  int16_t context_op = -1;  // M70 M71 M73 (tenths): what commit does to the level's context
  ModalContext context;     // M70/M73: the state saved (set whole when context_op says so)
  PointNm home_via{0, 0, 0};
  CyclePlan cycle{};
  SplinePlan spline;  // set whole by run_spline before anything reads it
  int16_t stop = -1;  // M0/M1/M2/M30/M60 in tenths
  CompOps comp;       // cutter compensation (off_flush and motion false unless it acts)
  Plan() {
    comp.off_flush = false;
    comp.motion = false;
  }
};

}  // namespace dexmill

#endif
