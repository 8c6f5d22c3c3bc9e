// `dexmill run`: the options into a job for the engine, and the files and
// views around it. Two passes over the program:
//   scan  the interpreter alone (core/sim/scan.h): motion counts and
//         boxes, the time estimate, the tools it uses; every G-code error
//         and warning is reported here; a program with an error is cut up
//         to its first bad block (with --strict not at all: exit 1, the
//         report still written);
//   cut   the simulation (core/sim/simulation.h) on a grid planned from the
//         scan (core/sim/stock_plan.h), a line a step, with frames, the live
//         view and the progress bar between steps (tools/run/run_views.h);
// then the outputs: --image, --heightmap, --stl, --report, each written
// completely or not at all (exit 3 when one cannot be written).
#ifndef DEXMILL_TOOLS_RUN_RUN_JOB_H
#define DEXMILL_TOOLS_RUN_RUN_JOB_H

#include <cstdint>
#include <string>
#include <vector>

#include "platform/input/file_guard.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

// What the subcommands that run a job for its findings read from it.
struct RunResult {
  bool finished = false;     // the run went through to its verdict (exit 0, 1 for a partial cut, or 4)
  std::string shown_name;    // the program's name in messages
  uint64_t safety_findings = 0;
  bool gouged = false;
  // With JobOptions::feed_limits: per line (the index), the lowest max feed
  // among the materials that line's feed moves removed (kNoFeedLimit: none;
  // core/safety/material_limits.h); what `dexmill optimize` lowers feeds to.
  std::vector<int64_t> line_feed_limits;
  // With JobOptions::engage_target: per line, the feed that meets it
  // (INT64_MAX: no feed move measured), and whether a move of the line
  // kept its programmed feed (a plunge, no spindle speed, ...).
  std::vector<int64_t> line_target_feeds;
  std::vector<uint8_t> line_target_kept;
  // With a split rule: the moves split, each its pieces in order (the
  // last marked), and how many moves were left whole for want of room.
  std::vector<EngageSplitPiece> target_splits;
  uint64_t splits_left = 0;
  // With JobOptions::keep_tops: the final tops (LSB, nx * ny) and where
  // the grid is, and the largest tool radius the program uses.
  std::vector<uint32_t> tops;
  GridGeometry grid{};
  int64_t max_tool_radius_nm = 0;
  EngageSummary engagement;  // the run's largest (with engagement measured)
  bool have_engagement = false;
  // What it found, at its lines (the first kChainFindingsKept, and the
  // count of all): a chain's next program reports them.
  ProgramFindings findings;
};

// Runs the job; returns the exit status (the man page's). Every file it
// reads, writes or removes goes through the command's `guard`
// (platform/input/file_guard.h), with what the command registered before.
int run_job(RunOptions o, FileGuard* guard, RunResult* result = nullptr);

}  // namespace cli
}  // namespace dexmill

#endif
