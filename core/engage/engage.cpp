// core/engage/engage.h: the engaged arc of a tool, sampled on the grid.
#include "core/engage/engage.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

void engage_tool_init(const Tool& t, int64_t pitch_nm, EngageTool* out) {
  EngageTool& e = *out;
  e.profile = tool_profile(t);
  e.flute_nm = t.flute_length_nm > 0 ? t.flute_length_nm : t.length_nm;
  e.flutes = t.flutes > 0 ? t.flutes : kToolFlutesAssumed;
  const int64_t R = e.profile.radius_nm;
  // Inner rings only where the surface rises with r: none for a flat, the
  // corner's for a bull nose (beyond its flat radius R - rc).
  const int64_t inner_end = t.kind == ToolKind::kFlat ? R : t.kind == ToolKind::kBullNose ? R - e.profile.corner_nm : 0;
  const int64_t step = max_of(max_of(pitch_nm, R / kEngageMaxRings), int64_t{1});
  e.nrings = 0;
  e.cells_narrow = true;
  for (int64_t r = R; e.nrings < kEngageMaxRings && (r == R || r > inner_end); r -= step) {
    e.ring_r_nm[e.nrings] = r;
    e.ring_h_nm[e.nrings] = profile_height_nm(e.profile, r);
    e.ring_cells_q16[e.nrings] = muldiv_round(r, int64_t{1} << 16, max_of<int64_t>(pitch_nm, 1));
    if (e.ring_cells_q16[e.nrings] >= (int64_t{1} << 31)) e.cells_narrow = false;
    e.ring_dphi_nm[e.nrings] = muldiv_round(r, 3373259426LL, int64_t{90} << 30);  // r pi / 90 (pi q30)
    ++e.nrings;
  }
  for (int k = 0; k <= kEngageSteps; ++k) {
    const SinCosQ30 sc = sincos_bam(static_cast<uint32_t>(k) * kEngageStepBam);
    e.cos_q30[k] = sc.cos_q30;
    e.sin_q30[k] = sc.sin_q30;
  }
  const bool flat = e.profile.kind == ToolKind::kFlat;
  for (int ring = 0; ring < e.nrings; ++ring)
    for (int k = 0; k <= kEngageSteps; ++k) {
      const int64_t cross = mul_shift(e.ring_r_nm[ring], e.cos_q30[k], 30);
      e.ring_floor_nm[ring][k] = flat ? 0 : static_cast<int32_t>(profile_height_nm(e.profile, cross < 0 ? -cross : cross));
    }
}

