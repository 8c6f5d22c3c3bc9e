// Where a straight probe move (G38.2-G38.5) meets the simulated stock: the
// tool in the spindle, or a probe's ball tip, moving from `from` to `to`,
// touches material when its lower surface reaches below a column's top
// (the column's axis within its radius: paper §2.1's dexels, each a point
// of the surface). The machine stops there; dexmill can say where,
// because it has the stock as cut so far (core/sim/simulation.h waits for
// the cut before a probe line).
//
//   toward (G38.2, G38.3): the first point of the move in contact;
//   away (G38.4, G38.5): the first point out of contact.
//
// Exact for a move along Z alone (the contact height is the highest of
// top(c) - height(r_c) over the footprint, a linear function of z). Any
// other direction is sampled at steps of at most a quarter pitch and, in
// Z, 1 um, then bisected to 1 nm: a feature narrower than a quarter pitch
// across the path can be passed over between two samples (the grid holds
// nothing narrower than a pitch).
#ifndef DEXMILL_CORE_CUT_PROBE_H
#define DEXMILL_CORE_CUT_PROBE_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace dexmill {

enum class ProbeResult : uint8_t {
  kTripped = 0,     // *stop is where the probe tripped
  kNoContact,       // it reached `to` without tripping
  kAlreadyTripped,  // in contact (toward) or out of it (away) at `from` already
};

// How far a tool with its tip at p is into material: the largest, over the
// columns under it, of top - (p.z + height(r)), nm (> 0: into it; INT64_MIN
// when no column with material is under it). A tool so thin that no
// column's axis is under it is measured on the column of the cell its tip
// is in (the nearest axis), at its tip.
template <class H>
int64_t probe_depth_nm(const DexelGrid<H>& g, const ToolProfile& tool, const PointNm& p);

template <class H>
ProbeResult probe_move(const DexelGrid<H>& g, const ToolProfile& tool, const PointNm& from, const PointNm& to,
                       bool toward, PointNm* stop);

}  // namespace dexmill

#endif
