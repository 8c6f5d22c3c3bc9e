// The toolpath over a frame; see backplot.h.
#include "display/overlay/backplot.h"

#include "display/raster/clip.h"

namespace dexmill {

namespace {

int64_t plane_distance(const ClipPlane& q, const ClipVertex& c) { return q.a * c.x + q.b * c.y + q.c * c.w + q.e; }

ClipVertex midpoint(const ClipVertex& a, const ClipVertex& b) {
  ClipVertex m;
  m.x = (a.x + b.x) >> 1;
  m.y = (a.y + b.y) >> 1;
  m.w = (a.w + b.w) >> 1;
  m.depth = static_cast<int32_t>((static_cast<int64_t>(a.depth) + b.depth) >> 1);
  m.shade = 0;
  return m;
}

// Moves `out` (outside plane q) towards `in` (inside it) until it is
// inside, by halving: no products that could overflow, and the same new
// end whichever way round the segment came. Clip coordinates are below
// 2^41, so 48 halvings bring the two ends together.
ClipVertex cut_to_plane(const ClipPlane& q, ClipVertex in, ClipVertex out) {
  for (int k = 0; k < 48; ++k) {
    const ClipVertex m = midpoint(in, out);
    if (plane_distance(q, m) >= 0) in = m;
    else out = m;
  }
  return in;
}

// The part of segment ab inside every plane of the view, projected; false
// when none of it is.
bool project_segment(const View& v, const PathSegment& s, RasterVertex* ra, RasterVertex* rb) {
  ClipVertex a = view_point(v, s.a), b = view_point(v, s.b);
  for (int k = 0; k < v.proj.nplanes; ++k) {
    const ClipPlane& q = v.proj.plane[k];
    const bool a_in = plane_distance(q, a) >= 0, b_in = plane_distance(q, b) >= 0;
    if (!a_in && !b_in) return false;
    if (!a_in) a = cut_to_plane(q, b, a);
    if (!b_in) b = cut_to_plane(q, a, b);
  }
  *ra = clip_project(v.proj, a);
  *rb = clip_project(v.proj, b);
  return true;
}

int32_t floor_div16(int64_t q4) { return static_cast<int32_t>(q4 >= 0 ? q4 >> 4 : -((-q4 + 15) >> 4)); }

// The first pixel whose centre (16 p + 8) is at or after q4 coordinate c.
int32_t first_centre(int64_t c) { return floor_div16(c - 8 + 15); }

struct Plot {
  const FrameView* fb;
  int64_t bias;
  const DepthView* z;
  ScreenRect clip;
  uint32_t value;
  bool dashed;
  bool depth_test;
  int32_t width_px;  // pixels across the line (backplot.h)
  ScreenRect touched{0, 0, 0, 0};

  // One pixel of the line at depth d; `step` is its index along the longer
  // axis (the dash pattern, as long on the picture at any width).
  void pixel(int32_t x, int32_t y, int64_t d, int32_t step) {
    if (x < clip.x0 || x >= clip.x1 || y < clip.y0 || y >= clip.y1) return;
    if (dashed && ((step / (kBackplotDashPx * width_px)) & 1)) return;
    touched = rect_union(touched, ScreenRect{x, y, x + 1, y + 1});
    uint8_t* crow = static_cast<uint8_t*>(fb->pixels) + static_cast<int64_t>(y) * fb->stride_bytes;
    if (depth_test && hidden(x, y, d)) return;
    if (fb->format == PixelFormat::kRgb565) reinterpret_cast<uint16_t*>(crow)[x] = static_cast<uint16_t>(value);
    else reinterpret_cast<uint32_t*>(crow)[x] = value;
  }

