// Cell classification and triangle streaming (see mesh.h).
#include "display/mesh.h"

#include "display/clip.h"

namespace dexmill {

// Corners: 0 = (i, j), 1 = (i+1, j), 2 = (i+1, j+1), 3 = (i, j+1). A wall
// runs along the material's boundary in its counterclockwise direction.
const CellCase kCellCases[16] = {
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 0: all holes
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 1: c0
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 2: c1
    {0, {{0, 0, 0}, {0, 0, 0}}, 1, {1, 0}},  // 3: c0 c1, wall facing +y
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 4: c2
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 5: c0 c2 diagonal
    {0, {{0, 0, 0}, {0, 0, 0}}, 1, {2, 1}},  // 6: c1 c2, wall facing -x
    {1, {{0, 1, 2}, {0, 0, 0}}, 1, {2, 0}},  // 7: no c3
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 8: c3
    {0, {{0, 0, 0}, {0, 0, 0}}, 1, {0, 3}},  // 9: c3 c0, wall facing +x
    {0, {{0, 0, 0}, {0, 0, 0}}, 0, {0, 0}},  // 10: c1 c3 diagonal
    {1, {{0, 1, 3}, {0, 0, 0}}, 1, {1, 3}},  // 11: no c2
    {0, {{0, 0, 0}, {0, 0, 0}}, 1, {3, 2}},  // 12: c2 c3, wall facing -y
    {1, {{0, 2, 3}, {0, 0, 0}}, 1, {0, 2}},  // 13: no c1
    {1, {{1, 2, 3}, {0, 0, 0}}, 1, {3, 1}},  // 14: no c0
    {2, {{0, 1, 2}, {0, 2, 3}}, 0, {0, 0}},  // 15: all material
};

namespace {

// A dexel end (top or bottom) placed on the screen.
struct MeshVertex {
  int32_t cx, cy, cw;  // clip space (orthographic: q4 x, y and depth; perspective: x, y, w in U)
  RasterVertex r;      // screen vertex, valid when oc == 0 (shade set per use)
  uint8_t oc;          // clip outcode
};

struct Corner {
  MeshVertex top, bot;
  size_t k;       // dexel index
  bool material;
  bool has_bot;   // bot computed
};

// kOrtho: the orthographic fast path (clip space is the screen; outcodes are
// four comparisons); otherwise the general projection.
template <class H, bool kOrtho>
class CellDrawer {
 public:
  explicit CellDrawer(const MeshPass<H>& p) : p_(p), g_(*p.grid), v_(*p.view), top_shade_(p.shades->top) {}

  void draw(GridRect c, bool i_desc, bool j_desc) {
    n_ = c.i1 - c.i0 + 1;
    i0_ = c.i0;
    Corner* lo = rows_[0];
    Corner* hi = rows_[1];
    // Vertex rows j and j + 1 of the current cell row, reused as the walk
    // moves on.
    const int32_t jstep = j_desc ? -1 : 1;
    int32_t jc = j_desc ? c.j1 - 1 : c.j0;
    build_row(jc, lo);
    build_row(jc + 1, hi);
    for (int32_t n = 0; n < c.j1 - c.j0; ++n) {
      if (n > 0) {
        jc += jstep;
        if (j_desc) {  // the old row j is the new row j + 1
          Corner* t = hi; hi = lo; lo = t;
          build_row(jc, lo);
        } else {
          Corner* t = lo; lo = hi; hi = t;
          build_row(jc + 1, hi);
        }
      }
      for (int32_t m = 0; m < n_ - 1; ++m) {
        const int32_t a = i_desc ? n_ - 2 - m : m;
        Corner* q[4] = {&lo[a], &lo[a + 1], &hi[a + 1], &hi[a]};
        const int mask = q[0]->material | q[1]->material << 1 | q[2]->material << 2 | q[3]->material << 3;
        if (mask) cell(q, kCellCases[mask]);
      }
    }
  }

 private:
  // Clip space of dexel (i, j) at height h from the row's running sum
  // acc = m[.][0] i + m[.][1] j + c (exactly the grid map: integer sums).
  void finish(const int64_t acc[3], int64_t h, MeshVertex* mv) const {
    const AffineQ32& a = v_.grid;
    mv->cx = static_cast<int32_t>((acc[0] + a.m[0][2] * h) >> 32);
    mv->cy = static_cast<int32_t>((acc[1] + a.m[1][2] * h) >> 32);
    mv->cw = static_cast<int32_t>((acc[2] + a.m[2][2] * h) >> 32);
    if (kOrtho) {
      // The four guard planes of clip_set_planes, as comparisons.
      mv->oc = static_cast<uint8_t>((mv->cx < gx0_) | (mv->cx > gx1_) << 1 | (mv->cy < gy0_) << 2 | (mv->cy > gy1_) << 3);
      mv->r.x_q4 = mv->cx;
      mv->r.y_q4 = mv->cy;
      mv->r.depth = mv->cw;
    } else {
      mv->oc = clip_outcode(v_.proj, mv->cx, mv->cy, mv->cw);
      if (mv->oc == 0) mv->r = clip_project(v_.proj, clip_vertex(*mv, 0));
    }
  }

  void place(int32_t i, int32_t j, int64_t h, MeshVertex* mv) const {
    const AffineQ32& a = v_.grid;
    int64_t acc[3];
    for (int k = 0; k < 3; ++k) acc[k] = a.m[k][0] * i + a.m[k][1] * j + a.c[k];
    finish(acc, h, mv);
  }

