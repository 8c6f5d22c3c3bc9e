// Zig milling from a design part (paper §3: "the design part is scanned for
// height in x-parallel stripes; at the edge the cutter is lifted and returns
// to the other edge without cutting"): tool positions along
// stripes of the design's dexel rows, each the lowest at which the tool
// touches but does not cut into the design.
//
// Inverse tool offset: with the tool's tip over the point p, a design
// column c at horizontal distance r within the tool's radius is cut unless
// tip >= top(c) - h(r), h the tool's lower surface (core/tool/tool.h). The
// lowest safe tip is the maximum of top(c) - h(r) over the footprint.
//
// Between two positions the machine moves in a straight line, and the
// requirement along the way must stay under that chord. Along a stripe the
// tip's distance r(t) to a column is convex in t and h is convex and
// rising in r for every tool shape, so h(r(t)) is convex in t: on each
// interval of 1 / kZigPhases of a pitch, the secant of the interval before
// (or after), extended, lies under it. The tables hold that lower line's
// values at each interval's two ends (floored to LSB; a column that enters
// or leaves the tool's radius within two intervals takes h at its closest
// approach, flat), so "chord >= top - line at both ends of every interval,
// for every column" guarantees chord >= requirement everywhere: no gouge
// from the path itself, exactly, for any design. The price is tips raised
// by up to h'' (pitch / kZigPhases)^2 over the exact requirement at one end
// of an interval (0.16 um for a 1.5 mm ball at 0.25 mm, h'' = 1 / R at the
// tip), plus under 1 LSB of flooring; where the chord dips under an
// interval's line both of its ends are raised.
//
// Integer only, no heap: the tables and a stripe's requirements are caller
// memory.
#ifndef DEXMILL_CORE_CAM_ZIG_H
#define DEXMILL_CORE_CAM_ZIG_H

#include <stddef.h>
#include <stdint.h>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/status.h"
#include "core/tool/tool.h"

namespace dexmill {

constexpr int32_t kZigPhases = 16;           // requirement intervals per dexel along a stripe
constexpr int64_t kZigNone = INT64_MIN / 4;  // no design under the tool

// The tool's lower surface at the design's pitch and LSB: for each
// interval k (the tip from k / kZigPhases to (k + 1) / kZigPhases of a
// pitch past a dexel axis along the stripe) and each column offset (a
// along, b across), lower bounds of h at the interval's two ends in LSB, or
// kZigMiss where the column is never under the tool in the interval.
constexpr int32_t kZigMiss = INT32_MIN;
struct ZigTool {
  int32_t reach_dex = 0;  // K: columns |a|, |b| <= K + 1 can be under the tool
  int32_t side = 0;       // 2K + 3
  const int32_t* h_lsb = nullptr;  // [k][b + K + 1][a + K + 1][end 0 or 1]
  // [k][b + K + 1][3]: the first and last a + K + 1 not kZigMiss (first >
  // last: none), and the row's least h (to skip rows that cannot matter).
  const int32_t* span = nullptr;
};

// int32 words zig_tool_build needs for tool p at the geometry's pitch.
size_t zig_tool_words(const ToolProfile& p, const GridGeometry& geo);
// kBufferTooSmall when `n` words are too few; kToolTooLarge for a reach
// beyond kZigMaxReach dexels.
constexpr int32_t kZigMaxReach = 1023;
Status zig_tool_build(const ToolProfile& p, const GridGeometry& geo, int32_t* words, size_t n, ZigTool* out);

struct ZigOptions {
  bool along_y = false;      // stripes parallel to y (else x, the paper's)
  int32_t stepover_dex = 1;  // a stripe every this many dexel rows (the paper: 1)
  int32_t step_dex = 1;      // a position every this many dexels along it (the paper: 1)
  int64_t allowance_nm = 0;  // stock left above the design (roughing), >= 0
};

// What interval k past dexel u of the stripe at dexel row v (u, v: i, j
// for x stripes, j, i for y stripes) asks of the chord at its two ends
// (LSB above the design's z0): *left at k / kZigPhases, *right at
// (k + 1) / kZigPhases; kZigNone when no design column is under the tool.
void zig_interval_need(const DesignGrid& d, const ZigTool& t, bool along_y, int32_t u, int32_t v, int32_t k,
                       int64_t* left, int64_t* right);

// The stripes: along x, rows v = 0, stepover, ... and the last row; along y
// the same over columns. Positions along a stripe: u = 0, step, ... and the
// last dexel.
int32_t zig_stripe_count(const DesignGrid& d, const ZigOptions& o);
int32_t zig_stripe_row(const DesignGrid& d, const ZigOptions& o, int32_t s);  // v of stripe s
int32_t zig_positions(const DesignGrid& d, const ZigOptions& o);              // per stripe
int32_t zig_position_u(const DesignGrid& d, const ZigOptions& o, int32_t k);  // u of position k

// int64 words of scratch zig_stripe needs (one stripe's interval needs and
// the window maxima of the rows under the tool).
size_t zig_stripe_scratch(const DesignGrid& d, const ZigTool& t, const ZigOptions& o);

// The tips of stripe s, z_lsb[k] for position k (zig_positions of them):
// what the intervals on both sides ask at each position, raised where the
// chord to the next position passes under an interval's need, plus the
// allowance; never under `floor_lsb` (also what a tool over no design
// takes). kBufferTooSmall when scratch is short.
Status zig_stripe(const DesignGrid& d, const ZigTool& t, const ZigOptions& o, int32_t s, int64_t floor_lsb,
                  int64_t* scratch, size_t scratch_words, int64_t* z_lsb);

}  // namespace dexmill

#endif
