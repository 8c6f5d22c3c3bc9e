// Shading: normals from the dexel grid, a fixed-point light, and the colour
// ramps the rasterizer indexes.
//
// Normals (paper §2.1 eq. 1, §2.4.2): the height gradient of every dexel by
// central differences (core/grid/grid.h grid_gradient, one-sided at the grid's
// edge), blurred with the 3x3 kernel [1 2 1; 2 4 2; 1 2 1] so that the
// staircase of vertical side faces shades smoothly (the paper's figure 7).
// Steep slopes take their direction from a wider blur, 9x9 binomial
// [1 8 28 56 70 56 28 8 1] each way, and keep the 3x3's length: on a steep
// wall along a curve the dexels form a staircase, and the 3x3 sees the
// direction of the stair, not of the curve (around a 30 mm circle at
// 0.19 mm pitch up to 20 degrees off, RMS 6.4, alternating from one dexel to
// the next: a vertical streak per stair step under a grazing light); the 9x9
// is within 9 degrees, RMS 2.8, and spreads what is left over nine dexels.
// The wide direction weighs 0 up to a slope of 45 degrees (gentle surfaces,
// reliefs and scallops shade as the paper's) and all from 72 degrees, in a
// linear blend between; the slope is the octagonal length of the 3x3
// gradient (max + min / 2) against eq. 1's constant. Within kShadeReach of
// the grid's edge (the stock's straight outer walls) the 3x3 stands alone. The price is the reach:
// a change of one top moves the shades up to kShadeReach dexels away, and an
// incremental redraw repaints that far.
// A top vertex uses the blurred normal (-gx, -gy, 16 dz); a side-face vertex
// uses its horizontal part (-gx, -gy, 0), which points out of the material
// towards the hole it borders (when that part vanishes, as on a fin one
// dexel thick, the top normal stands in).
//
// Light (a key and a fill light, directional, by default following the
// camera): the brightness of a unit normal n is
//   b = ambient + diffuse * max(0, n.L) + fill * max(0, n.F) + specular * max(0, n.H)^32
// (Blinn-Phong on the key, H the half vector between L and the view
// direction, taken constant over the frame as OpenGL's infinite viewer
// does). The fill comes from the side the key leaves dark, so that no face
// the camera sees falls to the ambient alone: with the defaults every
// visible face is at least a third of its colour's brightness
// (tests/test_render_light.cpp). b maps linearly to a shade index 0..255,
// and a material's ramp turns the index into a pixel value: black to the
// material's colour at b = ambient + diffuse, then on towards white, so a
// highlight (or key and fill together) over-exposes the colour. Vertices carry the
// index and triangles interpolate it (Gouraud): one interpolant and a table
// look-up per pixel. The index is within 1 of the double-precision oracle
// (tests/test_shade.cpp).
#ifndef DEXMILL_DISPLAY_SURFACE_SHADE_H
#define DEXMILL_DISPLAY_SURFACE_SHADE_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "display/raster/approx.h"
#include "display/raster/framebuffer.h"

