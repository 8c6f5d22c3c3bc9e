// The workpiece as a dexel set, paper §2.1-2.2.1.
//
// D = (R, X, L, C):
//   R = (nx, ny), the resolution;
//   X = the nx*ny dexels, `top` and `bottom` heights in two caller-owned
//       arrays (row-major, index j*nx + i), m-bit unsigned integers;
//   L = the location: dexel (i, j) stands on the column axis
//       (x0_nm + i*pitch_nm, y0_nm + j*pitch_nm) in machine coordinates;
//   C = the local frame. dexmill simulates 3-axis milling, so C is the machine
//       frame with dexels along +z; it is implied, not stored.
// A height h means z = z0_nm + h*lsb_nm (a fixed LSB per grid). A dexel with
// top = bottom = 0 is a hole (paper §2.4).
#ifndef DEXMILL_CORE_GRID_GRID_H
#define DEXMILL_CORE_GRID_GRID_H

#include <stddef.h>
#include <stdint.h>
#include <limits>

#include "core/math/fixed.h"
#include "core/status.h"

namespace dexmill {

// A half-open rectangle of dexel indices [i0, i1) x [j0, j1); empty when
// i0 >= i1 or j0 >= j1.
struct GridRect {
  int32_t i0, j0, i1, j1;

  bool empty() const { return i0 >= i1 || j0 >= j1; }
  static GridRect none() { return GridRect{0, 0, 0, 0}; }
  void include(const GridRect& r) {
    if (r.empty()) return;
    if (empty()) { *this = r; return; }
    i0 = min_of(i0, r.i0); j0 = min_of(j0, r.j0);
    i1 = max_of(i1, r.i1); j1 = max_of(j1, r.j1);
  }
};

// Largest height of an m-bit height type: 2^m - 1.
template <class H>
constexpr int64_t height_max() { return static_cast<int64_t>(std::numeric_limits<H>::max()); }

template <class H>
struct DexelGrid {
  static_assert(std::is_unsigned<H>::value && sizeof(H) <= 4, "m-bit heights: uint8/16/32");
  int32_t nx = 0, ny = 0;      // R: dexels along x and y
  H* top = nullptr;            // X: top heights, LSB, caller memory of nx*ny
  H* bottom = nullptr;         // X: bottom heights, LSB, caller memory of nx*ny
  int64_t x0_nm = 0, y0_nm = 0;  // L: machine x, y of dexel (0, 0)'s axis
  int64_t pitch_nm = 0;        // spacing of dexel axes in x and y
  int64_t z0_nm = 0;           // machine z of height 0
  int64_t lsb_nm = 0;          // z of one height step
  GridRect dirty = GridRect::none();  // dexels changed since the consumer last cleared it
  // True while every bottom is 0 (set by grid_block_stock, cleared by a
  // case-c cut): lets the cutting loops reduce the figure-2 cases to a min().
  bool bottoms_zero = false;
  // No top is above this (LSB): the m-bit maximum from grid_init, the stock
  // height from grid_block_stock; cuts only lower tops. A tool whose shaft
  // reaches it cuts every column as a min() (core/cut/sweep.h).
  int64_t top_bound_lsb = 0;

  size_t index(int32_t i, int32_t j) const { return static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i); }
  bool contains(int32_t i, int32_t j) const { return i >= 0 && j >= 0 && i < nx && j < ny; }
  GridRect bounds() const { return GridRect{0, 0, nx, ny}; }
  bool is_hole(int32_t i, int32_t j) const { size_t k = index(i, j); return top[k] == 0 && bottom[k] == 0; }
};

// Where the grid sits and how fine it is.
struct GridGeometry {
  int32_t nx, ny;
  int64_t x0_nm, y0_nm, pitch_nm;
  int64_t z0_nm, lsb_nm;
};

// Bounds of the geometry (the grid's ranges): 2 <= nx, ny <=
// 65535, pitch and LSB in [1 nm, 1 m], origins within +-1 km. So an index
// times the pitch is below 2^46 nm and every dexel axis within 1 km + 65.5
// km < 2^46.1 nm of the origin; a height is at most 2^m - 1 LSB (2^32 - 1
// for 32-bit heights), its z within 1 km + 2^32 m. The cut's proofs start
// from these (core/cut/sweep.h, core/cut/stamp.cpp); core/sim/stock_plan.h
// narrows them for a run's stock.
Status grid_check_geometry(const GridGeometry& geo);

