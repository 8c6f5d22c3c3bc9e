// The default stock of a scanned program; see scan_stock.h.
#include "core/sim/scan_stock.h"

namespace dexmill {

const char* scan_stock_source_name(ScanStockSource s) {
  switch (s) {
    case ScanStockSource::kWorkpiece: return "workpiece comment";
    case ScanStockSource::kWorkpieceBox: return "workpiece comment's box";
    case ScanStockSource::kBlkForm: return "BLK FORM comments";
    default: return "program";
  }
}

ScanStockSource scan_default_stock(const ProgramScan& scan, StockBox* out) {
  if (!scan.have_workpiece) {
    *out = default_stock(scan.summary, scan.max_radius_nm);
    return ScanStockSource::kProgram;
  }
  // The program's (WORKPIECE,...) comment, as LinuxCNC's preview reads it.
  *out = scan.workpiece;
  if (scan.blk_form) return ScanStockSource::kBlkForm;
  return scan.workpiece_kind == WorkpieceKind::kBox ? ScanStockSource::kWorkpiece : ScanStockSource::kWorkpieceBox;
}

}  // namespace dexmill
