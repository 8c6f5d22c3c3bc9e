// Engagement: what the cutting edge meets at a position of a move, read
// from the stock as it stands before the move cuts (Fussell, Jerard and
// Hemmett, J. Manuf. Sci. Eng. 123(2), 2001: a discrete height model is
// enough to tell a tool's load). Integer only, no heap: it runs on the
// panel beside the cut.
//
// The tooth angle phi runs over the front half of the cutter, from the
// side a tooth enters the cut to the side it leaves: 0 beside the tool on
// the left of the feed direction for a spindle turning clockwise seen from
// above (M3; on the right for M4), a quarter turn straight ahead, a half
// turn beside it on the other side. A tooth's chip there is f_z sin(phi)
// thick.
//
// Where the edge meets material: at a height h above the tip the edge is
// a circle of radius r(h), and in a move the front half of that circle is
// the front of what the move has swept at that height. A point there is
// at least r(h) from every earlier position of the move, where the tool's
// surface stood at least as high (for a level or descending move), so the
// stock before the move is the stock the edge meets there. The samples:
// rings of radius r about the axis, every kEngageStepBam of phi, on the
// periphery and, where the lower surface rises with r (a ball, a bull
// nose's corner, a V-bit), rings inward a pitch apart (at most
// kEngageMaxRings); a sample bears material when the column under it
// (the nearest axis) has its top more than one LSB above the surface there
// (tip + height(r)). At each phi the outermost ring that bears material
// counts. (A flat's or a bull's flat inner rings are inside what the move
// has already cut to the tip's height: they do not count. A rising ramp
// meets less than the stock before it shows: there an upper bound.)
//
// What a position gives (EngageAt): the first and last engaged phi (entry
// and exit), the radial width a_e (the engaged samples' spread across the
// feed direction), the axial depth a_p (the highest material above the tip
// among them, at most the flute length), and the chip's cross-section A
// across the feed: at each engaged phi the material above the tool's
// lower surface, min(top, tip + flutes) - (tip + height(|y|)) at y = r
// cos(phi) across the feed, over a strip r sin(phi) dphi wide (the front's
// arc element seen across the feed), summed; A times the feed is the
// removal rate there. Error: the angles within half a step (1 degree) plus
// the grid's pitch seen from the ring (pitch / r radians); a_e within a
// pitch and a ring step; a_p within an LSB; A within 0.1 % of the
// sampled sum's integral (2-degree strips) plus a pitch's strip of the
// depth on either edge (core/engage/README.md).
#ifndef DEXMILL_CORE_ENGAGE_ENGAGE_H
#define DEXMILL_CORE_ENGAGE_ENGAGE_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace dexmill {

constexpr int kEngageSteps = 90;                               // phi from 0 to a half turn, both ends included
constexpr uint32_t kEngageStepBam = 0x80000000u / kEngageSteps;  // two degrees, binary angle
constexpr int kEngageMaxRings = 64;

// A tool prepared for engagement on a grid: its profile, its flute length,
// and the rings' radii (outermost first) and the lower surface's height on
// each.
struct EngageTool {
  ToolProfile profile{};
  int64_t flute_nm = 0;  // cutting length above the tip
  int32_t flutes = kToolFlutesAssumed;  // the tool's, or the assumed count
  int32_t nrings = 0;
  int64_t ring_r_nm[kEngageMaxRings] = {};
  int64_t ring_h_nm[kEngageMaxRings] = {};
  int64_t ring_cells_q16[kEngageMaxRings] = {};  // r in the grid's pitches, q16 (the samples' offsets without a division)
  int64_t ring_dphi_nm[kEngageMaxRings] = {};    // r times a step (pi / 90): a strip's width over sin(phi)
  // The lower surface's height under each ring's sample k across the feed
  // (at |r cos(phi_k)|; 0 for a flat): the chip's strip there, looked up
  // rather than a square root a sample (a radius of at most half a metre:
  // it fits).
  int32_t ring_floor_nm[kEngageMaxRings][kEngageSteps + 1] = {};
  bool cells_narrow = true;  // every ring_cells_q16 below 2^31: an offset is one 64-bit product
  // cos and sin of each step's phi, q30 (phi_k = k * kEngageStepBam).
  int32_t cos_q30[kEngageSteps + 1] = {};
  int32_t sin_q30[kEngageSteps + 1] = {};
};
void engage_tool_init(const Tool& t, int64_t pitch_nm, EngageTool* out);

struct EngageAt {
  bool engaged = false;
  uint32_t entry_bam = 0, exit_bam = 0;  // phi of the first and last engaged samples
  int64_t ae_nm = 0;                     // radial width of cut
  int64_t ap_nm = 0;                     // axial depth of cut
  int64_t area_um2 = 0;                  // the chip's cross-section across the feed
  uint32_t angle_bam() const { return engaged ? exit_bam - entry_bam : 0; }
};

// The tool with its tip at `at`, feeding along the horizontal direction
// (ex, ey) (a q30 unit vector), the spindle clockwise (M3) or not. The
// grid is the stock before the move.
template <class H>
void engage_at(const DexelGrid<H>& g, const EngageTool& t, const PointNm& at, int64_t ex_q30, int64_t ey_q30,
               bool clockwise, EngageAt* out);
// The same on tops alone (nx * ny of geo, LSB; 0: no material): a shadow
// of the stock before the move (core/engage/engage_meter.h). `cap` (or
// null): where the tool stood at the move's start, its footprint there
// already cut to its lower surface (the cut defers that end cap to the
// next record, so the shadow may still show it: core/cut/mill.h).
void engage_at_tops(const GridGeometry& geo, const uint32_t* tops, const EngageTool& t, const PointNm& at,
                    int64_t ex_q30, int64_t ey_q30, bool clockwise, const PointNm* cap, EngageAt* out);

// The uncut chip's thickness over the engaged arc for a feed per tooth
// f_z: the largest, f_z sin(phi) at the phi nearest a quarter turn, and
// the mean, f_z (cos(entry) - cos(exit)) / (exit - entry) (radians): chip
// thinning in both. Within 2 nm + 1e-8 f_z of the exact (CORDIC, q30).
struct EngageChip {
  int64_t max_nm = 0, mean_nm = 0;
};
EngageChip engage_chip(const EngageTool& t, const EngageAt& e, int64_t fz_nm);

}  // namespace dexmill

#endif
