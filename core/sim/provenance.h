// Which tool, and which program line, last lowered each column: the
// simulation's provenance observer (core/sim/simulation.h). What `--color
// tool` draws (display/colour/tool_colours.h: AXIS and CAMotics colour a
// simulation by tool), what the embedding API answers for a point, what a
// saved stock will carry.
//
// After every record the simulation reports the rectangle it changed
// (provenance_record), and the columns whose top went down there against
// a shadow of the tops (core/grid/removals.h) take the class of the tool
// in the spindle, and (when kept) the record's line. A column cut through
// (now a hole) also gives its class to the uncut columns beside it, whose
// side faces are the hole's walls (display/surface/mesh.cpp draws a wall in its own
// dexel's class), so a drilled hole shows its drill rather than uncut
// stock. Nothing of this runs unless it is set up: off, it costs nothing.
//
// Classes: 0 uncut, then one per tool in the order the tools first cut
// (the 1st tool class 1, ..., the slots-th class `slots`, the next class 1
// again: with more tools than slots the classes wrap, and a class stands for
// every tool whose position in that order is the same modulo slots).
#ifndef DEXMILL_CORE_SIM_PROVENANCE_H
#define DEXMILL_CORE_SIM_PROVENANCE_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/point.h"
#include "core/tool/tool.h"

namespace dexmill {

// Tools listed in the order they first cut; the ones after share the last
// listed tool's class (and are counted in `unlisted`).
constexpr int32_t kProvenanceMaxTools = 64;

template <class H>
struct ToolProvenance {
  const DexelGrid<H>* grid = nullptr;
  uint8_t* cls = nullptr;               // nx*ny classes, caller memory
  uint32_t* shadow = nullptr;           // nx*ny tops (LSB) as of the last record, caller memory
  uint32_t* line = nullptr;             // nx*ny: the line that last lowered each top (0: none); null: not kept
  uint8_t* program = nullptr;           // nx*ny: and the chain's program it is in (with line; null: not kept)
  uint8_t program_index = 0;            // the program this run is in the chain (a saved stock's count of programs)
  int32_t slots = 1;                    // classes 1..slots for the tools
  GridRect pending = GridRect::none();  // changes noted since the last record (provenance_note)
  int32_t tool[kProvenanceMaxTools] = {};  // tool numbers, in the order they first lowered a top
  int32_t ntools = 0;
  int32_t unlisted = 0;       // first cuts of tools past kProvenanceMaxTools
  int32_t current = 0;        // the tool number in the spindle
  uint8_t current_class = 0;  // its class; 0 until it first lowers a top
};

// The class of the n-th tool (0-based) in the order of first cuts.
inline uint8_t provenance_class_of(int32_t n, int32_t slots) {
  return static_cast<uint8_t>(1 + (n < kProvenanceMaxTools ? n : kProvenanceMaxTools - 1) % slots);
}

// Sets p up for grid g as it is now (every dexel uncut) with tool number
// `first_tool` in the spindle and `slots` classes (1..255) for the tools;
// cls (nx*ny bytes), shadow (nx*ny words) and lines (nx*ny words, or null)
// are caller memory.
template <class H>
void provenance_init(ToolProvenance<H>* p, const DexelGrid<H>& g, int32_t first_tool, int32_t slots, uint8_t* cls,
                     uint32_t* shadow, uint32_t* lines);

// A tool change: the tops lowered from the next record on are number's.
// (The record of the change itself cuts the previous tool's deferred end
// cap, which stays the previous tool's.)
template <class H>
void provenance_set_tool(ToolProvenance<H>* p, int32_t number);

// Sets p up for grid g over a saved stock's classes, lines and programs
// (core/stock/stock_file.h, read into cls, lines and programs already):
// its tools listed in the order they first cut (ntools of them, then
// `unlisted` more), tool number `current` in the spindle, this run the
// chain's program `program_index`. Null arrays are cleared-as-uncut ones
// the stock did not hold (then every column is uncut, line 0).
template <class H>
void provenance_resume(ToolProvenance<H>* p, const DexelGrid<H>& g, int32_t current, int32_t slots, uint8_t* cls,
                       uint32_t* shadow, uint32_t* lines, uint8_t* programs, bool have_classes, bool have_lines,
                       const int32_t* tools, int32_t ntools, int32_t unlisted, uint8_t program_index);

// Changes that are not a record's (a frame's flush showing a deferred end
// cap, which the next record puts back and cuts for good): kept for the
// next record's walk, not classified now, so that the classes do not depend
// on when frames are drawn.
template <class H>
void provenance_note(ToolProvenance<H>* p, GridRect changed);

// Where the line before left the tool: a deferred end cap (the Mill cuts
// the tool standing at a move's end with the next record, core/cut/mill.h)
// is that line's, as the gouge watch and the safety checks charge it
// (core/tool/tool.h profile_explains_cut).
struct ProvenanceOrigin {
  uint32_t line;
  PointNm end;
  const ToolProfile* tool;
};

// After a record of `line` that changed `changed` (and what was noted): the
// tops lowered there take the class of the tool in the spindle and, when
// lines are kept, the line (prev's where prev, or null, explains the cut).
// True when that tool is listed for the first time (a legend to update).
template <class H>
bool provenance_record(ToolProvenance<H>* p, GridRect changed, uint32_t line, const ProvenanceOrigin* prev = nullptr);

#define DEXMILL_PROVENANCE_EXTERN(H)                                                                                \
  extern template void provenance_init<H>(ToolProvenance<H>*, const DexelGrid<H>&, int32_t, int32_t, uint8_t*,    \
                                          uint32_t*, uint32_t*);                                                \
  extern template void provenance_resume<H>(ToolProvenance<H>*, const DexelGrid<H>&, int32_t, int32_t, uint8_t*,  \
                                            uint32_t*, uint32_t*, uint8_t*, bool, bool, const int32_t*, int32_t,   \
                                            int32_t, uint8_t);                                                     \
  extern template void provenance_set_tool<H>(ToolProvenance<H>*, int32_t);                                       \
  extern template void provenance_note<H>(ToolProvenance<H>*, GridRect);                                          \
  extern template bool provenance_record<H>(ToolProvenance<H>*, GridRect, uint32_t, const ProvenanceOrigin*);
DEXMILL_PROVENANCE_EXTERN(uint8_t)
DEXMILL_PROVENANCE_EXTERN(uint16_t)
DEXMILL_PROVENANCE_EXTERN(uint32_t)
#undef DEXMILL_PROVENANCE_EXTERN

}  // namespace dexmill

#endif
