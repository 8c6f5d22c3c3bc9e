// Safety checks a preview exists for, traced to the program
// line that trips them:
// - a rapid (G0) that removes material, and the volume rapids removed;
// - material removed while the spindle is stopped (no M3/M4, or after M5):
//   one finding per stretch of cutting without it, on its first line;
// - the tool tip below the stock's bottom, or below a table plane;
// - the shank: material the cut removed above the flute length (the first
//   tool position over a column meets it: core/safety/body.h), and the
//   shank where wider than the cut, touching material left;
// - the holder (core/safety/body.h) touching material left;
// - fixtures: boxes in a grid of their own that the whole tool, cutter,
//   shank and holder, must never enter (the cutter is swept into it exactly
//   as into the stock, and what it would cut is put back);
// - a tool that is not centre cutting plunging straight down into material
//   deeper than kPlungeDepthNm at its axis.
// The removals are what the cut removed, exactly: a shadow of the grid's
// tops before each record is compared with the tops after it, over the
// columns the record changed, and then brought up to date. A deferred end
// cap (the Mill cuts the tool standing at a move's end with the next
// record) is charged to the move that brought the tool there, as the gouge
// watch does (core/tool/tool.h profile_explains_cut). Bounded: the first
// kSafetyEventsMax events are kept, the rest counted.
#ifndef DEXMILL_CORE_SAFETY_SAFETY_H
#define DEXMILL_CORE_SAFETY_SAFETY_H

#include <stddef.h>
#include <stdint.h>

#include "core/safety/body.h"
#include "core/cut/sweep.h"
#include "core/grid/grid.h"
#include "core/canon/canon.h"
#include "core/point.h"
#include "core/status.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class SafetyKind : uint8_t {
  kRapidIntoStock = 0,
  kSpindleStopped = 1,
  kBelowStock = 2,
  kIntoTable = 3,
  kShank = 4,
  kHolder = 5,
  kFixture = 6,
  kPlunge = 7,
};
constexpr int kSafetyKinds = 8;
// A non-centre-cutting tool may push this far into material at its axis.
constexpr int64_t kPlungeDepthNm = 100000;
// Tiles of the material's highest tops that let the holder check skip what
// lies under it (a tile's bound stays true: cuts only lower tops).
constexpr int kSafetyTileBits = 4;
// A tile's highest top not known since a record changed it (tile_top).
constexpr uint32_t kSafetyTileUnknown = UINT32_MAX;
// Blocks of 4 x 4 tiles over them, which a look skips with one comparison.
constexpr int kSafetyBlockBits = 2;
constexpr size_t kSafetyEventsMax = 64;

// The report's name of a kind: "rapid", "spindle_stopped", "below_stock",
// "table", "shank", "holder", "fixture", "plunge".
const char* safety_kind_name(SafetyKind k);

struct SafetyEvent {
  SafetyKind kind = SafetyKind::kRapidIntoStock;
  uint32_t line = 0;
  PointNm at{0, 0, 0};        // removals: the deepest cut column, at its top after the cut; below: the lowest tip;
                              // contacts: the deepest column, at the part's lowest point there
  uint64_t removed_lsb = 0;   // removals: sum of heights removed, LSB x dexels (x lsb x pitch^2 = volume);
                              // contacts: the overlap, the same way
  int64_t depth_nm = 0;       // below kinds: how far under the limit the tip went; removals: the deepest column's
                              // cut; contacts: the deepest overlap
  uint64_t columns = 0;       // removals, contacts: columns
  uint32_t last_line = 0;     // spindle stopped: the stretch's last line that cut; shank, holder: the last
                              // line of the stretch of contact it begins (safety.cpp, body_stretch)
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
  // A straight plunge (no XY motion, down) by a tool that is not centre
  // cutting: safety_is_plunge.
  bool plunge = false;
  PointNm end{0, 0, 0};         // where it ended (the plunge's axis)
  const ToolBody* body = nullptr;  // the tool's (null: no shank, holder or fixture check)
};

