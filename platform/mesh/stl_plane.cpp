// Nearly planar top faces; see stl_plane.h.
#include "platform/mesh/stl_plane.h"

#include <algorithm>

namespace dexmill {

template <class H>
bool PlaneRuns<H>::fits(int32_t lo, int32_t hi, int32_t j0, int32_t j1) const {
  const int64_t w = hi - lo, h = j1 - j0;
  const int64_t z00 = top(lo, j0), z10 = top(hi, j0), z01 = top(lo, j1), z11 = top(hi, j1);
  // Slopes A / 2w along x and B / 2h along y; everything times 2wh, so
  // exact: T - slopes becomes r = 2wh T - hA (x - lo) - wB (y - j0), at
  // most 2^50 in magnitude for 32-bit tops and sides of kPlaneSideCells.
  const int64_t a = z10 + z11 - z00 - z01, b = z01 + z11 - z00 - z10;
  const int64_t scale = 2 * w * h, limit = scale * tolerance_lsb_;
  int64_t r_min = INT64_MAX, r_max = INT64_MIN, top_min = INT64_MAX, bottom_max = INT64_MIN;
  for (int32_t y = j0; y <= j1; ++y) {
    const H* t = g_.top + g_.index(lo, y);
    const H* u = g_.bottom + g_.index(lo, y);
    const int64_t row_r = -w * b * (y - j0);
    for (int32_t x = 0; x <= hi - lo; ++x) {
      const int64_t tz = static_cast<int64_t>(t[x]);
      const int64_t r = scale * tz - h * a * x + row_r;
      r_min = std::min(r_min, r);
      r_max = std::max(r_max, r);
      top_min = std::min(top_min, tz);
      bottom_max = std::max(bottom_max, static_cast<int64_t>(u[x]));
    }
    if (r_max - r_min > limit) return false;
  }
  return top_min > bottom_max;
}

template <class H>
void PlaneRuns<H>::row(int32_t j, const std::vector<uint8_t>& mask, std::vector<int32_t>* lo, std::vector<int32_t>* hi,
                       std::vector<int64_t>* j0) {
  const int32_t n = static_cast<int32_t>(mask.size());
  std::fill(lo->begin(), lo->end(), -1);
  std::fill(hi->begin(), hi->end(), -1);
  auto take = [&](const PlaneRect& r) {
    for (int32_t i = r.lo; i < r.hi; ++i) (*lo)[i] = r.lo, (*hi)[i] = r.hi, (*j0)[i] = r.j0;
    next_.push_back(r);
  };
  next_.clear();
  // The faces through the last row go on first, where the whole
  // rectangle still fits with this row.
  for (const PlaneRect& r : open_) {
    bool full = j + 1 - r.j0 <= kPlaneSideCells;
    for (int32_t i = r.lo; full && i < r.hi; ++i) full = mask[i] == 15;
    if (full && fits(r.lo, r.hi, r.j0, j + 1)) take(r);
  }
  // The rest starts new runs, each as long as it fits.
  for (int32_t i = 0; i < n; ++i) {
    if ((*lo)[i] >= 0 || mask[i] != 15 || !fits(i, i + 1, j, j + 1)) continue;
    int32_t e = i + 1;
    while (e < n && (*lo)[e] < 0 && mask[e] == 15 && e + 1 - i <= kPlaneSideCells && fits(i, e + 1, j, j + 1)) ++e;
    take(PlaneRect{i, e, j});
    i = e - 1;
  }
  std::sort(next_.begin(), next_.end(), [](const PlaneRect& x, const PlaneRect& y) { return x.lo < y.lo; });
  open_.swap(next_);
}

template class PlaneRuns<uint8_t>;
template class PlaneRuns<uint16_t>;
template class PlaneRuns<uint32_t>;

}  // namespace dexmill
