// A zig-milling program from a design part (paper §3): the
// positions of core/cam/zig.h written as plain RS274/NGC that dexmill and
// LinuxCNC both read. One program per design grid: stripes cut in the same
// direction with the tool lifted to the safe height and returned at rapid
// (the paper's way), or zigzag, every other stripe reversed and the step to
// the next stripe fed at a height no design column under it reaches.
// Positions on one straight line in space are merged (the sweep of the
// merged move is the same set), so flat stretches take one move.
#ifndef DEXMILL_TOOLS_CAM_ZIG_PROGRAM_H
#define DEXMILL_TOOLS_CAM_ZIG_PROGRAM_H

#include <cstdint>
#include <string>

#include "core/cam/zig.h"
#include "core/design/design.h"
#include "core/tool/tool.h"

namespace dexmill {
namespace cli {

struct ZigProgramOptions {
  ZigOptions zig;
  bool zigzag = false;             // else lifted returns
  int64_t safe_z_nm = 0;           // rapids between stripes
  int64_t feed_nm_per_min = 1000 * kNmPerMm;
  int64_t plunge_nm_per_min = 300 * kNmPerMm;
  int32_t spindle_rpm = 12000;
  std::string header;              // comment lines (without parentheses) saying how it was made
};

struct ZigProgramStats {
  uint64_t positions = 0;  // tool positions worked out
  uint64_t moves = 0;      // G1 moves written (after merging)
  uint32_t stripes = 0;
  double seconds = 0;      // generation time
};

// The program for design d and tool p (its tables built here); false with a
// message when the tool is too large for the tables. floor_nm: the lowest
// tip height anywhere (a tool over no design goes there).
bool zig_program(const DesignGrid& d, const ToolProfile& p, const ZigProgramOptions& o, int64_t floor_nm,
                 std::string* text, ZigProgramStats* stats, std::string* err);

}  // namespace cli
}  // namespace dexmill

#endif