// True for a straight move down without XY motion.
bool safety_is_plunge(const CanonRecord& r);

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
  bool check_shank = false, check_holder = false, check_plunge = false;
  int64_t bottom_nm = 0, table_nm = 0;
  uint32_t* shadow = nullptr;  // caller memory, nx * ny: the tops before the record
  // Caller memory, safety_tile_words: per tile a bound on its tops (what a
  // shank and holder look leaves: its stretch ends where every bound in
  // reach is under the body), then per tile its highest top as it is now
  // (kSafetyTileUnknown: a record changed the tile since it was read), so
  // that a look tightens a bound without reading the tile again.
  // Then per block the highest of its tiles' bounds, and whether a tile's
  // bound is not its highest top as now (1) or all are (0): a block of 0
  // needs no tightening, so a look skips it when its bound is under the body.
  uint32_t* tile_max = nullptr;
  uint32_t* tile_top = nullptr;
  uint32_t* block_max = nullptr;
  uint32_t* block_stale = nullptr;
  int32_t tiles_x = 0, tiles_y = 0, blocks_x = 0, blocks_y = 0;
  // On: a shank and holder look reads a column only where its top is over
  // the lowest point of a ring whose reach holds it, and a tile only where
  // its highest top is (safety.cpp, body_contacts); off: every column over
  // the whole body's lowest point, the reference the fast look gives the
  // same findings as (tests/test_safety_body_fast.cpp). The caller's, as the
  // check_* fields.
  bool body_fast = true;
  // Fixtures (null: none): a grid of their own, on the stock grid's lattice
  // and LSB, and the boxes it is made from (to put back what a check cuts).
  DexelGrid<uint32_t>* fixtures = nullptr;
  const BoxNm* fixture_boxes = nullptr;
  int nfixture_boxes = 0;
  SweepTool fixture_tool{};     // the tool in the spindle, prepared for the fixture grid
  bool fixture_tool_ok = false;
  SafetyEvent events[kSafetyEventsMax];
  size_t nevents = 0;
  uint64_t total = 0;              // events in all (kept and not)
  uint64_t rapid_removed_lsb = 0;  // all rapids removed
  size_t spindle_stretch = kSafetyEventsMax;  // the open spindle-stopped event (kSafetyEventsMax: none)
  bool spindle_stretch_open = false;          // a stretch is open (its event may not be kept)
  // The first line that moved with the spindle on since the open stretch
  // began (0: none yet): the stretch holds the stopped moves before it. A
  // stopped move's end cap is cut by the next record, which may be that
  // line's: the cap is still the stretch's.
  uint32_t spindle_on_line = 0;
  uint32_t unkept_line[kSafetyKinds] = {};   // per kind, the last line counted past the list
  // The shank and holder's stretch of contact (safety.cpp, body_stretch).
  bool body_stretch_open = false;
  int64_t body_stretch_low_nm = 0;   // the lowest tip looked at in it
  uint32_t body_stretch_line = 0;    // the line of its last finding
};

// Starts a watch on g: the shadow takes g's tops (shadow_words >= nx * ny,
// else kBufferTooSmall); events emptied. The check_* fields and limits are
// the caller's to set, before or after. With tile memory (tile_words >=
// safety_tile_words(g); else null and 0) the holder check skips tiles
// of material under it.
template <class H>
Status safety_watch_init(SafetyWatch* w, const DexelGrid<H>& g, uint32_t* shadow, size_t shadow_words,
                         uint32_t* tiles = nullptr, size_t tile_words = 0);
// Two words a tile of 16 x 16 dexels (the bound and the highest top) and
// two a block of 64 x 64: 0.033 bytes a dexel, taken only when a check is
// on (core/sim/simulation_impl.h).
template <class H>
size_t safety_tile_words(const DexelGrid<H>& g) {
  const size_t tx = (static_cast<size_t>(g.nx) >> kSafetyTileBits) + 1, ty = (static_cast<size_t>(g.ny) >> kSafetyTileBits) + 1;
  const size_t bx = (tx >> kSafetyBlockBits) + 1, by = (ty >> kSafetyBlockBits) + 1;
  return 2 * tx * ty + 2 * bx * by;
}

// Fixtures: the grid (caller memory of its nx * ny, tops and bottoms) that
// holds boxes[0, n) on g's lattice and LSB, every column from its lowest
// box's bottom to its highest box's top. fixture_grid_size gives its size
// (false: no box, or boxes beyond the grid limits); fixture_grid_fill fills
// a grid of that size and geometry. Boxes in nm, machine coordinates.
template <class H>
bool fixture_grid_size(const DexelGrid<H>& g, const BoxNm* boxes, int n, DexelGrid<uint32_t>* out);
void fixture_grid_fill(DexelGrid<uint32_t>* f, const BoxNm* boxes, int n);

// The tool in the spindle, for the fixture check's sweep (call at the
// start and at every tool change).
void safety_watch_set_tool(SafetyWatch* w, const ToolProfile& p);

// After the cut of record r (state m), the columns it changed in g being
// `changed`: checks r and the removals, updates the shadow. `prev` (or
// null) as above. True when this call added an event.
template <class H>
bool safety_watch_record(SafetyWatch* w, const DexelGrid<H>& g, GridRect changed, const CanonRecord& r,
                         const SafetyMove& m, const SafetyOrigin* prev);

#define DEXMILL_SAFETY_EXTERN(H)                                                                                    \
  extern template Status safety_watch_init<H>(SafetyWatch*, const DexelGrid<H>&, uint32_t*, size_t, uint32_t*,   \
                                             size_t);                                                            \
  extern template bool fixture_grid_size<H>(const DexelGrid<H>&, const BoxNm*, int, DexelGrid<uint32_t>*);       \
  extern template bool safety_watch_record<H>(SafetyWatch*, const DexelGrid<H>&, GridRect, const CanonRecord&,     \
                                              const SafetyMove&, const SafetyOrigin*);
DEXMILL_SAFETY_EXTERN(uint8_t)
DEXMILL_SAFETY_EXTERN(uint16_t)
DEXMILL_SAFETY_EXTERN(uint32_t)
#undef DEXMILL_SAFETY_EXTERN

}  // namespace dexmill

#endif
