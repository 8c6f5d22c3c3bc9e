// Cell classification and triangle streaming (see mesh.h).
#include "display/surface/mesh.h"

#include "core/math/fixed.h"
#include "display/raster/clip.h"

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

// A point of a textured side face's vertical edge (SurfaceTexture): its
// height and the colours (unlit) of the strips below and above it, equal
// but at a break.
struct EdgeColour {
  uint32_t h, lo, hi;
};
constexpr int kEdgePointsMax = 2 + kWallSplitsMax + kTextureBreaksMax;

struct Corner {
  MeshVertex top, bot;
  size_t k;       // dexel index
  bool material;
  bool has_bot;   // bot computed
  uint8_t nedge;  // edge[0, nedge) worked out (0: not yet), kept while the
                  // vertex row is: the faces on both sides of an edge share it
  EdgeColour edge[kEdgePointsMax];
};

// kOrtho: the orthographic fast path (clip space is the screen; outcodes are
// four comparisons); otherwise the general projection.
template <class H, bool kOrtho>
class CellDrawer {
 public:
  explicit CellDrawer(const MeshPass<H>& p) : p_(p), g_(*p.grid), v_(*p.view), top_shade_(p.shades->top) {}

  void draw(GridRect c, bool i_desc, bool j_desc, bool cull, uint32_t zlo, uint32_t zhi) {
    n_ = c.i1 - c.i0 + 1;
    i0_ = c.i0;
    const int32_t rows = c.j1 - c.j0;
    // The q4 range of pixel centres inside the clip rectangle.
    const ScreenRect& clip = p_.target->clip;
    const int32_t xlo = clip.x0 * kSubpixelOne + kSubpixelOne / 2, xhi = (clip.x1 - 1) * kSubpixelOne + kSubpixelOne / 2;
    const int32_t ylo = clip.y0 * kSubpixelOne + kSubpixelOne / 2, yhi = (clip.y1 - 1) * kSubpixelOne + kSubpixelOne / 2;
    // Skipping a cell by its top corners is only right when it draws nothing
    // else; the row windows below use heights that include bottoms.
    const bool cull_tops = cull && !p_.bottoms;
    // Cells [ca, cb) of each cell row (relative to c.i0) that can reach the
    // clip rectangle, and the dexels [va, vb] of each vertex row they use.
    int32_t ca[kBlockCells], cb[kBlockCells], va[kBlockCells + 1], vb[kBlockCells + 1];
    for (int32_t r = 0; r < rows; ++r) {
      ca[r] = 0;
      cb[r] = n_ - 1;
      if (kOrtho && cull) {
        int64_t lo = c.i0, hi = c.i1;
        axis_range(0, c.j0 + r, zlo, zhi, xlo, xhi, &lo, &hi);
        axis_range(1, c.j0 + r, zlo, zhi, ylo, yhi, &lo, &hi);
        ca[r] = static_cast<int32_t>(lo - c.i0);
        cb[r] = static_cast<int32_t>(max_of(hi, lo) - c.i0);
      }
    }
    for (int32_t v = 0; v <= rows; ++v) {
      va[v] = n_;
      vb[v] = -1;
      for (int32_t r = v - 1; r <= v; ++r) {
        if (r < 0 || r >= rows || ca[r] >= cb[r]) continue;
        va[v] = min_of(va[v], ca[r]);
        vb[v] = max_of(vb[v], cb[r]);
      }
    }
    Corner* lo = rows_[0];
    Corner* hi = rows_[1];
    // Vertex rows r and r + 1 of the current cell row, reused as the walk
    // moves on.
    int32_t r = j_desc ? rows - 1 : 0;
    build_row(c.j0 + r, lo, va[r], vb[r]);
    build_row(c.j0 + r + 1, hi, va[r + 1], vb[r + 1]);
    for (int32_t n = 0; n < rows; ++n) {
      if (n > 0) {
        if (j_desc) {  // the old row r is row r + 1 now
          --r;
          Corner* t = hi; hi = lo; lo = t;
          build_row(c.j0 + r, lo, va[r], vb[r]);
        } else {
          ++r;
          Corner* t = lo; lo = hi; hi = t;
          build_row(c.j0 + r + 1, hi, va[r + 1], vb[r + 1]);
        }
      }
      for (int32_t m = 0; m < cb[r] - ca[r]; ++m) {
        const int32_t a = i_desc ? cb[r] - 1 - m : ca[r] + m;
        Corner* q[4] = {&lo[a], &lo[a + 1], &hi[a + 1], &hi[a]};
        const int mask = q[0]->material | q[1]->material << 1 | q[2]->material << 2 | q[3]->material << 3;
        if (mask == 15 && cull_tops && (q[0]->top.oc | q[1]->top.oc | q[2]->top.oc | q[3]->top.oc) == 0) {
          // A cell of top triangles only, every pixel centre it holds
          // outside the clip rectangle: skip it (the rasterizer would).
          const RasterVertex& v0 = q[0]->top.r;
          const RasterVertex& v1 = q[1]->top.r;
          const RasterVertex& v2 = q[2]->top.r;
          const RasterVertex& v3 = q[3]->top.r;
          const int32_t x0 = min_of(min_of(v0.x_q4, v1.x_q4), min_of(v2.x_q4, v3.x_q4));
          const int32_t x1 = max_of(max_of(v0.x_q4, v1.x_q4), max_of(v2.x_q4, v3.x_q4));
          const int32_t y0 = min_of(min_of(v0.y_q4, v1.y_q4), min_of(v2.y_q4, v3.y_q4));
          const int32_t y1 = max_of(max_of(v0.y_q4, v1.y_q4), max_of(v2.y_q4, v3.y_q4));
          if (x1 < xlo || x0 > xhi || y1 < ylo || y0 > yhi) continue;
        }
        if (mask) cell(q, kCellCases[mask]);
      }
    }
  }

