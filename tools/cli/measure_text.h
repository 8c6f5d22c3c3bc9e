// The text of one point's measurement, as `dexmill measure --at` prints it
// and the live window prints it for a click (tools/run/run_live.cpp): one
// writer, so the two never say different things about the same column.
// The measurement is core/measure/measure_at.h's; this only words it.
#ifndef DEXMILL_TOOLS_CLI_MEASURE_TEXT_H
#define DEXMILL_TOOLS_CLI_MEASURE_TEXT_H

#include <cstdint>
#include <string>

#include "core/config.h"
#include "core/grid/grid.h"
#include "core/measure/measure_at.h"
#include "core/stock/stock_file.h"

namespace dexmill {
namespace cli {

// What a measurement reads: the grid and whichever layers there are.
struct MeasureSource {
  const DexelGrid<height_t>* grid = nullptr;
  const uint32_t* lines = nullptr;          // the line that last cut each column (null: not kept)
  const uint8_t* programs = nullptr;        // and its program in the chain (null: not kept)
  const StockProgram* program_list = nullptr;  // the chain's programs, for their names
  int32_t nprograms = 0;
  const int32_t* design_top_lsb = nullptr;  // the design's tops on the grid (null: no design)
  // Said in place of the line where none are kept.
  const char* no_lines = "the stock kept no lines";
};

// The line for the point (x, y), nm, e.g. "X12.000 Y8.000: top Z-3.0000,
// bottom Z-10.0000 mm (the column at ..., heights within ...); last cut by
// line 12; design Z-3.0000, cut - design +0.0000 mm (within 0.0004 mm)",
// without a newline; *got (when given) the measurement it words. False
// (nothing written) when the point is off the grid.
bool measure_at_text(const MeasureSource& s, int64_t x_nm, int64_t y_nm, std::string* out, MeasureAt* got = nullptr);

// The same for dexel (i, j) of the grid, measured at its axis.
bool measure_dexel_text(const MeasureSource& s, int32_t i, int32_t j, std::string* out, MeasureAt* got = nullptr);

}  // namespace cli
}  // namespace dexmill

#endif
