// Normals, light and colour ramps (see shade.h).
#include "display/surface/shade.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int32_t kOneQ14 = 1 << 14;

int32_t dot_q14(const UnitQ14& a, const UnitQ14& b) {
  const int64_t d = static_cast<int64_t>(a.x) * b.x + static_cast<int64_t>(a.y) * b.y + static_cast<int64_t>(a.z) * b.z;
  return static_cast<int32_t>((d + (kOneQ14 >> 1)) >> 14);
}


}  // namespace

void lighting_finish(Lighting* l, const UnitQ14& eye) {
  l->half = normal_unit_q14(static_cast<int64_t>(l->light.x) + eye.x, static_cast<int64_t>(l->light.y) + eye.y,
                            static_cast<int64_t>(l->light.z) + eye.z);
  const int64_t total = static_cast<int64_t>(l->ambient_q14) + l->diffuse_q14 + l->fill_q14 + l->specular_q14;
  l->index_scale_q30 = div_round(static_cast<int64_t>(255) << 30, max_of<int64_t>(total, 1));
}

namespace {

// Index from the three cosines (q14, already clamped at 0): brightness in
// q28, then index = b * 255 / total = b * scale >> 44.
inline int32_t index_of(const Lighting& l, int32_t diff, int32_t fill, int32_t spec) {
  for (int k = 0; k < 5; ++k) spec = (spec * spec + (kOneQ14 >> 1)) >> 14;  // ^32
  const int64_t b = static_cast<int64_t>(l.ambient_q14) * kOneQ14 + static_cast<int64_t>(l.diffuse_q14) * diff +
                    static_cast<int64_t>(l.fill_q14) * fill + static_cast<int64_t>(l.specular_q14) * spec;
  const int64_t idx = (b * l.index_scale_q30 + (static_cast<int64_t>(1) << 43)) >> 44;
  return static_cast<int32_t>(idx > 255 ? 255 : idx);
}

inline int32_t cos_q14(int64_t dot, ScaledRecip r) {
  return dot <= 0 ? 0 : static_cast<int32_t>((static_cast<uint64_t>(dot) * r.m) >> r.shift);
}

}  // namespace

int32_t shade_of_normal(const Lighting& l, const UnitQ14& n) {
  return index_of(l, max_of<int32_t>(0, dot_q14(n, l.light)), max_of<int32_t>(0, dot_q14(n, l.fill_light)),
                  max_of<int32_t>(0, dot_q14(n, l.half)));
}

int32_t shade_of_vector(const Lighting& l, int64_t nx, int64_t ny, int64_t nz) {
  const uint64_t m = abs_u64(nx) | abs_u64(ny) | abs_u64(nz);
  if (m == 0) return shade_of_normal(l, UnitQ14{0, 0, kOneQ14});
  // Keep 15 bits of the largest component: squares sum below 2^32.
  const int bits = 64 - __builtin_clzll(m);
  const int sh = bits > 15 ? bits - 15 : 0;
  const int32_t x = static_cast<int32_t>(nx >> sh), y = static_cast<int32_t>(ny >> sh), z = static_cast<int32_t>(nz >> sh);
  const uint32_t s = static_cast<uint32_t>(x * x) + static_cast<uint32_t>(y * y) + static_cast<uint32_t>(z * z);
  ScaledRecip r = rsqrt_fast_u32(s);
  const int64_t dl = static_cast<int64_t>(x) * l.light.x + static_cast<int64_t>(y) * l.light.y + static_cast<int64_t>(z) * l.light.z;
  const int64_t df = static_cast<int64_t>(x) * l.fill_light.x + static_cast<int64_t>(y) * l.fill_light.y +
                     static_cast<int64_t>(z) * l.fill_light.z;
  const int64_t dh = static_cast<int64_t>(x) * l.half.x + static_cast<int64_t>(y) * l.half.y + static_cast<int64_t>(z) * l.half.z;
  return index_of(l, cos_q14(dl, r), cos_q14(df, r), cos_q14(dh, r));
}