// Points `g` at caller memory for top and bottom (`cells` entries each) and
// sets the geometry. Heights are left as they are. Fails with kBufferTooSmall
// when cells < nx*ny, kBadArgument on a geometry outside the bounds above.
template <class H>
Status grid_init(DexelGrid<H>* g, const GridGeometry& geo, H* top, H* bottom, size_t cells);

// Block of stock, paper §2.2.1: every dexel top = height_lsb (saturated to
// 2^m - 1), bottom = 0, except the border dexels (i = 0, j = 0, i = nx-1,
// j = ny-1), which are holes so that the block's edges draw as side faces.
// Marks the whole grid dirty.
template <class H>
void grid_block_stock(DexelGrid<H>* g, int64_t height_lsb);

// Height-gradient normal by central differences, paper §2.1 eq. 1:
//   n = (top(i+1,j) - top(i-1,j), top(i,j+1) - top(i,j-1), 2*pitch/lsb),
// all in LSB. At the grid's edge the missing neighbour is the dexel itself
// (a one-sided difference). The surface normal pointing out of the material
// is (-dx, -dy, dz).
struct GradientLsb {
  int64_t dx, dy, dz;
};
template <class H>
GradientLsb grid_gradient(const DexelGrid<H>& g, int32_t i, int32_t j);

// The height in LSB of machine z, rounded to nearest (not clamped: values
// outside [0, 2^m-1] mean below or above the representable range).
template <class H>
int64_t grid_height_of_z(const DexelGrid<H>& g, int64_t z_nm) { return div_round(z_nm - g.z0_nm, g.lsb_nm); }

// Nearest dexel index of machine x or y (not clamped; may be outside).
template <class H>
int64_t grid_i_of_x(const DexelGrid<H>& g, int64_t x_nm) { return div_round(x_nm - g.x0_nm, g.pitch_nm); }
template <class H>
int64_t grid_j_of_y(const DexelGrid<H>& g, int64_t y_nm) { return div_round(y_nm - g.y0_nm, g.pitch_nm); }

// FNV-1a 64 of the grid: nx, ny (4 bytes each), then every top, then every
// bottom, each as sizeof(H) little-endian bytes. Same value on every CPU.
template <class H>
uint64_t grid_hash(const DexelGrid<H>& g);

// A height LSB for `range_nm` of material in an m-bit height: the smallest
// 1, 2 or 5 times a power of ten (nm) with range_nm / lsb <= 2^m - 1.
int64_t lsb_for_range(int64_t range_nm, int bits);

extern template Status grid_init<uint8_t>(DexelGrid<uint8_t>*, const GridGeometry&, uint8_t*, uint8_t*, size_t);
extern template Status grid_init<uint16_t>(DexelGrid<uint16_t>*, const GridGeometry&, uint16_t*, uint16_t*, size_t);
extern template Status grid_init<uint32_t>(DexelGrid<uint32_t>*, const GridGeometry&, uint32_t*, uint32_t*, size_t);
extern template void grid_block_stock<uint8_t>(DexelGrid<uint8_t>*, int64_t);
extern template void grid_block_stock<uint16_t>(DexelGrid<uint16_t>*, int64_t);
extern template void grid_block_stock<uint32_t>(DexelGrid<uint32_t>*, int64_t);
extern template GradientLsb grid_gradient<uint8_t>(const DexelGrid<uint8_t>&, int32_t, int32_t);
extern template GradientLsb grid_gradient<uint16_t>(const DexelGrid<uint16_t>&, int32_t, int32_t);
extern template GradientLsb grid_gradient<uint32_t>(const DexelGrid<uint32_t>&, int32_t, int32_t);
extern template uint64_t grid_hash<uint8_t>(const DexelGrid<uint8_t>&);
extern template uint64_t grid_hash<uint16_t>(const DexelGrid<uint16_t>&);
extern template uint64_t grid_hash<uint32_t>(const DexelGrid<uint32_t>&);

}  // namespace dexmill

#endif