 private:
  // Narrows [*lo, *hi) to the cells i of cell row j whose box (corners i,
  // i+1, j, j+1, heights zlo..zhi) reaches the pixel centres [p0, p1] along
  // screen axis k. Exact: the box's screen extent along k is
  // floor((a i + kmin) / 2^32) .. floor((a i + kmax) / 2^32) with a, kmin,
  // kmax from the grid map, and the rasterizer covers nothing outside it.
  void axis_range(int k, int32_t j, int64_t zlo, int64_t zhi, int64_t p0, int64_t p1, int64_t* lo, int64_t* hi) const {
    const AffineQ32& m = v_.grid;
    const int64_t a = m.m[k][0], b = m.m[k][1], hz0 = m.m[k][2] * zlo, hz1 = m.m[k][2] * zhi;
    const int64_t base = b * j + m.c[k];
    const int64_t kmin = base + min_of<int64_t>(0, b) + min_of(hz0, hz1) + min_of<int64_t>(0, a);
    const int64_t kmax = base + max_of<int64_t>(0, b) + max_of(hz0, hz1) + max_of<int64_t>(0, a);
    const int64_t t0 = p0 * (static_cast<int64_t>(1) << 32), t1 = (p1 + 1) * (static_cast<int64_t>(1) << 32);
    // Keep i when a i + kmax >= t0 and a i + kmin < t1.
    if (a > 0) {
      *lo = max_of(*lo, div_ceil(t0 - kmax, a));
      *hi = min_of(*hi, div_ceil(t1 - kmin, a));
    } else if (a < 0) {
      *lo = max_of(*lo, div_floor(kmin - t1, -a) + 1);
      *hi = min_of(*hi, div_floor(kmax - t0, -a) + 1);
    } else if (kmax < t0 || kmin >= t1) {
      *hi = *lo;
    }
  }

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
    c.rgb = m.r.rgb;
    if (v_.proj.kind == Projection::kOrthographic) {
      c.w = 1;
      c.depth = m.cw;
    } else {
      c.w = m.cw;
      c.depth = 0;
    }
    return c;
  }

  // Vertex row j for the dexels [from, to] of the block (relative to i0_).
  void build_row(int32_t j, Corner* row, int32_t from, int32_t to) {
    if (from > to) return;
    const AffineQ32& a = v_.grid;
    int64_t acc[3];
    for (int k = 0; k < 3; ++k) acc[k] = a.m[k][0] * (i0_ + from) + a.m[k][1] * j + a.c[k];
    size_t k = g_.index(i0_ + from, j);
    for (int32_t n = from; n <= to; ++n, ++k) {
      Corner& c = row[n];
      c.k = k;
      const H t = g_.top[k], b = g_.bottom[k];
      c.material = (t | b) != 0;
      c.has_bot = false;
      c.nedge = 0;
      if (c.material) {
        finish(acc, t, &c.top);
        c.top.r.shade = top_shade_[k];
        if (tex_) c.top.r.rgb = lit_rgb(*p_.lit, tex_->top_rgb[k], top_shade_[k]);
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

  // With a colour mode, the ramp of corner c's class.
  void use_class_of(const Corner* c) {
    if (colours_ && !tex_) p_.target->lut = colours_->luts + static_cast<size_t>(colours_->cls[c->k]) * kShadeLevels;
  }

  // A top triangle's class: its lowest corner's (the first of equals), so a
  // slope takes the colour of the floor it drops to: a gouge's walls show
  // red, a ridge left standing keeps its green on top and white flanks.
  void use_class_of_top(const Corner* a, const Corner* b, const Corner* c) {
    if (!colours_ || tex_) return;
    const Corner* lo = g_.top[b->k] < g_.top[a->k] ? b : a;
    use_class_of(g_.top[c->k] < g_.top[lo->k] ? c : lo);
  }

  // Twice the screen area of a b c, positive when counterclockwise (front
  // facing), as the rasterizer decides it.
  static int64_t area2(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c) {
    return (static_cast<int64_t>(c.x_q4) - a.x_q4) * (static_cast<int64_t>(b.y_q4) - a.y_q4) -
           (static_cast<int64_t>(b.x_q4) - a.x_q4) * (static_cast<int64_t>(c.y_q4) - a.y_q4);
  }

  // A bottom vertex with shade s (and, textured, the colour of the column's
  // lowest slab).
  MeshVertex bottom_shaded(Corner* c, int32_t s) {
    MeshVertex m = shaded(bottom(c), s);
    if (tex_) {
      const int32_t i = static_cast<int32_t>(c->k % static_cast<size_t>(g_.nx));
      const int32_t j = static_cast<int32_t>(c->k / static_cast<size_t>(g_.nx));
      m.r.rgb = lit_rgb(*p_.lit, tex_->colour_at(tex_->ctx, i, j, static_cast<uint32_t>(g_.bottom[c->k]) + 1), s);
    }
    return m;
  }

  struct EdgePoint {
    MeshVertex v;
    uint32_t h;
    uint32_t lo, hi;  // lit
  };

  // The colours along corner c's vertical edge, bottom to top: lattice and
  // breaks strictly between its bottom and top (the texture evaluated once
  // per edge and vertex row).
  void edge_colours(Corner* c) {
    if (c->nedge) return;
    const int32_t i = static_cast<int32_t>(c->k % static_cast<size_t>(g_.nx));
    const int32_t j = static_cast<int32_t>(c->k / static_cast<size_t>(g_.nx));
    const uint32_t b = g_.bottom[c->k], t = g_.top[c->k];
    const SurfaceTexture& x = *tex_;
    int n = 0;
    auto add = [&](uint32_t h, uint32_t lo, uint32_t hi) { c->edge[n++] = EdgeColour{h, lo, hi}; };
    const uint32_t first = x.colour_at(x.ctx, i, j, b + 1);
    add(b, first, first);
    // The lattice, coarsened by powers of two until it fits the bound: at
    // most kWallSplitsMax strips, and none much under kWallStripPx pixels
    // on the screen (the edge's length decides, the same for both faces).
    uint32_t limit = kWallSplitsMax;
    const MeshVertex& bv = bottom(c);
    if ((c->top.oc | bv.oc) == 0) {
      const int32_t dx = c->top.r.x_q4 - bv.r.x_q4, dy = c->top.r.y_q4 - bv.r.y_q4;
      const int32_t len_px = max_of(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy) >> kSubpixelBits;
      limit = static_cast<uint32_t>(clamp<int32_t>(len_px / kWallStripPx, 1, kWallSplitsMax));
    }
    uint32_t step = x.split_lsb;
    if (step) while ((t - b) / step > limit) step *= 2;
    uint32_t h = step ? (b / step + 1) * step : t;
    int32_t k = 0;
    while (k < x.nbreaks && x.breaks_lsb[k] <= b) ++k;
    for (;;) {
      const uint32_t brk = k < x.nbreaks ? x.breaks_lsb[k] : t;
      const uint32_t next = min_of(min_of(h, brk), t);
      if (next >= t) break;
      if (next == brk) {
        add(brk, x.colour_at(x.ctx, i, j, brk), x.colour_at(x.ctx, i, j, brk + 1));
        ++k;
        if (h == brk) h += step;
      } else {
        const uint32_t col = x.colour_at(x.ctx, i, j, h);
        add(h, col, col);
        h += step;
      }
    }
    add(t, x.top_rgb[c->k], x.top_rgb[c->k]);
    c->nedge = static_cast<uint8_t>(n);
  }

  // Corner c's edge points placed and lit with `shade`; returns how many.
  int edge_points(Corner* c, int32_t shade, EdgePoint* out) {
    edge_colours(c);
    const int32_t i = static_cast<int32_t>(c->k % static_cast<size_t>(g_.nx));
    const int32_t j = static_cast<int32_t>(c->k / static_cast<size_t>(g_.nx));
    const LitRamp& lit = *p_.lit;
    for (int n = 0; n < c->nedge; ++n) {
      const EdgeColour& e = c->edge[n];
      EdgePoint& o = out[n];
      o.h = e.h;
      place(i, j, e.h, &o.v);
      o.v.r.shade = shade;
      o.lo = lit_rgb(lit, e.lo, shade);
      o.hi = e.lo == e.hi ? o.lo : lit_rgb(lit, e.hi, shade);
    }
    return c->nedge;
  }

  // A side face between corners P (left, seen from the hole) and Q, split
  // at both edges' points and zipped up from the bottoms: each triangle
  // takes one edge's next point, the lower one first.
  void textured_wall(Corner* P, Corner* Q) {
    const int32_t sp = p_.shades->wall[P->k], sq = p_.shades->wall[Q->k];
    // Back-facing (both halves, all on screen): nothing to evaluate.
    const MeshVertex& pt = P->top;
    const MeshVertex& qt = Q->top;
    const MeshVertex& pb = bottom(P);
    const MeshVertex& qb = bottom(Q);
    if (p_.target->cull_back && (pt.oc | qt.oc | pb.oc | qb.oc) == 0 && area2(pt.r, pb.r, qb.r) <= 0 &&
        area2(pt.r, qb.r, qt.r) <= 0)
      return;
    EdgePoint ep[kEdgePointsMax], eq[kEdgePointsMax];
    const int np = edge_points(P, sp, ep), nq = edge_points(Q, sq, eq);
    // A break point takes its colour above when the triangle reaches above
    // it, else its colour below.
    auto put = [this](const EdgePoint& x, const EdgePoint& y, const EdgePoint& z) {
      const uint32_t top = max_of(x.h, max_of(y.h, z.h));
      MeshVertex v[3] = {x.v, y.v, z.v};
      const EdgePoint* e[3] = {&x, &y, &z};
      for (int k = 0; k < 3; ++k) v[k].r.rgb = e[k]->h < top ? e[k]->hi : e[k]->lo;
      tri(v[0], v[1], v[2]);
    };
    int a = 0, b = 0;
    while (a < np - 1 || b < nq - 1) {
      if (b == nq - 1 || (a < np - 1 && ep[a + 1].h <= eq[b + 1].h)) {
        put(ep[a + 1], ep[a], eq[b]);
        ++a;
      } else {
        put(ep[a], eq[b], eq[b + 1]);
        ++b;
      }
    }
  }

  void cell(Corner* q[4], const CellCase& cc) {
    for (int t = 0; t < cc.ntop; ++t) {
      use_class_of_top(q[cc.top[t][0]], q[cc.top[t][1]], q[cc.top[t][2]]);
      tri(q[cc.top[t][0]]->top, q[cc.top[t][1]]->top, q[cc.top[t][2]]->top);
    }
    if (cc.has_wall && tex_) {
      textured_wall(q[cc.wall[0]], q[cc.wall[1]]);
    } else if (cc.has_wall) {
      // Left (P) and right (Q) seen from the hole: P top, P bottom, Q bottom, Q top.
      Corner* P = q[cc.wall[0]];
      Corner* Q = q[cc.wall[1]];
      use_class_of(P);
      const int32_t sp = p_.shades->wall[P->k], sq = p_.shades->wall[Q->k];
      const MeshVertex pt = shaded(P->top, sp), pb = shaded(bottom(P), sp);
      const MeshVertex qt = shaded(Q->top, sq), qb = shaded(bottom(Q), sq);
      tri(pt, pb, qb);
      tri(pt, qb, qt);
    }
    if (p_.bottoms) {
      const int32_t s = p_.bottom_shade;
      for (int t = 0; t < cc.ntop; ++t) {  // turned over: seen from below
        use_class_of_top(q[cc.top[t][0]], q[cc.top[t][1]], q[cc.top[t][2]]);
        const MeshVertex a = bottom_shaded(q[cc.top[t][0]], s);
        const MeshVertex b = bottom_shaded(q[cc.top[t][1]], s);
        const MeshVertex c = bottom_shaded(q[cc.top[t][2]], s);
        tri(a, c, b);
      }
    }
  }

  const MeshPass<H>& p_;
  const DexelGrid<H>& g_;
  const View& v_;
  const uint8_t* top_shade_;
  const SurfaceColours* colours_ = p_.colours;
  const SurfaceTexture* tex_ = colours_ && p_.lit ? colours_->texture : nullptr;
  // Orthographic guard band in q4: planes x + e0 >= 0, -x + e1 >= 0, ...
  // (clip_set_planes).
  const int32_t gx0_ = static_cast<int32_t>(-v_.proj.plane[0].e), gx1_ = static_cast<int32_t>(v_.proj.plane[1].e);
  const int32_t gy0_ = static_cast<int32_t>(-v_.proj.plane[2].e), gy1_ = static_cast<int32_t>(v_.proj.plane[3].e);
  Corner rows_[2][kBlockCells + 1];
  int32_t n_ = 0, i0_ = 0;
};

}  // namespace

template <class H>
void mesh_draw_cells(const MeshPass<H>& p, GridRect c, bool i_desc, bool j_desc, bool cull, uint32_t zlo, uint32_t zhi) {
  if (c.empty() || c.i1 - c.i0 > kBlockCells || c.j1 - c.j0 > kBlockCells) return;
  if (p.view->proj.kind == Projection::kOrthographic) {
    CellDrawer<H, true> d(p);
    d.draw(c, i_desc, j_desc, cull, zlo, zhi);
  } else {
    CellDrawer<H, false> d(p);
    d.draw(c, i_desc, j_desc, cull, zlo, zhi);
  }
}

template void mesh_draw_cells<uint8_t>(const MeshPass<uint8_t>&, GridRect, bool, bool, bool, uint32_t, uint32_t);
template void mesh_draw_cells<uint16_t>(const MeshPass<uint16_t>&, GridRect, bool, bool, bool, uint32_t, uint32_t);
template void mesh_draw_cells<uint32_t>(const MeshPass<uint32_t>&, GridRect, bool, bool, bool, uint32_t, uint32_t);

}  // namespace dexmill
