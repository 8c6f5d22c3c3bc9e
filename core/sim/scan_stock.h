// The stock and the pitch a run chooses from its first pass when it is
// given neither (core/sim/stock_plan.h says the rules): the program's
// (WORKPIECE,...) or BLK FORM comments' box when it has one, else the box
// of its motion. `dexmill run` (tools/run/run_setup.cpp plan_stock) and the
// embedding API's dm_scan_result both ask here, so that they agree.
#ifndef DEXMILL_CORE_SIM_SCAN_STOCK_H
#define DEXMILL_CORE_SIM_SCAN_STOCK_H

#include <stdint.h>

#include "core/sim/scan.h"
#include "core/sim/stock_plan.h"

namespace dexmill {

// Where a default stock comes from (the numbers are dexmill.h's DM_STOCK_FROM_*).
enum class ScanStockSource : uint8_t { kProgram = 0, kWorkpiece = 1, kWorkpieceBox = 2, kBlkForm = 3 };

// "program", "workpiece comment", "workpiece comment's box" (a cylinder's or
// tube's), "BLK FORM comments": the report's stock source.
const char* scan_stock_source_name(ScanStockSource s);

// The default stock of a scanned program.
ScanStockSource scan_default_stock(const ProgramScan& scan, StockBox* out);

// The default pitch for that stock: from the smallest tool the program loads.
inline int64_t scan_default_pitch_nm(const ProgramScan& scan, const StockBox& stock) {
  return default_pitch_nm(stock, scan.smallest_diameter_nm());
}

}  // namespace dexmill

#endif
