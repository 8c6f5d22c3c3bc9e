// The engagement colour mode (`--color engagement`): every dexel in the
// colour of the load band (core/engage/engage_band.h) of the move that last
// lowered its top, from cool (a light cut) to hot (a full slot, or over
// the limit), and the dexels no measured move lowered in the tool mode's
// neutral grey. The classes are the simulation's (Simulation::engage_classes,
// written as it cuts); the renderer has nothing to classify.
#ifndef DEXMILL_DISPLAY_COLOUR_ENGAGE_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_ENGAGE_COLOURS_H

#include <stdint.h>

#include "core/engage/engage_band.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

// Blue to crimson in steps a colour-blind reader tells apart by lightness
// as well as hue; none is the workpiece's grey or the cutter's red.
extern const Rgb kEngageBandColour[kEngageBands];
extern const Rgb kEngageUnmeasuredColour;  // plunges: a pale neutral, lighter than uncut stock

// The mode's colours over classes cls (nx * ny, 0 uncut, 1..kEngageBands,
// kEngageBandUnmeasured);
// luts: kMaxColourClasses * kShadeLevels words of caller memory.
void engage_colours_init(SurfaceColours* c, uint8_t* cls, uint32_t* luts);

}  // namespace dexmill

#endif
