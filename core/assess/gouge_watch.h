// Gouges traced to the program line that made them (paper §2.5 goes as far
// as the finished part; a preview wants the line): after each record of the
// cut, the columns it changed are compared with the design, and every column
// that goes below its design top by more than its tolerance for the first
// time is charged to that record's line. One event per line (records of
// one line in a row share it): its deepest column, the depth, where that
// line left the tool, and how many columns it gouged. Bounded: the first
// kGougeEventsMax events are kept, the rest counted, never silently dropped.
//
// Attribution: the Mill cuts a straight move's end cap (the tool standing
// at its end) with the next record, for the chain of moves to share it.
// The caller says where the previous line left the tool and with which
// profile: a column first gouged during a record whose new height is what
// the tool standing there cuts (within 1 LSB) is charged to the previous
// line, the one that brought the tool there; the rest to the record's own.
#ifndef DEXMILL_CORE_ASSESS_GOUGE_WATCH_H
#define DEXMILL_CORE_ASSESS_GOUGE_WATCH_H

#include <stddef.h>
#include <stdint.h>

#include "core/assess/assess.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace dexmill {

constexpr size_t kGougeEventsMax = 64;

struct GougeEvent {
  uint32_t line = 0;          // the record's program line
  int32_t i = -1, j = -1;     // the deepest column it gouged (first of equals)
  int64_t depth_lsb = 0;      // design top - cut top there, LSB
  int64_t design_lsb = 0;     // the design top there
  PointNm tool{0, 0, 0};      // the tool tip at the record's end
  uint64_t columns = 0;       // columns this line gouged first
};

struct GougeWatch {
  const DesignGrid* design = nullptr;
  AssessOptions opt;
  uint8_t* seen = nullptr;    // caller memory, (nx*ny + 7) / 8 bytes: columns already reported
  GougeEvent events[kGougeEventsMax];
  size_t nevents = 0;         // kept
  uint64_t total = 0;         // events in all (kept + not kept)
};

// Where the line before left the tool: its end and its profile.
struct GougeOrigin {
  uint32_t line;
  PointNm end;
  const ToolProfile* tool;
};

// Bytes of `seen` for a grid.
inline size_t gouge_watch_seen_bytes(int32_t nx, int32_t ny) {
  return (static_cast<size_t>(nx) * static_cast<size_t>(ny) + 7) / 8;
}

// Starts a watch: seen is cleared (`seen_bytes` must be at least
// gouge_watch_seen_bytes), events emptied. kBufferTooSmall otherwise.
Status gouge_watch_init(GougeWatch* w, const DesignGrid* d, const AssessOptions& o, uint8_t* seen, size_t seen_bytes);

// Checks the columns of `changed` (clipped to the grid and to o.region)
// after the record of `line` with the tool at `tool`; `prev` (or null) as
// above. True when this call found a new gouge (its events are the last
// ones, or counted in total when the list is full).
template <class H>
bool gouge_watch_check(GougeWatch* w, const DexelGrid<H>& g, GridRect changed, uint32_t line, const PointNm& tool,
                       const GougeOrigin* prev);

#define DEXMILL_GOUGE_EXTERN(H) \
  extern template bool gouge_watch_check<H>(GougeWatch*, const DexelGrid<H>&, GridRect, uint32_t, const PointNm&, const GougeOrigin*);
DEXMILL_GOUGE_EXTERN(uint8_t)
DEXMILL_GOUGE_EXTERN(uint16_t)
DEXMILL_GOUGE_EXTERN(uint32_t)
#undef DEXMILL_GOUGE_EXTERN

}  // namespace dexmill

#endif
