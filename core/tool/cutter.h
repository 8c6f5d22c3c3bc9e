// The cutter as a dexel set, paper §2.2.2.
//
// For each (di, dj) of the cutter's own grid, at the workpiece pitch and
// centred on the spindle axis, a vertical ray at horizontal distance
// r = pitch*sqrt(di^2 + dj^2) is intersected with the tool (its cutting shape
// and its shaft): the lower hit is the dexel's bottom, the shaft top its top.
// Rays that miss (r > R) belong to no dexel. Rows store the span of hit
// dexels, so the cutting loop needs no sentinel.
#ifndef DEXMILL_CORE_TOOL_CUTTER_H
#define DEXMILL_CORE_TOOL_CUTTER_H

#include <stddef.h>
#include <stdint.h>

#include "core/status.h"
#include "core/tool/tool.h"

namespace dexmill {

// Heights are relative to the tool tip, in workpiece LSB.
struct CutterDexels {
  int32_t reach_dex = 0;            // K = floor(R / pitch): rays at |di|, |dj| <= K can hit
  int32_t side = 0;                 // 2K + 1
  const int32_t* row_lo = nullptr;  // per row (dj + K): first di + K hit
  const int32_t* row_hi = nullptr;  // per row: last di + K hit (row_lo > row_hi: none)
  const int32_t* bottom_lsb = nullptr;  // side*side, index (dj+K)*side + (di+K)
  const int32_t* top_lsb = nullptr;     // side*side
  int32_t min_bottom_lsb = 0, max_bottom_lsb = 0;  // over hit dexels
  int32_t min_top_lsb = 0, max_top_lsb = 0;
};

// Largest K accepted (a 4095 x 4095 cutter set).
constexpr int32_t kCutterMaxReach = 2047;

// Number of int32 words of storage a cutter of reach K needs.
constexpr size_t cutter_storage_words(int32_t reach_dex) {
  return 2u * static_cast<size_t>(2 * reach_dex + 1) +
         2u * static_cast<size_t>(2 * reach_dex + 1) * static_cast<size_t>(2 * reach_dex + 1);
}

// K for a tool at a pitch.
int32_t cutter_reach_dex(const ToolProfile& p, int64_t pitch_nm);

// Builds the set into `words` (cutter_storage_words(K) of them). Heights are
// rounded to the nearest LSB (error <= 0.5 LSB + 0.5 nm). Fails with
// kToolTooLarge when K > kCutterMaxReach or the tool is longer than 2^30 LSB,
// kBufferTooSmall when `nwords` is short.
Status cutter_build(const ToolProfile& p, int64_t pitch_nm, int64_t lsb_nm, int32_t* words, size_t nwords,
                    CutterDexels* out);

}  // namespace dexmill

#endif
