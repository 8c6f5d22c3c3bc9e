// What a simulation is asked to do (core/sim/simulation.h): the grid and
// stock, the tools, how the program is read, and which observers watch
// the cut. Plain values and pointers to inputs the caller keeps (a tool
// library, a design part, a stock's materials): never a file name, never
// an output. The CLI fills one from its options (tools/run/run_job.cpp), the
// embedding API from its calls (display/api/dexmill.h), a panel from its
// flash.
#ifndef DEXMILL_CORE_SIM_JOB_H
#define DEXMILL_CORE_SIM_JOB_H

#include <stddef.h>
#include <stdint.h>

#include "core/assess/assess.h"
#include "core/cut/mill.h"
#include "core/design/design.h"
#include "core/engage/engage_meter.h"
#include "core/canon/machine.h"
#include "core/engage/engage_split.h"
#include "core/engage/engage_target.h"
#include "core/gcode/error.h"
#include "core/material/material.h"
#include "core/interp/interp.h"
#include "core/canon/summary.h"
#include "core/point.h"
#include "core/sim/stock_plan.h"
#include "core/stock/stock_file.h"
#include "core/stock/stock_transform.h"
#include "core/tool/tool.h"

namespace dexmill {

// The safety checks (core/safety/safety.h) and their limits.
struct SimChecks {
  bool rapid = false, spindle = false, below = false, shank = false, holder = false, plunge = false;
  bool has_table = false;
  int64_t table_nm = 0;             // the table's Z (machine, nm)
  const BoxNm* fixtures = nullptr;  // boxes the tool must never enter (caller memory)
  int nfixtures = 0;
  bool any() const { return rapid || spindle || below || shank || holder || plunge || has_table || nfixtures > 0; }
};

// What a tool describes is checked: a flute length turns on the shank
// check, a holder the holder check, a tool that is not centre cutting the
// plunge check.
void sim_checks_for_tools(SimChecks* c, const Tool* tools, int ntools);

// Every T is one tool (no tool table): its length for G43 is 0, its
// radius G41/G42's.
class SingleToolLibrary final : public ToolLibrary, public ToolTable {
 public:
  explicit SingleToolLibrary(const Tool& t) : tool_(t) {}
  bool tool(int32_t, Tool* out) const override {
    *out = tool_;
    return true;
  }
  bool tool_length_nm(int32_t, int64_t* z_nm) const override {
    *z_nm = 0;
    return true;
  }
  bool tool_radius_nm(int32_t, int64_t* r_nm) const override {
    *r_nm = tool_.diameter_nm / 2;
    return true;
  }

 private:
  Tool tool_;
};

struct SimJob {
  GridPlan plan{};                  // the grid and the stock it holds (core/sim/stock_plan.h)
  CutMode mode = CutMode::kSweep;   // exact swept envelope, or the paper's instances
  Tool tool{};                      // in the spindle before any M6
  const ToolLibrary* library = nullptr;  // what T/M6 load (null: every T is `tool`)
  const ToolTable* offsets = nullptr;    // G43 H lengths, G41/G42 radii (null: as SingleToolLibrary's)
  // The tools a program may load besides `tool` (the Mill's memory is sized
  // for the largest; a larger one loaded later cannot cut: SimError::kToolCannotCut).
  const Tool* tools = nullptr;
  int ntools = 0;

  // Reading the program (core/interp/interp.h InterpOptions).
  bool inch = false;                    // units before any G20/G21
  bool units_given = false;             // the caller chose them: no warning for a program that sets none
  bool feed_in_line_units = false;      // F on a G20/G21 line in that line's units, as grbl (InterpOptions)
  int64_t default_feed_nm_per_min = 0;  // a controller's feed for moves with none in force (0: an error)
  uint64_t max_blocks = kDefaultMaxBlocks;
  GcodeDiagSink* warnings = nullptr;    // the interpreter's warnings as they come (the simulation also counts them)
  GcodeMessageSink* notes = nullptr;    // DEBUG/PRINT/MSG comments
  // Program text fed in pieces (Simulation::feed): the reader's buffer;
  // 0 when lines come from a LineInput the caller gives (Simulation::read_from).
  size_t input_buffer_bytes = 0;
  // Records of one line held back when a step's budget runs out in it
  // (a canned cycle, a spline); a line with more is cut past the budget.
  uint32_t queue_records = 64;