  ClipVertex clip_vertex(const MeshVertex& m, int32_t shade) const {
    ClipVertex c;
    c.x = m.cx;
    c.y = m.cy;
    c.shade = shade;
    if (v_.proj.kind == Projection::kOrthographic) {
      c.w = 1;
      c.depth = m.cw;
    } else {
      c.w = m.cw;
      c.depth = 0;
    }
    return c;
  }

  void build_row(int32_t j, Corner* row) {
    const AffineQ32& a = v_.grid;
    int64_t acc[3];
    for (int k = 0; k < 3; ++k) acc[k] = a.m[k][0] * i0_ + a.m[k][1] * j + a.c[k];
    size_t k = g_.index(i0_, j);
    for (int32_t n = 0; n < n_; ++n, ++k) {
      Corner& c = row[n];
      c.k = k;
      const H t = g_.top[k], b = g_.bottom[k];
      c.material = (t | b) != 0;
      c.has_bot = false;
      if (c.material) {
        finish(acc, t, &c.top);
        c.top.r.shade = top_shade_[k];
      }
      acc[0] += a.m[0][0];
      acc[1] += a.m[1][0];
      acc[2] += a.m[2][0];
    }
  }

  const MeshVertex& bottom(Corner* c) {
    if (!c->has_bot) {
      const int32_t i = static_cast<int32_t>(c->k % static_cast<size_t>(g_.nx));
      const int32_t j = static_cast<int32_t>(c->k / static_cast<size_t>(g_.nx));
      place(i, j, g_.bottom[c->k], &c->bot);
      c->has_bot = true;
    }
    return c->bot;
  }

  // A triangle of vertices with their shades already in r.shade.
  void tri(const MeshVertex& a, const MeshVertex& b, const MeshVertex& c) {
    if ((a.oc | b.oc | c.oc) == 0) {
      raster_triangle(p_.target, a.r, b.r, c.r);
    } else if ((a.oc & b.oc & c.oc) == 0) {
      clip_draw_triangle(p_.target, v_.proj, clip_vertex(a, a.r.shade), clip_vertex(b, b.r.shade),
                         clip_vertex(c, c.r.shade));
    }
  }

  // A copy of a vertex with another shade (side and bottom faces).
  static MeshVertex shaded(const MeshVertex& m, int32_t s) {
    MeshVertex r = m;
    r.r.shade = s;
    return r;
  }

  void cell(Corner* q[4], const CellCase& cc) {
    for (int t = 0; t < cc.ntop; ++t) tri(q[cc.top[t][0]]->top, q[cc.top[t][1]]->top, q[cc.top[t][2]]->top);
    if (cc.has_wall) {
      // Left (P) and right (Q) seen from the hole: P top, P bottom, Q bottom, Q top.
      Corner* P = q[cc.wall[0]];
      Corner* Q = q[cc.wall[1]];
      const int32_t sp = p_.shades->wall[P->k], sq = p_.shades->wall[Q->k];
      const MeshVertex pt = shaded(P->top, sp), pb = shaded(bottom(P), sp);
      const MeshVertex qt = shaded(Q->top, sq), qb = shaded(bottom(Q), sq);
      tri(pt, pb, qb);
      tri(pt, qb, qt);
    }
    if (p_.bottoms) {
      const int32_t s = p_.bottom_shade;
      for (int t = 0; t < cc.ntop; ++t) {  // turned over: seen from below
        const MeshVertex a = shaded(bottom(q[cc.top[t][0]]), s);
        const MeshVertex b = shaded(bottom(q[cc.top[t][1]]), s);
        const MeshVertex c = shaded(bottom(q[cc.top[t][2]]), s);
        tri(a, c, b);
      }
    }
  }

  const MeshPass<H>& p_;
  const DexelGrid<H>& g_;
  const View& v_;
  const uint8_t* top_shade_;
  // Orthographic guard band in q4: planes x + e0 >= 0, -x + e1 >= 0, ...
  // (clip_set_planes).
  const int32_t gx0_ = static_cast<int32_t>(-v_.proj.plane[0].e), gx1_ = static_cast<int32_t>(v_.proj.plane[1].e);
  const int32_t gy0_ = static_cast<int32_t>(-v_.proj.plane[2].e), gy1_ = static_cast<int32_t>(v_.proj.plane[3].e);
  Corner rows_[2][kBlockCells + 1];
  int32_t n_ = 0, i0_ = 0;
};

}  // namespace

template <class H>
void mesh_draw_cells(const MeshPass<H>& p, GridRect c, bool i_desc, bool j_desc) {
  if (c.empty() || c.i1 - c.i0 > kBlockCells || c.j1 - c.j0 > kBlockCells) return;
  if (p.view->proj.kind == Projection::kOrthographic) {
    CellDrawer<H, true> d(p);
    d.draw(c, i_desc, j_desc);
  } else {
    CellDrawer<H, false> d(p);
    d.draw(c, i_desc, j_desc);
  }
}

template void mesh_draw_cells<uint8_t>(const MeshPass<uint8_t>&, GridRect, bool, bool);
template void mesh_draw_cells<uint16_t>(const MeshPass<uint16_t>&, GridRect, bool, bool);
template void mesh_draw_cells<uint32_t>(const MeshPass<uint32_t>&, GridRect, bool, bool);

}  // namespace dexmill
