// The marks a run draws over its pictures, once for `dexmill run`
// (tools/run/run_views.cpp) and the embedding API's views
// (display/api/view.cpp): each gouge the design's watch keeps, in red, at
// the design's top of its deepest column; each safety finding kept, in
// magenta, where it was when first kept (a line's finding grows while its
// end cap is cut: the mark stays where it was seen); after the cut, the
// tool's place where an input error stopped it, in amber, and the finding a
// --stop-at collision stopped at, in red. Brought up to date after every
// record (a SimObserver's record) and once after the cut; fixed arrays, no
// heap.
#ifndef DEXMILL_DISPLAY_API_RUN_MARKS_H
#define DEXMILL_DISPLAY_API_RUN_MARKS_H

#include <stddef.h>
#include <stdint.h>

#include "core/assess/gouge_watch.h"
#include "core/safety/safety.h"
#include "core/sim/simulation.h"
#include "display/view/stock_view.h"

namespace dexmill {

constexpr Rgb kGougeMarkColour{255, 32, 24};
constexpr Rgb kSafetyMarkColour{255, 40, 255};
constexpr Rgb kInputErrorMarkColour{255, 190, 0};
constexpr Rgb kStopMarkColour{255, 32, 24};
// A point a user picked (the live window's click, the API's dm_view_set_mark).
constexpr Rgb kClickMarkColour{40, 200, 255};

struct RunMarks {
  PointNm gouges[kGougeEventsMax];
  uint32_t ngouges = 0;
  uint64_t gouge_finds = 0;  // the simulation's count when the gouges were last taken
  PointNm safety[kSafetyEventsMax];
  uint32_t nsafety = 0;
  PointNm error_at{0, 0, 0}, stop_at{0, 0, 0};
  bool error = false, stop = false;
  ViewMarks lists[4];
};

// Where a gouge is marked: the design's top over its deepest column.
PointNm gouge_mark_point(const GougeEvent& e, const DexelGrid<height_t>& g);

// After a record: the gouges again when the watch found more, the safety
// findings kept since.
void run_marks_record(RunMarks* m, const Simulation& s);
// After the cut (s finished): the finish's gouges and findings, and the
// amber mark when the cut stopped at an input error, the red one when it
// stopped at a collision.
void run_marks_after_cut(RunMarks* m, const Simulation& s, bool stopped_at_input_error);
// The lists to draw, in order (gouges with a design, findings with the
// checks on, then the marks after the cut): their count, into m->lists.
int32_t run_marks_lists(RunMarks* m, const Simulation& s);

}  // namespace dexmill

#endif
