// Safety checks a preview exists for (issue 20), traced to the program
// line that trips them:
// - a rapid (G0) that removes material, and the volume rapids removed;
// - material removed while the spindle is stopped (no M3/M4, or after M5):
//   one finding per stretch of cutting without it, on its first line;
// - the tool tip below the stock's bottom, or below a table plane.
// The removals are what the cut removed, exactly: a shadow of the grid's
// tops before each record is compared with the tops after it, over the
// columns the record changed, and then brought up to date. A deferred end
// cap (the Mill cuts the tool standing at a move's end with the next
// record) is charged to the move that brought the tool there, as the gouge
// watch does (core/tool/tool.h profile_explains_cut). Bounded: the first
// kSafetyEventsMax events are kept, the rest counted.
#ifndef DEXMILL_CORE_CHECK_SAFETY_H
#define DEXMILL_CORE_CHECK_SAFETY_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/motion/canon.h"
#include "core/point.h"
#include "core/status.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class SafetyKind : uint8_t { kRapidIntoStock = 0, kSpindleStopped = 1, kBelowStock = 2, kIntoTable = 3 };
constexpr int kSafetyKinds = 4;
constexpr size_t kSafetyEventsMax = 64;

// The report's name of a kind: "rapid", "spindle_stopped", "below_stock", "table".
const char* safety_kind_name(SafetyKind k);

struct SafetyEvent {
  SafetyKind kind = SafetyKind::kRapidIntoStock;
  uint32_t line = 0;
  PointNm at{0, 0, 0};        // removals: the deepest cut column, at its top after the cut; below: the lowest tip
  uint64_t removed_lsb = 0;   // removals: sum of heights removed, LSB x dexels (x lsb x pitch^2 = volume)
  int64_t depth_nm = 0;       // below kinds: how far under the limit the tip went; removals: the deepest column's cut
  uint64_t columns = 0;       // removals: columns cut
  uint32_t last_line = 0;     // spindle stopped: the stretch's last line that cut
};

// The state a record ran in, as the caller (the cut pass) knows it.
struct SafetyMove {
  uint32_t line = 0;
  bool rapid = false;
  bool spindle_on = false;
  // False for the program's first move: it starts where the machine was
  // before the program, which a preview can only assume (the origin), so
  // what it removes is no finding.
  bool start_known = true;
};

// Where the line before left the tool, and in what state it moved.
struct SafetyOrigin {
  SafetyMove move;
  PointNm end;
  const ToolProfile* tool;
};

struct SafetyWatch {
  bool check_rapid = true, check_spindle = true;
  bool check_below = true;     // below bottom_nm
  bool check_table = false;    // below table_nm
  int64_t bottom_nm = 0, table_nm = 0;
  uint32_t* shadow = nullptr;  // caller memory, nx * ny: the tops before the record
  SafetyEvent events[kSafetyEventsMax];
  size_t nevents = 0;
  uint64_t total = 0;              // events in all (kept and not)
  uint64_t rapid_removed_lsb = 0;  // all rapids removed
  size_t spindle_stretch = kSafetyEventsMax;  // the open spindle-stopped event (kSafetyEventsMax: none)
  bool spindle_stretch_open = false;          // a stretch is open (its event may not be kept)
};

// Starts a watch on g: the shadow takes g's tops (shadow_words >= nx * ny,
// else kBufferTooSmall); events emptied. The check_* fields and limits are
// the caller's to set, before or after.
template <class H>
Status safety_watch_init(SafetyWatch* w, const DexelGrid<H>& g, uint32_t* shadow, size_t shadow_words);

// After the cut of record r (state m), the columns it changed in g being
// `changed`: checks r and the removals, updates the shadow. `prev` (or
// null) as above. True when this call added an event.
template <class H>
bool safety_watch_record(SafetyWatch* w, const DexelGrid<H>& g, GridRect changed, const CanonRecord& r,
                         const SafetyMove& m, const SafetyOrigin* prev);

#define DEXMILL_SAFETY_EXTERN(H)                                                                                    \
  extern template Status safety_watch_init<H>(SafetyWatch*, const DexelGrid<H>&, uint32_t*, size_t);               \
  extern template bool safety_watch_record<H>(SafetyWatch*, const DexelGrid<H>&, GridRect, const CanonRecord&,     \
                                              const SafetyMove&, const SafetyOrigin*);
DEXMILL_SAFETY_EXTERN(uint8_t)
DEXMILL_SAFETY_EXTERN(uint16_t)
DEXMILL_SAFETY_EXTERN(uint32_t)
#undef DEXMILL_SAFETY_EXTERN

}  // namespace dexmill

#endif
