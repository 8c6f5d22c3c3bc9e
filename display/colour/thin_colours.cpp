// The thin-floor colour mode; see thin_colours.h.
#include "display/colour/thin_colours.h"

namespace dexmill {

const Rgb kThinBandColour[kThinBands] = {{196, 204, 214}, {240, 150, 40}, {220, 40, 32}};

namespace {

template <class H>
void classify(void* ctx, GridRect r, uint8_t* cls) {
  const ThinColours<H>* t = static_cast<const ThinColours<H>*>(ctx);
  const DexelGrid<H>& g = *t->grid;
  const GridRect c = clip_to_grid(g, r);
  for (int32_t j = c.j0; j < c.j1; ++j)
    for (int32_t i = c.i0; i < c.i1; ++i) cls[g.index(i, j)] = thin_band(g, i, j, t->limit_nm);
}

}  // namespace

template <class H>
ThinBand thin_band(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t limit_nm) {
  const size_t k = g.index(i, j);
  // Twice the thickness against the limit: "under half" without rounding it.
  const int64_t twice_nm = 2 * (static_cast<int64_t>(g.top[k]) - static_cast<int64_t>(g.bottom[k])) * g.lsb_nm;
  if (twice_nm < limit_nm) return kThinUnderHalf;
  return twice_nm < 2 * limit_nm ? kThinUnder : kThinNot;
}

template <class H>
void thin_colours_init(ThinColours<H>* t, const DexelGrid<H>& g, int64_t limit_nm, uint8_t* cls, uint32_t* luts) {
  t->grid = &g;
  t->limit_nm = limit_nm;
  surface_colours_set(&t->colours, cls, luts, kThinBandColour, kThinBands, classify<H>, t);
}

#define DEXMILL_THIN_COLOURS_INSTANTIATE(H)                                         \
  template ThinBand thin_band<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t); \
  template void thin_colours_init<H>(ThinColours<H>*, const DexelGrid<H>&, int64_t, uint8_t*, uint32_t*);
DEXMILL_THIN_COLOURS_INSTANTIATE(uint8_t)
DEXMILL_THIN_COLOURS_INSTANTIATE(uint16_t)
DEXMILL_THIN_COLOURS_INSTANTIATE(uint32_t)

}  // namespace dexmill
