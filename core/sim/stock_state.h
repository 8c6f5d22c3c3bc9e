// A run's stock as a stock file holds it (core/stock/stock_file.h): the
// grid plan a saved stock gives the next run, and the meta a run saves its
// stock with, the chain it continues plus itself. What the front ends
// (`dexmill run --stock/--save-stock`, the panel, the embedding API) share.
#ifndef DEXMILL_CORE_SIM_STOCK_STATE_H
#define DEXMILL_CORE_SIM_STOCK_STATE_H

#include <stdint.h>

#include "core/sim/simulation.h"
#include "core/sim/stock_plan.h"
#include "core/stock/stock_file.h"

namespace dexmill {

// The grid plan of a saved stock (its geometry, stock box and top).
GridPlan sim_plan_of_stock(const StockMeta& m);

// Why a stock cannot be continued or saved.
enum class StockStateError : uint8_t {
  kOk = 0,
  kHeightBits,     // the stock's heights are not this build's m bits
  kTooManyPrograms,  // the chain already holds kStockMaxPrograms programs
};

// A saved stock this build can continue: its heights' m bits are H's.
template <class H>
StockStateError sim_stock_fits(const StockMeta& m);

// The meta to save sim's stock with, after its run: the grid, the layers it
// keeps (provenance's), where the tool is, the chain (job.resume's programs,
// then this one, named `program`) and its totals. Material and design names
// are the front end's to fill (it knows the files).
// program_us is the time recorded for this program: the front end's best
// estimate where it has one (a blended plan's, core/canon/motion_plan.h),
// or -1 for the engine's own per-move clock.
template <class H>
StockStateError sim_stock_meta(const SimulationT<H>& sim, const char* program, StockMeta* out, int64_t program_us = -1);

}  // namespace dexmill

#endif
