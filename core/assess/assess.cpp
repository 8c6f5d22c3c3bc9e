// Global and per-column error figures; see assess.h.
#include "core/assess/assess.h"

#include "core/math/wide.h"

namespace dexmill {

const int64_t kAssessBinEdgesNm[kAssessEdges] = {-1000000, -500000, -200000, -100000, -50000, -20000, -10000,
                                                 10000,    20000,   50000,   100000,  200000, 500000, 1000000};

int64_t assess_tolerance_nm(const AssessOptions& o, const GridGeometry& geo, int32_t i, int32_t j) {
  const int64_t x = geo.x0_nm + i * geo.pitch_nm, y = geo.y0_nm + j * geo.pitch_nm;
  int64_t tol = o.tol_nm;
  for (size_t k = 0; k < o.nboxes; ++k) {
    const ToleranceBox& b = o.boxes[k];
    if (x >= b.x0_nm && x <= b.x1_nm && y >= b.y0_nm && y <= b.y1_nm) tol = b.tol_nm;
  }
  return tol;
}

namespace {

// The tolerance of column (i, j) in LSB: |d| <= tol_nm <=> |d| <= floor(tol_nm
// / lsb) for integer d. Without boxes every column has tol_all_lsb.
int64_t column_tol_lsb(const AssessOptions& o, const GridGeometry& geo, int32_t i, int32_t j, int64_t tol_all_lsb) {
  return o.nboxes ? assess_tolerance_nm(o, geo, i, j) / geo.lsb_nm : tol_all_lsb;
}

template <class H>
GridGeometry geometry_of(const DexelGrid<H>& g) {
  return GridGeometry{g.nx, g.ny, g.x0_nm, g.y0_nm, g.pitch_nm, g.z0_nm, g.lsb_nm};
}

bool same_geometry(const GridGeometry& a, const GridGeometry& b) {
  return a.nx == b.nx && a.ny == b.ny && a.x0_nm == b.x0_nm && a.y0_nm == b.y0_nm && a.pitch_nm == b.pitch_nm &&
         a.z0_nm == b.z0_nm && a.lsb_nm == b.lsb_nm;
}

int histogram_bin(int64_t d_nm) {
  int k = 0;
  while (k < kAssessEdges && d_nm > kAssessBinEdgesNm[k]) ++k;
  return k;
}

}  // namespace

ErrorBand error_band(int64_t d_lsb, int64_t tol_lsb) {
  if (d_lsb > tol_lsb) return d_lsb > kBandStep3 * tol_lsb ? kBandLeft3 : d_lsb > kBandStep2 * tol_lsb ? kBandLeft2 : kBandLeft1;
  if (d_lsb < -tol_lsb) return -d_lsb > kBandStep3 * tol_lsb ? kBandGouge3 : -d_lsb > kBandStep2 * tol_lsb ? kBandGouge2 : kBandGouge1;
  return kBandWithin;
}

template <class H>
void assess_bands(const DexelGrid<H>& g, const DesignGrid& d, const AssessOptions& o, GridRect r, uint8_t* band) {
  const GridGeometry geo = geometry_of(g);
  const int64_t tol_all = o.tol_nm / g.lsb_nm;
  const int32_t i0 = max_of(r.i0, int32_t{0}), i1 = min_of(r.i1, g.nx);
  const int32_t j0 = max_of(r.j0, int32_t{0}), j1 = min_of(r.j1, g.ny);
  for (int32_t j = j0; j < j1; ++j)
    for (int32_t i = i0; i < i1; ++i) {
      const size_t k = g.index(i, j);
      const int32_t dt = d.top_lsb[k];
      if (dt == kNoDesign) {
        band[k] = kBandNone;
        continue;
      }
      band[k] = error_band(static_cast<int64_t>(g.top[k]) - dt, column_tol_lsb(o, geo, i, j, tol_all));
    }
}


template <class H>
Status assess(const DexelGrid<H>& g, const DesignGrid& d, const AssessOptions& o, AssessResult* r) {
  const GridGeometry geo = geometry_of(g);
  if (!d.top_lsb || !same_geometry(geo, d.geo) || o.tol_nm < 0) return Status::kBadArgument;
  *r = AssessResult{};
  const int64_t tol_lsb_all = o.tol_nm / g.lsb_nm;
  const int32_t i0 = max_of(o.region.i0, int32_t{0}), i1 = min_of(o.region.i1, g.nx);
  const int32_t j0 = max_of(o.region.j0, int32_t{0}), j1 = min_of(o.region.j1, g.ny);
  for (int32_t j = j0; j < j1; ++j) {
    for (int32_t i = i0; i < i1; ++i) {
      const size_t k = g.index(i, j);
      const int64_t w = g.top[k];  // a hole's top is 0: the grid's floor
      const int32_t dt = d.top_lsb[k];
      if (dt == kNoDesign) {
        if (w > 0) {
          ++r->outside_columns;
          r->outside_lsb += static_cast<uint64_t>(w);
        }
        continue;
      }
      ++r->design_columns;
      r->sum_design_top_lsb += dt > 0 ? static_cast<uint64_t>(dt) : 0;
      const int64_t dl = w - dt;  // |dl| < 2^33
      r->e_lsb2 = u128_add(r->e_lsb2, sq_u128(dl));
      ++r->histogram[histogram_bin(dl * g.lsb_nm)];
      const int64_t tol_lsb = column_tol_lsb(o, geo, i, j, tol_lsb_all);
      if (dl >= -tol_lsb && dl <= tol_lsb) {
        ++r->within_tol_columns;
      } else if (dl < 0) {
        ++r->gouge_columns;
        r->gouge_lsb += static_cast<uint64_t>(-dl);
        if (-dl > r->max_gouge_lsb) {
          r->max_gouge_lsb = -dl;
          r->max_gouge_i = i;
          r->max_gouge_j = j;
        }
      } else {
        ++r->leftover_columns;
        r->leftover_lsb += static_cast<uint64_t>(dl);
        if (dl > r->max_leftover_lsb) {
          r->max_leftover_lsb = dl;
          r->max_leftover_i = i;
          r->max_leftover_j = j;
        }
      }
    }
  }
  return Status::kOk;
}

template void assess_bands<uint8_t>(const DexelGrid<uint8_t>&, const DesignGrid&, const AssessOptions&, GridRect, uint8_t*);
template void assess_bands<uint16_t>(const DexelGrid<uint16_t>&, const DesignGrid&, const AssessOptions&, GridRect, uint8_t*);
template void assess_bands<uint32_t>(const DexelGrid<uint32_t>&, const DesignGrid&, const AssessOptions&, GridRect, uint8_t*);
template Status assess<uint8_t>(const DexelGrid<uint8_t>&, const DesignGrid&, const AssessOptions&, AssessResult*);
template Status assess<uint16_t>(const DexelGrid<uint16_t>&, const DesignGrid&, const AssessOptions&, AssessResult*);
template Status assess<uint32_t>(const DexelGrid<uint32_t>&, const DesignGrid&, const AssessOptions&, AssessResult*);

}  // namespace dexmill
