// The load of every move, measured as the simulation cuts it (core/engage/README.md):
// a feed move's path is sampled (core/engage/engage.h) on the stock before
// it (a shadow of the tops, read once the move is cut) at
// a spacing of max(pitch, R / 2), at most kEngageMaxSamples samples a
// move (a longer move's samples are its length over that apart), arcs
// along chords of a quarter-pitch sagitta; after it is cut, the volume it
// removed is read off a shadow of the tops (exact at grid precision: the
// sum of the top decrements times the cell area). A move whose engagement
// changes along it (entering a corner, breaking into a pocket) keeps its
// worst sample, not an average. Integer only, caller memory: it runs on
// the panel.
#ifndef DEXMILL_CORE_ENGAGE_ENGAGE_METER_H
#define DEXMILL_CORE_ENGAGE_ENGAGE_METER_H

#include <stddef.h>
#include <stdint.h>

#include "core/canon/canon.h"
#include "core/engage/engage.h"
#include "core/grid/grid.h"
#include "core/status.h"

namespace dexmill {

constexpr int kEngageMaxSamples = 128;

// One record's measurements.
struct EngageMove {
  uint32_t line = 0;
  bool feed = false;          // a feed or arc move (the others are not sampled)
  uint32_t samples = 0;
  EngageAt worst;             // the sample engaged over the widest arc (the first of equals)
  PointNm worst_at{0, 0, 0};  // its tip
  int64_t ae_max_nm = 0, ap_max_nm = 0;  // the largest of each over the samples
  EngageAt section;           // the sample of the largest cross-section (engage.h EngageAt::area_um2)
  PointNm area_at{0, 0, 0};   // where its edge met material: a radius ahead of its tip, half its depth up
  int64_t mrr_um3_per_min = 0;  // that cross-section times the feed: the removal rate at its peak
  uint64_t removed_lsb = 0;   // what the record removed, LSB x dexels
  int64_t feed_nm_per_min = 0;
  int32_t spindle_rpm = 0;
  int64_t time_us = 0;        // the record's estimated time (the simulation's time model)
  int64_t end_us = 0;         // the program's estimated time at its end
  // The uncut chip at the widest sample, from the feed per tooth F / (S z)
  // (0 without a spindle speed).
  int64_t fz_nm = 0;
  EngageChip chip;
  int32_t tool = 0;           // the tool number in the spindle
  // With the material's cutting coefficients (core/engage/engage_load.h;
  // has_load false without them): the tooth's largest tangential force,
  // and the spindle's torque and power at the largest cross-section.
  bool has_load = false;
  uint8_t material = 0;       // the material met there (an index of the run's composition)
  int64_t force_mn = 0, torque_mn_m = 0, power_mw = 0;
};

// Where a front end takes each move's measurements (a CSV, a plot).
class EngageSink {
 public:
  virtual void move(const EngageMove& m) = 0;

 protected:
  ~EngageSink() = default;
};

// The program's largest: the widest arc, the widest cut, the deepest, the
// highest removal rate (at the largest cross-section), the thickest chip,
// the largest force and power, each the first move that reached it, and
// how many feed moves were measured and engaged (and how many of those
// had no spindle speed).
struct EngageSummary {
  uint64_t moves = 0, engaged = 0;
  uint64_t no_speed = 0;  // engaged moves with no spindle speed: their chip, force and power unmeasured
  EngageMove angle, ae, ap, rate, chip, force, power;
};
void engage_summary_add(EngageSummary* s, const EngageMove& m);

// One sample of a straight feed move: where along it (horizontal distance
// from its start) and what it met.
struct EngageSample {
  int64_t s_nm = 0;
  EngageAt at;
};

struct EngageMeter {
  EngageTool tool;
  uint32_t* shadow = nullptr;  // caller memory, nx * ny: the tops before the record
  int64_t spacing_nm = 0;
  EngageMove move;             // the record being measured
  CanonRecord record{};        // and the record itself, sampled once it is cut
  GridRect pending = GridRect::none();  // changes between records (engage_meter_note), counted with the next
  // A straight feed move's samples, when kept (caller memory,
  // kEngageMaxSamples of them; null: not kept): engage_split.h splits a
  // move at their changes.
  EngageSample* trace = nullptr;
  uint32_t ntrace = 0;
  bool clockwise = true;
};

// Starts a meter of g (kBufferTooSmall: shadow_words < nx * ny).
template <class H>
Status engage_meter_init(EngageMeter* m, const DexelGrid<H>& g, uint32_t* shadow, size_t shadow_words);
// The tool in the spindle (its rings on this grid's pitch).
void engage_meter_set_tool(EngageMeter* m, const Tool& t, int64_t pitch_nm);
// Before the record is cut: the record, the spindle clockwise (M3) or not.
template <class H>
void engage_meter_before(EngageMeter* m, const DexelGrid<H>& g, const CanonRecord& r, bool clockwise,
                         int32_t spindle_rpm);
// After it is cut (`changed`: the grid's dirty rectangle): the removal;
// for a feed or arc move that removed anything, its path sampled on the
// shadow, which still holds the stock before it (a move that removed
// nothing was in air: no samples, no cost); the record's measurements in
// *out. Every record passes here, so that the shadow follows the grid.
// (The cut defers a move's end cap to the next record: a move's removal
// holds the previous one's end cap and leaves out its own.)
template <class H>
void engage_meter_after(EngageMeter* m, const DexelGrid<H>& g, GridRect changed, EngageMove* out);
// engage_meter_after in two steps, for a caller that colours the stock by
// each move's load (core/engage/engage_band.h) once it has measured it:
// measure (the shadow left as it was), then commit, which makes the
// shadow follow the grid and, with cls (nx * ny bytes, caller memory),
// gives `band` to every column the record lowered.
// The grid changed between records (a front end's frame made the cut
// flush a deferred end cap): the next record counts it as its own, as it
// would without the frame, so that frames change no measurement.
void engage_meter_note(EngageMeter* m, GridRect changed);
template <class H>
void engage_meter_measure(EngageMeter* m, const DexelGrid<H>& g, GridRect changed, EngageMove* out);
template <class H>
void engage_meter_commit(EngageMeter* m, const DexelGrid<H>& g, GridRect changed, uint8_t* cls, uint8_t band);

}  // namespace dexmill

#endif