int32_t shade_base_index(const Lighting& l) {
  const int64_t total = static_cast<int64_t>(l.ambient_q14) + l.diffuse_q14 + l.fill_q14 + l.specular_q14;
  return static_cast<int32_t>(div_round((static_cast<int64_t>(l.ambient_q14) + l.diffuse_q14) * 255, max_of<int64_t>(total, 1)));
}

void shade_ramp(PixelFormat f, Rgb c, int32_t base, uint32_t lut[256]) {
  base = clamp<int32_t>(base, 1, 255);
  const int32_t ch[3] = {c.r, c.g, c.b};
  for (int32_t i = 0; i < 256; ++i) {
    int32_t o[3];
    for (int k = 0; k < 3; ++k) {
      if (i <= base) o[k] = (ch[k] * i + base / 2) / base;
      else o[k] = ch[k] + ((255 - ch[k]) * (i - base) + (255 - base) / 2) / max_of<int32_t>(255 - base, 1);
    }
    lut[i] = pixel_pack(f, Rgb{static_cast<uint8_t>(o[0]), static_cast<uint8_t>(o[1]), static_cast<uint8_t>(o[2])});
  }
}

void lit_ramp(int32_t base, LitRamp* out) {
  base = clamp<int32_t>(base, 1, 255);
  for (int32_t i = 0; i < 256; ++i) {
    if (i <= base) {
      out->mul_q8[i] = static_cast<uint16_t>((i * 256 + base / 2) / base);
      out->add_q8[i] = 0;
    } else {  // t = (i - base) / (255 - base): c (1 - t) + 255 t
      const int32_t t_q8 = ((i - base) * 256 + (255 - base) / 2) / (255 - base);
      out->mul_q8[i] = static_cast<uint16_t>(256 - t_q8);
      out->add_q8[i] = static_cast<uint16_t>(255 * t_q8);
    }
  }
}

template <class H>
void blurred_gradient(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t* gx, int64_t* gy) {
  static const int32_t kW[3] = {1, 2, 1};
  int64_t sx = 0, sy = 0;
  for (int32_t b = -1; b <= 1; ++b) {
    for (int32_t a = -1; a <= 1; ++a) {
      const int32_t ii = clamp<int32_t>(i + a, 0, g.nx - 1), jj = clamp<int32_t>(j + b, 0, g.ny - 1);
      const GradientLsb n = grid_gradient(g, ii, jj);
      sx += kW[a + 1] * kW[b + 1] * n.dx;
      sy += kW[a + 1] * kW[b + 1] * n.dy;
    }
  }
  *gx = sx;
  *gy = sy;
}

namespace {

// Octagonal length of (x, y): the larger plus half the smaller, within 12 %
// of the Euclidean length: enough to weigh a slope and to scale a direction.
inline int64_t oct_len(int64_t x, int64_t y) {
  const int64_t ax = static_cast<int64_t>(abs_u64(x)), ay = static_cast<int64_t>(abs_u64(y));
  return ax > ay ? ax + ay / 2 : ay + ax / 2;
}

// The wide blur of steep slopes (shade.h): [1 8 28 56 70 56 28 8 1] each way.
constexpr int32_t kWideWeight[2 * kSteepRadius + 1] = {1, 8, 28, 56, 70, 56, 28, 8, 1};
static_assert(kShadeReach == kSteepRadius + 1, "central differences reach one dexel past the blur");
// The blur of central differences along one axis, written as taps on the
// tops: kWideDiff[c] (t[+c] - t[-c]) for c = 1 .. kShadeReach, the weights
// w[c - 1] - w[c + 1].
constexpr int32_t kWideDiff[kShadeReach + 1] = {0, 42, 48, 27, 8, 1};

// wide_gradient away from the grid's edge (every tap at most kShadeReach
// from p, rows `stride` apart), with the same sums.
template <class H>
void wide_gradient_interior(const H* p, ptrdiff_t stride, int64_t* gx, int64_t* gy) {
  int64_t sx = 0, sy = 0;
  for (int32_t b = -kSteepRadius; b <= kSteepRadius; ++b) {
    const H* row = p + b * stride;
    int64_t dx = 0;
    for (int32_t c = 1; c <= kShadeReach; ++c) dx += kWideDiff[c] * (static_cast<int64_t>(row[c]) - row[-c]);
    sx += kWideWeight[b + kSteepRadius] * dx;
  }
  for (int32_t c = 1; c <= kShadeReach; ++c) {
    const H* up = p + c * stride;
    const H* down = p - c * stride;
    int64_t d = 0;
    for (int32_t a = -kSteepRadius; a <= kSteepRadius; ++a)
      d += kWideWeight[a + kSteepRadius] * (static_cast<int64_t>(up[a]) - down[a]);
    sy += kWideDiff[c] * d;
  }
  *gx = sx;
  *gy = sy;
}

}  // namespace

