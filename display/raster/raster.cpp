// Span rasterizer: coverage set-up, the depth-tested Gouraud span filler.
#include "display/raster/raster.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

// Pixel centre of pixel p in q4.
inline int64_t centre_q4(int32_t p) { return static_cast<int64_t>(p) * kSubpixelOne + kSubpixelOne / 2; }

// Range of pixels whose centre 16p + 8 lies in [lo, hi] (q4): first, last.
inline int32_t first_centre(int32_t lo) { return (lo - kSubpixelOne / 2 + kSubpixelOne - 1) >> kSubpixelBits; }
inline int32_t last_centre(int32_t hi) { return (hi - kSubpixelOne / 2) >> kSubpixelBits; }

// Fraction bits of the interpolated depth and shade.
constexpr int kDepthFrac = 7;   // depth < 2^24, so depth << 7 < 2^31
constexpr int kShadeFrac = 16;  // shade < 2^8

inline int32_t min3(int32_t a, int32_t b, int32_t c) { return min_of(a, min_of(b, c)); }
inline int32_t max3(int32_t a, int32_t b, int32_t c) { return max_of(a, max_of(b, c)); }

// One triangle's edge functions over the pixels of its clipped bounding
// box. E_k(p) for the edge from v[k+1] to v[k+2] is
// (p.x - a.x)(b.y - a.y) - (p.y - a.y)(b.x - a.x): area2 at v[k], 0 on the
// edge, positive inside. The stored values carry the top-left bias (-1 on
// edges that are neither top nor left), so covered means all three >= 0.
struct Tri {
  const RasterVertex* v[3];    // counterclockwise on screen (area2 > 0)
  int64_t area2;               // twice the area, q8
  int32_t bx0, by0, bx1, by1;  // pixel bounding box, inclusive, clipped
  int64_t e[3];                // biased edge values at the centre of (bx0, by0)
  int64_t dx[3], dy[3];        // change per pixel step in x and in y
  int32_t bias[3];             // 0 or 1
};

// One edge from p to q: its biased value at (px, py) and its steps.
inline void edge(Tri* t, int k, const RasterVertex& p, const RasterVertex& q, int64_t px, int64_t py) {
  const int64_t ex = static_cast<int64_t>(q.x_q4) - p.x_q4, ey = static_cast<int64_t>(q.y_q4) - p.y_q4;
  // Top-left rule for counterclockwise-on-screen triangles (y down): left
  // edges run downwards, top edges run leftwards; the others lose centres
  // exactly on them.
  t->bias[k] = (ey < 0) | ((ey == 0) & (ex >= 0));
  t->e[k] = (px - p.x_q4) * ey - (py - p.y_q4) * ex - t->bias[k];
  t->dx[k] = ey * kSubpixelOne;
  t->dy[k] = -ex * kSubpixelOne;
}

inline void edges(Tri* t) {
  const int64_t px = centre_q4(t->bx0), py = centre_q4(t->by0);
  edge(t, 0, *t->v[1], *t->v[2], px, py);
  edge(t, 1, *t->v[2], *t->v[0], px, py);
  edge(t, 2, *t->v[0], *t->v[1], px, py);
}

