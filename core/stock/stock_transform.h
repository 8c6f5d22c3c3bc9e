// A setup: the stock turned into the next program's fixturing, exactly.
// Dexels hold a top and a bottom per column (paper §2.1), so a part turned
// over about X or Y is the same grid with rows or columns mirrored and each
// column's interval mirrored in z; a quarter turn about Z moves columns
// only. No resampling: every setup here is a permutation of the columns
// and an exact map of the heights, so turning back gives the same bits.
//
// A turn is about the centre of the stock's box (GridPlan::stock, whose
// edges are dexel axes: core/sim/stock_plan.h), so the part occupies the
// same box afterwards (a quarter turn of a non-square box swaps its X and
// Y extents about that centre): the usual second setup against the same
// stops. An offset then moves it, by whole dexels in X and Y and whole
// LSBs in Z; anything else is refused (a resample would lose the
// bit-exactness the project promises), with the nearest exact offset.
#ifndef DEXMILL_CORE_STOCK_STOCK_TRANSFORM_H
#define DEXMILL_CORE_STOCK_STOCK_TRANSFORM_H

#include <stddef.h>
#include <stdint.h>

#include "core/point.h"
#include "core/stock/stock_file.h"

namespace dexmill {

// One setup: first the flips (about the box's X axis: Y and Z mirrored;
// about its Y axis: X and Z mirrored), then quarter turns counterclockwise
// seen from above (0 to 3), then the offset. What `--setup flip-x`,
// `flip-y`, `rotate-90|180|270`, `offset=X,Y,Z` and their combinations give.
struct StockSetup {
  bool flip_x = false, flip_y = false;
  int quarter_turns = 0;
  PointNm offset_nm{0, 0, 0};
  bool identity() const {
    return !flip_x && !flip_y && quarter_turns % 4 == 0 && offset_nm.x_nm == 0 && offset_nm.y_nm == 0 &&
           offset_nm.z_nm == 0;
  }
};

enum class StockSetupError : uint8_t {
  kOk = 0,
  kOffsetNotExact,  // the offset is not whole dexels (X, Y) and LSBs (Z): *nearest says the exact one
  kCentreNotExact,  // a quarter turn of a box whose turned lattice falls between nanometres
  kScratch,         // a quarter turn of a non-square grid without scratch memory (stock_setup_scratch_bytes)
  kTopAboveStock,   // a flip of a column whose top is above the stock's top (nothing to mirror it about)
  kOutOfRange,      // the moved grid would leave the grid's ranges (core/grid/grid.h)
};
const char* stock_setup_message(StockSetupError e);

// The meta of the stock after s (geometry, plan, box, frame; bottoms_zero
// as a flip may leave it): what a front end plans the next run's grid
// with before the columns are there. The exactness checks of
// stock_apply_setup but the columns' (kScratch, kTopAboveStock).
StockSetupError stock_setup_meta(const StockSetup& s, StockMeta* m, PointNm* nearest = nullptr);

// Scratch bytes a setup of this stock needs (0 when it turns in place: no
// quarter turn, or a square grid).
size_t stock_setup_scratch_bytes(const StockMeta& m, const StockSetup& s);

// Applies s to the stock: its columns (tops, bottoms and the layers given:
// classes, lines, programs move with their columns), its geometry, plan
// and box, and the part's frame (so a design or a material can be met in
// the part's own frame). The tool's place is the machine's and stays.
// scratch: stock_setup_scratch_bytes of memory aligned for 32-bit words
// (null when that is 0). On an error nothing is changed; for
// kOffsetNotExact, *nearest (when not null) is the nearest exact offset.
StockSetupError stock_apply_setup(const StockSetup& s, StockMeta* m, const StockColumns& c, void* scratch,
                                  size_t scratch_bytes, PointNm* nearest = nullptr);

// What a program's setups did, as the chain records it (StockProgram's
// setup and setup_offset_nm): the part turned about its box's centre by a
// rotation or reflection, then moved. Every turn keeps the box's centre,
// so setups in a row compose as the product of their turns and the sum of
// their offsets. stock_setup_record starts from identity when *turn is all
// zeros.
void stock_setup_record(const StockSetup& s, int8_t turn[9], int64_t offset_nm[3]);
// A recorded turn and offset as a setup (flip-x when the turn negates Z,
// then the quarter turns); false when the turn is none a setup can make.
bool stock_setup_of_record(const int8_t turn[9], const int64_t offset_nm[3], StockSetup* out);

}  // namespace dexmill

#endif
