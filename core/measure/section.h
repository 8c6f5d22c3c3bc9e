// A section of the simulated part along a segment (`dexmill measure STOCK
// --distance X0,Y0,X1,Y1`): the grid sampled at n + 1 evenly spaced points
// from (x0, y0) to (x1, y1), n the segment's length over the pitch,
// rounded (about one sample a pitch; at least one step). Each sample is the
// column nearest its point (core/measure/measure_at.h): its heights within
// one LSB, the column within pitch / sqrt 2 of the point; the distance
// along is the point's own, exact to 1 nm. The design's height there when
// the caller gives the design's columns (core/design/design.h top_lsb, or
// kNoDesign where it misses). Integer only, no heap: a sample at a time.
#ifndef DEXMILL_CORE_MEASURE_SECTION_H
#define DEXMILL_CORE_MEASURE_SECTION_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/measure/measure_at.h"

namespace dexmill {

struct SectionSegment {
  int64_t x0_nm = 0, y0_nm = 0, x1_nm = 0, y1_nm = 0;
  int64_t length_nm = 0;  // sqrt((x1 - x0)^2 + (y1 - y0)^2), floored
  int32_t steps = 0;      // n: samples are 0..n
};

struct SectionSample {
  int64_t along_nm = 0;        // from (x0, y0) to the sample's point
  int64_t x_nm = 0, y_nm = 0;  // the sample's point
  MeasureAt at;                // the column nearest it
  bool have_design = false;    // the design covers the column
  int64_t design_nm = 0;       // its machine Z there
};

// The segment's length and steps for grid pitch pitch_nm; steps is capped at
// max_steps (then the samples are farther apart than a pitch).
SectionSegment section_segment(int64_t x0_nm, int64_t y0_nm, int64_t x1_nm, int64_t y1_nm, int64_t pitch_nm,
                               int32_t max_steps);

// Sample k (0..steps) of segment s over g; lines, programs and design_lsb
// (nx * ny each, or null) the stock's layers and the design's columns.
template <class H>
SectionSample section_sample(const DexelGrid<H>& g, const SectionSegment& s, int32_t k, const uint32_t* lines,
                             const uint8_t* programs, const int32_t* design_lsb);

}  // namespace dexmill

#endif