  bool hidden(int32_t x, int32_t y, int64_t d) const {
    const int64_t biased = d - bias < 0 ? 0 : d - bias;
    const uint8_t* zrow = z->z + static_cast<int64_t>(y) * z->stride_bytes;
    // Stored depths as the rasterizer keeps them: 24 integer and 7 fraction
    // bits, of which a 16-bit buffer holds the top 16.
    const uint32_t stored = static_cast<uint32_t>(biased) << 7;
    if (z->format == ZFormat::kZ16) return (stored >> 15) > reinterpret_cast<const uint16_t*>(zrow)[x];
    return stored > reinterpret_cast<const uint32_t*>(zrow)[x];
  }

  // The pixels across the line at minor-axis q4 coordinate c, from *first:
  // width_px of them, those whose centres lie within half the width of c
  // (one: the pixel c falls in).
  int32_t across(int64_t c) const { return width_px == 1 ? floor_div16(c) : first_centre(c - 8 * width_px); }

  // A projected segment: width_px pixels per pixel centre along its longer
  // axis.
  void line(RasterVertex a, RasterVertex b) {
    const int64_t adx = b.x_q4 > a.x_q4 ? b.x_q4 - a.x_q4 : a.x_q4 - b.x_q4;
    const int64_t ady = b.y_q4 > a.y_q4 ? b.y_q4 - a.y_q4 : a.y_q4 - b.y_q4;
    const bool x_major = adx >= ady;
    // Walk from the smaller end of the major axis: the same pixels whichever
    // way the tool went.
    if ((x_major && b.x_q4 < a.x_q4) || (!x_major && b.y_q4 < a.y_q4)) {
      const RasterVertex t = a;
      a = b;
      b = t;
    }
    const int64_t a0 = x_major ? a.x_q4 : a.y_q4, a1 = x_major ? b.x_q4 : b.y_q4;
    const int64_t m0 = x_major ? a.y_q4 : a.x_q4, m1 = x_major ? b.y_q4 : b.x_q4;
    const int64_t span = a1 - a0, dm = m1 - m0, dd = static_cast<int64_t>(b.depth) - a.depth;
    int32_t p0 = first_centre(a0), p1 = floor_div16(a1 - 8);
    if (p0 > p1) {  // shorter than a pixel: the pixel of its middle
      const int32_t mx = across((static_cast<int64_t>(a.x_q4) + b.x_q4) >> 1);
      const int32_t my = across((static_cast<int64_t>(a.y_q4) + b.y_q4) >> 1);
      for (int32_t i = 0; i < width_px; ++i)
        for (int32_t j = 0; j < width_px; ++j)
          pixel(mx + i, my + j, (static_cast<int64_t>(a.depth) + b.depth) >> 1, x_major ? mx : my);
      return;
    }
    // Only the steps inside the clip rectangle: the pixels do not change.
    const int32_t lo = x_major ? clip.x0 : clip.y0, hi = (x_major ? clip.x1 : clip.y1) - 1;
    if (p0 < lo) p0 = lo;
    if (p1 > hi) p1 = hi;
    for (int32_t p = p0; p <= p1; ++p) {
      const int64_t t = static_cast<int64_t>(p) * 16 + 8 - a0;  // q4 along the major axis, 0..span
      const int32_t m = across(m0 + (span ? dm * t / span : 0));
      const int64_t d = a.depth + (span ? dd * t / span : 0);
      for (int32_t i = 0; i < width_px; ++i) {
        if (x_major) pixel(p, m + i, d, p);
        else pixel(m + i, p, d, p);
      }
    }
  }
};

// Every pixel a projected segment w pixels wide may light: the pixels its
// ends fall in, and w more round them (the pixels across the line reach
// one before the pixel of the line's centre and w - 1 after it; one more
// each way keeps the exact box's rounding out of the question).
ScreenRect segment_box(const RasterVertex& a, const RasterVertex& b, int32_t w) {
  const int32_t x0 = floor_div16(a.x_q4 < b.x_q4 ? a.x_q4 : b.x_q4), x1 = floor_div16(a.x_q4 < b.x_q4 ? b.x_q4 : a.x_q4);
  const int32_t y0 = floor_div16(a.y_q4 < b.y_q4 ? a.y_q4 : b.y_q4), y1 = floor_div16(a.y_q4 < b.y_q4 ? b.y_q4 : a.y_q4);
  return ScreenRect{x0 - w, y0 - w, x1 + 1 + w, y1 + 1 + w};
}

PointNm along(const PointNm& p, const int32_t dir_q30[3], int64_t len_nm) {
  return PointNm{p.x_nm + ((dir_q30[0] * len_nm) >> 30), p.y_nm + ((dir_q30[1] * len_nm) >> 30),
                 p.z_nm + ((dir_q30[2] * len_nm) >> 30)};
}

}  // namespace

int32_t backplot_depth_bias(const View& v) {
  // A pixel's length at the scene's centre: 1 mm to the right on screen.
  const int64_t mm = 1000000;
  const RasterVertex o = clip_project(v.proj, view_point(v, v.origin));
  const RasterVertex r = clip_project(v.proj, view_point(v, along(v.origin, v.right_q30, mm)));
  const int64_t q4_per_mm = r.x_q4 > o.x_q4 ? r.x_q4 - o.x_q4 : o.x_q4 - r.x_q4;
  const int64_t px_nm = q4_per_mm > 0 ? 16 * mm / q4_per_mm : mm;
  // Two of them along the view axis, in depth units.
  const RasterVertex e = clip_project(v.proj, view_point(v, along(v.origin, v.eye_q30, 2 * px_nm)));
  const int64_t units = e.depth > o.depth ? e.depth - o.depth : o.depth - e.depth;
  return static_cast<int32_t>(units > kBackplotMinDepthBias ? (units < kDepthMax / 16 ? units : kDepthMax / 16)
                                                            : kBackplotMinDepthBias);
}

ScreenRect backplot_draw(const FrameView& fb, const DepthView& z, const View& v, const PathSegment* segs, uint32_t n,
                         uint32_t done, ScreenRect clip, const BackplotColours& colours, int32_t width_px) {
  Plot plot;
  plot.width_px = width_px < 1 ? 1 : width_px;
  plot.fb = &fb;
  plot.z = &z;
  plot.bias = backplot_depth_bias(v);
  plot.clip = rect_intersect(clip, ScreenRect{0, 0, fb.width, fb.height});
  if (plot.clip.empty() || !z.z) return ScreenRect{0, 0, 0, 0};
  const uint32_t values[4] = {pixel_pack(fb.format, colours.rapid_todo), pixel_pack(fb.format, colours.rapid_done),
                              pixel_pack(fb.format, colours.feed_todo), pixel_pack(fb.format, colours.feed_done)};
  for (uint32_t k = 0; k < n; ++k) {
    RasterVertex a, b;
    if (!project_segment(v, segs[k], &a, &b)) continue;
    // A cheap test first: the segment's screen box, widened by the pixels
    // across the line (backplot_bounds), against the rectangle.
    if (rect_intersect(segment_box(a, b, plot.width_px), plot.clip).empty()) continue;
    const bool feed = segs[k].kind == PathKind::kFeed;
    plot.value = values[(feed ? 2 : 0) + (k < done ? 1 : 0)];
    plot.dashed = !feed;
    plot.depth_test = k < done;
    plot.line(a, b);
  }
  return plot.touched;
}

ScreenRect backplot_bounds(const FrameView& fb, const View& v, const PathSegment* segs, uint32_t from, uint32_t to,
                           int32_t width_px) {
  const int32_t w = width_px < 1 ? 1 : width_px;
  ScreenRect box{0, 0, 0, 0};
  for (uint32_t k = from; k < to; ++k) {
    RasterVertex a, b;
    if (!project_segment(v, segs[k], &a, &b)) continue;
    box = rect_union(box, segment_box(a, b, w));
  }
  return rect_intersect(box, ScreenRect{0, 0, fb.width, fb.height});
}

}  // namespace dexmill
