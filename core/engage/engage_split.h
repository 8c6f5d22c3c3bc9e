// Long moves split where their load changes (`dexmill optimize --target`):
// a straight feed move whose samples (engage_meter.h EngageMeter::trace)
// want different feeds along it (it breaks into a pocket, enters a corner,
// leaves the stock) becomes pieces, each at the lowest feed its samples
// and their neighbours want, so that the load between two samples is
// covered by the slower side: where the load rises, the slow piece
// starts at the last light sample; where it falls, it ends at the first
// light one. Pieces shorter than the rule's minimum are merged with a
// neighbour (at the lower feed), then the closest pair until at most
// max_segments are left; a move that would gain less than kEngageSplitGain
// of its time stays whole. Integer only, caller memory: the panel's too.
#ifndef DEXMILL_CORE_ENGAGE_ENGAGE_SPLIT_H
#define DEXMILL_CORE_ENGAGE_ENGAGE_SPLIT_H

#include <stddef.h>
#include <stdint.h>

#include "core/engage/engage_target.h"
#include "core/point.h"

namespace dexmill {

constexpr int32_t kEngageMaxSegments = 8;
// A feed change between neighbours that starts a new piece (15 %), and the
// time a split must save (5 % of the move's at its single feed).
constexpr int64_t kEngageSplitChangePpm = 150000;
constexpr int64_t kEngageSplitGainPpm = 50000;

struct EngageSplitRule {
  int64_t min_segment_nm = 0;  // no piece shorter (horizontal length)
  int32_t max_segments = 0;    // at most this many pieces a move (0: no splitting; at most kEngageMaxSegments)
};

struct EngageSegment {
  int64_t end_nm = 0;           // where the piece ends: horizontal distance from the move's start
  int64_t feed_nm_per_min = 0;  // its feed
  PointNm end_at{0, 0, 0};      // and the point it ends at, on the move exactly (engage_split_snap)
};

// The pieces of a move of horizontal length length_nm from n samples
// (positions s_nm ascending within it, each with its feed), into out
// (kEngageMaxSegments); the count, 1 when the move stays whole (out[0]
// then holds the lowest feed over the move).
int32_t engage_split(const int64_t* s_nm, const int64_t* feed_nm_per_min, int32_t n, int64_t length_nm,
                     const EngageSplitRule& rule, EngageSegment* out);

// The pieces' ends moved onto the move's nm lattice, the points start +
// j (end - start) / g, g the greatest common divisor of the move's three
// differences in nm: points on the line exactly, so that the pieces cut
// what the move cut, dexel for dexel. Each end moves towards the faster
// piece (the slower one grows: the load stays covered); pieces left empty
// merge at the lower feed. Returns the count (1: no point of the lattice
// falls between, the move stays whole).
int32_t engage_split_snap(const PointNm& start, const PointNm& end, EngageSegment* seg, int32_t count);

// The feed the target wants at one sample of move m (as engage_target_feed
// for the move, with that sample's engagement: its chip, cross-section
// and load on the move's material); a sample it cannot read (engaged at
// one end of the arc only: no chip) takes the move's own feed,
// move_feed_nm_per_min.
int64_t engage_sample_feed(const EngageTarget& target, const EngageTool& tool, const EngageMove& m,
                           const EngageAt& at, const CuttingCoefficients& c, int64_t max_chip_nm,
                           int64_t material_max_feed_nm_per_min, int64_t move_feed_nm_per_min);

// The program's pieces, for the lines of moves split (caller memory):
// each split move's pieces in order, the last marked. At most cap pieces
// in all (the bound on the lines a rewrite adds); a move whose pieces no
// longer fit stays whole and is counted.
struct EngageSplitPiece {
  uint32_t line = 0;
  bool last = false;  // the move's last piece
  EngageSegment segment;
};
struct EngageSplits {
  EngageSplitPiece* pieces = nullptr;
  size_t cap = 0, n = 0;
  uint64_t moves = 0;     // moves split
  uint64_t left = 0;      // moves left whole for want of room
};
// Adds a move's pieces (count > 1); false when they did not fit.
bool engage_splits_add(EngageSplits* s, uint32_t line, const EngageSegment* seg, int32_t count);

}  // namespace dexmill

#endif