namespace {

// The material a column holds where the tool already stood at `cap` (its
// footprint cut to its lower surface there): top_nm at most that surface.
inline int64_t below_cap(const GridGeometry& g, const EngageTool& t, const PointNm& cap, int64_t i, int64_t j, int64_t top_nm) {
  const int64_t dx = g.x0_nm + i * g.pitch_nm - cap.x_nm, dy = g.y0_nm + j * g.pitch_nm - cap.y_nm;
  const int64_t R = t.profile.radius_nm;
  if (dx >= R || dx <= -R || dy >= R || dy <= -R) return top_nm;
  const uint64_t r2 = static_cast<uint64_t>(dx * dx) + static_cast<uint64_t>(dy * dy);
  if (r2 >= static_cast<uint64_t>(R) * static_cast<uint64_t>(R)) return top_nm;
  return min_of(top_nm, cap.z_nm + profile_height_r2_nm(t.profile, r2));
}

// top(cell): the column's top in LSB (0 or a negative: no material).
template <bool kNarrow, bool kInside, class Top>
void engage_on(const GridGeometry& g, Top top_of, const EngageTool& t, const PointNm& at, int64_t ex_q30, int64_t ey_q30,
               bool clockwise, const PointNm* cap, EngageAt* out) {
  EngageAt r;
  // phi = 0 on the entry side: left of the feed (clockwise spindle), or right.
  const int64_t sx = clockwise ? -ey_q30 : ey_q30, sy = clockwise ? ex_q30 : -ex_q30;
  int64_t cross_lo = INT64_MAX, cross_hi = INT64_MIN;
  int64_t area_nm2 = 0;
  int first = -1, last = -1;
  // The tool's axis in the grid's pitches, q16: the samples' columns are
  // offsets from it (the rings' radii in pitches, turned), no division.
  const int64_t ci_q16 = muldiv_floor(at.x_nm - g.x0_nm, int64_t{1} << 16, g.pitch_nm);
  const int64_t cj_q16 = muldiv_floor(at.y_nm - g.y0_nm, int64_t{1} << 16, g.pitch_nm);
  constexpr int64_t kHalf = int64_t{1} << 15, kFar = int64_t{1} << 48;
  // A column bears material at a ring when its top is more than an LSB
  // above the lower surface there: top_lsb above this threshold (at least
  // 0, so that an empty column, top 0, never does).
  int64_t above_lsb[kEngageMaxRings];
  for (int ring = 0; ring < t.nrings; ++ring)
    above_lsb[ring] = max_of(div_floor(at.z_nm + t.ring_h_nm[ring] + g.lsb_nm - g.z0_nm, g.lsb_nm), int64_t{0});
  for (int k = 0; k <= kEngageSteps; ++k) {
    // The sample's direction: side * cos(phi) + feed * sin(phi), q30.
    const int64_t ux = (sx * t.cos_q30[k] + ex_q30 * t.sin_q30[k]) >> 30;
    const int64_t uy = (sy * t.cos_q30[k] + ey_q30 * t.sin_q30[k]) >> 30;
    bool hit = false;
    for (int ring = 0; ring < t.nrings && !hit; ++ring) {  // the outermost that bears material
      const int64_t rr = t.ring_r_nm[ring], rc = t.ring_cells_q16[ring];
      // rc < 2^31 and |u| <= 2^30 + 2: the product fits; a ring of 2^15
      // pitches and more (a tool far wider than its grid) takes the
      // clamped path, and lands off any grid.
      const int64_t di = kNarrow ? (rc * ux) >> 30 : clamp(mul_shift(rc, ux, 30), -kFar, kFar);
      const int64_t dj = kNarrow ? (rc * uy) >> 30 : clamp(mul_shift(rc, uy, 30), -kFar, kFar);
      const int64_t i = (ci_q16 + di + kHalf) >> 16, j = (cj_q16 + dj + kHalf) >> 16;
      if (!kInside && (i < 0 || j < 0 || i >= g.nx || j >= g.ny)) continue;
      const int64_t lsb = top_of(static_cast<size_t>(j) * static_cast<size_t>(g.nx) + static_cast<size_t>(i));
      if (lsb <= above_lsb[ring]) continue;
      int64_t top = g.z0_nm + lsb * g.lsb_nm;
      if (cap) {  // material in the shadow, but maybe inside the footprint left at the start
        top = below_cap(g, t, *cap, i, j, top);
        if (top <= at.z_nm + t.ring_h_nm[ring] + g.lsb_nm) continue;
      }
      hit = true;
      r.ap_nm = max_of(r.ap_nm, min_of(top - at.z_nm, t.flute_nm));
      const int64_t cross = mul_shift(rr, t.cos_q30[k], 30);  // across the feed, from the entry side
      cross_lo = min_of(cross_lo, cross);
      cross_hi = max_of(cross_hi, cross);
      // The strip across the feed at y = cross: the material above the
      // lower surface there (a flat's is its tip inside R; ring_floor_nm).
      const int64_t depth = min_of(top - at.z_nm, t.flute_nm) - t.ring_floor_nm[ring][k];
      if (depth > 0) area_nm2 += depth * ((t.ring_dphi_nm[ring] * t.sin_q30[k]) >> 30);  // a tool under a metre: a term below 2^55
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
    r.area_um2 = area_nm2 / 1000000;
  }
  *out = r;
}

// Every ring's samples on the grid when the tool's disc, a pitch wider,
// is inside it (the common case): no bounds test a sample.
template <class Top>
void engage_dispatch(const GridGeometry& g, Top top_of, const EngageTool& t, const PointNm& at, int64_t ex_q30,
                     int64_t ey_q30, bool clockwise, const PointNm* cap, EngageAt* out) {
  const int64_t reach = t.profile.radius_nm + 2 * g.pitch_nm;
  const bool inside = t.cells_narrow && at.x_nm - reach >= g.x0_nm && at.y_nm - reach >= g.y0_nm &&
                      at.x_nm + reach <= g.x0_nm + (g.nx - 1) * g.pitch_nm &&
                      at.y_nm + reach <= g.y0_nm + (g.ny - 1) * g.pitch_nm;
  if (inside) engage_on<true, true>(g, top_of, t, at, ex_q30, ey_q30, clockwise, cap, out);
  else if (t.cells_narrow) engage_on<true, false>(g, top_of, t, at, ex_q30, ey_q30, clockwise, cap, out);
  else engage_on<false, false>(g, top_of, t, at, ex_q30, ey_q30, clockwise, cap, out);
}

}  // namespace

template <class H>
void engage_at(const DexelGrid<H>& g, const EngageTool& t, const PointNm& at, int64_t ex_q30, int64_t ey_q30,
               bool clockwise, EngageAt* out) {
  const GridGeometry geo{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm};
  auto top = [&g](size_t c) { return g.top[c] == 0 && g.bottom[c] == 0 ? int64_t{-1} : static_cast<int64_t>(g.top[c]); };
  engage_dispatch(geo, top, t, at, ex_q30, ey_q30, clockwise, nullptr, out);
}

void engage_at_tops(const GridGeometry& geo, const uint32_t* tops, const EngageTool& t, const PointNm& at,
                    int64_t ex_q30, int64_t ey_q30, bool clockwise, const PointNm* cap, EngageAt* out) {
  auto top = [tops](size_t c) { return static_cast<int64_t>(tops[c]); };
  engage_dispatch(geo, top, t, at, ex_q30, ey_q30, clockwise, cap, out);
}

EngageChip engage_chip(const EngageTool& t, const EngageAt& e, int64_t fz_nm) {
  EngageChip c;
  if (!e.engaged || fz_nm <= 0) return c;
  // The arc's ends are samples' angles: the tool's tables hold their sines
  // and cosines (a quarter turn is step kEngageSteps / 2).
  const int entry = static_cast<int>(e.entry_bam / kEngageStepBam), exit = static_cast<int>(e.exit_bam / kEngageStepBam);
  const int quarter = kEngageSteps / 2;
  const int nearest = entry > quarter ? entry : exit < quarter ? exit : quarter;
  c.max_nm = mul_shift(fz_nm, t.sin_q30[nearest], 30);
  const uint32_t span = e.exit_bam - e.entry_bam;
  if (span == 0) {
    c.mean_nm = c.max_nm;  // one sample: the chip there
    return c;
  }
  // (cos(entry) - cos(exit)) / span, span in radians: 2^32 bam = 2 pi.
  const int64_t dcos_q30 = static_cast<int64_t>(t.cos_q30[entry]) - t.cos_q30[exit];
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
