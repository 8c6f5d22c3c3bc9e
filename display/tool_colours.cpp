// The tool colour mode; see tool_colours.h.
#include "display/tool_colours.h"

#include "core/grid/removals.h"

namespace dexmill {

const Rgb kToolUncutColour{150, 150, 146};
const Rgb kToolPalette[kToolColourSlots] = {{230, 159, 0},  {86, 180, 233}, {0, 158, 115},  {240, 228, 66},
                                            {0, 114, 178},  {213, 94, 0},   {204, 121, 167}};

namespace {

// The class of the tool in the spindle, listing it on its first cut.
template <class H>
uint8_t current_class(ToolColours<H>* t, bool* listed) {
  if (t->current_class) return t->current_class;
  int32_t n = 0;
  while (n < t->ntools && t->tool[n] != t->current) ++n;
  if (n == t->ntools) {
    if (t->ntools < kToolColoursMaxTools) {
      t->tool[t->ntools++] = t->current;
      *listed = true;
    } else {
      ++t->unlisted;
    }
  }
  t->current_class = tool_colours_class_of(n);
  return t->current_class;
}

}  // namespace

template <class H>
void tool_colours_init(ToolColours<H>* t, const DexelGrid<H>& g, int32_t first_tool, uint8_t* cls, uint32_t* shadow,
                       uint32_t* luts) {
  t->grid = &g;
  t->shadow = shadow;
  t->pending = GridRect::none();
  t->ntools = 0;
  t->unlisted = 0;
  t->current = first_tool;
  t->current_class = 0;
  Rgb colour[kMaxColourClasses];
  colour[0] = kToolUncutColour;
  for (int32_t k = 0; k < kToolColourSlots; ++k) colour[k + 1] = kToolPalette[k];
  surface_colours_set(&t->colours, cls, luts, colour, kMaxColourClasses, nullptr, nullptr);
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  for (size_t k = 0; k < n; ++k) {
    cls[k] = 0;
    shadow[k] = g.top[k];
  }
}

template <class H>
void tool_colours_set_tool(ToolColours<H>* t, int32_t number) {
  if (number == t->current) return;
  t->current = number;
  t->current_class = 0;
}

template <class H>
void tool_colours_note(ToolColours<H>* t, GridRect changed) {
  t->pending.include(changed);
}

template <class H>
bool tool_colours_record(ToolColours<H>* t, GridRect changed) {
  GridRect r = t->pending;
  r.include(changed);
  t->pending = GridRect::none();
  bool listed = false;
  const DexelGrid<H>& g = *t->grid;
  uint8_t* cls = t->colours.cls;
  each_removal(t->shadow, g, r, [&](int32_t i, int32_t j, uint32_t, uint32_t now) {
    const uint8_t c = current_class(t, &listed);
    const size_t k = g.index(i, j);
    cls[k] = c;
    if (now != 0 || g.bottom[k] != 0) return;
    // Cut through: the hole's walls are the side faces of the dexels
    // around it, which take their own dexel's class (display/mesh.cpp).
    // Those no tool lowered take this one's, so a drilled hole shows its
    // drill rather than uncut stock (a ring a dexel wide on their tops too).
    const int32_t ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
    for (int n = 0; n < 4; ++n) {
      if (!g.contains(ni[n], nj[n])) continue;
      const size_t m = g.index(ni[n], nj[n]);
      if (cls[m] == 0 && !g.is_hole(ni[n], nj[n])) cls[m] = c;
    }
  });
  return listed;
}

#define DEXMILL_TOOL_COLOURS_INSTANTIATE(H)                                                                          \
  template void tool_colours_init<H>(ToolColours<H>*, const DexelGrid<H>&, int32_t, uint8_t*, uint32_t*, uint32_t*); \
  template void tool_colours_set_tool<H>(ToolColours<H>*, int32_t);                                                  \
  template void tool_colours_note<H>(ToolColours<H>*, GridRect);                                                     \
  template bool tool_colours_record<H>(ToolColours<H>*, GridRect);
DEXMILL_TOOL_COLOURS_INSTANTIATE(uint8_t)
DEXMILL_TOOL_COLOURS_INSTANTIATE(uint16_t)
DEXMILL_TOOL_COLOURS_INSTANTIATE(uint32_t)

}  // namespace dexmill
