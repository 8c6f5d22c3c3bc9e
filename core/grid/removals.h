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

}  // namespace dexmill

#endif
