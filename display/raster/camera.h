// The camera: an orbit around a target (azimuth, elevation, distance), the
// four presets `iso`, `top`, `front`, `right`, fitting to the stock, and the
// per-frame maps from grid and machine coordinates to clip space
// (display/raster/clip.h).
//
// Angles are binary angles (core/math/trig.h). The eye sits in the direction
//   d = (cos e cos a, cos e sin a, sin e)
// from the target; screen right is r = (-sin a, cos a, 0) and screen up
// u = d x r, so world z stays vertical on the screen. azimuth -90 deg,
// elevation 0 looks along +y (front view, x to the right).
#ifndef DEXMILL_DISPLAY_RASTER_CAMERA_H
#define DEXMILL_DISPLAY_RASTER_CAMERA_H

#include <stdint.h>

#include "core/point.h"
#include "display/raster/clip.h"
#include "display/raster/framebuffer.h"

namespace dexmill {

enum class ViewPreset : uint8_t { kIso = 0, kTop = 1, kFront = 2, kRight = 3 };

struct Camera {
  Projection projection = Projection::kOrthographic;
  uint32_t azimuth_bam = 0;    // direction of the eye around +z, from +x, counterclockwise seen from above
  int32_t elevation_bam = 0;   // eye above the xy plane; clamped to [-90, 90] degrees
  PointNm target{0, 0, 0};     // the point at the centre of the frame
  int64_t distance_nm = 0;     // perspective: eye to target
  int64_t view_height_nm = 0;  // orthographic: the height of world the frame shows
  uint32_t fov_bam = 0;        // perspective: vertical field of view, (0, 180) degrees
};

// A preset's direction, orthographic, other fields zero (camera_fit sets
// them). iso: azimuth -45 deg, elevation atan(1/sqrt 2) = 35.26 deg (x to the
// lower right, y to the upper right); top: x right, y up; front: looking
// along +y; right: looking along -x.
Camera camera_preset(ViewPreset v);
// "iso", "top", "front", "right"; false for any other name.
bool view_preset_from_name(const char* name, ViewPreset* out);

// Aims at the box's centre and sets the view height (orthographic) or the
// distance (perspective, with a 40 deg field of view when none is set) so the
// whole box fits the frame with a 5 % margin. Keeps the direction.
void camera_fit(Camera* c, const BoxNm& box, int32_t width, int32_t height);
// The same, fitting the box into `inside` (a part of the frame, e.g. above
// a legend): the zoom from inside's size, the target moved so the box's
// centre lands on inside's centre. The whole frame gives camera_fit's
// camera exactly. Orthographic: the box's projection lies inside with the
// margin (tests/test_camera.cpp); perspective: its bounding sphere, up to
// the sphere's off-axis widening.
void camera_fit_inside(Camera* c, const BoxNm& box, int32_t width, int32_t height, const ScreenRect& inside);

// out_k = (m[k][0]*in_0 + m[k][1]*in_1 + m[k][2]*in_2 + c[k]) >> 32 (c holds
// half a unit, so this rounds to nearest). Orthographic screen positions of
// dexels and machine points are within 1/32 px plus 2^-33 px per dexel and
// per LSB of the exact projection; perspective ones within 1/16 px plus
// (f + d) R 2^-16 / w (camera space is kept in units of R / 2^16, R the
// scene's radius, f the focal length and d the offset from the frame's
// centre in pixels, w the distance from the eye) (tests/test_camera.cpp).
struct AffineQ32 {
  int64_t m[3][3];
  int64_t c[3];
};

// Everything a frame needs to place geometry on the screen.
struct View {
  Projector proj;
  // Dexel (i, j) at height h LSB to clip space: x, y and, orthographic, depth
  // (clamped afterwards) or, perspective, w.
  AffineQ32 grid;
  // A machine point as an offset from `origin` (nm) to clip space; the
  // offsets must stay within +-2^40 nm.
  AffineQ32 world;
  PointNm origin;
  int32_t right_q30[3], up_q30[3], eye_q30[3];  // the camera basis r, u, d
  bool sees_below;  // the eye can see faces that point down (below the stock top)
  PointNm eye;      // perspective: the eye position; orthographic: the target (the frame's centre)
  // The frame the maps were built for, and (orthographic) the height of
  // world it shows after view_build's zoom limit: what turns a pixel back
  // into a ray (display/view/pick.h).
  int32_t width = 0, height = 0;
  int64_t view_height_nm = 0;
};

// What the camera looks at: the box that holds the stock, the table and the
// tool standing on the stock (its bounding sphere sets the depth range), and
// the grid's geometry.
struct SceneFrame {
  BoxNm box;
  int64_t x0_nm, y0_nm, z0_nm, pitch_nm, lsb_nm;
  int64_t stock_top_nm;  // machine z of the highest top
};

// Builds the frame's maps. The orthographic zoom is limited so the scene's
// bounding sphere spans at most 2^20 pixels, the perspective eye to 64 scene
// radii from the scene, and the target to 16 radii from its centre.
void view_build(const Camera& cam, const SceneFrame& scene, int32_t width, int32_t height, View* v);

// A machine point in clip space (orthographic depth clamped to the depth
// range). Points farther than 2^40 nm from the view's origin are clamped.
ClipVertex view_point(const View& v, PointNm p);

}  // namespace dexmill

#endif
