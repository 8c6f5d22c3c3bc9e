// core/measure/scallop.h: the highest scallop, by scans along X and Y.
#include "core/measure/scallop.h"

namespace dexmill {

namespace {

int64_t larger(int64_t a, int64_t b) { return a > b ? a : b; }

// The turning points of one scan as they come, the crests evaluated when
// the valley after them is found.
struct ScallopScan {
  bool have_prev = false, have_before = false;
  int64_t prev = 0, before = 0;  // the plateau's value and the one before it (LSB)
  int32_t plateau_start = 0;
  int dir = 0;  // +1 rising into the plateau, -1 falling, 0 not yet known
  bool have_valley = false;
  int64_t valley = 0, valley_step = 0;
  bool have_crest = false;
  int64_t crest = 0, crest_step = 0;
  int32_t crest_k = 0;
};

template <class H>
void take_crest(const DexelGrid<H>& g, ScallopScan* s, int64_t valley, int64_t valley_step, int32_t ci, int32_t cj,
                Scallop* best) {
  const bool left_higher = s->valley >= valley;
  const int64_t hv = left_higher ? s->valley : valley;
  const int64_t h = s->crest - hv;
  ++best->crests;
  if (best->found && h <= best->height_nm / g.lsb_nm) return;
  best->found = true;
  best->i = ci;
  best->j = cj;
  best->x_nm = g.x0_nm + static_cast<int64_t>(ci) * g.pitch_nm;
  best->y_nm = g.y0_nm + static_cast<int64_t>(cj) * g.pitch_nm;
  best->height_nm = h * g.lsb_nm;
  best->crest_nm = g.z0_nm + s->crest * g.lsb_nm;
  best->valley_nm = g.z0_nm + hv * g.lsb_nm;
  best->error_nm = (2 + s->crest_step + (left_higher ? s->valley_step : valley_step)) * g.lsb_nm;
}

// One scan from (i0, j0) by (di, dj), n columns.
template <class H>
void scan_scallops(const DexelGrid<H>& g, int32_t i0, int32_t j0, int32_t di, int32_t dj, int32_t n, Scallop* best) {
  ScallopScan s;
  for (int32_t k = 0; k < n; ++k) {
    const int32_t i = i0 + di * k, j = j0 + dj * k;
    if (g.is_hole(i, j)) {  // a through-cut: no valley, the scan starts again
      s = ScallopScan();
      continue;
    }
    const int64_t v = static_cast<int64_t>(g.top[g.index(i, j)]);
    if (!s.have_prev || v == s.prev) {
      if (!s.have_prev) s.plateau_start = k;
      s.have_prev = true;
      s.prev = v;
      continue;
    }
    if (v < s.prev && s.dir > 0 && s.have_valley) {  // the plateau was a crest
      s.have_crest = true;
      s.crest = s.prev;
      s.crest_step = larger(s.prev - s.before, s.prev - v);
      s.crest_k = (s.plateau_start + k - 1) / 2;
    } else if (v > s.prev && s.dir < 0) {  // the plateau was a valley
      const int64_t step = larger(s.have_before ? s.before - s.prev : 0, v - s.prev);
      if (s.have_crest)
        take_crest(g, &s, s.prev, step, i0 + di * s.crest_k, j0 + dj * s.crest_k, best);
      s.have_crest = false;
      s.have_valley = true;
      s.valley = s.prev;
      s.valley_step = step;
    }
    s.dir = v > s.prev ? 1 : -1;
    s.have_before = true;
    s.before = s.prev;
    s.prev = v;
    s.plateau_start = k;
  }
}

}  // namespace

template <class H>
ScallopAnswer scallop(const DexelGrid<H>& g, GridRect r) {
  ScallopAnswer a;
  r.i0 = r.i0 < 0 ? 0 : r.i0;
  r.j0 = r.j0 < 0 ? 0 : r.j0;
  r.i1 = r.i1 > g.nx ? g.nx : r.i1;
  r.j1 = r.j1 > g.ny ? g.ny : r.j1;
  if (r.empty()) return a;
  for (int32_t j = r.j0; j < r.j1; ++j) scan_scallops(g, r.i0, j, 1, 0, r.i1 - r.i0, &a.along_x);
  for (int32_t i = r.i0; i < r.i1; ++i) scan_scallops(g, i, r.j0, 0, 1, r.j1 - r.j0, &a.along_y);
  return a;
}

template ScallopAnswer scallop<uint8_t>(const DexelGrid<uint8_t>&, GridRect);
template ScallopAnswer scallop<uint16_t>(const DexelGrid<uint16_t>&, GridRect);
template ScallopAnswer scallop<uint32_t>(const DexelGrid<uint32_t>&, GridRect);

}  // namespace dexmill