namespace dexmill {

// The wide blur's radius, and how far a change of one top reaches in the
// shades: a central difference (one dexel) blurred over kSteepRadius more.
constexpr int32_t kSteepRadius = 4;
constexpr int32_t kShadeReach = kSteepRadius + 1;

struct Lighting {
  UnitQ14 light;  // towards the key light
  UnitQ14 fill_light{0, 0, 0};  // towards the fill light
  UnitQ14 half;   // normalised key light + view direction
  int32_t ambient_q14 = 5571;   // 0.34
  int32_t diffuse_q14 = 10813;  // the key's; ambient + diffuse = 1
  int32_t fill_q14 = 4915;      // 0.3; 0 turns the fill off
  int32_t specular_q14 = 4000;
  int64_t index_scale_q30 = 0;  // 255 / (ambient + diffuse + fill + specular), set by lighting_finish
};

// Sets `half` and `index_scale_q30` from light, view direction and the
// coefficients.
void lighting_finish(Lighting* l, const UnitQ14& toward_eye);
// The shade index 0..255 of a unit normal.
int32_t shade_of_normal(const Lighting& l, const UnitQ14& n);
// The same for the direction of any non-zero integer vector, without forming
// the unit vector (dot products first, one reciprocal square root): what
// the per-dexel pass uses.
int32_t shade_of_vector(const Lighting& l, int64_t nx, int64_t ny, int64_t nz);
// The index at which a ramp reaches the material's own colour.
int32_t shade_base_index(const Lighting& l);

// A material's ramp in a pixel format: index 0 black, `base_index` the
// colour, 255 white.
void shade_ramp(PixelFormat f, Rgb colour, int32_t base_index, uint32_t lut[256]);

// The same ramp applied to any colour, for colours per vertex (a 3-D
// texture evaluated at the vertices, paper §2.7.1): a channel c at shade
// index s becomes (c * mul_q8[s] + add_q8[s] + 128) >> 8, which is c s / base
// up to the base index and c + (255 - c)(s - base) / (255 - base) above it,
// within one step of shade_ramp's value (tests/test_shade.cpp).
struct LitRamp {
  uint16_t mul_q8[256];
  uint16_t add_q8[256];
};
void lit_ramp(int32_t base_index, LitRamp* out);
// The lit colour (0x00RRGGBB) of colour rgb (0x00RRGGBB) at shade s.
inline uint32_t lit_rgb(const LitRamp& l, uint32_t rgb, int32_t s) {
  const uint32_t m = l.mul_q8[s], a = l.add_q8[s] + 128u;
  return ((((rgb >> 16) & 0xFF) * m + a) >> 8) << 16 | ((((rgb >> 8) & 0xFF) * m + a) >> 8) << 8 |
         (((rgb & 0xFF) * m + a) >> 8);
}

// Per-dexel shades for the rasterizer: top vertices and side-face vertices,
// one byte each, caller memory of nx*ny each.
struct ShadeCache {
  uint8_t* top = nullptr;
  uint8_t* wall = nullptr;
};

// Recomputes the shades of the dexels in `r` (clipped to the grid). Hole
// dexels are skipped (they are never vertices).
template <class H>
void shade_grid(const DexelGrid<H>& g, const Lighting& l, GridRect r, ShadeCache* cache);

// The blurred gradient of one dexel (the reference the fast path of
// shade_grid must equal; tests use it): sums of 16 weighted grid_gradient
// values with clamped neighbours.
template <class H>
void blurred_gradient(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t* gx, int64_t* gy);

// The same over the 9x9 wide blur (steep slopes' direction), summed over
// grid_gradient with clamped neighbours: the definition that shade_grid's
// taps on the tops (used kShadeReach or more from the grid's edge) equal.
template <class H>
void wide_gradient(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t* gx, int64_t* gy);
// The gradient a dexel is shaded with (the reference shade_grid must
// equal): blurred_gradient, turned towards wide_gradient's direction on
// steep slopes kShadeReach or more from the grid's edge.
template <class H>
void shade_gradient(const DexelGrid<H>& g, int32_t i, int32_t j, int64_t* gx, int64_t* gy);

#define DEXMILL_SHADE_EXTERN(H)                                                                         \
  extern template void shade_grid<H>(const DexelGrid<H>&, const Lighting&, GridRect, ShadeCache*);   \
  extern template void blurred_gradient<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t*, int64_t*); \
  extern template void wide_gradient<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t*, int64_t*);    \
  extern template void shade_gradient<H>(const DexelGrid<H>&, int32_t, int32_t, int64_t*, int64_t*);
DEXMILL_SHADE_EXTERN(uint8_t)
DEXMILL_SHADE_EXTERN(uint16_t)
DEXMILL_SHADE_EXTERN(uint32_t)
#undef DEXMILL_SHADE_EXTERN

}  // namespace dexmill

#endif
