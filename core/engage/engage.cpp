// core/engage/engage.h: the engaged arc of a tool, sampled on the grid.
#include "core/engage/engage.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

void engage_tool_init(const Tool& t, int64_t pitch_nm, EngageTool* out) {
  EngageTool& e = *out;
  e.profile = tool_profile(t);
  e.flute_nm = t.flute_length_nm > 0 ? t.flute_length_nm : t.length_nm;
  const int64_t R = e.profile.radius_nm;
  // Inner rings only where the surface rises with r: none for a flat, the
  // corner's for a bull nose (beyond its flat radius R - rc).
  const int64_t inner_end = t.kind == ToolKind::kFlat ? R : t.kind == ToolKind::kBullNose ? R - e.profile.corner_nm : 0;
  const int64_t step = max_of(max_of(pitch_nm / 2, R / kEngageMaxRings), int64_t{1});
  e.nrings = 0;
  for (int64_t r = R; e.nrings < kEngageMaxRings && (r == R || r > inner_end); r -= step) {
    e.ring_r_nm[e.nrings] = r;
    e.ring_h_nm[e.nrings] = profile_height_nm(e.profile, r);
    ++e.nrings;
  }
  for (int k = 0; k <= kEngageSteps; ++k) {
    const SinCosQ30 sc = sincos_bam(static_cast<uint32_t>(k) * kEngageStepBam);
    e.cos_q30[k] = sc.cos_q30;
    e.sin_q30[k] = sc.sin_q30;
  }
}

template <class H>
void engage_at(const DexelGrid<H>& g, const EngageTool& t, const PointNm& at, int64_t ex_q30, int64_t ey_q30,
               bool clockwise, EngageAt* out) {
  EngageAt r;
  // phi = 0 on the entry side: left of the feed (clockwise spindle), or right.
  const int64_t sx = clockwise ? -ey_q30 : ey_q30, sy = clockwise ? ex_q30 : -ex_q30;
  int64_t cross_lo = INT64_MAX, cross_hi = INT64_MIN;
  int first = -1, last = -1;
  for (int k = 0; k <= kEngageSteps; ++k) {
    // The sample's direction: side * cos(phi) + feed * sin(phi), q30.
    const int64_t ux = (sx * t.cos_q30[k] + ex_q30 * t.sin_q30[k]) >> 30;
    const int64_t uy = (sy * t.cos_q30[k] + ey_q30 * t.sin_q30[k]) >> 30;
    bool hit = false;
    for (int ring = 0; ring < t.nrings && !hit; ++ring) {  // the outermost that bears material
      const int64_t rr = t.ring_r_nm[ring];
      const int64_t qx = at.x_nm + mul_shift(rr, ux, 30), qy = at.y_nm + mul_shift(rr, uy, 30);
      const int64_t i = div_round(qx - g.x0_nm, g.pitch_nm), j = div_round(qy - g.y0_nm, g.pitch_nm);
      if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) continue;
      const size_t c = g.index(static_cast<int32_t>(i), static_cast<int32_t>(j));
      if (g.top[c] == 0 && g.bottom[c] == 0) continue;
      const int64_t top = g.z0_nm + static_cast<int64_t>(g.top[c]) * g.lsb_nm;
      const int64_t surface = at.z_nm + t.ring_h_nm[ring];
      if (top <= surface + g.lsb_nm) continue;
      hit = true;
      r.ap_nm = max_of(r.ap_nm, min_of(top - at.z_nm, t.flute_nm));
      const int64_t cross = mul_shift(rr, t.cos_q30[k], 30);  // across the feed, from the entry side
      cross_lo = min_of(cross_lo, cross);
      cross_hi = max_of(cross_hi, cross);
    }
    if (!hit) continue;
    if (first < 0) first = k;
    last = k;
  }
  if (first >= 0) {
    r.engaged = true;
    r.entry_bam = static_cast<uint32_t>(first) * kEngageStepBam;
    r.exit_bam = static_cast<uint32_t>(last) * kEngageStepBam;
    r.ae_nm = cross_hi - cross_lo;
  }
  *out = r;
}

EngageChip engage_chip(const EngageAt& e, int64_t fz_nm) {
  EngageChip c;
  if (!e.engaged || fz_nm <= 0) return c;
  const uint32_t quarter = 0x40000000u;
  const uint32_t nearest = e.entry_bam > quarter ? e.entry_bam : e.exit_bam < quarter ? e.exit_bam : quarter;
  c.max_nm = mul_shift(fz_nm, sincos_bam(nearest).sin_q30, 30);
  const uint32_t span = e.exit_bam - e.entry_bam;
  if (span == 0) {
    c.mean_nm = c.max_nm;  // one sample: the chip there
    return c;
  }
  // (cos(entry) - cos(exit)) / span, span in radians: 2^32 bam = 2 pi.
  const int64_t dcos_q30 = static_cast<int64_t>(sincos_bam(e.entry_bam).cos_q30) - sincos_bam(e.exit_bam).cos_q30;
  // span_rad_q30 = span * 2 pi / 2^32 * 2^30 = span * pi / 2.
  const int64_t span_rad_q30 = muldiv_round(static_cast<int64_t>(span), 3373259426LL, int64_t{1} << 31);  // pi * 2^30
  c.mean_nm = muldiv_round(fz_nm, dcos_q30, span_rad_q30);
  return c;
}

#define DEXMILL_ENGAGE_INSTANTIATE(H) \
  template void engage_at<H>(const DexelGrid<H>&, const EngageTool&, const PointNm&, int64_t, int64_t, bool, EngageAt*);
DEXMILL_ENGAGE_INSTANTIATE(uint8_t)
DEXMILL_ENGAGE_INSTANTIATE(uint16_t)
DEXMILL_ENGAGE_INSTANTIATE(uint32_t)

}  // namespace dexmill
