// Cutter dexel set by analytic ray casts, paper §2.2.2.
#include "core/tool/cutter.h"

#include "core/math/fixed.h"

namespace dexmill {

int32_t cutter_reach_dex(const ToolProfile& p, int64_t pitch_nm) {
  int64_t k = p.radius_nm / pitch_nm;
  return k > kCutterMaxReach ? kCutterMaxReach + 1 : static_cast<int32_t>(k);
}

Status cutter_build(const ToolProfile& p, int64_t pitch_nm, int64_t lsb_nm, int32_t* words, size_t nwords,
                    CutterDexels* out) {
  if (pitch_nm <= 0 || lsb_nm <= 0) return Status::kBadArgument;
  const int32_t k = cutter_reach_dex(p, pitch_nm);
  if (k > kCutterMaxReach) return Status::kToolTooLarge;
  const int64_t top = div_round(p.length_nm, lsb_nm);
  if (top > (static_cast<int64_t>(1) << 30)) return Status::kToolTooLarge;
  if (!words || nwords < cutter_storage_words(k)) return Status::kBufferTooSmall;

  const int32_t side = 2 * k + 1;
  int32_t* row_lo = words;
  int32_t* row_hi = row_lo + side;
  int32_t* bottom = row_hi + side;
  int32_t* tops = bottom + static_cast<size_t>(side) * side;
  const int64_t r2max = p.radius_nm * p.radius_nm;
  int32_t min_b = INT32_MAX, max_b = INT32_MIN;
  for (int32_t dj = -k; dj <= k; ++dj) {
    int32_t lo = side, hi = -1;
    for (int32_t di = -k; di <= k; ++di) {
      const size_t idx = static_cast<size_t>(dj + k) * side + static_cast<size_t>(di + k);
      const int64_t x = di * pitch_nm, y = dj * pitch_nm;
      if (x * x + y * y > r2max) {  // the ray misses the tool: no dexel
        bottom[idx] = 0;
        tops[idx] = 0;
        continue;
      }
      const int64_t b = div_round(profile_height_r2_nm(p, static_cast<uint64_t>(x * x + y * y)), lsb_nm);
      bottom[idx] = static_cast<int32_t>(b);
      tops[idx] = static_cast<int32_t>(top);
      min_b = min_of<int32_t>(min_b, static_cast<int32_t>(b));
      max_b = max_of<int32_t>(max_b, static_cast<int32_t>(b));
      if (lo == side) lo = di + k;
      hi = di + k;
    }
    row_lo[dj + k] = lo;
    row_hi[dj + k] = hi;
  }
  out->reach_dex = k;
  out->side = side;
  out->row_lo = row_lo;
  out->row_hi = row_hi;
  out->bottom_lsb = bottom;
  out->top_lsb = tops;
  out->min_bottom_lsb = min_b;
  out->max_bottom_lsb = max_b;
  out->min_top_lsb = static_cast<int32_t>(top);
  out->max_top_lsb = static_cast<int32_t>(top);
  return Status::kOk;
}

}  // namespace dexmill