// Calls span(y, x0, x1) for each row with covered pixels [x0, x1), top to
// bottom.
template <class Span>
void spans(const Tri& t, Span& span) {
  int64_t r0 = t.e[0], r1 = t.e[1], r2 = t.e[2];
  const int32_t width = t.bx1 - t.bx0 + 1;
  if (width <= 24) {
    // Narrow: walk the row from the box's left edge. A row crosses the
    // triangle at most once (it is convex).
    for (int32_t y = t.by0; y <= t.by1; ++y, r0 += t.dy[0], r1 += t.dy[1], r2 += t.dy[2]) {
      int64_t e0 = r0, e1 = r1, e2 = r2;
      int32_t x = t.bx0;
      while (x <= t.bx1 && (e0 | e1 | e2) < 0) {
        ++x;
        e0 += t.dx[0];
        e1 += t.dx[1];
        e2 += t.dx[2];
      }
      if (x > t.bx1) continue;
      const int32_t xs = x;
      while (x <= t.bx1 && (e0 | e1 | e2) >= 0) {
        ++x;
        e0 += t.dx[0];
        e1 += t.dx[1];
        e2 += t.dx[2];
      }
      span(y, xs, x);
    }
    return;
  }
  // Wide: solve each edge for the row's first and last covered pixel.
  for (int32_t y = t.by0; y <= t.by1; ++y, r0 += t.dy[0], r1 += t.dy[1], r2 += t.dy[2]) {
    int64_t lo = 0, hi = width - 1;
    const int64_t e[3] = {r0, r1, r2};
    for (int k = 0; k < 3; ++k) {
      const int64_t s = t.dx[k];
      if (s > 0) {  // e + s*n >= 0  <=>  n >= ceil(-e / s)
        const int64_t n = -e[k];
        const int64_t c = n >= 0 ? (n + s - 1) / s : -((-n) / s);
        lo = c > lo ? c : lo;
      } else if (s < 0) {  // e + s*n >= 0  <=>  n <= floor(e / -s)
        const int64_t d = -s, n = e[k];
        const int64_t f = n >= 0 ? n / d : -((-n + d - 1) / d);
        hi = f < hi ? f : hi;
      } else if (e[k] < 0) {
        hi = -1;
      }
    }
    if (lo <= hi) span(y, t.bx0 + static_cast<int32_t>(lo), t.bx0 + static_cast<int32_t>(hi) + 1);
  }
}

// An attribute plane: value(px, py) = base + floor((gx * X + gy * Y) / 16)
// with X, Y the q4 offsets of the pixel centre from vertex 0. Since X and Y
// move by 16 per pixel, stepping by gx and gy gives exactly these values
// wherever the stepping starts (so clipping changes no bit). Computed modulo
// 2^64 and 2^32: only the values at covered pixels (which fit) matter, and
// modular arithmetic gets those exactly even when a sliver's gradient is huge.
struct Plane {
  int64_t gx, gy;  // per pixel, with the attribute's fraction bits
  uint32_t row;    // value at pixel (bx0, y) of the current row

  void setup(const Tri& t, int32_t a0, int32_t a1, int32_t a2, int frac, int64_t bias) {
    const RasterVertex& v0 = *t.v[0];
    const int64_t d1 = static_cast<int64_t>(a1) - a0, d2 = static_cast<int64_t>(a2) - a0;
    const int64_t x1 = static_cast<int64_t>(t.v[1]->x_q4) - v0.x_q4, y1 = static_cast<int64_t>(t.v[1]->y_q4) - v0.y_q4;
    const int64_t x2 = static_cast<int64_t>(t.v[2]->x_q4) - v0.x_q4, y2 = static_cast<int64_t>(t.v[2]->y_q4) - v0.y_q4;
    // Solving a1 - a0 = gx x1 + gy y1, a2 - a0 = gx x2 + gy y2 (per q4
    // unit); per pixel is 16 times that. Truncated: under one unit of the
    // last fraction bit per pixel.
    const int64_t scale = static_cast<int64_t>(kSubpixelOne) << frac;
    gx = (d2 * y1 - d1 * y2) * scale / t.area2;
    gy = (x2 * d1 - x1 * d2) * scale / t.area2;
    const uint64_t X = static_cast<uint64_t>(centre_q4(t.bx0) - v0.x_q4);
    const uint64_t Y = static_cast<uint64_t>(centre_q4(t.by0) - v0.y_q4);
    const uint64_t s = static_cast<uint64_t>(gx) * X + static_cast<uint64_t>(gy) * Y;
    row = static_cast<uint32_t>(static_cast<uint64_t>(a0) * (static_cast<uint64_t>(1) << frac) + static_cast<uint64_t>(bias) +
                                static_cast<uint64_t>(static_cast<int64_t>(s) >> kSubpixelBits));
  }
};

// Writes one fragment (depth-tested); returns 1 when it passed. The pixel
// value is only worked out then.
template <class Pix, class Z, class Value>
inline uint32_t fragment(Pix* cp, Z* zp, uint32_t zv, const Value& value) {
  // 31-bit depth; a 16-bit buffer keeps its top 16 bits.
  const Z zs = static_cast<Z>(sizeof(Z) == 2 ? zv >> 15 : zv);
  if (zs < *zp) {
    *zp = zs;
    *cp = static_cast<Pix>(value());
    return 1;
  }
  return 0;
}

