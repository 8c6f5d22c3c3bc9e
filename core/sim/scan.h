// The first pass over a program, before anything is cut: what the CLI
// needs to plan a run it was not given in full (core/sim/stock_plan.h: the
// default stock from the motion's extents, the default pitch from the
// smallest tool; the Mill's memory from the largest), the report's counts,
// bounds and time, the tools it loads and the units its moves are in.
// It stops at the first input error, or at a T the library does not have
// (bad_tool_line): the cut goes as far (core/sim/job.h stop_line).
#ifndef DEXMILL_CORE_SIM_SCAN_H
#define DEXMILL_CORE_SIM_SCAN_H

#include <stddef.h>
#include <stdint.h>

#include "core/cut/mill.h"
#include "core/gcode/line_reader.h"
#include "core/gcode/messages.h"
#include "core/interp/interp.h"
#include "core/canon/summary.h"
#include "core/sim/job.h"
#include "core/sim/comment_tools.h"
#include "core/sim/gcode_runner.h"
#include "core/sim/blk_form_comment.h"
#include "core/sim/workpiece_comment.h"
#include "core/sim/tool_choice.h"
#include "core/tool/tool.h"

namespace dexmill {

// Distinct tools a scan lists (the tool before any M6 is the first); a
// program that loads more is counted (unlisted) and its later tools are
// not sized for.
constexpr int kScanToolsMax = 128;

// One tool's share of the time estimate (MotionSummary's MoveTimes, the
// blended figure where the planner ran), summed by ProgramScan.
struct ScanToolTime {
  int64_t estimated_us = 0, feed_us = 0, rapid_us = 0, dwell_us = 0;
  uint64_t moves = 0;  // straight moves and arcs
};

class ScanPass;

class ProgramScan final : public CanonSink, public LineWatcher, private MoveTimeSink {
 public:
  // The job's tool and library (null: every T is the tool), time model and
  // reading options (kept: a copy).
  explicit ProgramScan(const SimJob& job);
  ProgramScan(const ProgramScan&) = delete;
  ProgramScan& operator=(const ProgramScan&) = delete;

  // Reads the program from `in` with the job's reading options: lines up
  // to the first error or bad T (messages get the errors and, when the job
  // has none of its own, the warnings). mem: the program's parameters and
  // o-word flow. Records also go to `also` (a backplot), when not null.
  // A ScanPass of its own, run to its end.
  void run(LineInput* in, GcodeMessages* messages, ProgramMemory* mem, CanonSink* also = nullptr);
  // The run's tool choice, when the job's library is it: run() reads the
  // program's tool comments into it, and lists the tools it chose in the
  // end (tools[0] its initial tool).
  void set_tool_choice(ToolChoice* c) { choice_ = c; }
  // The blended time estimate's look-ahead memory (core/canon/summary.h),
  // before run(); without it the estimate is the model's.
  void set_planner(MotionPlanner* p) { summary.set_planner(p); }

  void emit(const CanonRecord& r) override;
  // LineWatcher: the program's (WORKPIECE,...) comments (core/sim/workpiece_comment.h)
  // and (BLK FORM ...) pairs (core/sim/blk_form_comment.h).
  void line(const char* text, size_t n, uint32_t line_no) override;

  MotionSummary summary;
  bool inch_moves = false, mm_moves = false;  // units the moves were written in
  // The tools in the order first loaded: [0] the job's tool (number -1),
  // then each T number's the first time an M6 loads it.
  Tool tools[kScanToolsMax];
  int32_t numbers[kScanToolsMax];
  int ntools = 0;
  // Whether each made a feed or arc move, and the line of the M6 that first
  // loaded it ([0]: of its first such move).
  bool cuts[kScanToolsMax] = {};
  uint32_t first_lines[kScanToolsMax] = {};
  // The line of each one's last feed or arc move (0: none), so that a
  // tool's lines are first_lines[k] .. last_lines[k] (a tool loaded again
  // later spans the lines between its loads too).
  uint32_t last_lines[kScanToolsMax] = {};
  // The time each one took (its moves are timed once the look-ahead is
  // done with them, always before the next tool change is read: a tool
  // change stops the machine). Time with an unlisted tool is in none.
  ScanToolTime tool_time[kScanToolsMax];
  // The largest G64 P of a move (nm; -1: no move under G64 with P).
  int32_t path_tolerance_max_nm = -1;
  uint32_t unlisted = 0;       // loads of tools past kScanToolsMax
  int64_t max_radius_nm = 0;   // of every tool loaded
  uint32_t bad_tool_line = 0;  // the first M6 of a T the library lacks (0: none), and its number
  int32_t bad_tool = 0;
  uint32_t lines = 0;          // lines read
  uint32_t probes = 0;         // probe moves (G38.2-G38.5): the cut, with the stock, says where they stop
  // The stock the program's (WORKPIECE,...) or BLK FORM comments declare, in the record
  // frame (the work offsets and G92 in force where each stands added; the
  // union of them all), the first one's line, and the first one not read.
  bool have_workpiece = false;
  StockBox workpiece{};
  WorkpieceKind workpiece_kind = WorkpieceKind::kNone;
  uint32_t workpiece_line = 0;
  uint32_t workpiece_bad_line = 0;
  const char* workpiece_bad = nullptr;
  const char* workpiece_bad_form = "(WORKPIECE,...)";  // or "(BLK FORM ...)"
  bool blk_form = false;       // the stock is a BLK FORM's (else WORKPIECE's)
  bool io_error = false;
  // The units a tool table is read in by core/sim/tool_units.h's rule: the
  // program's at its first T word when it set them by then, else the job's.
  // (A pass stopped by an input error before any T reads no table tool.)
  bool table_inch = false;

  // The smallest diameter among the tools (0 with none).
  int64_t smallest_diameter_nm() const;

 private:
  friend class ScanPass;
  void move_time(const MoveTimes& t) override;
  void finish(const GcodeRunner& runner, const Interp& interp);

  BlkForm blk_{};  // a BLK FORM 0.1 waiting for its 0.2
  SimJob job_;
  SingleToolLibrary single_;
  const ToolLibrary* lib_;
  const Interp* interp_ = nullptr;
  CanonSink* also_ = nullptr;
  ToolChoice* choice_ = nullptr;
  int in_spindle_ = 0;  // tools[] index of the tool in the spindle (-1: unlisted)
};

// The first pass a step at a time, for input that comes in pieces (the
// embedding API's dm_scan_feed, core/sim/chunk_input.h): the reading state
// ProgramScan::run keeps on its stack, held here. The scan is filled in
// once step() returns kDone.
class ScanPass {
 public:
  enum class State : uint8_t { kReading, kWaiting, kDone };
  // As ProgramScan::run's arguments; all must outlive the pass.
  ScanPass(ProgramScan* scan, LineInput* in, GcodeMessages* messages, ProgramMemory* mem, CanonSink* also = nullptr);
  ScanPass(const ScanPass&) = delete;
  ScanPass& operator=(const ScanPass&) = delete;
  // Reads up to `lines` lines (0: no limit): kWaiting when the input has no
  // whole line yet (feed it more, or close it), kDone at the scan's end.
  State step(uint32_t lines);
  uint32_t lines() const { return runner_.lines(); }

 private:
  ProgramScan* scan_;
  Interp interp_;
  CommentTap tap_;
  GcodeRunner runner_;
  bool done_ = false;
};

}  // namespace dexmill

#endif
