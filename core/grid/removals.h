// The columns a record lowered, against a shadow of the tops before it:
// what the safety checks (core/safety/safety.h) and the process rules
// (core/safety/material_limits.h) walk after every record to charge each removal to
// the move that made it, and the tool colour mode (display/colour/tool_colours.h)
// to colour each column by the tool that lowered it. A walk over the grid
// alone, so it lives with the grid, where display/ may use it too.
#ifndef DEXMILL_CORE_GRID_REMOVALS_H
#define DEXMILL_CORE_GRID_REMOVALS_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/math/fixed.h"

namespace dexmill {

// For each column of `changed` (clipped to g) whose top is now below the
// shadow's, calls fn(i, j, was, now) with both tops in LSB; the shadow (nx *
// ny words) follows the grid over the whole rectangle.
template <class H, class Fn>
void each_removal(uint32_t* shadow, const DexelGrid<H>& g, GridRect changed, Fn fn) {
  const int32_t i0 = max_of(changed.i0, int32_t{0}), i1 = min_of(changed.i1, g.nx);
  const int32_t j0 = max_of(changed.j0, int32_t{0}), j1 = min_of(changed.j1, g.ny);
  for (int32_t j = j0; j < j1; ++j) {
    const size_t row = g.index(0, j);
    for (int32_t i = i0; i < i1; ++i) {
      uint32_t& was = shadow[row + static_cast<size_t>(i)];
      const uint32_t now = g.top[row + static_cast<size_t>(i)];
      const uint32_t before = was;
      was = now;
      if (now < before) fn(i, j, before, now);
    }
  }
}

// A colour mode's classes (cls, nx * ny) when column (i, j), just given
// class c, was cut through (now a hole): the hole's walls are the side
// faces of the columns around it, which take their own column's class
// (display/surface/mesh.cpp), so those no record lowered take c (a ring a
// dexel wide on their tops too) and a drilled hole shows its cut rather
// than uncut stock.
template <class H>
void class_hole_walls(uint8_t* cls, const DexelGrid<H>& g, int32_t i, int32_t j, uint32_t now, uint8_t c) {
  if (now != 0 || g.bottom[g.index(i, j)] != 0) return;
  const int32_t ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
  for (int n = 0; n < 4; ++n) {
    if (!g.contains(ni[n], nj[n])) continue;
    const size_t m = g.index(ni[n], nj[n]);
    if (cls[m] == 0 && !g.is_hole(ni[n], nj[n])) cls[m] = c;
  }
}

}  // namespace dexmill

#endif
