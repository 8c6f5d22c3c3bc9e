// Error assessment, paper §2.5: the workpiece D_W against the design D_D,
// dexel by dexel, with d = W.top - D.top (LSB; a hole's top is 0, the
// grid's z0). d > 0 is material left (undercut), d < 0 a gouge (overcut).
//
// Global error (§2.5.2): E = sum of d^2 over the columns with design
// material (eq. 2), E_rel = E / sum of D.top (eq. 3, heights above z0), kept
// as exact integers in LSB units; the caller converts once, at the end.
// Beside the paper's two figures: the largest gouge and leftover with their
// columns, the columns (area) and LSB columns (volume) beyond tolerance each
// way, the columns within tolerance, and a histogram of d in fixed bins.
// Columns outside the design that still hold material are counted apart:
// the design says nothing should be there, and E does not include them.
#ifndef DEXMILL_CORE_ASSESS_ASSESS_H
#define DEXMILL_CORE_ASSESS_ASSESS_H

#include <stddef.h>
#include <stdint.h>

#include "core/design/design.h"
#include "core/grid/grid.h"
#include "core/math/fixed.h"

namespace dexmill {

// A rectangle of machine XY (inclusive) with a tolerance of its own (the
// paper's §2.6: tight for bearing and contact faces, looser elsewhere). The
// last box containing a column wins.
struct ToleranceBox {
  int64_t x0_nm, y0_nm, x1_nm, y1_nm;
  int64_t tol_nm;
};

struct AssessOptions {
  // The columns assessed (clipped to the grid): a run passes its stock's,
  // leaving out the ring of holes around it (paper §2.2.1), which is no
  // material and no cut.
  GridRect region{0, 0, INT32_MAX, INT32_MAX};
  int64_t tol_nm = 50000;               // |d| <= tol is "within tolerance" (0.05 mm)
  const ToleranceBox* boxes = nullptr;  // per-region overrides
  size_t nboxes = 0;
};

// Histogram of d: bin k holds kAssessBinEdgesNm[k - 1] < d <= kAssessBinEdgesNm[k]
// (nm; the first bin is everything at or below the first edge, the last
// everything above the last edge).
constexpr int kAssessEdges = 14;
constexpr int kAssessBins = kAssessEdges + 1;
extern const int64_t kAssessBinEdgesNm[kAssessEdges];

struct AssessResult {
  uint64_t design_columns = 0;      // columns with design material
  uint64_t within_tol_columns = 0;  // of which |d| <= their tolerance
  U128 e_lsb2{0, 0};                // E = sum d^2 (LSB^2)
  uint64_t sum_design_top_lsb = 0;  // sum of D.top (LSB, tops below z0 count 0)
  uint64_t gouge_columns = 0, leftover_columns = 0;  // beyond tolerance
  uint64_t gouge_lsb = 0, leftover_lsb = 0;          // sum of |d| over those (LSB columns: volume)
  int64_t max_gouge_lsb = 0, max_leftover_lsb = 0;   // largest |d| each way (0: none)
  int32_t max_gouge_i = -1, max_gouge_j = -1;        // its column (first in row order)
  int32_t max_leftover_i = -1, max_leftover_j = -1;
  uint64_t outside_columns = 0;     // no design, but material in the workpiece
  uint64_t outside_lsb = 0;         // sum of their tops (LSB columns)
  uint64_t histogram[kAssessBins] = {};
};

// Paper §2.5.1's second view: d through a transfer function to a colour
// class per column (figure 10). White within the tolerance, then three bands
// each way: beyond tol, beyond 4 tol, beyond 16 tol (light to dark), green
// for material left, red for a gouge. Columns with no design, and holes where
// the design has none, are kBandNone.
enum ErrorBand : uint8_t {
  kBandNone = 0,
  kBandLeft1 = 1, kBandLeft2 = 2, kBandLeft3 = 3,  // d > tol, > 4 tol, > 16 tol
  kBandWithin = 4,                                   // |d| <= tol
  kBandGouge1 = 5, kBandGouge2 = 6, kBandGouge3 = 7,  // d < -tol, < -4 tol, < -16 tol
};
constexpr int kErrorBands = 8;
// The band limits in multiples of the tolerance.
constexpr int64_t kBandStep2 = 4, kBandStep3 = 16;

// The band of a difference d against a tolerance, both LSB.
ErrorBand error_band(int64_t d_lsb, int64_t tol_lsb);

// The bands of the columns in r (clipped to the grid) into band[] (nx*ny,
// row-major like the grid).
template <class H>
void assess_bands(const DexelGrid<H>& g, const DesignGrid& d, const AssessOptions& o, GridRect r, uint8_t* band);

// The tolerance of column (i, j), nm.
int64_t assess_tolerance_nm(const AssessOptions& o, const GridGeometry& geo, int32_t i, int32_t j);

// Compares grid g with design d (same geometry, else kBadArgument).
template <class H>
Status assess(const DexelGrid<H>& g, const DesignGrid& d, const AssessOptions& o, AssessResult* r);

extern template void assess_bands<uint8_t>(const DexelGrid<uint8_t>&, const DesignGrid&, const AssessOptions&, GridRect, uint8_t*);
extern template void assess_bands<uint16_t>(const DexelGrid<uint16_t>&, const DesignGrid&, const AssessOptions&, GridRect, uint8_t*);
extern template void assess_bands<uint32_t>(const DexelGrid<uint32_t>&, const DesignGrid&, const AssessOptions&, GridRect, uint8_t*);
extern template Status assess<uint8_t>(const DexelGrid<uint8_t>&, const DesignGrid&, const AssessOptions&, AssessResult*);
extern template Status assess<uint16_t>(const DexelGrid<uint16_t>&, const DesignGrid&, const AssessOptions&, AssessResult*);
extern template Status assess<uint32_t>(const DexelGrid<uint32_t>&, const DesignGrid&, const AssessOptions&, AssessResult*);

}  // namespace dexmill

#endif
