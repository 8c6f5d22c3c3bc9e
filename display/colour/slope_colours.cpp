// The slope colour mode; see slope_colours.h.
#include "display/colour/slope_colours.h"

#include "core/math/fixed.h"

namespace dexmill {

const int32_t kSlopeLimitDeg[kSlopeBands - 1] = {5, 30, 60};
const Rgb kSlopeBandColour[kSlopeBands] = {{196, 204, 214}, {236, 206, 110}, {226, 126, 44}, {150, 32, 36}};

namespace {

// tan^2 of each limit as num / den: tan^2 5 deg = 0.0076543 (8026 / 2^20,
// within 1e-7), tan^2 30 deg = 1/3, tan^2 60 deg = 3, exactly.
struct Tan2 {
  int64_t num, den;
};
const Tan2 kLimitTan2[kSlopeBands - 1] = {{8026, int64_t{1} << 20}, {1, 3}, {3, 1}};

template <class H>
void classify(void* ctx, GridRect r, uint8_t* cls) {
  const DexelGrid<H>& g = *static_cast<const SlopeColours<H>*>(ctx)->grid;
  // A dexel's gradient reads its four neighbours: the classes one past r.
  const GridRect c = clip_to_grid(g, GridRect{r.i0 - 1, r.j0 - 1, r.i1 + 1, r.j1 + 1});
  for (int32_t j = c.j0; j < c.j1; ++j)
    for (int32_t i = c.i0; i < c.i1; ++i) cls[g.index(i, j)] = slope_band(g, i, j);
}

}  // namespace

template <class H>
SlopeBand slope_band(const DexelGrid<H>& g, int32_t i, int32_t j) {
  const GradientLsb n = grid_gradient(g, i, j);
  // tan(angle) = |(dx, dy)| / dz. Scaled below 2^20 (exact for 16-bit
  // heights at any usual pitch), so |g|^2 * den stays under 2^62.
  int64_t dx = n.dx < 0 ? -n.dx : n.dx, dy = n.dy < 0 ? -n.dy : n.dy, dz = max_of<int64_t>(n.dz, 1);
  while (max_of(max_of(dx, dy), dz) >= (int64_t{1} << 20)) {
    dx >>= 1;
    dy >>= 1;
    dz = max_of<int64_t>(dz >> 1, 1);
  }
  const int64_t g2 = dx * dx + dy * dy, z2 = dz * dz;
  int32_t band = 0;
  while (band < kSlopeBands - 1 && g2 * kLimitTan2[band].den >= kLimitTan2[band].num * z2) ++band;
  return static_cast<SlopeBand>(band);
}

template <class H>
void slope_colours_init(SlopeColours<H>* s, const DexelGrid<H>& g, uint8_t* cls, uint32_t* luts) {
  s->grid = &g;
  surface_colours_set(&s->colours, cls, luts, kSlopeBandColour, kSlopeBands, classify<H>, s);
}

#define DEXMILL_SLOPE_COLOURS_INSTANTIATE(H)                                   \
  template SlopeBand slope_band<H>(const DexelGrid<H>&, int32_t, int32_t); \
  template void slope_colours_init<H>(SlopeColours<H>*, const DexelGrid<H>&, uint8_t*, uint32_t*);
DEXMILL_SLOPE_COLOURS_INSTANTIATE(uint8_t)
DEXMILL_SLOPE_COLOURS_INSTANTIATE(uint16_t)
DEXMILL_SLOPE_COLOURS_INSTANTIATE(uint32_t)

}  // namespace dexmill
