// Which tool and line last cut each column; see provenance.h.
#include "core/sim/provenance.h"

#include "core/grid/removals.h"

namespace dexmill {

namespace {

// The class of the tool in the spindle, listing it on its first cut.
template <class H>
uint8_t current_class(ToolProvenance<H>* p, bool* listed) {
  if (p->current_class) return p->current_class;
  int32_t n = 0;
  while (n < p->ntools && p->tool[n] != p->current) ++n;
  if (n == p->ntools) {
    if (p->ntools < kProvenanceMaxTools) {
      p->tool[p->ntools++] = p->current;
      *listed = true;
    } else {
      ++p->unlisted;
    }
  }
  p->current_class = provenance_class_of(n, p->slots);
  return p->current_class;
}

}  // namespace

template <class H>
void provenance_resume(ToolProvenance<H>* p, const DexelGrid<H>& g, int32_t current, int32_t slots, uint8_t* cls,
                       uint32_t* shadow, uint32_t* lines, uint8_t* programs, bool have_classes, bool have_lines,
                       const int32_t* tools, int32_t ntools, int32_t unlisted, uint8_t program_index) {
  p->grid = &g;
  p->cls = cls;
  p->shadow = shadow;
  p->line = lines;
  p->program = lines ? programs : nullptr;
  p->program_index = program_index;
  p->slots = slots < 1 ? 1 : (slots > 255 ? 255 : slots);
  p->pending = GridRect::none();
  p->ntools = have_classes ? (ntools < 0 ? 0 : ntools > kProvenanceMaxTools ? kProvenanceMaxTools : ntools) : 0;
  for (int32_t k = 0; k < p->ntools; ++k) p->tool[k] = tools[k];
  p->unlisted = have_classes ? unlisted : 0;
  p->current = current;
  p->current_class = 0;
  // The tool in the spindle keeps its class when it cut before.
  for (int32_t k = 0; k < p->ntools; ++k)
    if (p->tool[k] == current) p->current_class = provenance_class_of(k, p->slots);
  const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
  for (size_t k = 0; k < n; ++k) {
    if (!have_classes) cls[k] = 0;
    shadow[k] = g.top[k];
    if (lines && !have_lines) lines[k] = 0;
    if (p->program && !have_lines) p->program[k] = 0;
  }
}

template <class H>
void provenance_init(ToolProvenance<H>* p, const DexelGrid<H>& g, int32_t first_tool, int32_t slots, uint8_t* cls,
                     uint32_t* shadow, uint32_t* lines) {
  provenance_resume(p, g, first_tool, slots, cls, shadow, lines, nullptr, false, false, nullptr, 0, 0, 0);
}

template <class H>
void provenance_set_tool(ToolProvenance<H>* p, int32_t number) {
  if (number == p->current) return;
  p->current = number;
  p->current_class = 0;
}

template <class H>
void provenance_note(ToolProvenance<H>* p, GridRect changed) {
  p->pending.include(changed);
}

template <class H>
bool provenance_record(ToolProvenance<H>* p, GridRect changed, uint32_t line, const ProvenanceOrigin* prev) {
  GridRect r = p->pending;
  r.include(changed);
  p->pending = GridRect::none();
  bool listed = false;
  const DexelGrid<H>& g = *p->grid;
  uint8_t* cls = p->cls;
  each_removal(p->shadow, g, r, [&](int32_t i, int32_t j, uint32_t, uint32_t now) {
    const uint8_t c = current_class(p, &listed);
    const size_t k = g.index(i, j);
    cls[k] = c;
    if (p->line) {
      const int64_t x = g.x0_nm + i * g.pitch_nm, y = g.y0_nm + j * g.pitch_nm, z = g.z0_nm + int64_t{now} * g.lsb_nm;
      p->line[k] = prev && profile_explains_cut(*prev->tool, prev->end, x, y, z, g.lsb_nm) ? prev->line : line;
      if (p->program) p->program[k] = p->program_index;
    }
    class_hole_walls(cls, g, i, j, now, c);  // a cut through: its walls show this class
  });
  return listed;
}

#define DEXMILL_PROVENANCE_INSTANTIATE(H)                                                                          \
  template void provenance_resume<H>(ToolProvenance<H>*, const DexelGrid<H>&, int32_t, int32_t, uint8_t*,         \
                                     uint32_t*, uint32_t*, uint8_t*, bool, bool, const int32_t*, int32_t, int32_t,  \
                                     uint8_t);                                                                    \
  template void provenance_init<H>(ToolProvenance<H>*, const DexelGrid<H>&, int32_t, int32_t, uint8_t*, uint32_t*, \
                                   uint32_t*);                                                                    \
  template void provenance_set_tool<H>(ToolProvenance<H>*, int32_t);                                              \
  template void provenance_note<H>(ToolProvenance<H>*, GridRect);                                                 \
  template bool provenance_record<H>(ToolProvenance<H>*, GridRect, uint32_t, const ProvenanceOrigin*);
DEXMILL_PROVENANCE_INSTANTIATE(uint8_t)
DEXMILL_PROVENANCE_INSTANTIATE(uint16_t)
DEXMILL_PROVENANCE_INSTANTIATE(uint32_t)
#undef DEXMILL_PROVENANCE_INSTANTIATE

}  // namespace dexmill
