// Instances of motion, paper §2.3.
//
// Ranges (core/tool/cutter.h, core/grid/grid.h): a cutter reaches K <= 2047
// dexels and holds heights below 2^30 LSB; tops are below 2^32; points are
// clamped to 2^46 nm, so a tip is within 2^46.1 LSB of z0 and an index
// offset within 2^47 dexels (pitch >= 1 nm). Products: the reach (K + 1)
// pitch <= 2^41 nm; steps = max(|dx|, |dy|) / pitch <= 2^47; clip_steps'
// (lo - a) n / d by muldiv (128-bit), |k| < 2^49 since n / |d| <= 2 /
// pitch; the DDA's d k in 128 bits, its remainder mod 2^64 (exact);
// stamp_instance's tip + offset in W: past its early return the tip is in
// (-2^30, 2^32) (above every top or below every bottom otherwise), so tip
// + cb, tip + ct < 2^31 for 8 and 16-bit heights, 64-bit for 32.
#include "core/cut/stamp.h"

namespace dexmill {
namespace {

// Wide enough for tip + offset without overflow: offsets are below 2^30
// (cutter_build checks) and the tip is limited per instance to the range
// where the cutter can overlap the grid, so int32 serves m = 8 and 16.
template <class H> struct WideOf { using type = int32_t; };
template <> struct WideOf<uint32_t> { using type = int64_t; };

// Exact integer DDA for a + d*k/n (floor), k stepping by one: no 128-bit
// product per step.
struct Dda {
  int64_t pos;      // a + floor(d*k/n)
  uint64_t rem;     // (d*k) mod n, in [0, n)
  int64_t step_q;   // floor(d/n)
  uint64_t step_r;  // d mod n
  uint64_t n;