template <class H>
void wide_gradient(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t* gx, int64_t* gy) {
  int64_t sx = 0, sy = 0;
  for (int32_t b = -kSteepRadius; b <= kSteepRadius; ++b) {
    for (int32_t a = -kSteepRadius; a <= kSteepRadius; ++a) {
      const int32_t ii = clamp<int32_t>(i + a, 0, g.nx - 1), jj = clamp<int32_t>(j + b, 0, g.ny - 1);
      const GradientLsb n = grid_gradient(g, ii, jj);
      const int64_t w = static_cast<int64_t>(kWideWeight[a + kSteepRadius]) * kWideWeight[b + kSteepRadius];
      sx += w * n.dx;
      sy += w * n.dy;
    }
  }
  *gx = sx;
  *gy = sy;
}

namespace {

// A dexel whose wide window lies inside the grid. Within kShadeReach of
// its edge lie the stock's straight outer walls (the hole border of
// grid_block_stock), which make no staircase, and the 81 clamped taps there
// would cost more than the rest of a frame's shading: the 3x3 stands alone.
template <class H>
bool wide_window_inside(const DexelGrid<H>& g, int32_t i, int32_t j) {
  constexpr int32_t R = kShadeReach;
  return i >= R && i <= g.nx - 1 - R && j >= R && j <= g.ny - 1 - R;
}

// A steep slope: the 3x3 gradient's octagonal length above eq. 1's dz16
// (more than 45 degrees).
inline bool is_steep(int64_t dz16, int64_t gx, int64_t gy) { return oct_len(gx, gy) > dz16; }

// Turns a steep dexel's blurred gradient (gx, gy) towards the wide blur's
// direction (wx, wy) (shade.h), keeping its length.
void steep_turn(int64_t dz16, int64_t wx, int64_t wy, int64_t* gx, int64_t* gy) {
  const int64_t n = oct_len(*gx, *gy);
  // The wide vector cut to about 20 bits first, so that scaling it to the
  // local length stays within 64 bits (n < 2^38 for 32-bit heights).
  const uint64_t big = abs_u64(wx) | abs_u64(wy);
  const int bits = big ? 64 - __builtin_clzll(big) : 0;
  if (bits > 20) {
    wx >>= bits - 20;
    wy >>= bits - 20;
  }
  const int64_t m = oct_len(wx, wy);
  if (m == 0) return;
  // The weight of the wide direction in q8: 0 at a slope of 1, 256 from 3
  // (72 degrees) up, so that the normal turns smoothly from one to the other.
  const int64_t w = n >= 3 * dz16 ? 256 : (n - dz16) * 256 / (2 * dz16);
  const int64_t sx = div_round(wx * n, m), sy = div_round(wy * n, m);  // the wide direction, the local length
  *gx = div_round(*gx * (256 - w) + sx * w, 256);
  *gy = div_round(*gy * (256 - w) + sy * w, 256);
}

// shade_grid's steep turn, with the wide blur as taps on the tops.
template <class H>
void steep_blend(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t dz16, int64_t* gx, int64_t* gy) {
  if (!is_steep(dz16, *gx, *gy) || !wide_window_inside(g, i, j)) return;
  int64_t wx, wy;
  wide_gradient_interior(g.top + g.index(i, j), static_cast<ptrdiff_t>(g.nx), &wx, &wy);
  steep_turn(dz16, wx, wy, gx, gy);
}

}  // namespace