  MotionTimeModel time{};               // the time estimate's machine
  // The time estimate observer (SimStatus::sim_us); the process rules need
  // it and turn it on. Off, a record costs no length or time arithmetic
  // (on a Cortex-M4 about 1 % of a cut's instructions: arcs' 128-bit roots).
  bool time_estimate = true;
  SimChecks checks{};                   // the safety observer (any(): on)
  const DesignGrid* design = nullptr;   // the gouge watch against this part (null: off); its geometry is plan.geo's
  AssessOptions assess{};               // its tolerances and the columns assessed
  const StockComposition* material = nullptr;  // the process rules of the stock's materials (null: off)
  // The machine (core/canon/machine.h; null: none) and its soft limits as
  // findings (core/safety/travel_watch.h; needs machine).
  const MachineSpec* machine = nullptr;
  bool travel_check = false;
  // Engagement (core/engage/engage_meter.h): every feed move's load,
  // measured on the stock before it cuts, given to engage_sink when set
  // and summed up (Simulation::engagement()). Off: nothing is sampled.
  bool engagement = false;
  EngageSink* engage_sink = nullptr;
  // Load limits (core/engage/load_watch.h; needs engagement): the chip
  // against each material's max_chip_nm, the power against the spindle's
  // (0: none). Force and power need `material`'s cutting coefficients.
  bool load_check = false;
  int64_t spindle_power_mw = 0;
  // The speed engagement takes where the program gives none (no S word,
  // or no M3 at all: a router's spindle switched by hand; 0: none, the
  // chip per tooth unmeasured).
  int32_t default_spindle_rpm = 0;
  // `--color engagement` (core/engage/engage_band.h; needs engagement):
  // the columns each record lowered take its move's load band, by the
  // limits where the run knows one (spindle_power_mw, a material's
  // max_chip_nm), else by the engagement angle (Simulation::engage_classes()).
  bool engage_colours = false;
  // `dexmill optimize --target` (core/engage/engage_target.h; needs
  // engagement and material): each line's feed for the target, lines
  // 0 .. target_lines - 1 (Simulation::target_feeds()).
  const EngageTarget* engage_target = nullptr;
  size_t target_lines = 0;
  // And straight moves split where the target's feed changes along them
  // (core/engage/engage_split.h; max_segments 0: not split), at most
  // split_pieces pieces in all (Simulation::target_splits()).
  EngageSplitRule split_rule;
  size_t split_pieces = 0;
  size_t line_feed_lines = 0;           // > 0: each line's lowest feed limit kept for lines 0..n-1 (`dexmill optimize`)
  // The process rules' findings of lines 0..n-1 told apart exactly (3 bytes
  // a line; core/safety/material_limits.h): the program's line count + 1. 0: only
  // the last few are (a line met again later counts again).
  size_t process_lines = 0;
  bool provenance = false;              // which tool last cut each column
  bool provenance_lines = false;        // and which line (needs provenance)
  bool provenance_programs = false;     // and which of the chain's programs (needs provenance_lines; a saved stock's layer)
  int32_t provenance_slots = 7;         // classes for the tools (display/colour/tool_colours.h kToolColourSlots)
  int32_t provenance_first_tool = -1;   // the number the tool before any M6 is listed under

  // A saved stock this run continues (core/stock/stock_file.h; the plan is
  // its grid, sim_plan_of_stock): the simulation leaves its grid unfilled
  // for the front end to read the stock's columns into stock_columns()
  // before start(), and takes from it the stock's bounds, the tool's place
  // and number, the provenance's tool order and the chain's programs.
  // Null: a fresh stock from the plan.
  const StockMeta* resume = nullptr;
  // The setups that turned it into this program's fixturing
  // (core/stock/stock_transform.h), for the chain's record of this program.
  const StockSetup* setups = nullptr;
  int32_t nsetups = 0;
  // The coordinate systems' origins G54..G59.3 (9, machine nm) when the
  // program starts, as a controller's parameter file holds them (a setup's
  // work offsets). Null: all at the machine's origin.
  const PointNm* work_offsets = nullptr;
  // The coordinate system in force, the G92 offset and a G43.1 tool length
  // offset when it starts (the machine's: core/interp/interp.h InterpOptions).
  uint8_t start_coord_system = 0;
  PointNm start_g92{0, 0, 0};
  int64_t start_tlo_nm = 0;
  // Probe moves (G38.2-G38.5) stop where the tool, or a ball tip of this
  // diameter (> 0), trips on the stock as cut so far (core/cut/probe.h).
  // 0: the tool in the spindle.
  int64_t probe_tip_nm = 0;

  // Stopping: at the first record of line stop_line or later (a program cut
  // up to its first bad block: 0, none), and at the end of a line that
  // gouged or collided, when asked.
  uint32_t stop_line = 0;
  bool stop_at_gouge = false;
  bool stop_at_collision = false;
};

// The memory of one reading of a program (about 68 KB): its parameters
// (core/gcode/params.h) and its o-word control flow (core/interp/oword_store.h).
struct ProgramMemory {
  ParamStore params;
  OwordStore control;
};

// The interpreter's options for reading the job's program: its units, feed
// and block limits, notes, and offsets (`fallback` when the job gives
// none); mem (or null: no parameters) cleared. Warnings go to the job's sink.
InterpOptions sim_interp_options(const SimJob& job, const ToolTable* fallback, ProgramMemory* mem);

}  // namespace dexmill

#endif
