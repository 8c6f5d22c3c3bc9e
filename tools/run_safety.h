// The safety checks of `dexmill run` (core/check/safety.h): which are on,
// the watch and its memory, the warnings and the marks in the frames.
#ifndef DEXMILL_TOOLS_RUN_SAFETY_H
#define DEXMILL_TOOLS_RUN_SAFETY_H

#include <cstdint>
#include <string>
#include <vector>

#include "core/check/safety.h"
#include "core/config.h"
#include "core/grid/grid.h"
#include "platform/report_json.h"
#include "tools/run_options.h"

namespace dexmill {
namespace cli {

struct RunSafety {
  SafetyWatch watch;
  std::vector<uint32_t> shadow;
  std::vector<uint32_t> tiles;     // the holder check's bounds on tops
  std::vector<BoxNm> boxes;        // --fixture
  DexelGrid<uint32_t> fixture_grid;
  std::vector<uint32_t> fixture_top, fixture_bottom;
  std::vector<PointNm> marks;  // where the kept events are, for the frames
  size_t marked = 0;           // events already in marks
};


// Starts the watch on the grid as stocked: the stock's bottom is the grid's
// z0, the table (when has_table) at table_nm, the fixtures in a grid of
// their own on the stock's lattice. False (with *why) when the fixtures
// cannot be gridded (too many columns or too tall for the LSB).
bool safety_start(RunSafety* s, const DexelGrid<height_t>& g, const SafetyChoice& c, std::string* why);

// Marks the events found since the last call in the frames.
void safety_mark_new(RunSafety* s);

// Prints every kept event as FILE:LINE:1: warning: ... (at the end: a
// line's event grows while its end cap is cut), and how many were not kept.
void safety_print(const RunSafety& s, const std::string& file, const DexelGrid<height_t>& g);

// Into the report.
void safety_to_report(const RunSafety& s, RunReport* rep);

}  // namespace cli
}  // namespace dexmill

#endif
