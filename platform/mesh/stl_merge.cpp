// The merged STL surface; see stl_merge.h.
#include "platform/mesh/stl_merge.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "display/surface/mesh.h"
#include "platform/mesh/stl_ladder.h"
#include "platform/mesh/stl_plane.h"

namespace dexmill {
namespace {

// A cell's sides, in kCellCases' corner order: c0-c1 (low y), c1-c2 (high
// x), c2-c3 (high y), c3-c0 (low x).
enum Side : int { kLowY = 0, kHighX = 1, kHighY = 2, kLowX = 3 };

// The side an axis-aligned wall stands on (masks 3, 6, 12, 9), else -1.
int wall_side(int mask) {
  switch (mask) {
    case 3: return kLowY;
    case 6: return kHighX;
    case 12: return kHighY;
    case 9: return kLowX;
    default: return -1;
  }
}

const int kDi[4] = {0, 1, 1, 0}, kDj[4] = {0, 0, 1, 1};

// Which face a cell's triangle along one of its sides belongs to. Equal
// keys of two cells next to each other mean one merged face: the same run
// of flat cells (a rectangle continues only through rows with the same
// run), or the same wall strip (same line and facing, same heights).
struct FaceKey {
  enum Kind : uint8_t { kSingle, kTop, kBottom, kWall };
  Kind kind;
  int32_t a, b;  // a run's [lo, hi); a wall's mask
  int64_t h0_lsb, h1_lsb;  // a level run's height, a planar run's first row (h0); a wall's top and bottom
};

bool same_face(const FaceKey& x, const FaceKey& y) {
  return x.kind != FaceKey::kSingle && x.kind == y.kind && x.a == y.a && x.b == y.b && x.h0_lsb == y.h0_lsb &&
         x.h1_lsb == y.h1_lsb;
}

// One row of cells, classified.
struct CellRow {
  int32_t j = -1;                  // cell row; outside the grid every cell is empty
  std::vector<uint8_t> mask;       // kCellCases index
  std::vector<int32_t> lo[2], hi[2];  // [0] tops, [1] bottoms: the run of flat cells [lo, hi) holding the cell, or -1
  std::vector<int64_t> key[2];        // with lo: the run's height, or (planar tops) the first row of its rectangle
  std::vector<uint8_t> wall_ok;    // an axis wall with one top and one bottom height, top above bottom
};

template <class H>
class Merger {
 public:
  Merger(const DexelGrid<H>& g, const SurfaceMaterial& m, int64_t tolerance_lsb, TriangleSink* out)
      : g_(g), m_(m), out_(out), ncx_(g.nx - 1), ncy_(g.ny - 1), planar_(tolerance_lsb > 1),
        planes_(g, tolerance_lsb), lift_(g, out) {
    for (CellRow& r : rows_) {
      r.mask.resize(ncx_);
      r.wall_ok.resize(ncx_);
      for (int b = 0; b < 2; ++b) {
        r.lo[b].resize(ncx_);
        r.hi[b].resize(ncx_);
        r.key[b].resize(ncx_);
      }
    }
    for (int b = 0; b < 2; ++b) {
      flat_open_[b].resize(ncx_);
      material_[b].resize(g.nx);
    }
    ywall_open_.resize(ncx_);
    ywall_continues_.resize(ncx_);
  }

  void run() {
    CellRow *prev = &rows_[0], *cur = &rows_[1], *next = &rows_[2];
    classify(prev, -1);
    classify(cur, 0);
    for (int32_t j = 0; j < ncy_; ++j) {
      classify(next, j + 1);
      for (int b = 0; b < 2; ++b) flat_faces(*prev, *cur, *next, b == 1);
      ywall_faces(*cur, *next);
      xwall_faces(*prev, *cur, *next);
      single_cells(*cur);
      CellRow* t = prev;
      prev = cur;
      cur = next;
      next = t;
    }
  }

 private:
  int64_t height(int32_t i, int32_t j, bool bottom) const {
    const size_t k = g_.index(i, j);
    return static_cast<int64_t>(bottom ? g_.bottom[k] : g_.top[k]);
  }
  // The top and bottom of an axis wall (of its first dexel).
  int64_t wall_height(int32_t i, int32_t j, int mask, bool bottom) const {
    const int c = kCellCases[mask].wall[0];
    return height(i + kDi[c], j + kDj[c], bottom);
  }