// A pixel value from interpolated channels (kShadeFrac fraction bits each),
// packed as pixel_pack does.
template <class Pix>
inline uint32_t pack_channels(uint32_t r, uint32_t g, uint32_t b) {
  r >>= kShadeFrac;
  g >>= kShadeFrac;
  b >>= kShadeFrac;
  if (sizeof(Pix) == 2) return (r >> 3) << 11 | (g >> 2) << 5 | b >> 3;
  return 0xFF000000u | r << 16 | g << 8 | b;
}

inline int32_t channel(uint32_t rgb, int k) { return static_cast<int32_t>((rgb >> (16 - 8 * k)) & 0xFF); }

// The attribute planes of a triangle: depth, and the shade or (kRgb) the
// three colour channels.
template <bool kRgb>
struct Planes {
  Plane z, s[kRgb ? 3 : 1];

  void setup(const Tri& tri) {
    z.setup(tri, tri.v[0]->depth, tri.v[1]->depth, tri.v[2]->depth, kDepthFrac, 0);
    // Half a step of bias: the rounding error stays inside [0, 256).
    for (int k = 0; k < (kRgb ? 3 : 1); ++k) {
      const int32_t a0 = kRgb ? channel(tri.v[0]->rgb, k) : tri.v[0]->shade;
      const int32_t a1 = kRgb ? channel(tri.v[1]->rgb, k) : tri.v[1]->shade;
      const int32_t a2 = kRgb ? channel(tri.v[2]->rgb, k) : tri.v[2]->shade;
      s[k].setup(tri, a0, a1, a2, kShadeFrac, 1 << (kShadeFrac - 1));
    }
  }
};

template <class Pix, class Z, bool kRgb>
struct SpanFill {
  RasterTarget* t;
  const Tri* tri;
  Planes<kRgb> p;
  int32_t y_row;  // the row the planes' row values hold
  bool ready;
  uint32_t written;

  void operator()(int32_t y, int32_t x0, int32_t x1) {
    constexpr int kN = kRgb ? 3 : 1;
    if (!ready) {
      // Set up on the first covered span only: many triangles of a fine grid
      // cover no pixel centre and never pay for the divisions.
      p.setup(*tri);
      ready = true;
    }
    for (; y_row < y; ++y_row) {
      p.z.row += static_cast<uint32_t>(p.z.gy);
      for (int k = 0; k < kN; ++k) p.s[k].row += static_cast<uint32_t>(p.s[k].gy);
    }
    Pix* cp = reinterpret_cast<Pix*>(t->color + static_cast<ptrdiff_t>(y) * t->color_stride);
    Z* zp = reinterpret_cast<Z*>(t->z + static_cast<ptrdiff_t>(y) * t->z_stride);
    const uint32_t dx = static_cast<uint32_t>(x0 - tri->bx0);
    const uint32_t zg = static_cast<uint32_t>(p.z.gx);
    uint32_t zv = p.z.row + zg * dx;
    uint32_t sg[kN], sv[kN];
    for (int k = 0; k < kN; ++k) {
      sg[k] = static_cast<uint32_t>(p.s[k].gx);
      sv[k] = p.s[k].row + sg[k] * dx;
    }
    const uint32_t* lut = t->lut;
    for (int32_t x = x0; x < x1; ++x, zv += zg) {
      written += fragment(cp + x, zp + x, zv, [&] {
        return kRgb ? pack_channels<Pix>(sv[0], sv[kN > 1 ? 1 : 0], sv[kN > 2 ? 2 : 0]) : lut[sv[0] >> kShadeFrac];
      });
      for (int k = 0; k < kN; ++k) sv[k] += sg[k];
    }
  }
};

struct SpanCount {
  RasterTarget* t;
  void operator()(int32_t y, int32_t x0, int32_t x1) {
    uint8_t* row = t->color + static_cast<ptrdiff_t>(y) * t->color_stride;
    for (int32_t x = x0; x < x1; ++x) ++row[x];
    t->stats.pixels_written += static_cast<uint64_t>(x1 - x0);
  }
};

