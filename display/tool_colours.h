// The tool colour mode (`--color tool`, issue 19): every dexel in the colour
// of the tool that last lowered its top, as AXIS and CAMotics colour a
// simulation by tool, and the dexels no tool lowered in a neutral grey of
// their own, so stock left standing stands out. The class byte of each
// dexel is written as the cut happens: after every record the cutting
// stage reports the rectangle it changed (tool_colours_record), and the
// columns whose top went down there against a shadow of the tops
// (core/grid/removals.h) take the class of the tool in the spindle. The
// renderer then has nothing to classify (classify is null). A column cut
// through (now a hole) also gives its class to the uncut columns beside it,
// whose side faces are the hole's walls. Nothing of
// this runs unless the mode is set up: off, it costs nothing.
//
// Classes: 0 uncut, then one per tool in the order the tools first cut
// (the 1st tool class 1, ..., the 7th class 7, the 8th class 1 again: with
// more than kToolColourSlots tools the palette wraps, and a colour stands
// for every tool whose position in that order is the same modulo 7).
#ifndef DEXMILL_DISPLAY_TOOL_COLOURS_H
#define DEXMILL_DISPLAY_TOOL_COLOURS_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "display/surface_colours.h"

namespace dexmill {

constexpr int32_t kToolColourSlots = kMaxColourClasses - 1;  // class 0 is uncut
// Tools listed in the order they first cut; the ones after share the last
// listed tool's class (and are counted in `unlisted`).
constexpr int32_t kToolColoursMaxTools = 64;

extern const Rgb kToolUncutColour;
// Distinct hues (Okabe and Ito's colour-blind-safe set, less black): none
// is the workpiece's grey, the cutter's red or the fixtures' steel blue.
extern const Rgb kToolPalette[kToolColourSlots];

template <class H>
struct ToolColours {
  const DexelGrid<H>* grid = nullptr;
  uint32_t* shadow = nullptr;           // nx*ny tops (LSB) as of the last record, caller memory
  GridRect pending = GridRect::none();  // changes noted since the last record (tool_colours_note)
  int32_t tool[kToolColoursMaxTools] = {};  // tool numbers, in the order they first lowered a top
  int32_t ntools = 0;
  int32_t unlisted = 0;       // first cuts of tools past kToolColoursMaxTools
  int32_t current = 0;        // the tool number in the spindle
  uint8_t current_class = 0;  // its class; 0 until it first lowers a top
  SurfaceColours colours;     // what the renderer takes (renderer_set_colours)
};

// The class of the n-th tool (0-based) in the order of first cuts.
inline uint8_t tool_colours_class_of(int32_t n) {
  return static_cast<uint8_t>(1 + (n < kToolColoursMaxTools ? n : kToolColoursMaxTools - 1) % kToolColourSlots);
}

// Sets t up for grid g as it is now (every dexel uncut) with tool number
// `first_tool` in the spindle; cls (nx*ny bytes), shadow (nx*ny words) and
// luts (kMaxColourClasses * kShadeLevels words) are caller memory. t must
// stay where it is while a renderer uses t->colours.
template <class H>
void tool_colours_init(ToolColours<H>* t, const DexelGrid<H>& g, int32_t first_tool, uint8_t* cls, uint32_t* shadow,
                       uint32_t* luts);

// A tool change: the tops lowered from the next record on are number's.
// Record what the previous tool cut first (the record of the change itself
// cuts the previous tool's deferred end cap).
template <class H>
void tool_colours_set_tool(ToolColours<H>* t, int32_t number);

// Changes that are not a record's (a frame's flush showing a deferred end
// cap, which the next record puts back and cuts for good): kept for the
// next record's walk, not classified now, so that the classes do not depend
// on when frames are drawn (the cap shows its old class meanwhile, under
// the drawn cutter).
template <class H>
void tool_colours_note(ToolColours<H>* t, GridRect changed);

// After a record that changed `changed` (and what was noted): the tops
// lowered there take the class of the tool in the spindle. True when that
// tool is listed for the first time (a legend to update).
template <class H>
bool tool_colours_record(ToolColours<H>* t, GridRect changed);

#define DEXMILL_TOOL_COLOURS_EXTERN(H)                                                                       \
  extern template void tool_colours_init<H>(ToolColours<H>*, const DexelGrid<H>&, int32_t, uint8_t*, uint32_t*, \
                                            uint32_t*);                                                      \
  extern template void tool_colours_set_tool<H>(ToolColours<H>*, int32_t);                                   \
  extern template void tool_colours_note<H>(ToolColours<H>*, GridRect);                                      \
  extern template bool tool_colours_record<H>(ToolColours<H>*, GridRect);
DEXMILL_TOOL_COLOURS_EXTERN(uint8_t)
DEXMILL_TOOL_COLOURS_EXTERN(uint16_t)
DEXMILL_TOOL_COLOURS_EXTERN(uint32_t)
#undef DEXMILL_TOOL_COLOURS_EXTERN

}  // namespace dexmill

#endif
