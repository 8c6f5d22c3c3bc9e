// Zig milling positions; see zig.h.
#include "core/cam/zig.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

int32_t reach_of(const ToolProfile& p, int64_t pitch_nm) {
  return static_cast<int32_t>(p.radius_nm / pitch_nm);
}

int32_t along_n(const DesignGrid& d, const ZigOptions& o) { return o.along_y ? d.geo.ny : d.geo.nx; }
int32_t across_n(const DesignGrid& d, const ZigOptions& o) { return o.along_y ? d.geo.nx : d.geo.ny; }

// Positions 0, n, 2n, ... and last: how many.
int32_t ladder_count(int32_t len, int32_t n) { return (len - 1 + n - 1) / n + 1; }
int32_t ladder_at(int32_t len, int32_t n, int32_t k) { return min_of(k * n, len - 1); }

}  // namespace

size_t zig_tool_words(const ToolProfile& p, const GridGeometry& geo) {
  const int64_t side = 2 * static_cast<int64_t>(reach_of(p, geo.pitch_nm)) + 3;
  return static_cast<size_t>(kZigPhases * side * (2 * side + 3));
}

namespace {

// The along offset (nm) from the tip, at t / kZigPhases of a pitch past the
// dexel axis, of a column a pitches along: rounded towards zero (a lower
// height, the safe side).
int64_t along_nm(int32_t a, int32_t t, int64_t pitch_nm) {
  return (static_cast<int64_t>(a) * kZigPhases - t) * pitch_nm / kZigPhases;
}

uint64_t sq(int64_t v) { return static_cast<uint64_t>(v) * static_cast<uint64_t>(v); }

// h in LSB, floored, with 2 nm off for the profile's own rounding.
int32_t lsb_floor(int64_t h_nm, int64_t lsb_nm) { return static_cast<int32_t>(div_floor(h_nm - 2, lsb_nm)); }

}  // namespace

Status zig_tool_build(const ToolProfile& p, const GridGeometry& geo, int32_t* words, size_t n, ZigTool* out) {
  const int32_t reach = reach_of(p, geo.pitch_nm);
  if (reach > kZigMaxReach) return Status::kToolTooLarge;
  if (!words || n < zig_tool_words(p, geo)) return Status::kBufferTooSmall;
  const int32_t side = 2 * reach + 3;
  const uint64_t r2_max = sq(p.radius_nm);
  int32_t* spans = words + static_cast<size_t>(2) * kZigPhases * side * side;
  for (int32_t k = 0; k < kZigPhases; ++k)
    for (int32_t b = -reach - 1; b <= reach + 1; ++b) {
      int32_t* span = spans + (static_cast<size_t>(k) * side + static_cast<size_t>(b + reach + 1)) * 3;
      span[0] = side;
      span[1] = -1;
      span[2] = INT32_MAX;
      const uint64_t db2 = sq(static_cast<int64_t>(b) * geo.pitch_nm);
      for (int32_t a = -reach - 1; a <= reach + 1; ++a) {
        int32_t* h = words + ((static_cast<size_t>(k) * side + static_cast<size_t>(b + reach + 1)) * side +
                              static_cast<size_t>(a + reach + 1)) * 2;
        // The tip at the ends of the interval and one interval beyond each.
        uint64_t r2[4];
        bool inside = true;
        for (int32_t e = 0; e < 4; ++e) {
          r2[e] = sq(along_nm(a, k - 1 + e, geo.pitch_nm)) + db2;
          inside &= r2[e] <= r2_max;
        }
        if (inside) {
          // Convex in t: the secant of the interval before, extended on,
          // lies under h over this interval (exact at its start), and so
          // does the one of the interval after, extended back (exact at
          // its end); the one that gives more.
          const int64_t h0 = profile_height_r2_nm(p, r2[0]), h1 = profile_height_r2_nm(p, r2[1]);
          const int64_t h2 = profile_height_r2_nm(p, r2[2]), h3 = profile_height_r2_nm(p, r2[3]);
          const int64_t before_end = 2 * h1 - h0, after_start = 2 * h2 - h3;
          const bool before = h1 + before_end >= after_start + h2;
          h[0] = lsb_floor(before ? h1 : after_start, geo.lsb_nm);
          h[1] = lsb_floor(before ? before_end : h2, geo.lsb_nm);
          continue;
        }
        // Entering or leaving the radius nearby: h at the closest approach
        // within the interval, for both ends (h rises with r).
        const int64_t lo = along_nm(a, k + 1, geo.pitch_nm), hi = along_nm(a, k, geo.pitch_nm);  // lo <= hi
        const int64_t da = lo > 0 ? lo : (hi < 0 ? hi : 0);
        const uint64_t r2c = sq(da) + db2;
        h[0] = h[1] = r2c > r2_max ? kZigMiss : lsb_floor(profile_height_r2_nm(p, r2c), geo.lsb_nm);
      }
      // The row's columns under the tool (a disc: one run).
      for (int32_t a = 0; a < side; ++a) {
        const int32_t* h = words + ((static_cast<size_t>(k) * side + static_cast<size_t>(b + reach + 1)) * side +
                                    static_cast<size_t>(a)) * 2;
        if (h[0] == kZigMiss) continue;
        span[0] = min_of(span[0], a);
        span[1] = a;
        span[2] = min_of(span[2], min_of(h[0], h[1]));
      }
    }
  out->reach_dex = reach;
  out->side = side;
  out->h_lsb = words;
  out->span = spans;
  return Status::kOk;
}