template <class Pix, class Z, bool kRgb>
void fill(RasterTarget* t, const Tri& tri) {
  SpanFill<Pix, Z, kRgb> f{t, &tri, {}, tri.by0, false, 0};
  spans(tri, f);
  t->stats.pixels_written += f.written;
}

// A triangle whose unclipped bounding box holds at most 3 x 3 pixel centres
// (most triangles of a fine grid): the coverage test at each centre, and the
// attributes by barycentric weights, with no plane to set up. The weights
// are the unbiased edge values over area2, so the values are convex
// combinations of the vertices'; truncating towards vertex 0 keeps them
// there, and the shade gets the plane path's half-step bias. The path is
// chosen from the unclipped box, so a pixel gets the same value whatever
// the clip rectangle. Colour channels (kRgb) share two q16 weights, one
// division each per pixel instead of one per channel.
template <class Pix, class Z, bool kRgb>
void small(RasterTarget* t, const Tri& tri) {
  const RasterVertex& a = *tri.v[0];
  const RasterVertex& b = *tri.v[1];
  const RasterVertex& c = *tri.v[2];
  // The box is under 4 pixels each way: |w| <= area2 < 2^13, so the
  // products below stay under 2^46.
  constexpr int64_t kZOne = static_cast<int64_t>(1) << kDepthFrac, kSOne = static_cast<int64_t>(1) << kShadeFrac;
  const int64_t dz1 = (b.depth - a.depth) * kZOne, dz2 = (c.depth - a.depth) * kZOne;
  const int64_t ds1 = (b.shade - a.shade) * kSOne, ds2 = (c.shade - a.shade) * kSOne;
  const int64_t z0 = a.depth * kZOne, s0 = a.shade * kSOne + kSOne / 2;
  int32_t c0[3] = {}, c1[3] = {}, c2[3] = {};
  if (kRgb)
    for (int k = 0; k < 3; ++k) {
      c0[k] = channel(a.rgb, k);
      c1[k] = channel(b.rgb, k) - c0[k];
      c2[k] = channel(c.rgb, k) - c0[k];
    }
  uint32_t written = 0;
  int64_t r0 = tri.e[0], r1 = tri.e[1], r2 = tri.e[2];
  for (int32_t y = tri.by0; y <= tri.by1; ++y, r0 += tri.dy[0], r1 += tri.dy[1], r2 += tri.dy[2]) {
    Pix* cp = reinterpret_cast<Pix*>(t->color + static_cast<ptrdiff_t>(y) * t->color_stride);
    Z* zp = reinterpret_cast<Z*>(t->z + static_cast<ptrdiff_t>(y) * t->z_stride);
    int64_t e0 = r0, e1 = r1, e2 = r2;
    for (int32_t x = tri.bx0; x <= tri.bx1; ++x, e0 += tri.dx[0], e1 += tri.dx[1], e2 += tri.dx[2]) {
      if ((e0 | e1 | e2) < 0) continue;
      const int64_t w1 = e1 + tri.bias[1], w2 = e2 + tri.bias[2];
      const uint32_t zv = static_cast<uint32_t>(z0 + (w1 * dz1 + w2 * dz2) / tri.area2);
      written += fragment(cp + x, zp + x, zv, [&]() -> uint32_t {
        if (!kRgb) return t->lut[static_cast<uint32_t>(s0 + (w1 * ds1 + w2 * ds2) / tri.area2) >> kShadeFrac];
        // Weights in q16, each in [0, 2^16] and summing to at most 2^16;
        // w < area2 < 2^13 here, so 32-bit divisions (one instruction on a
        // Cortex-M4, where a 64-bit one is a library call).
        const int32_t a2 = static_cast<int32_t>(tri.area2);
        const int64_t l1 = static_cast<int32_t>(w1 << 16) / a2, l2 = static_cast<int32_t>(w2 << 16) / a2;
        uint32_t ch[3];
        for (int k = 0; k < 3; ++k)
          ch[k] = static_cast<uint32_t>((static_cast<int64_t>(c0[k]) << 16) + kSOne / 2 + l1 * c1[k] + l2 * c2[k]);
        return pack_channels<Pix>(ch[0], ch[1], ch[2]);
      });
    }
  }
  t->stats.pixels_written += written;
}