// The reference: the wide blur summed over grid_gradient as shade.h states
// it, so that tests/test_shade.cpp checks shade_grid's taps against it.
template <class H>
void shade_gradient(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t* gx, int64_t* gy) {
  blurred_gradient(g, i, j, gx, gy);
  const int64_t dz16 = 16 * div_round(2 * g.pitch_nm, g.lsb_nm);
  if (!is_steep(dz16, *gx, *gy) || !wide_window_inside(g, i, j)) return;
  int64_t wx, wy;
  wide_gradient(g, i, j, &wx, &wy);
  steep_turn(dz16, wx, wy, gx, gy);
}

template <class H>
void shade_grid(const DexelGrid<H>& g, const Lighting& l, GridRect r, ShadeCache* cache) {
  r.i0 = max_of<int32_t>(r.i0, 0);
  r.j0 = max_of<int32_t>(r.j0, 0);
  r.i1 = min_of(r.i1, g.nx);
  r.j1 = min_of(r.j1, g.ny);
  const int64_t dz16 = 16 * div_round(2 * g.pitch_nm, g.lsb_nm);  // eq. 1's constant, times the kernel's weight
  const size_t nx = static_cast<size_t>(g.nx);
  for (int32_t j = r.j0; j < r.j1; ++j) {
    const bool row_inside = j >= 2 && j <= g.ny - 3;
    const H* t = g.top + g.index(0, j);
    const H* bt = g.bottom + g.index(0, j);
    for (int32_t i = r.i0; i < r.i1; ++i) {
      if (t[i] == 0 && bt[i] == 0) continue;  // a hole is never a vertex
      int64_t gx, gy;
      bool near_hole = true;
      if (row_inside && i >= 2 && i <= g.nx - 3) {
        // Interior: the blur of central differences written out, a 5x3
        // kernel [-1 -2 0 2 1] x [1 2 1] on the tops (and its transpose).
        const H* p = t + i;
        const H* u1 = p + nx;
        const H* u2 = u1 + nx;
        const H* d1 = p - nx;
        const H* d2 = d1 - nx;
        auto dxrow = [](const H* q) -> int64_t {
          return static_cast<int64_t>(q[2]) + 2 * static_cast<int64_t>(q[1]) - 2 * static_cast<int64_t>(q[-1]) -
                 static_cast<int64_t>(q[-2]);
        };
        auto blur3 = [](const H* q) -> int64_t {
          return static_cast<int64_t>(q[-1]) + 2 * static_cast<int64_t>(q[0]) + static_cast<int64_t>(q[1]);
        };
        gx = dxrow(d1) + 2 * dxrow(p) + dxrow(u1);
        gy = blur3(u2) + 2 * blur3(u1) - 2 * blur3(d1) - blur3(d2);
        // Side faces start only at dexels next to a hole, and a hole has top
        // 0: without a zero top around, the wall shade is never used.
        near_hole = (d1[-1] == 0) | (d1[0] == 0) | (d1[1] == 0) | (p[-1] == 0) | (p[1] == 0) | (u1[-1] == 0) |
                    (u1[0] == 0) | (u1[1] == 0);
      } else {
        blurred_gradient(g, i, j, &gx, &gy);
      }
      steep_blend(g, i, j, dz16, &gx, &gy);
      const size_t k = g.index(i, j);
      const uint8_t top = static_cast<uint8_t>(shade_of_vector(l, -gx, -gy, dz16));
      cache->top[k] = top;
      cache->wall[k] = (!near_hole || (gx == 0 && gy == 0)) ? top : static_cast<uint8_t>(shade_of_vector(l, -gx, -gy, 0));
    }
  }
}

#define DEXMILL_SHADE_INSTANTIATE(H)                                                           \
  template void shade_grid<H>(const DexelGrid<H>&, const Lighting&, GridRect, ShadeCache*); \
  template void blurred_gradient<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t*, int64_t*); \
  template void wide_gradient<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t*, int64_t*);   \
  template void shade_gradient<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t*, int64_t*);
DEXMILL_SHADE_INSTANTIATE(uint8_t)
DEXMILL_SHADE_INSTANTIATE(uint16_t)
DEXMILL_SHADE_INSTANTIATE(uint32_t)

}  // namespace dexmill