namespace {

// zig_interval_need, with the rows' window maxima (wmax: per row offset b,
// the highest design top over the columns a row of the footprint can
// cover, for each u; null: none) to skip rows that cannot raise the need:
// rows from the middle out, so that the first give a high bound.
void interval_need(const DesignGrid& d, const ZigTool& t, bool along_y, int32_t u, int32_t v, int32_t k,
                   const int32_t* wmax, int32_t len, int64_t* left, int64_t* right) {
  const int32_t K = t.reach_dex;
  const int32_t nu = along_y ? d.geo.ny : d.geo.nx, nv = along_y ? d.geo.nx : d.geo.ny;
  const int32_t a0 = max_of(-K - 1, -u), a1 = min_of(K + 1, nu - 1 - u);
  const int32_t b0 = max_of(-K - 1, -v), b1 = min_of(K + 1, nv - 1 - v);
  int64_t l = kZigNone, r = kZigNone;
  for (int32_t n = 0; n < 2 * K + 3; ++n) {
    const int32_t b = n % 2 ? (n + 1) / 2 : -(n / 2);  // 0, 1, -1, 2, -2, ...
    if (b < b0 || b > b1) continue;
    const size_t row = static_cast<size_t>(k) * t.side + static_cast<size_t>(b + K + 1);
    const int32_t* span = t.span + row * 3;
    if (span[0] > span[1]) continue;
    if (wmax) {
      const int32_t w = wmax[static_cast<size_t>(b + K + 1) * static_cast<size_t>(len) + static_cast<size_t>(u)];
      if (w == kNoDesign || static_cast<int64_t>(w) - span[2] <= min_of(l, r)) continue;
    }
    const int32_t* h = t.h_lsb + row * t.side * 2;
    for (int32_t a = max_of(a0, span[0] - K - 1); a <= min_of(a1, span[1] - K - 1); ++a) {
      const int32_t* ha = h + static_cast<size_t>(a + K + 1) * 2;
      if (ha[0] == kZigMiss) continue;
      const size_t at = along_y ? d.index(v + b, u + a) : d.index(u + a, v + b);
      const int64_t top = d.top_lsb[at];
      if (top == kNoDesign) continue;
      l = max_of(l, top - ha[0]);
      r = max_of(r, top - ha[1]);
    }
  }
  *left = l;
  *right = r;
}

// wmax for stripe row v: for each row offset b and each u, the highest top
// of row v + b over columns u - K - 1 .. u + K + 1 (kNoDesign: none), by
// the van Herk / Gil-Werman block maxima (prefix and suffix maxima in
// blocks of the window's width: two passes per row, whatever the width).
void window_maxima(const DesignGrid& d, const ZigTool& t, bool along_y, int32_t v, int32_t len, int32_t* wmax,
                   int32_t* pre, int32_t* suf) {
  const int32_t K = t.reach_dex, w = 2 * K + 3, nv = along_y ? d.geo.nx : d.geo.ny;
  for (int32_t b = -K - 1; b <= K + 1; ++b) {
    int32_t* out = wmax + static_cast<size_t>(b + K + 1) * static_cast<size_t>(len);
    if (v + b < 0 || v + b >= nv) {
      for (int32_t u = 0; u < len; ++u) out[u] = kNoDesign;
      continue;
    }
    auto top = [&](int32_t u) { return d.top_lsb[along_y ? d.index(v + b, u) : d.index(u, v + b)]; };
    for (int32_t u = 0; u < len; ++u) pre[u] = u % w == 0 ? top(u) : max_of(pre[u - 1], top(u));
    for (int32_t u = len - 1; u >= 0; --u) suf[u] = (u % w == w - 1 || u == len - 1) ? top(u) : max_of(suf[u + 1], top(u));
    for (int32_t u = 0; u < len; ++u) {
      const int32_t lo = max_of<int32_t>(u - K - 1, 0), hi = min_of<int32_t>(u + K + 1, len - 1);
      // [lo, hi] spans at most two blocks: the suffix of lo's and the
      // prefix of hi's, exactly; within one block the suffix reaches past
      // hi, an upper bound, which is all the pruning needs.
      out[u] = max_of(suf[lo], pre[hi]);
    }
  }
}

}  // namespace