template <class Pix, class Z>
void draw(RasterTarget* t, const Tri& tri, bool is_small) {
  if (t->vertex_rgb) {
    if (is_small) small<Pix, Z, true>(t, tri);
    else fill<Pix, Z, true>(t, tri);
  } else {
    if (is_small) small<Pix, Z, false>(t, tri);
    else fill<Pix, Z, false>(t, tri);
  }
}

}  // namespace

int32_t z_bytes(ZFormat f) { return f == ZFormat::kZ16 ? 2 : 4; }

void raster_triangle(RasterTarget* t, const RasterVertex& a, const RasterVertex& b, const RasterVertex& c) {
  ++t->stats.triangles;
  // The pixel centres of the bounding box first: most triangles of a fine
  // grid hold none and stop here.
  Tri tri;
  tri.bx0 = first_centre(min3(a.x_q4, b.x_q4, c.x_q4));
  tri.bx1 = last_centre(max3(a.x_q4, b.x_q4, c.x_q4));
  if (tri.bx0 > tri.bx1) return;
  tri.by0 = first_centre(min3(a.y_q4, b.y_q4, c.y_q4));
  tri.by1 = last_centre(max3(a.y_q4, b.y_q4, c.y_q4));
  if (tri.by0 > tri.by1) return;
  const bool is_small = tri.bx1 - tri.bx0 <= 2 && tri.by1 - tri.by0 <= 2;
  tri.bx0 = max_of(tri.bx0, t->clip.x0);
  tri.bx1 = min_of(tri.bx1, t->clip.x1 - 1);
  tri.by0 = max_of(tri.by0, t->clip.y0);
  tri.by1 = min_of(tri.by1, t->clip.y1 - 1);
  if (tri.bx0 > tri.bx1 || tri.by0 > tri.by1) return;
  int64_t area2 = (static_cast<int64_t>(c.x_q4) - a.x_q4) * (static_cast<int64_t>(b.y_q4) - a.y_q4) -
                  (static_cast<int64_t>(b.x_q4) - a.x_q4) * (static_cast<int64_t>(c.y_q4) - a.y_q4);
  tri.v[0] = &a;
  if (area2 > 0) {
    tri.v[1] = &b;
    tri.v[2] = &c;
  } else {
    if (area2 == 0 || t->cull_back) return;
    tri.v[1] = &c;
    tri.v[2] = &b;
    area2 = -area2;
  }
  tri.area2 = area2;
  edges(&tri);
  if (t->count_coverage) {
    SpanCount sc{t};
    spans(tri, sc);
    return;
  }
  const bool c565 = t->format == PixelFormat::kRgb565, z16 = t->zformat == ZFormat::kZ16;
  if (c565) {
    if (z16) draw<uint16_t, uint16_t>(t, tri, is_small);
    else draw<uint16_t, uint32_t>(t, tri, is_small);
  } else {
    if (z16) draw<uint32_t, uint16_t>(t, tri, is_small);
    else draw<uint32_t, uint32_t>(t, tri, is_small);
  }
}

void raster_clear(RasterTarget* t, const ScreenRect& r, uint32_t color_value) {
  for (int32_t y = r.y0; y < r.y1; ++y) {
    uint8_t* zrow = t->z + static_cast<ptrdiff_t>(y) * t->z_stride;
    uint8_t* crow = t->color + static_cast<ptrdiff_t>(y) * t->color_stride;
    if (t->zformat == ZFormat::kZ16) {
      uint16_t* z = reinterpret_cast<uint16_t*>(zrow);
      for (int32_t x = r.x0; x < r.x1; ++x) z[x] = 0xFFFF;
    } else {
      uint32_t* z = reinterpret_cast<uint32_t*>(zrow);
      for (int32_t x = r.x0; x < r.x1; ++x) z[x] = 0xFFFFFFFFu;
    }
    if (t->format == PixelFormat::kRgb565) {
      uint16_t* c = reinterpret_cast<uint16_t*>(crow);
      for (int32_t x = r.x0; x < r.x1; ++x) c[x] = static_cast<uint16_t>(color_value);
    } else {
      uint32_t* c = reinterpret_cast<uint32_t*>(crow);
      for (int32_t x = r.x0; x < r.x1; ++x) c[x] = color_value;
    }
  }
}

}  // namespace dexmill
