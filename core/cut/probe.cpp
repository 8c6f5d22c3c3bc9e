// core/cut/probe.h: contact of a probe move with the stock.
#include "core/cut/probe.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

int64_t abs_i64(int64_t v) { return v < 0 ? -v : v; }  // |v| of coordinates within 10 m

// Touching: the lower surface at or below a top (depth >= 0).
bool touching(int64_t depth_nm) { return depth_nm != INT64_MIN && depth_nm >= 0; }

PointNm lerp(const PointNm& a, const PointNm& b, int64_t k, int64_t n) {
  return PointNm{a.x_nm + muldiv_floor(b.x_nm - a.x_nm, k, n), a.y_nm + muldiv_floor(b.y_nm - a.y_nm, k, n),
                 a.z_nm + muldiv_floor(b.z_nm - a.z_nm, k, n)};
}

}  // namespace

template <class H>
int64_t probe_depth_nm(const DexelGrid<H>& g, const ToolProfile& tool, const PointNm& p) {
  const int64_t r = tool.radius_nm, pitch = g.pitch_nm;
  const int64_t i0 = max_of<int64_t>(0, div_ceil(p.x_nm - r - g.x0_nm, pitch));
  const int64_t i1 = min_of<int64_t>(g.nx - 1, div_floor(p.x_nm + r - g.x0_nm, pitch));
  const int64_t j0 = max_of<int64_t>(0, div_ceil(p.y_nm - r - g.y0_nm, pitch));
  const int64_t j1 = min_of<int64_t>(g.ny - 1, div_floor(p.y_nm + r - g.y0_nm, pitch));
  const uint64_t r2 = static_cast<uint64_t>(r) * static_cast<uint64_t>(r);
  int64_t best = INT64_MIN;
  bool any_axis = false;
  for (int64_t j = j0; j <= j1; ++j) {
    const int64_t dy = g.y0_nm + j * pitch - p.y_nm;
    for (int64_t i = i0; i <= i1; ++i) {
      const int64_t dx = g.x0_nm + i * pitch - p.x_nm;
      const uint64_t d2 = static_cast<uint64_t>(dx * dx) + static_cast<uint64_t>(dy * dy);
      if (d2 > r2) continue;
      any_axis = true;
      const size_t k = g.index(static_cast<int32_t>(i), static_cast<int32_t>(j));
      if (g.top[k] == 0 && g.bottom[k] == 0) continue;  // a hole: no material
      const int64_t top_z = g.z0_nm + static_cast<int64_t>(g.top[k]) * g.lsb_nm;
      best = max_of(best, top_z - (p.z_nm + profile_height_r2_nm(tool, d2)));
    }
  }
  if (!any_axis) {
    // A tip narrower than the cells with no axis under it (a PCB probe on a
    // coarse grid) touches the column of the cell it is in: the grid holds
    // nothing finer, and a probe must not pass through the stock between
    // two axes.
    const int64_t i = div_round(p.x_nm - g.x0_nm, pitch), j = div_round(p.y_nm - g.y0_nm, pitch);
    if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) return best;
    const size_t k = g.index(static_cast<int32_t>(i), static_cast<int32_t>(j));
    if (g.top[k] == 0 && g.bottom[k] == 0) return best;
    best = g.z0_nm + static_cast<int64_t>(g.top[k]) * g.lsb_nm - p.z_nm;
  }
  return best;
}

template <class H>
ProbeResult probe_move(const DexelGrid<H>& g, const ToolProfile& tool, const PointNm& from, const PointNm& to,
                       bool toward, PointNm* stop) {
  auto tripped = [&](const PointNm& p) { return touching(probe_depth_nm(g, tool, p)) == toward; };
  if (tripped(from)) return ProbeResult::kAlreadyTripped;
  if (from.x_nm == to.x_nm && from.y_nm == to.y_nm) {
    // Along Z: the contact height is z_c = max(top - height(r)); in contact
    // at z <= z_c.
    const int64_t d = probe_depth_nm(g, tool, PointNm{from.x_nm, from.y_nm, 0});
    if (d == INT64_MIN) {
      if (!toward) return ProbeResult::kAlreadyTripped;  // no material under it: out of contact already
      return ProbeResult::kNoContact;
    }
    const int64_t zc = d;  // the depth at z = 0 is z_c itself
    const int64_t lo = min_of(from.z_nm, to.z_nm), hi = max_of(from.z_nm, to.z_nm);
    // toward: moving down to z_c (touching there); away: moving up past it.
    const int64_t z_stop = toward ? zc : zc + 1;
    if (z_stop < lo || z_stop > hi) return ProbeResult::kNoContact;
    *stop = PointNm{from.x_nm, from.y_nm, z_stop};
    return ProbeResult::kTripped;
  }
  // Sampled: steps of at most a quarter pitch across, 1 um in Z.
  const int64_t span = max_of(max_of(abs_i64(to.x_nm - from.x_nm), abs_i64(to.y_nm - from.y_nm)) * 4 / max_of<int64_t>(g.pitch_nm, 1),
                              abs_i64(to.z_nm - from.z_nm) / 1000);
  const int64_t n = max_of<int64_t>(1, span + 1);
  int64_t miss = 0, hit = -1;
  for (int64_t k = 1; k <= n; ++k)
    if (tripped(lerp(from, to, k, n))) {
      hit = k;
      break;
    } else {
      miss = k;
    }
  if (hit < 0) return ProbeResult::kNoContact;
  // Bisect between the two samples on a nanometre parameter of the move.
  const int64_t len = max_of(max_of(abs_i64(to.x_nm - from.x_nm), abs_i64(to.y_nm - from.y_nm)), abs_i64(to.z_nm - from.z_nm));
  int64_t a = muldiv_floor(miss, len, n), b = muldiv_floor(hit, len, n);
  while (b - a > 1) {
    const int64_t m = a + (b - a) / 2;
    if (tripped(lerp(from, to, m, len))) b = m; else a = m;
  }
  *stop = lerp(from, to, b, len);
  return ProbeResult::kTripped;
}

#define DEXMILL_PROBE_INSTANTIATE(H)                                                                     \
  template int64_t probe_depth_nm<H>(const DexelGrid<H>&, const ToolProfile&, const PointNm&);         \
  template ProbeResult probe_move<H>(const DexelGrid<H>&, const ToolProfile&, const PointNm&, const PointNm&, \
                                     bool, PointNm*);
DEXMILL_PROBE_INSTANTIATE(uint8_t)
DEXMILL_PROBE_INSTANTIATE(uint16_t)
DEXMILL_PROBE_INSTANTIATE(uint32_t)

}  // namespace dexmill
