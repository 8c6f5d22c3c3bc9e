// Point markers; see marker.h.
#include "display/overlay/marker.h"

#include "display/raster/clip.h"

namespace dexmill {

ScreenRect marker_draw(const FrameView& fb, const View& v, PointNm p, int32_t radius_px, uint32_t value) {
  const ClipVertex c = view_point(v, p);
  if (clip_outcode(v.proj, c.x, c.y, c.w) != 0) return ScreenRect{0, 0, 0, 0};
  const RasterVertex s = clip_project(v.proj, c);
  const int32_t cx = s.x_q4 >> kSubpixelBits, cy = s.y_q4 >> kSubpixelBits, r = radius_px;
  const ScreenRect box = rect_intersect(ScreenRect{cx - r - 1, cy - r - 1, cx + r + 2, cy + r + 2},
                                        ScreenRect{0, 0, fb.width, fb.height});
  // The ring: pixels whose squared distance lies within a band around r^2;
  // the dot: within a third of r.
  const int64_t outer = static_cast<int64_t>(r) * r + r, inner = static_cast<int64_t>(r - 2) * (r - 2), dot = (r / 3) * (r / 3);
  for (int32_t y = box.y0; y < box.y1; ++y)
    for (int32_t x = box.x0; x < box.x1; ++x) {
      const int64_t d2 = static_cast<int64_t>(x - cx) * (x - cx) + static_cast<int64_t>(y - cy) * (y - cy);
      if ((d2 <= outer && d2 >= inner) || d2 <= dot) frame_fill(fb, ScreenRect{x, y, x + 1, y + 1}, value);
    }
  return box;
}

}  // namespace dexmill
