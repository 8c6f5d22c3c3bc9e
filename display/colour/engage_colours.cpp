// The engagement colour mode; see engage_colours.h.
#include "display/colour/engage_colours.h"

#include "display/colour/tool_colours.h"

namespace dexmill {

const Rgb kEngageBandColour[kEngageBands] = {{40, 90, 200}, {40, 170, 215}, {90, 190, 110},
                                             {235, 205, 50}, {240, 130, 30}, {190, 20, 90}};

const Rgb kEngageUnmeasuredColour{222, 218, 200};

void engage_colours_init(SurfaceColours* c, uint8_t* cls, uint32_t* luts) {
  Rgb colour[kEngageBandUnmeasured + 1];
  colour[0] = kToolUncutColour;
  for (int32_t k = 0; k < kEngageBands; ++k) colour[k + 1] = kEngageBandColour[k];
  colour[kEngageBandUnmeasured] = kEngageUnmeasuredColour;
  surface_colours_set(c, cls, luts, colour, kEngageBandUnmeasured + 1, nullptr, nullptr);
}

}  // namespace dexmill
