// The tool colour mode; see tool_colours.h.
#include "display/colour/tool_colours.h"

namespace dexmill {

const Rgb kToolUncutColour{150, 150, 146};
const Rgb kToolPalette[kToolColourSlots] = {{230, 159, 0},  {86, 180, 233}, {0, 158, 115},  {240, 228, 66},
                                            {0, 114, 178},  {213, 94, 0},   {204, 121, 167}};

template <class H>
void tool_colours_init(SurfaceColours* c, const ToolProvenance<H>& p, uint32_t* luts) {
  Rgb colour[kMaxColourClasses];
  colour[0] = kToolUncutColour;
  for (int32_t k = 0; k < kToolColourSlots; ++k) colour[k + 1] = kToolPalette[k];
  surface_colours_set(c, p.cls, luts, colour, kMaxColourClasses, nullptr, nullptr);
}

#define DEXMILL_TOOL_COLOURS_INSTANTIATE(H) \
  template void tool_colours_init<H>(SurfaceColours*, const ToolProvenance<H>&, uint32_t*);
DEXMILL_TOOL_COLOURS_INSTANTIATE(uint8_t)
DEXMILL_TOOL_COLOURS_INSTANTIATE(uint16_t)
DEXMILL_TOOL_COLOURS_INSTANTIATE(uint32_t)

}  // namespace dexmill
