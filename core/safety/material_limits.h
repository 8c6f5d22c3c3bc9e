// The process rules of an inhomogeneous stock (paper §2.6): for
// every record, the materials the cut actually removed (each lowered dexel
// column's lost z range through the composition, core/material/column.h)
// against the limits each material brings:
// - a feed move (G1, arcs) faster than a removed material's max feed;
// - a spindle speed (S, with M3/M4 on) outside a removed material's range;
// - coolant (M7/M8) on while removing a material that forbids it (the
//   paper's wood, which soaks it up).
// A finding is one (line, rule, material): a line that breaks a rule on a
// material is one finding however many records, loop passes or columns
// show it (a column's removal charged to the line before and the
// next one alternately counted it again and again, 21 M "violations" for a
// 41 799-line program). The first kProcessViolationsMax are kept, each
// once; total and each material's tally count every finding once. Which
// findings were counted is kept per line in caller memory (3 bytes a line:
// process_watch_track_findings) for the program's lines; a line past them
// (a subroutine file longer than the program, a job that gave no count)
// is told apart from the last kProcessRecentMax findings only, so a line
// met again after that many others counts again. Lines are the records'
// (core/canon/canon.h): a subroutine file's line 12 is the program's 12.
// Per material the watch also tallies the volume removed (sum of lengths,
// nm x columns: x pitch^2 is the volume) and the cutting time of the
// records that removed it.
//
// Removals are compared against a shadow of the tops (caller memory), as the
// safety watch does (core/safety/safety.h); a deferred end cap cut by the
// next record is charged to the move that brought the tool there
// (profile_explains_cut).
#ifndef DEXMILL_CORE_SAFETY_MATERIAL_LIMITS_H
#define DEXMILL_CORE_SAFETY_MATERIAL_LIMITS_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/material/material.h"
#include "core/canon/canon.h"
#include "core/point.h"
#include "core/status.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class ProcessRule : uint8_t { kFeed = 0, kSpindle = 1, kCoolant = 2 };
constexpr int kProcessRules = 3;
constexpr size_t kProcessViolationsMax = 64;
constexpr size_t kProcessRecentMax = 32;

// "feed", "spindle", "coolant".
const char* process_rule_name(ProcessRule r);

struct ProcessViolation {
  ProcessRule rule = ProcessRule::kFeed;
  uint32_t line = 0;
  uint8_t material = 0;
  int64_t value = 0;  // feed: nm/min; spindle: rpm; coolant: the M7/M8 bits
  PointNm at{0, 0, 0};  // a column it removed there
};

// The state a record ran in, as the caller (the cut pass) knows it.
struct ProcessState {
  uint32_t line = 0;
  bool feed_move = false;         // G1 or an arc (rapids are the safety checks' business)
  int64_t feed_nm_per_min = 0;
  int32_t spindle_rpm = 0;
  bool spindle_on = false;        // M3/M4
  uint8_t coolant = 0;            // bit 0 mist (M7), bit 1 flood (M8)
  int64_t time_us = 0;            // the record's time
};

struct MaterialTally {
  uint64_t removed_nm_columns = 0;  // sum over columns of the length removed, nm
  int64_t cut_time_us = 0;
  uint64_t violations = 0;          // findings (line, rule, this material)
};

struct ProcessWatch {
  const StockComposition* comp = nullptr;
  uint32_t* shadow = nullptr;  // caller memory, nx * ny: the tops before the record
  ProcessViolation kept[kProcessViolationsMax];
  size_t nkept = 0;
  uint64_t total = 0;  // findings, each (line, rule, material) once
  // The findings counted (process_watch_track_findings): for line l < seen_lines,
  // byte 3 l + rule, bit m for material m. Past them, the last few.
  uint8_t* seen = nullptr;
  size_t seen_lines = 0;
  uint64_t recent[kProcessRecentMax] = {};  // (line, rule, material) + 1; 0: none
  size_t recent_next = 0;
  MaterialTally tally[kCompositionMaxMaterials];
  // Optional (process_watch_track_lines), caller memory: per program line
  // (the index), the lowest max feed among the materials that line's feed
  // moves removed, charged as the feed rule charges them; what `dexmill
  // optimize` lowers each line's feed to. null: not tracked.
  int64_t* line_feed_limit = nullptr;
  size_t line_feed_limits = 0;  // entries, lines 0 .. line_feed_limits - 1
};

// No material limits the line's feed (the line removed nothing by feeding).
constexpr int64_t kNoFeedLimit = INT64_MAX;

// Where the move before left the tool (its deferred end cap is its).
struct ProcessOrigin {
  ProcessState state;
  PointNm end;
  const ToolProfile* tool;
};

// Starts a watch of g made of *comp (kBufferTooSmall: shadow_words < nx * ny).
template <class H>
Status process_watch_init(ProcessWatch* w, const DexelGrid<H>& g, const StockComposition* comp, uint32_t* shadow,
                          size_t shadow_words);

// Bytes of caller memory that tell apart the findings of lines 0 .. n - 1.
constexpr size_t process_seen_bytes(size_t lines) { return lines * kProcessRules; }
static_assert(kCompositionMaxMaterials <= 8, "a byte's bits for a line and rule's materials");

// Tells apart the findings of lines 0 .. n - 1 exactly, in seen[0,
// process_seen_bytes(n)) (cleared here). After process_watch_init, which
// stops it.
void process_watch_track_findings(ProcessWatch* w, uint8_t* seen, size_t n);

// Tracks the lines' feed limits into limits[0, n), each set to kNoFeedLimit
// here; lines past n are not tracked (the caller sizes it for the program).
// After process_watch_init, which stops any tracking.
void process_watch_track_lines(ProcessWatch* w, int64_t* limits, size_t n);

// After the cut of record r in state s, the columns it changed in g being
// `changed`. True when a violation was added.
template <class H>
bool process_watch_record(ProcessWatch* w, const DexelGrid<H>& g, GridRect changed, const ProcessState& s,
                          const ProcessOrigin* prev);

#define DEXMILL_PROCESS_EXTERN(H)                                                                               \
  extern template Status process_watch_init<H>(ProcessWatch*, const DexelGrid<H>&, const StockComposition*,    \
                                               uint32_t*, size_t);                                            \
  extern template bool process_watch_record<H>(ProcessWatch*, const DexelGrid<H>&, GridRect, const ProcessState&, \
                                               const ProcessOrigin*);
DEXMILL_PROCESS_EXTERN(uint8_t)
DEXMILL_PROCESS_EXTERN(uint16_t)
DEXMILL_PROCESS_EXTERN(uint32_t)
#undef DEXMILL_PROCESS_EXTERN

}  // namespace dexmill

#endif