  void start(int64_t a, int64_t d, int64_t steps, int64_t k) {
    n = static_cast<uint64_t>(steps);
    step_q = div_floor(d, steps);
    step_r = static_cast<uint64_t>(d) - static_cast<uint64_t>(step_q) * n;  // exact mod 2^64
    const int64_t q = muldiv_floor(d, k, steps);
    pos = a + q;
    rem = static_cast<uint64_t>(d) * static_cast<uint64_t>(k) - static_cast<uint64_t>(q) * n;
  }
  void next() {
    pos += step_q;
    rem += step_r;
    if (rem >= n) {
      rem -= n;
      ++pos;
    }
  }
};

// Narrows [*k_lo, *k_hi] to the k whose coordinate a + d*k/n lies within
// [lo, hi] (with a one-step margin for the floor in the DDA).
void clip_steps(int64_t a, int64_t d, int64_t n, int64_t lo, int64_t hi, int64_t* k_lo, int64_t* k_hi) {
  if (d == 0) {
    if (a < lo || a > hi) *k_hi = *k_lo - 1;
    return;
  }
  // a + d*k/n >= lo and <= hi, solved for k.
  int64_t k1 = muldiv_floor(lo - a, n, d), k2 = muldiv_floor(hi - a, n, d);
  if (k1 > k2) { int64_t t = k1; k1 = k2; k2 = t; }
  *k_lo = max_of(*k_lo, k1 - 1);
  *k_hi = min_of(*k_hi, k2 + 1);
}

}  // namespace

template <class H>
void stamp_instance(DexelGrid<H>* g, const CutterDexels& c, int64_t ci, int64_t cj, int64_t tip_lsb, CutStats* st) {
  using W = typename WideOf<H>::type;
  const int32_t k = c.reach_dex;
  if (ci + k < 0 || cj + k < 0 || ci - k >= g->nx || cj - k >= g->ny) return;
  st->instances++;
  constexpr int64_t hmax = height_max<H>();
  // Entirely above every possible top, or entirely below the grid's floor.
  if (tip_lsb + c.min_bottom_lsb >= hmax || tip_lsb + c.max_top_lsb <= 0) return;
  const W tip = static_cast<W>(tip_lsb);
  // When the shaft reaches above the range everywhere, c.top >= w.top always
  // holds and only cases a, b and e remain.
  const bool shaft_above = tip_lsb + c.min_top_lsb >= hmax;
  const int32_t ci32 = static_cast<int32_t>(ci), cj32 = static_cast<int32_t>(cj);
  const int32_t dj0 = max_of(-k, -cj32), dj1 = min_of(k, g->ny - 1 - cj32);
  bool changed = false;
  int32_t i_min = g->nx, i_max = -1;
  for (int32_t dj = dj0; dj <= dj1; ++dj) {
    const int32_t row = dj + k;
    // Row span in cutter coordinates (0..side-1), clipped to the grid.
    const int32_t lo = max_of(c.row_lo[row], k - ci32);
    const int32_t hi = min_of(c.row_hi[row], g->nx - 1 - ci32 + k);
    if (lo > hi) continue;
    // Pointers start at the first visited column: forming one before the
    // row (a cutter overhanging the left edge) would be undefined.
    const size_t wbase = g->index(ci32 - k + lo, cj32 + dj);
    const size_t cbase = static_cast<size_t>(row) * static_cast<size_t>(c.side) + static_cast<size_t>(lo);
    H* wt = g->top + wbase;
    H* wb = g->bottom + wbase;
    const int32_t* cb = c.bottom_lsb + cbase;
    const int32_t n = hi - lo;
    st->dexel_updates += static_cast<uint64_t>(hi - lo + 1);
    if (st->log) st->log->add(cj32 + dj, ci32 - k + lo, ci32 - k + hi);
    bool row_changed = false;
    if (shaft_above) {
      for (int32_t x = 0; x <= n; ++x) {
        const W b = tip + cb[x];
        if (b < static_cast<W>(wt[x])) {
          if (b > static_cast<W>(wb[x])) {
            wt[x] = static_cast<H>(b);  // case b
          } else {
            wt[x] = 0;  // case e: a hole
            wb[x] = 0;
          }
          row_changed = true;
        }
      }
    } else {
      const int32_t* ct = c.top_lsb + cbase;
      for (int32_t x = 0; x <= n; ++x) {
        const CutCase cc = apply_cut<H, W>(&wt[x], &wb[x], tip + cb[x], tip + ct[x]);
        row_changed |= cut_changed(cc);
        if (cc == CutCase::kC) g->bottoms_zero = false;
      }
    }
    if (row_changed) {
      changed = true;
      i_min = min_of(i_min, ci32 - k + lo);
      i_max = max_of(i_max, ci32 - k + hi);
    }
  }
  if (changed) g->dirty.include(GridRect{i_min, cj32 + dj0, i_max + 1, cj32 + dj1 + 1});
}

template <class H>
void stamp_line(DexelGrid<H>* g, const CutterDexels& c, PointNm a, PointNm b, CutStats* st, bool include_start) {
  a = clamp_point(a);
  b = clamp_point(b);
  const int64_t dx = b.x_nm - a.x_nm, dy = b.y_nm - a.y_nm, dz = b.z_nm - a.z_nm;
  const int64_t p = g->pitch_nm;
  // A plunge (dx = dy = 0) still places the cutter at both ends; a move of
  // zero length is one instance.
  const bool still = dx == 0 && dy == 0 && dz == 0;
  const int64_t steps = still ? 0 : max_of<int64_t>(1, max_of(div_ceil(dx < 0 ? -dx : dx, p), div_ceil(dy < 0 ? -dy : dy, p)));
  // Only instances whose footprint can touch the grid.
  const int64_t reach = static_cast<int64_t>(c.reach_dex + 1) * p;
  int64_t k_lo = include_start ? 0 : 1, k_hi = steps;
  clip_steps(a.x_nm, dx, steps, g->x0_nm - reach, g->x0_nm + (g->nx - 1) * p + reach, &k_lo, &k_hi);
  clip_steps(a.y_nm, dy, steps, g->y0_nm - reach, g->y0_nm + (g->ny - 1) * p + reach, &k_lo, &k_hi);
  k_lo = max_of<int64_t>(k_lo, include_start ? 0 : 1);
  k_hi = min_of(k_hi, steps);
  if (k_lo > k_hi) return;
  if (still) {
    if (!include_start) return;
    stamp_instance(g, c, grid_i_of_x(*g, a.x_nm), grid_j_of_y(*g, a.y_nm), grid_height_of_z(*g, a.z_nm), st);
    return;
  }
  Dda x, y, z;
  x.start(a.x_nm, dx, steps, k_lo);
  y.start(a.y_nm, dy, steps, k_lo);
  z.start(a.z_nm, dz, steps, k_lo);
  for (int64_t k = k_lo;; ++k) {
    stamp_instance(g, c, grid_i_of_x(*g, x.pos), grid_j_of_y(*g, y.pos), grid_height_of_z(*g, z.pos), st);
    if (k == k_hi) break;
    x.next();
    y.next();
    z.next();
  }
}

#define DEXMILL_STAMP_INSTANTIATE(H)                                                                       \
  template void stamp_instance<H>(DexelGrid<H>*, const CutterDexels&, int64_t, int64_t, int64_t, CutStats*); \
  template void stamp_line<H>(DexelGrid<H>*, const CutterDexels&, PointNm, PointNm, CutStats*, bool);
DEXMILL_STAMP_INSTANTIATE(uint8_t)
DEXMILL_STAMP_INSTANTIATE(uint16_t)
DEXMILL_STAMP_INSTANTIATE(uint32_t)

}  // namespace dexmill