  void classify(CellRow* r, int32_t j) {
    r->j = j;
    if (j < 0 || j >= ncy_) {
      std::fill(r->mask.begin(), r->mask.end(), 0);
      for (int b = 0; b < 2; ++b) std::fill(r->lo[b].begin(), r->lo[b].end(), -1);
      return;
    }
    for (int32_t i = 0; i < g_.nx; ++i) {
      material_[0][i] = m_.at(i, j);
      material_[1][i] = m_.at(i, j + 1);
    }
    for (int32_t i = 0; i < ncx_; ++i)
      r->mask[i] = static_cast<uint8_t>(material_[0][i] | material_[0][i + 1] << 1 | material_[1][i + 1] << 2 |
                                        material_[1][i] << 3);
    const H* const rows[2][2] = {{g_.top + g_.index(0, j), g_.top + g_.index(0, j + 1)},
                                 {g_.bottom + g_.index(0, j), g_.bottom + g_.index(0, j + 1)}};
    for (int b = 0; b < 2; ++b) {
      if (b == 0 && planar_) {
        planes_.row(j, r->mask, &r->lo[0], &r->hi[0], &r->key[0]);
        continue;
      }
      const H *h0 = rows[b][0], *h1 = rows[b][1];
      // Flat cells next to each other share two corners: one height.
      int32_t run_lo = -1;
      for (int32_t i = 0; i < ncx_; ++i) {
        const bool flat = r->mask[i] == 15 && h0[i] == h0[i + 1] && h0[i] == h1[i] && h0[i] == h1[i + 1];
        run_lo = !flat ? -1 : run_lo >= 0 ? run_lo : i;
        r->lo[b][i] = run_lo;
        r->key[b][i] = static_cast<int64_t>(h0[i]);
      }
      for (int32_t i = ncx_ - 1, run_hi = -1; i >= 0; --i) {
        if (r->lo[b][i] < 0) run_hi = -1;
        else if (run_hi < 0) run_hi = i + 1;
        r->hi[b][i] = run_hi;
      }
    }
    for (int32_t i = 0; i < ncx_; ++i) {
      const int mask = r->mask[i];
      if (wall_side(mask) < 0) {
        r->wall_ok[i] = 0;
        continue;
      }
      const CellCase& cc = kCellCases[mask];
      const int ca = cc.wall[0], cb = cc.wall[1];
      const H ta = rows[0][kDj[ca]][i + kDi[ca]], tb = rows[0][kDj[cb]][i + kDi[cb]];
      const H ba = rows[1][kDj[ca]][i + kDi[ca]], bb = rows[1][kDj[cb]][i + kDi[cb]];
      r->wall_ok[i] = ta == tb && ba == bb && ta > ba;
    }
  }

  // The face of cell i of row r along its side `side`, on the top surface
  // or (bottom) the bottom one.
  FaceKey face(const CellRow& r, int32_t i, int side, bool bottom) const {
    FaceKey k{FaceKey::kSingle, 0, 0, 0, 0};
    if (r.j < 0 || r.j >= ncy_ || i < 0 || i >= ncx_) return k;
    const int b = bottom ? 1 : 0;
    if (r.lo[b][i] >= 0) return FaceKey{bottom ? FaceKey::kBottom : FaceKey::kTop, r.lo[b][i], r.hi[b][i], r.key[b][i], 0};
    const int mask = r.mask[i];
    if (r.wall_ok[i] && wall_side(mask) == side)
      return FaceKey{FaceKey::kWall, mask, 0, wall_height(i, r.j, mask, false), wall_height(i, r.j, mask, true)};
    return k;
  }
  // A point between two side segments is kept unless one merged face lies
  // across both (stl_merge.h).
  bool kept(const FaceKey& x, const FaceKey& y) const { return !same_face(x, y); }

  // The rectangles of flat tops (or bottoms) holding a run of row c; with
  // a tolerance the tops are planar ones, their points at their own tops.
  void flat_faces(const CellRow& p, const CellRow& c, const CellRow& n, bool bottom) {
    const int b = bottom ? 1 : 0;
    const int32_t j = c.j;
    for (int32_t lo = 0; lo < ncx_; ++lo) {
      if (c.lo[b][lo] != lo) continue;
      const int32_t hi = c.hi[b][lo];
      const int64_t key = c.key[b][lo];
      auto same_run = [&](const CellRow& r) { return r.lo[b][lo] == lo && r.hi[b][lo] == hi && r.key[b][lo] == key; };
      const bool lifted = planar_ && !bottom;
      const LadderPlane plane{LadderPlane::kXY, lifted ? 0 : key, bottom, lifted ? static_cast<TriangleSink*>(&lift_) : out_};
      Ladder& lad = flat_open_[b][lo];
      if (!same_run(p)) {
        cap_.clear();
        for (int32_t x = lo + 1; x < hi; ++x)
          if (kept(face(p, x - 1, kHighY, bottom), face(p, x, kHighY, bottom))) cap_.push_back(x);
        lad.open(lo, hi, j, cap_);
      }
      if (same_run(n)) {
        if (kept(face(c, lo - 1, kHighX, bottom), face(n, lo - 1, kHighX, bottom))) lad.feed(false, j + 1, plane);
        if (kept(face(c, hi, kLowX, bottom), face(n, hi, kLowX, bottom))) lad.feed(true, j + 1, plane);
      } else {
        cap_.clear();
        for (int32_t x = lo + 1; x < hi; ++x)
          if (kept(face(n, x - 1, kLowY, bottom), face(n, x, kLowY, bottom))) cap_.push_back(x);
        lad.close(j + 1, cap_, plane);
      }
    }
  }
  // Wall strips along y (on the lines x = const), continued row by row.
  void ywall_faces(const CellRow& c, const CellRow& n) {
    const int32_t j = c.j;
    for (int32_t i = 0; i < ncx_; ++i) {
      const int mask = c.mask[i];
      if ((mask != 6 && mask != 9) || !c.wall_ok[i]) continue;
      const int64_t top = wall_height(i, j, mask, false), bot = wall_height(i, j, mask, true);
      const FaceKey key{FaceKey::kWall, mask, 0, top, bot};
      // The material side: the cell across the wall's line.
      const int32_t o = mask == 9 ? i - 1 : i + 1;
      const int side = mask == 9 ? kHighX : kLowX;
      const LadderPlane plane{LadderPlane::kZY, mask == 9 ? i : i + 1, mask == 9, out_};
      Ladder& lad = ywall_open_[i];
      if (!ywall_continues_[i]) lad.open(bot, top, j, no_cap_);
      ywall_continues_[i] = same_face(key, face(n, i, wall_side(mask), false));
      if (ywall_continues_[i]) {
        if (kept(face(c, o, side, true), face(n, o, side, true))) lad.feed(false, j + 1, plane);
        if (kept(face(c, o, side, false), face(n, o, side, false))) lad.feed(true, j + 1, plane);
      } else {
        lad.close(j + 1, no_cap_, plane);
      }
    }
  }

