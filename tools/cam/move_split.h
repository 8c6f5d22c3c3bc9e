// `dexmill optimize --target`'s pieces of a long move (core/engage/engage_split.h)
// written as G-code: the lines put before the move's own line, each a
// piece at its feed, the move's line the last piece. The pieces are
// written incremental (G91: a piece's X, Y, Z are the difference of two
// points of the move, no offset to undo), the points on the move exactly
// (core/engage/engage_split.h engage_split_snap) and their differences
// written exactly (6 decimals in mm, 8 in inch); then G90, and the move's
// line as written takes the tool to its end. The pieces cut what the move
// cut, dexel for dexel. Only a line that is a straight feed move and nothing else
// is split, in G90 with no rotation, no cutter compensation and no
// diameter mode (move_splittable); the others keep one feed.
#ifndef DEXMILL_TOOLS_CAM_MOVE_SPLIT_H
#define DEXMILL_TOOLS_CAM_MOVE_SPLIT_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/canon/canon.h"
#include "core/engage/engage_split.h"
#include "core/gcode/block.h"
#include "core/interp/interp.h"

namespace dexmill {
namespace cli {

// Whether the line (its block b, its text, the state before and after it,
// the records it made) may be written in pieces.
bool move_splittable(const GcodeBlock& b, const char* text, std::size_t len, const InterpState& before,
                     const InterpState& after, const std::vector<CanonRecord>& records);

struct MoveSplit {
  std::string text;                 // the lines before the move's, each ending in `eol`
  std::vector<CanonRecord> pieces;  // every piece as a record (the last: the move's line), for the time estimate
  int64_t last_inserted_nm_per_min = 0;  // the modal feed the move's line meets
  int64_t last_feed_nm_per_min = 0;      // the last piece's (the move's line's) feed
};

// The pieces of r (a straight feed move, horizontal length > 0) at the
// segments' ends and feeds (count >= 2), in inch or mm.
MoveSplit move_split(const CanonRecord& r, const EngageSegment* seg, int32_t count, bool inch, const char* eol);

}  // namespace cli
}  // namespace dexmill

#endif
