// What the embedding API's handles (display/api/dexmill.h) hold in their
// caller memory, as its C++ side sees them. Internal to display/api.
//
// A dm_sim's block: the dm_sim, the design's tops (a job with a design),
// then the engine's own block (core/sim/simulation.h). A dm_view's block:
// the dm_view, then the renderer's scratch.
#ifndef DEXMILL_DISPLAY_API_HANDLES_H
#define DEXMILL_DISPLAY_API_HANDLES_H

#include <stddef.h>
#include <stdint.h>

#include <type_traits>

#include "core/design/design.h"
#include "core/material/material.h"
#include "core/sim/simulation.h"
#include "display/api/dexmill.h"
#include "display/api/run_marks.h"
#include "display/view/stock_view.h"

namespace dexmill {
namespace api {

// The job's numbered tools: what T/M6 load, the lengths G43 H applies, the
// radii G41/G42 use (half the diameter, as a tool table's D).
class NumberedTools final : public ToolLibrary, public ToolTable {
 public:
  bool tool(int32_t number, Tool* out) const override;
  bool tool_length_nm(int32_t number, int64_t* z_nm) const override;
  bool tool_radius_nm(int32_t number, int64_t* r_nm) const override;
  bool has(int32_t number) const { return find(number) >= 0; }

  Tool tools[DM_TOOLS_MAX];
  int32_t numbers[DM_TOOLS_MAX];
  int64_t lengths[DM_TOOLS_MAX];
  int32_t n = 0;

 private:
  int32_t find(int32_t number) const;
};

// A simulation's views: each is told of every grid change and tool load.
class ViewFan final : public SimObserver {
 public:
  void tool_loaded(const Tool& t) override;
  void changed(const GridRect& r) override;
  void record(const CanonRecord& r) override;  // the views' paths (dm_view_set_path), the marks
  dm_view* first = nullptr;
  Tool current{};  // the tool in the spindle, for a view made now
  // The run's marks every view draws, as `dexmill run` draws them
  // (display/api/run_marks.h): kept after every record of `sim`, and once
  // after the cut (final).
  RunMarks marks;
  const Simulation* sim = nullptr;
  bool marks_final = false;
};

// The program's first warnings, kept as they come (dm_warning_get).
constexpr uint32_t kWarningsKept = 16;
class KeptWarnings final : public GcodeDiagSink {
 public:
  void warning(const GcodeDiag& d) override {
    if (n < kWarningsKept) kept[n++] = d;
  }
  GcodeDiag kept[kWarningsKept];
  uint32_t n = 0;
};

// What a job becomes before the engine is made: the engine's job and the
// inputs it points to (inside the dm_sim once created).
struct JobInputs {
  NumberedTools library;
  BoxNm fixtures[DM_FIXTURES_MAX];
  DesignGrid design;
};

// Handle tags: a handle whose tag is not its kind's (null, destroyed, not
// a handle) is refused.
constexpr uint32_t kSimTag = 0x64736d31;   // "dsm1"
constexpr uint32_t kViewTag = 0x64766931;  // "dvi1"

// dm_status for an engine's SimError.
dm_status status_of(SimError e);

// What a first pass (display/api/scan.cpp) and a simulation both read of a
// job: its values checked (not its stock), the tools, units and reading
// limits (display/api/sim_create.cpp).
dm_status scan_job_of(const dm_job& in, NumberedTools* lib, SimJob* j);

}  // namespace api
}  // namespace dexmill

struct dm_sim {
  uint32_t tag;
  dexmill::api::JobInputs in;
  dexmill::StockComposition material;
  dexmill::api::ViewFan views;
  dexmill::api::KeptWarnings warnings;
  char line[DM_LINE_MAX + 1];  // dm_feed_line's copy and its line end
  bool ended;                  // dm_end_input was called
  dexmill::Simulation* sim;
};

namespace dexmill {
namespace api {
struct ViewColour;  // a colour mode's state, in its caller memory (view_colour.cpp)
}  // namespace api
}  // namespace dexmill

struct dm_view {
  uint32_t tag;
  dm_sim* sim;   // null once the simulation is destroyed
  dm_view* next; // the simulation's next view
  dexmill::StockView v;
  // dm_view_set_path: the toolpath cut so far, in the caller's memory.
  dexmill::PathSegment* path;
  uint32_t path_n, path_cap;
  uint64_t path_dropped;  // pieces that did not fit
  // dm_view_set_mark: one point marked over the picture, after the run's.
  dexmill::PointNm mark_at;
  bool has_mark;
  dexmill::ViewMarks marks[5];   // the run's lists and the mark, as drawn
  // The gouges' marks as last drawn: one that moves or goes leaves its
  // pixels behind, so the next render draws the whole frame.
  dexmill::PointNm drawn_gouges[dexmill::kGougeEventsMax];
  uint32_t ndrawn_gouges;
  dexmill::api::ViewColour* colour;  // dm_view_set_colour's (null: plain)
};

// Ending a handle is clearing its tag: nothing in it needs a destructor
// (the engine in a dm_sim is ended by its own destroy).
static_assert(std::is_trivially_destructible<dm_sim>::value && std::is_trivially_destructible<dm_view>::value,
              "a handle ends by its tag");

namespace dexmill {
namespace api {

// Before a render: a colour mode's legend as the simulation is now (the
// tool legend names the tools that have cut; view_colour.cpp).
void view_colour_update(dm_view* v);

// A handle the calls may use.
inline bool live(const dm_sim* s) { return s && s->tag == kSimTag; }
inline bool live(const dm_view* v) { return v && v->tag == kViewTag && live(v->sim); }

}  // namespace api
}  // namespace dexmill

#endif
