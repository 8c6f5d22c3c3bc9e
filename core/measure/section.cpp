// core/measure/section.h: a section along a segment.
#include "core/measure/section.h"

#include "core/design/design.h"
#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

SectionSegment section_segment(int64_t x0_nm, int64_t y0_nm, int64_t x1_nm, int64_t y1_nm, int64_t pitch_nm,
                               int32_t max_steps) {
  SectionSegment s;
  s.x0_nm = x0_nm;
  s.y0_nm = y0_nm;
  s.x1_nm = x1_nm;
  s.y1_nm = y1_nm;
  s.length_nm = hypot_floor(x1_nm - x0_nm, y1_nm - y0_nm);
  const int64_t n = pitch_nm > 0 ? div_round(s.length_nm, pitch_nm) : 1;
  s.steps = static_cast<int32_t>(n < 1 ? 1 : n > max_steps ? max_steps : n);
  return s;
}

template <class H>
SectionSample section_sample(const DexelGrid<H>& g, const SectionSegment& s, int32_t k, const uint32_t* lines,
                             const uint8_t* programs, const int32_t* design_lsb) {
  SectionSample o;
  // The point k / n of the way, rounded to the nanometre.
  o.x_nm = s.x0_nm + muldiv_round(s.x1_nm - s.x0_nm, k, s.steps);
  o.y_nm = s.y0_nm + muldiv_round(s.y1_nm - s.y0_nm, k, s.steps);
  o.along_nm = muldiv_round(s.length_nm, k, s.steps);
  o.at = measure_at(g, lines, programs, o.x_nm, o.y_nm);
  if (design_lsb && o.at.on_grid) {
    const int32_t d = design_lsb[g.index(o.at.i, o.at.j)];
    if (d != kNoDesign) {
      o.have_design = true;
      o.design_nm = g.z0_nm + static_cast<int64_t>(d) * g.lsb_nm;
    }
  }
  return o;
}

template SectionSample section_sample<uint8_t>(const DexelGrid<uint8_t>&, const SectionSegment&, int32_t,
                                               const uint32_t*, const uint8_t*, const int32_t*);
template SectionSample section_sample<uint16_t>(const DexelGrid<uint16_t>&, const SectionSegment&, int32_t,
                                                const uint32_t*, const uint8_t*, const int32_t*);
template SectionSample section_sample<uint32_t>(const DexelGrid<uint32_t>&, const SectionSegment&, int32_t,
                                                const uint32_t*, const uint8_t*, const int32_t*);

}  // namespace dexmill
