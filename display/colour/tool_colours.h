// The tool colour mode (`--color tool`): every dexel in the colour
// of the tool that last lowered its top, as AXIS and CAMotics colour a
// simulation by tool, and the dexels no tool lowered in a neutral grey of
// their own, so stock left standing stands out. The classes are the
// simulation's provenance (core/sim/provenance.h, set up with
// kToolColourSlots slots), written as the cut happens; the renderer has
// nothing to classify (classify is null). Off, it costs nothing.
//
// Classes: 0 uncut, then one per tool in the order the tools first cut
// (the 1st tool class 1, ..., the 7th class 7, the 8th class 1 again: with
// more than kToolColourSlots tools the palette wraps, and a colour stands
// for every tool whose position in that order is the same modulo 7).
#ifndef DEXMILL_DISPLAY_COLOUR_TOOL_COLOURS_H
#define DEXMILL_DISPLAY_COLOUR_TOOL_COLOURS_H

#include <stdint.h>

#include "core/sim/provenance.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

constexpr int32_t kToolColourSlots = kMaxColourClasses - 1;  // class 0 is uncut

extern const Rgb kToolUncutColour;
// Distinct hues (Okabe and Ito's colour-blind-safe set, less black): none
// is the workpiece's grey, the cutter's red or the fixtures' steel blue.
extern const Rgb kToolPalette[kToolColourSlots];

// The class of the n-th tool (0-based) in the order of first cuts.
inline uint8_t tool_colours_class_of(int32_t n) { return provenance_class_of(n, kToolColourSlots); }

// The mode's colours over provenance classes p (made with kToolColourSlots
// slots); luts: kMaxColourClasses * kShadeLevels words of caller memory.
// p must stay where it is while a renderer uses c.
template <class H>
void tool_colours_init(SurfaceColours* c, const ToolProvenance<H>& p, uint32_t* luts);

#define DEXMILL_TOOL_COLOURS_EXTERN(H) \
  extern template void tool_colours_init<H>(SurfaceColours*, const ToolProvenance<H>&, uint32_t*);
DEXMILL_TOOL_COLOURS_EXTERN(uint8_t)
DEXMILL_TOOL_COLOURS_EXTERN(uint16_t)
DEXMILL_TOOL_COLOURS_EXTERN(uint32_t)
#undef DEXMILL_TOOL_COLOURS_EXTERN

}  // namespace dexmill

#endif
