// Facets of the modal state, for telling a root error from its follow-ons
// (the rule is in interp_follow_on.cpp). A part of the block runner
// (block_runner.h), for the interpreter's own files only.
#ifndef DEXMILL_CORE_INTERP_FOLLOW_ON_H
#define DEXMILL_CORE_INTERP_FOLLOW_ON_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/block.h"
#include "core/gcode/error.h"
#include "core/interp/interp.h"

namespace dexmill {
namespace interp_detail {

enum Facet : uint16_t {
  kFacetX = 1 << 0,
  kFacetY = 1 << 1,
  kFacetZ = 1 << 2,
  kFacetPosition = kFacetX | kFacetY | kFacetZ,
  kFacetMotion = 1 << 3,       // modal motion, canned cycles' sticky R, Z, Q, P and levels
  kFacetFeed = 1 << 4,         // F and G93/G94
  kFacetPlane = 1 << 5,
  kFacetUnits = 1 << 6,
  kFacetDistance = 1 << 7,     // G90/G91
  kFacetArcDistance = 1 << 8,  // G90.1/G91.1
  kFacetOffsets = 1 << 9,      // work offsets, G92, tool length offset
  kFacetTool = 1 << 10,
  kFacetEnd = 1 << 11,         // whether the program ended (M2/M30)
  kFacetComp = 1 << 12,        // cutter radius compensation (G40, G41, G42)
  kFacetAll = (1 << 13) - 1,
};
// The facets a line would set, read leniently (it may not read at all).
uint16_t facets_written(const char* text, size_t len);
// The facets a block sets itself, from `s` (the state before it) on, given
// the facets now suspect.
uint16_t facets_set(const GcodeBlock& b, const InterpState& s, uint16_t suspect);
// Suspect facets once a block that sets `set` has run.
uint16_t suspect_after(uint16_t suspect, uint16_t set);
// What the check that raised an error read, and what the error blames.
struct ErrorFacets {
  uint16_t read;          // facets it read, after the block's own words applied
  uint16_t before_block;  // facets it read as they were before the block
  uint16_t blamed;        // facets the error says are wrong
};
ErrorFacets error_facets(GcodeError e, const GcodeBlock& b);

}  // namespace interp_detail
}  // namespace dexmill

#endif