void zig_interval_need(const DesignGrid& d, const ZigTool& t, bool along_y, int32_t u, int32_t v, int32_t k,
                       int64_t* left, int64_t* right) {
  interval_need(d, t, along_y, u, v, k, nullptr, 0, left, right);
}

int32_t zig_stripe_count(const DesignGrid& d, const ZigOptions& o) {
  return ladder_count(across_n(d, o), max_of<int32_t>(o.stepover_dex, 1));
}
int32_t zig_stripe_row(const DesignGrid& d, const ZigOptions& o, int32_t s) {
  return ladder_at(across_n(d, o), max_of<int32_t>(o.stepover_dex, 1), s);
}
int32_t zig_positions(const DesignGrid& d, const ZigOptions& o) { return ladder_count(along_n(d, o), max_of<int32_t>(o.step_dex, 1)); }
int32_t zig_position_u(const DesignGrid& d, const ZigOptions& o, int32_t k) {
  return ladder_at(along_n(d, o), max_of<int32_t>(o.step_dex, 1), k);
}

size_t zig_stripe_scratch(const DesignGrid& d, const ZigTool& t, const ZigOptions& o) {
  const size_t len = static_cast<size_t>(along_n(d, o));
  return (len - 1) * kZigPhases * 2 + (static_cast<size_t>(t.side + 2) * len + 1) / 2;
}

Status zig_stripe(const DesignGrid& d, const ZigTool& t, const ZigOptions& o, int32_t s, int64_t floor_lsb,
                  int64_t* scratch, size_t scratch_words, int64_t* z_lsb) {
  if (!scratch || scratch_words < zig_stripe_scratch(d, t, o)) return Status::kBufferTooSmall;
  const int32_t len = along_n(d, o), v = zig_stripe_row(d, o, s);
  // What each interval q (dexel q / K, interval q % K) asks of the chord at
  // its left end (scratch[2q]) and its right end (scratch[2q + 1]); after
  // them the rows' window maxima.
  const int32_t intervals = (len - 1) * kZigPhases;
  int32_t* wmax = reinterpret_cast<int32_t*>(scratch + 2 * static_cast<size_t>(intervals));
  int32_t* pre = wmax + static_cast<size_t>(t.side) * static_cast<size_t>(len);
  window_maxima(d, t, o.along_y, v, len, wmax, pre, pre + len);
  for (int32_t q = 0; q < intervals; ++q) {
    int64_t l, r;
    interval_need(d, t, o.along_y, q / kZigPhases, v, q % kZigPhases, wmax, len, &l, &r);
    scratch[2 * q] = max_of(l, floor_lsb);
    scratch[2 * q + 1] = max_of(r, floor_lsb);
  }
  const int32_t n = zig_positions(d, o);
  for (int32_t k = 0; k < n; ++k) {
    const int32_t q = zig_position_u(d, o, k) * kZigPhases;  // the interval starting here
    int64_t z = floor_lsb;
    if (q < intervals) z = max_of(z, scratch[2 * q]);
    if (q > 0) z = max_of(z, scratch[2 * q - 1]);
    z_lsb[k] = z;
  }
  // Each chord over every interval between its ends: raise both ends by
  // the largest shortfall (raising an end only lifts the neighbouring
  // chord).
  for (int32_t k = 0; k + 1 < n; ++k) {
    const int64_t qa = static_cast<int64_t>(zig_position_u(d, o, k)) * kZigPhases;
    const int64_t qb = static_cast<int64_t>(zig_position_u(d, o, k + 1)) * kZigPhases;
    const int64_t za = z_lsb[k], zb = z_lsb[k + 1], span = qb - qa;
    int64_t excess = 0;
    for (int64_t q = qa; q < qb; ++q) {
      // The chord at the interval's ends, rounded down.
      const int64_t c0 = za + div_floor((zb - za) * (q - qa), span), c1 = za + div_floor((zb - za) * (q + 1 - qa), span);
      excess = max_of(excess, max_of(scratch[2 * q] - c0, scratch[2 * q + 1] - c1));
    }
    z_lsb[k] += excess;
    z_lsb[k + 1] += excess;
  }
  const int64_t allowance = div_ceil(o.allowance_nm, d.geo.lsb_nm);
  for (int32_t k = 0; k < n; ++k) z_lsb[k] += allowance;
  return Status::kOk;
}

}  // namespace dexmill
