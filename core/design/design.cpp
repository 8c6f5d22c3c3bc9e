// Design dexels from triangles and height images; see design.h.
#include "core/design/design.h"

#include "core/math/fixed.h"

namespace dexmill {

namespace {

bool within_range(int64_t v) { return v >= -kDesignRangeNm && v <= kDesignRangeNm; }

// (b - a) x (p - a), exact: every coordinate within +-kDesignRangeNm, so
// each product is below 2^62 and the difference below 2^63.
int64_t edge(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

void raise_top(int32_t* top, int64_t z_lsb) {
  const int32_t z = sat_i32(z_lsb);
  if (*top == kNoDesign || z > *top) *top = z;
}

}  // namespace

Status design_init(DesignGrid* d, const GridGeometry& geo, int32_t* mem, size_t cells) {
  if (geo.nx <= 0 || geo.ny <= 0 || geo.pitch_nm <= 0 || geo.lsb_nm <= 0) return Status::kBadArgument;
  if (cells < static_cast<size_t>(geo.nx) * static_cast<size_t>(geo.ny)) return Status::kBufferTooSmall;
  if ((static_cast<int64_t>(max_of(geo.nx, geo.ny)) - 1) * geo.pitch_nm > kDesignRangeNm) return Status::kOutOfRange;
  d->geo = geo;
  d->top_lsb = mem;
  d->triangles = d->triangles_vertical = 0;
  const size_t n = static_cast<size_t>(geo.nx) * static_cast<size_t>(geo.ny);
  for (size_t k = 0; k < n; ++k) mem[k] = kNoDesign;
  return Status::kOk;
}

Status design_add_triangle(DesignGrid* d, const TriangleNm& t) {
  const GridGeometry& g = d->geo;
  int64_t x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = t.v[k].x_nm - g.x0_nm;
    y[k] = t.v[k].y_nm - g.y0_nm;
    z[k] = t.v[k].z_nm - g.z0_nm;
    if (!within_range(x[k]) || !within_range(y[k]) || !within_range(z[k])) return Status::kOutOfRange;
  }
  ++d->triangles;
  int64_t area2 = edge(x[0], y[0], x[1], y[1], x[2], y[2]);
  if (area2 == 0) {
    ++d->triangles_vertical;
    return Status::kOk;
  }
  if (area2 < 0) {  // counterclockwise in XY, so inside is every edge >= 0
    int64_t s = x[1]; x[1] = x[2]; x[2] = s;
    s = y[1]; y[1] = y[2]; y[2] = s;
    s = z[1]; z[1] = z[2]; z[2] = s;
    area2 = -area2;
  }
  const int64_t p = g.pitch_nm;
  const int64_t i0 = max_of(div_ceil(min_of(x[0], min_of(x[1], x[2])), p), int64_t{0});
  const int64_t i1 = min_of(div_floor(max_of(x[0], max_of(x[1], x[2])), p), int64_t{g.nx} - 1);
  const int64_t j0 = max_of(div_ceil(min_of(y[0], min_of(y[1], y[2])), p), int64_t{0});
  const int64_t j1 = min_of(div_floor(max_of(y[0], max_of(y[1], y[2])), p), int64_t{g.ny} - 1);
  // A column whose top is already at or above the triangle's highest vertex
  // needs no z (the common case deep inside a closed mesh's upper surface).
  const int64_t zmax_lsb = div_round(max_of(z[0], max_of(z[1], z[2])), g.lsb_nm);
  for (int64_t j = j0; j <= j1; ++j) {
    const int64_t py = j * p;
    for (int64_t i = i0; i <= i1; ++i) {
      const int64_t px = i * p;
      const int64_t w0 = edge(x[1], y[1], x[2], y[2], px, py);
      const int64_t w1 = edge(x[2], y[2], x[0], y[0], px, py);
      const int64_t w2 = edge(x[0], y[0], x[1], y[1], px, py);
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      int32_t* top = &d->top_lsb[d->index(static_cast<int32_t>(i), static_cast<int32_t>(j))];
      if (*top != kNoDesign && *top >= zmax_lsb) continue;
      // z = z0 + (w1 (z1 - z0) + w2 (z2 - z0)) / area2 (barycentric, w0 +
      // w1 + w2 = area2): each quotient floored, so 2 nm low at most.
      const int64_t z_nm = z[0] + muldiv_floor(w1, z[1] - z[0], area2) + muldiv_floor(w2, z[2] - z[0], area2);
      raise_top(top, div_round(z_nm, g.lsb_nm));
    }
  }
  return Status::kOk;
}

Status design_from_image(DesignGrid* d, const HeightImage& img, int64_t x0_nm, int64_t y0_nm, int64_t x1_nm,
                         int64_t y1_nm, int64_t z_low_nm, int64_t z_high_nm) {
  if (!img.samples || img.w <= 0 || img.h <= 0 || img.maxval == 0 || x1_nm <= x0_nm || y1_nm <= y0_nm)
    return Status::kBadArgument;
  const GridGeometry& g = d->geo;
  const int64_t zl = z_low_nm - g.z0_nm, dz = z_high_nm - z_low_nm;
  if (!within_range(zl) || !within_range(z_high_nm - g.z0_nm)) return Status::kOutOfRange;
  for (int32_t j = 0; j < g.ny; ++j) {
    const int64_t y = g.y0_nm + j * g.pitch_nm;
    for (int32_t i = 0; i < g.nx; ++i) {
      const int64_t x = g.x0_nm + i * g.pitch_nm;
      int32_t* top = &d->top_lsb[d->index(i, j)];
      if (x < x0_nm || x > x1_nm || y < y0_nm || y > y1_nm) {
        *top = kNoDesign;
        continue;
      }
      // The pixel covering the axis; the far edges belong to the last pixel.
      const int64_t u = min_of(muldiv_floor(x - x0_nm, img.w, x1_nm - x0_nm), int64_t{img.w} - 1);
      const int64_t v = min_of(muldiv_floor(y1_nm - y, img.h, y1_nm - y0_nm), int64_t{img.h} - 1);
      const int64_t s = min_of(int64_t{img.samples[v * img.w + u]}, int64_t{img.maxval});
      const int64_t z_nm = zl + muldiv_round(dz, s, img.maxval);
      *top = sat_i32(div_round(z_nm, g.lsb_nm));
    }
  }
  return Status::kOk;
}

template <class H>
void design_to_grid(const DesignGrid& d, GridRect region, DexelGrid<H>* g) {
  const int64_t hmax = height_max<H>();
  for (int32_t j = 0; j < g->ny; ++j)
    for (int32_t i = 0; i < g->nx; ++i) {
      const size_t k = g->index(i, j);
      const int32_t t = d.top_lsb[k];
      const bool in = i >= region.i0 && i < region.i1 && j >= region.j0 && j < region.j1;
      g->top[k] = static_cast<H>(in && t != kNoDesign ? clamp<int64_t>(t, 1, hmax) : 0);
      g->bottom[k] = 0;
    }
  g->bottoms_zero = true;
  g->top_bound_lsb = hmax;
  g->dirty = g->bounds();
}

template void design_to_grid<uint8_t>(const DesignGrid&, GridRect, DexelGrid<uint8_t>*);
template void design_to_grid<uint16_t>(const DesignGrid&, GridRect, DexelGrid<uint16_t>*);
template void design_to_grid<uint32_t>(const DesignGrid&, GridRect, DexelGrid<uint32_t>*);

uint64_t design_columns(const DesignGrid& d) {
  const size_t n = static_cast<size_t>(d.geo.nx) * static_cast<size_t>(d.geo.ny);
  uint64_t c = 0;
  for (size_t k = 0; k < n; ++k) c += d.top_lsb[k] != kNoDesign ? 1 : 0;
  return c;
}

}  // namespace dexmill