  // Wall strips along x (on the lines y = const), within the row.
  void xwall_faces(const CellRow& p, const CellRow& c, const CellRow& n) {
    const int32_t j = c.j;
    for (int32_t lo = 0; lo < ncx_;) {
      const int mask = c.mask[lo];
      if ((mask != 3 && mask != 12) || !c.wall_ok[lo]) {
        ++lo;
        continue;
      }
      const FaceKey key = face(c, lo, wall_side(mask), false);
      int32_t hi = lo + 1;
      while (hi < ncx_ && same_face(key, face(c, hi, wall_side(mask), false))) ++hi;
      const CellRow& o = mask == 3 ? p : n;
      const int side = mask == 3 ? kHighY : kLowY;
      const LadderPlane plane{LadderPlane::kZX, mask == 3 ? j : j + 1, mask == 12, out_};
      Ladder lad;
      lad.open(key.h1_lsb, key.h0_lsb, lo, no_cap_);
      for (int32_t x = lo + 1; x < hi; ++x) {
        if (kept(face(o, x - 1, side, true), face(o, x, side, true))) lad.feed(false, x, plane);
        if (kept(face(o, x - 1, side, false), face(o, x, side, false))) lad.feed(true, x, plane);
      }
      lad.close(hi, no_cap_, plane);
      lo = hi;
    }
  }

  // What no merged face holds, one or two triangles a cell as before.
  void single_cells(const CellRow& c) {
    for (int32_t i = 0; i < ncx_; ++i) {
      const int mask = c.mask[i];
      if (!mask) continue;
      unsigned parts = 0;
      if (kCellCases[mask].has_wall && !(wall_side(mask) >= 0 && c.wall_ok[i])) parts |= kCellWall;
      if (c.lo[0][i] < 0) parts |= kCellTop;
      if (c.lo[1][i] < 0) parts |= kCellBottom;
      if (parts) cell_triangles(g_, i, c.j, mask, parts, out_);
    }
  }

  const DexelGrid<H>& g_;
  const SurfaceMaterial& m_;
  TriangleSink* out_;
  int32_t ncx_, ncy_;
  bool planar_;  // tops merge within the tolerance (stl_plane.h), not only level ones
  PlaneRuns<H> planes_;
  TopLift<H> lift_;
  CellRow rows_[3];
  std::vector<Ladder> flat_open_[2];  // by the run's lo: the rectangle through the current row
  std::vector<Ladder> ywall_open_;    // by cell column: the strip through the current row
  std::vector<uint8_t> ywall_continues_;  // by cell column: the strip goes on into the next row
  std::vector<uint8_t> material_[2];  // dexel rows j and j + 1 while classifying cell row j
  std::vector<int64_t> cap_;
  const std::vector<int64_t> no_cap_;
};

}  // namespace

template <class H>
void merged_surface(const DexelGrid<H>& g, const SurfaceMaterial& m, int64_t tolerance_lsb, TriangleSink* out) {
  if (g.nx < 2 || g.ny < 2) return;
  Merger<H> merger(g, m, tolerance_lsb, out);
  merger.run();
}

template void merged_surface<uint8_t>(const DexelGrid<uint8_t>&, const SurfaceMaterial&, int64_t, TriangleSink*);
template void merged_surface<uint16_t>(const DexelGrid<uint16_t>&, const SurfaceMaterial&, int64_t, TriangleSink*);
template void merged_surface<uint32_t>(const DexelGrid<uint32_t>&, const SurfaceMaterial&, int64_t, TriangleSink*);

}  // namespace dexmill
