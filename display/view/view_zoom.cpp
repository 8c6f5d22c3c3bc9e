// Zoom about a point; see view_zoom.h.
#include "display/view/view_zoom.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

namespace {

// The pan kept within this many half pixels (times kZoomOne) of the given
// camera's target: a frame's side at the widest level and more.
constexpr int64_t kPanMax = int64_t{1} << 52;

}  // namespace

int64_t zoom_scale_q(int32_t level) {
  int64_t s = kZoomOne;
  for (int32_t k = 0; k < level; ++k) s = s * 9 / 10;
  for (int32_t k = 0; k > level; --k) s = s * 10 / 9;
  return s;
}

bool view_zoom_about(ViewZoom* z, int32_t steps, int32_t x_px, int32_t y_px, int32_t width, int32_t height) {
  const int32_t to = static_cast<int32_t>(clamp<int64_t>(static_cast<int64_t>(z->level) + steps, kZoomLevelMin,
                                                         kZoomLevelMax));
  if (to == z->level) return false;
  // The pixel's centre from the frame's, in half pixels; the world point
  // there is pan + d * scale (in the units of the pan): it stays when the
  // pan takes up the scale's change. Exact, so the way back is too.
  const int64_t dx = 2 * static_cast<int64_t>(x_px) + 1 - width, dy = 2 * static_cast<int64_t>(y_px) + 1 - height;
  const int64_t ds = zoom_scale_q(z->level) - zoom_scale_q(to);
  z->pan_right = clamp<int64_t>(z->pan_right + dx * ds, -kPanMax, kPanMax);
  z->pan_down = clamp<int64_t>(z->pan_down + dy * ds, -kPanMax, kPanMax);
  z->level = to;
  return true;
}

Camera view_zoom_apply(const Camera& c, const ViewZoom& z, int32_t height) {
  Camera out = c;
  const int64_t s = zoom_scale_q(z.level);
  if (c.projection == Projection::kPerspective) {
    out.distance_nm = max_of<int64_t>(muldiv_round(c.distance_nm, s, kZoomOne), 1000);
    return out;
  }
  out.view_height_nm = max_of<int64_t>(muldiv_round(c.view_height_nm, s, kZoomOne), 1000);
  if (height < 1 || (z.pan_right == 0 && z.pan_down == 0)) return out;
  // nm on the screen's plane: the pan's units are half pixels of c's frame
  // times kZoomOne; right = (-sin a, cos a, 0), up = (-sin e cos a, -sin e sin a, cos e).
  const int64_t unit = 2 * kZoomOne * static_cast<int64_t>(height);
  const int64_t right_nm = muldiv_round(z.pan_right, c.view_height_nm, unit);
  const int64_t up_nm = -muldiv_round(z.pan_down, c.view_height_nm, unit);
  const SinCosQ30 a = sincos_bam(c.azimuth_bam), e = sincos_bam(static_cast<uint32_t>(c.elevation_bam));
  const int64_t one_q30 = int64_t{1} << 30;
  const int64_t up_h = muldiv_round(up_nm, e.sin_q30, one_q30);  // the up vector's horizontal part, negated
  out.target.x_nm += muldiv_round(-right_nm, a.sin_q30, one_q30) - muldiv_round(up_h, a.cos_q30, one_q30);
  out.target.y_nm += muldiv_round(right_nm, a.cos_q30, one_q30) - muldiv_round(up_h, a.sin_q30, one_q30);
  out.target.z_nm += muldiv_round(up_nm, e.cos_q30, one_q30);
  return out;
}

}  // namespace dexmill
