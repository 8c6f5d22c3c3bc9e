// The rewriting pass of `dexmill optimize`: reads the program again, line
// by line as the cut read it (platform/input/gcode_file.h: the same line ends,
// the same numbers), through the interpreter for each line's feed moves,
// feed mode and units, and asks tools/cam/feed_rewrite.h what F word each line
// needs. Yields the splices into the program's bytes and the time estimates
// of the program before and after.
#ifndef DEXMILL_TOOLS_CAM_OPTIMIZE_PASS_H
#define DEXMILL_TOOLS_CAM_OPTIMIZE_PASS_H

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/canon/canon.h"
#include "core/canon/summary.h"
#include "core/engage/engage_split.h"
#include "platform/format/tool_table.h"

namespace dexmill {
namespace cli {

struct OptimizeInput {
  std::string read_path;                     // the program as the cut read it
  std::string shown_name;                    // its name in messages
  bool inch = false;                         // --units inch
  bool feed_in_line_units = false;           // a grbl machine's reading of F on a G20/G21 line
  int64_t default_feed_nm_per_min = 0;       // --default-feed, as the cut had it
  const ToolTable* tools = nullptr;          // --tools (or --tool), for G43 H and G41 D as the cut had it
  const std::vector<int64_t>* limits = nullptr;  // per line, from the cut (RunResult::line_feed_limits, tools/run/run_job.h)
  // --target: per line, the feed that meets it (RunResult::line_target_feeds;
  // INT64_MAX: none), bounded by the limits above; null: lower to the limits.
  const std::vector<int64_t>* targets = nullptr;
  // --target's pieces of long moves (RunResult::target_splits; null: none):
  // a line that can be written in pieces (tools/cam/move_split.h) is.
  const std::vector<EngageSplitPiece>* splits = nullptr;
  bool crlf = false;  // the program's lines end in CR LF: so do the pieces'
  MotionTimeModel time_model;
};

// A splice into the program's bytes: erase `erase` at `at`, insert `text`.
struct ProgramSplice {
  uint64_t at = 0, erase = 0;
  std::string text;
};

struct OptimizeResult {
  std::vector<ProgramSplice> splices;        // in the order of `at`
  uint32_t lines_changed = 0;
  uint32_t lines_lowered = 0;                // lines whose feed moves run slower
  uint32_t lines_restored = 0;               // lines given the programmed F back
  uint32_t lines_raised = 0;                 // lines whose feed moves run faster (--target)
  uint32_t moves_split = 0, lines_added = 0;  // moves written in pieces, and the lines that added
  uint32_t splits_kept_whole = 0;            // moves with pieces whose line could not be split
  std::vector<std::pair<uint32_t, CanonRecord>> split_moves;  // the moves written in pieces: line, record
  uint32_t splits_undone = 0;                // undone after the output's check cut (cmd_optimize.cpp)
  std::map<int64_t, uint32_t> lowered_to;    // lowered lines by their limit, nm/min
  uint32_t left_over = 0;                    // lines left over a limit (warned): G93 with F too small to lower
  int64_t before_us = 0, after_us = 0;       // estimated time (core/canon/summary.h)
};

// Runs the pass. Returns kExitOk, or prints the error and returns kExitIo
// (unreadable) or kExitInput (the program no longer reads as it did).
int optimize_pass(const OptimizeInput& in, OptimizeResult* out);

// The program's bytes with the splices made.
std::string apply_splices(const std::string& program, const std::vector<ProgramSplice>& splices);

}  // namespace cli
}  // namespace dexmill

#endif
