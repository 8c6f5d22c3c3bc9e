// The error view's colour mode; see error_colours.h.
#include "display/colour/error_colours.h"

namespace dexmill {

const Rgb kErrorBandColour[kErrorBands] = {{196, 204, 214}, {160, 222, 160}, {70, 180, 80},  {20, 110, 40},
                                           {248, 248, 248}, {250, 160, 150}, {228, 72, 60},  {140, 20, 20}};

namespace {
template <class H>
void classify(void* ctx, GridRect r, uint8_t* cls) {
  const ErrorColours<H>* e = static_cast<const ErrorColours<H>*>(ctx);
  assess_bands(*e->grid, *e->design, e->opt, r, cls);
}
}  // namespace

template <class H>
void error_colours_init(ErrorColours<H>* e, const DexelGrid<H>& g, const DesignGrid& d, const AssessOptions& o,
                        uint8_t* cls, uint32_t* luts) {
  e->grid = &g;
  e->design = &d;
  e->opt = o;
  e->colours.cls = cls;
  e->colours.luts = luts;
  e->colours.nclasses = kErrorBands;
  for (int k = 0; k < kErrorBands; ++k) e->colours.colour[k] = kErrorBandColour[k];
  e->colours.classify = classify<H>;
  e->colours.ctx = e;
}

template void error_colours_init<uint8_t>(ErrorColours<uint8_t>*, const DexelGrid<uint8_t>&, const DesignGrid&,
                                          const AssessOptions&, uint8_t*, uint32_t*);
template void error_colours_init<uint16_t>(ErrorColours<uint16_t>*, const DexelGrid<uint16_t>&, const DesignGrid&,
                                           const AssessOptions&, uint8_t*, uint32_t*);
template void error_colours_init<uint32_t>(ErrorColours<uint32_t>*, const DexelGrid<uint32_t>&, const DesignGrid&,
                                           const AssessOptions&, uint8_t*, uint32_t*);

}  // namespace dexmill
