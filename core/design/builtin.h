// The paper's four workpieces as built-in design parts (paper §3
// "Results"): the instrument panel, the smiley milled from the two-layer
// compound (figure 12), the free-form surface in marble (figures 14-15) and
// a tsuba in bronze (figure 16). Each is an analytic height field drawn in
// integer code (the paper's panel came from a scanned photograph; ours is
// drawn here), at the paper's resolution and with the paper's ball size in
// dexels, so that `dexmill run --demo NAME` can run the paper's loop: design
// -> zig path -> cut -> drawn in the stock's material -> assessed (§2.5).
//
// Integer only, no heap: a design is a pure function of the column's
// position, so a caller without memory for a whole design grid (a golden
// run on a microcontroller) can still evaluate it column by column.
#ifndef DEXMILL_CORE_DESIGN_BUILTIN_H
#define DEXMILL_CORE_DESIGN_BUILTIN_H

#include <stdint.h>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/status.h"

namespace dexmill {

struct BuiltinDesign {
  const char* name;          // "panel", "smiley", "freeform", "tsuba"
  const char* about;         // one line for `--demo list`
  int32_t nx, ny;            // the paper's resolution, dexels (Table 2)
  int64_t pitch_nm;          // dexel pitch: gives the part its physical size
  int64_t stock_height_nm;   // the block's height: bottom at z = 0, top here
  int32_t ball_dexels;       // the paper's ball-end cutter diameter, dexels (Table 2)
  const char* material;      // a preset of core/material/material_preset.h
  // The part's height over the point (x, y), nm above the block's bottom,
  // x and y in nm from dexel (0, 0)'s axis; within [floor_nm,
  // stock_height_nm] everywhere (every column has design material).
  int64_t (*height_nm)(int64_t x_nm, int64_t y_nm);
  int64_t floor_nm;          // the lowest height of the part (its thinnest floor)
};

int32_t builtin_design_count();
// i in [0, count); out of range gives the first design.
const BuiltinDesign& builtin_design_at(int32_t i);
// Null when `name` is no builtin's name.
const BuiltinDesign* builtin_design_find(const char* name);

// The geometry of a builtin's workpiece grid: nx x ny dexels of the
// builtin's pitch, x0 = y0 = 0 at the first dexel's axis, z0 = 0 at the
// block's bottom, the LSB from lsb_for_range(1.25 x stock height,
// height_bits) (headroom above the block, as the run's stock planning).
GridGeometry builtin_geometry(const BuiltinDesign& b, int height_bits);

// The design top of column (i, j) of a grid of geometry `geo` (the
// builtin's nx, ny, pitch and origin; any z0 and LSB): the height over the
// column's axis, rounded to the nearest LSB above z0 (error <= 0.5 LSB).
int32_t builtin_top_lsb(const BuiltinDesign& b, const GridGeometry& geo, int32_t i, int32_t j);

// Fills d (design_init'ed by the caller) with the part's design tops.
// kBadArgument when d's nx, ny, pitch or XY origin are not the builtin's
// (builtin_geometry), or its LSB is not positive.
Status builtin_design_fill(const BuiltinDesign& b, DesignGrid* d);

}  // namespace dexmill

#endif
