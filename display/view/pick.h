// Which dexel a pixel shows: the live window's click measures the part
// where it is clicked, so a pixel has to be turned back into the column of
// the grid drawn there.
//
// The pixel's ray (through its centre, from the eye in perspective, along
// the view direction in orthographic) is marched over the grid's columns
// from near to far (a 2D DDA over the dexels' squares, each column a box
// from its bottom to its top, holes skipped); the first column the ray
// meets is the answer. The ray comes from the view's own basis, target,
// zoom and focal length (display/raster/camera.h), and every step is
// integer: t at each square's side by a 128-bit-exact muldiv, so the march
// is exact to a few nm on the box model.
//
// Error bound against the picture: the renderer draws the top as triangles
// between the dexels' axes (display/surface/mesh.h), the march as boxes
// around them. On a level top or floor the two coincide and the returned
// dexel is the one nearest the drawn point, or (the pixel's centre within
// 1/16 px of a square's side, the projection's rounding) its neighbour.
// Where neighbours differ in height (walls, slopes) the drawn surface runs
// between their axes while the boxes step at half a pitch, so the returned
// dexel is the one drawn or a neighbour within one cell when the ray falls
// at least as steeply as the surface there (any view of a pocket's walls
// from above 45 degrees); a grazing ray over a long gentle slope can land
// further off, by the height step over the ray's slope. At the part's
// outline a pixel up to one cell outside the drawn silhouette may hit and
// one inside may miss (tests/test_pick.cpp holds both to a double oracle).
//
// Integer only, no heap: as the rest of display/.
#ifndef DEXMILL_DISPLAY_VIEW_PICK_H
#define DEXMILL_DISPLAY_VIEW_PICK_H

#include <stdint.h>

#include "core/grid/grid.h"
#include "core/point.h"
#include "display/raster/camera.h"

namespace dexmill {

struct PickHit {
  bool hit = false;       // false: the pixel shows no column (background, the table, a hole)
  int32_t i = 0, j = 0;   // the dexel
  PointNm point{0, 0, 0}; // where the ray meets its box (top, bottom or side), machine nm
};

// The dexel of g drawn at pixel (px, py) of the frame v was built for
// (view_build's width and height; pixel centres at px + 1/2, py + 1/2);
// a miss for pixels outside that frame.
template <class H>
PickHit pick_dexel(const View& v, const DexelGrid<H>& g, int32_t px, int32_t py);

extern template PickHit pick_dexel<uint8_t>(const View&, const DexelGrid<uint8_t>&, int32_t, int32_t);
extern template PickHit pick_dexel<uint16_t>(const View&, const DexelGrid<uint16_t>&, int32_t, int32_t);
extern template PickHit pick_dexel<uint32_t>(const View&, const DexelGrid<uint32_t>&, int32_t, int32_t);

}  // namespace dexmill

#endif
