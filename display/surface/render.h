// dexmill's display, in one header: the workpiece drawn from its dexel grid
// the way the paper's §2.4 does (polygons per cell, normals blurred), by an
// integer-only span rasterizer into a caller's framebuffer, with the cutter
// as a red solid and incremental redraw of what a cut changed.
//
// Set-up, all memory the caller's (nothing here allocates):
//
//   static Renderer<height_t> r;                       // about 22 KB of state
//   FrameView fb{pixels, 480, 272, 480 * 2, PixelFormat::kRgb565};
//   RenderOptions opt;                                  // defaults are fine
//   size_t n = renderer_scratch_bytes(grid, fb.width, fb.height, opt.zformat);
//   // n bytes, 8-byte aligned: z-buffer, shade cache, block table, tiles
//   renderer_init(&r, grid, fb, opt, scratch, n);
//   renderer_set_tool(&r, &profile);                    // tool_profile(tool)
//   renderer_set_camera(&r, renderer_fit(r, ViewPreset::kIso));
//   renderer_set_fixtures(&r, clamps, 2);               // optional: boxes drawn every frame
//
// Each frame:
//
//   CutterPose pose{true, tip};
//   RenderResult res = render_update(&r, &grid, pose);  // after cutting
//   for (int k = 0; k < res.nrects; ++k) present(res.rects[k]);
//
// render_update repaints only the screen area that the grid's dirty
// rectangle (which it consumes and clears) and the cutter's old and new
// positions can touch (the old one is where the renderer last drew it; pass
// the new one, or visible = false to hide the tool); the pixels come out
// bit-identical to render_full of the same scene. It falls back to
// render_full after set-up or a camera or tool change. The rectangles it
// returns (at most kMaxDirtyRects, on the 4-pixel tile grid, overlapping
// when many) cover every pixel that changed. The stock's size (its highest
// top) is taken at renderer_init; afterwards the grid may only be cut (not
// re-stocked) until the next renderer_init.
#ifndef DEXMILL_DISPLAY_SURFACE_RENDER_H
#define DEXMILL_DISPLAY_SURFACE_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/point.h"
#include "core/status.h"
#include "core/tool/tool.h"
#include "display/raster/camera.h"
#include "display/surface/cutter_draw.h"
#include "display/surface/fixture_draw.h"
#include "display/raster/framebuffer.h"
#include "display/raster/raster.h"
#include "display/surface/redraw.h"
#include "display/surface/shade.h"
#include "display/colour/surface_colours.h"

namespace dexmill {

struct RenderOptions {
  ZFormat zformat = ZFormat::kZ32;
  bool table = true;       // a machine table plane under the stock (drawn when seen from above)
  bool gradient = true;    // background: vertical gradient top to bottom (else top colour)
  Rgb background_top{44, 52, 66};
  Rgb background_bottom{150, 160, 176};
  Rgb workpiece{196, 204, 214};  // light aluminium
  Rgb cutter{215, 38, 30};       // red
  Rgb table_colour{92, 98, 108};
  // Fixtures (renderer_set_fixtures): steel blue, apart from the workpiece's
  // grey, the red cutter, the magenta safety marks and the amber partial-run
  // mark.
  Rgb fixture{64, 104, 176};
  // The key and fill lights (display/surface/shade.h): with light_follows_camera,
  // directions in the camera's frame (right, up, towards the eye), else in
  // machine coordinates; any length. The key from the upper left, the fill
  // from the lower right, which lights what the key leaves dark (faces
  // turned right and down on the screen).
  bool light_follows_camera = true;
  int32_t light[3] = {-5, 9, 13};
  int32_t fill_light[3] = {4, -8, 4};
  // Their strengths (display/surface/shade.h Lighting, q14: 16384 = 1): ambient +
  // key = 1 shows a face square to the key in its own colour. The defaults
  // keep every face the camera sees at a third of its colour or more.
  int32_t ambient_q14 = Lighting{}.ambient_q14;
  int32_t key_q14 = Lighting{}.diffuse_q14;
  int32_t fill_q14 = Lighting{}.fill_q14;  // 0: the key light alone
  bool specular = true;  // the key's highlight (Lighting::specular_q14)
};

// Where the tool tip is, if the tool is to be drawn.
struct CutterPose {
  bool visible = false;
  PointNm tip{0, 0, 0};
};

struct RenderResult {
  bool full = false;          // the whole frame was drawn
  int nrects = 0;             // changed screen rectangles, for present()
  ScreenRect rects[kMaxDirtyRects];
  RasterStats stats;          // triangles submitted, pixels written
};

// The renderer's state; fields are internal.
template <class H>
struct Renderer {
  FrameView fb;
  RenderOptions opt;
  int32_t nx = 0, ny = 0;
  SceneFrame scene;
  BoxNm stock;
  Camera cam;
  View view;
  Lighting light;
  uint32_t lut_work[kShadeLevels], lut_cutter[kShadeLevels], lut_table[kShadeLevels], lut_fixture[kShadeLevels];
  uint8_t* z = nullptr;
  ShadeCache shades;
  BlockInfo* blocks = nullptr;
  int32_t bnx = 0, bny = 0;
  TileMap tiles;
  CutterShape tool;
  CutterMesh cutter;
  CutterPose cutter_pose;       // as last drawn
  ScreenRect cutter_rect{0, 0, 0, 0};  // where it was last drawn (empty: not drawn)
  ClipVertex table_quad[4];
  BoxNm scene_bare;                // the scene's box before fixtures widened it
  const BoxNm* fixtures = nullptr; // caller memory, nfixtures boxes
  int nfixtures = 0;
  FixtureShades fixture_shades;    // per face, for the view
  FixtureMesh fixture_mesh[kFixturesMax];  // placed for the view
  bool table_visible = false;
  bool need_full = true;
  bool i_desc = false, j_desc = false;
  int32_t bottom_shade = 0;
  RasterTarget target;
  const SurfaceColours* colours = nullptr;
  LitRamp lit;                     // the light on colours per vertex (a texture)
};

// Scratch bytes for a grid's size, a frame size and a z format.
size_t renderer_scratch_bytes_for(int32_t nx, int32_t ny, int32_t width, int32_t height, ZFormat zf);
template <class H>
size_t renderer_scratch_bytes(const DexelGrid<H>& g, int32_t width, int32_t height, ZFormat zf) {
  return renderer_scratch_bytes_for(g.nx, g.ny, width, height, zf);
}

// kBadArgument for an unusable frame view or grid, kBufferTooSmall when
// `scratch` is null or shorter than renderer_scratch_bytes.
template <class H>
Status renderer_init(Renderer<H>* r, const DexelGrid<H>& g, const FrameView& fb, const RenderOptions& opt,
                     void* scratch, size_t scratch_bytes);

// The stock's box (the grid's dexel axes, heights 0 to the highest top at
// init), which renderer_fit frames.
template <class H>
BoxNm renderer_stock_box(const Renderer<H>& r);
// A preset camera fitted to the stock (orthographic).
template <class H>
Camera renderer_fit(const Renderer<H>& r, ViewPreset v);

template <class H>
void renderer_set_camera(Renderer<H>* r, const Camera& c);
// The tool to draw (null: none).
template <class H>
void renderer_set_tool(Renderer<H>* r, const ToolProfile* p);

// Fixtures (clamps, vices), drawn in opt.fixture as shaded boxes
// in every frame, depth-tested against the stock, the table and the tool:
// boxes[0, n) in machine coordinates (display/surface/fixture_draw.h; null or
// n = 0: none), caller memory that this call and every full frame read and
// that must not change while it is set (call again after changing it).
// The scene frame (camera.h SceneFrame, whose bounding sphere sets the
// depth range and, in perspective, the near plane) widens to hold them, so
// a fixture beside the stock is neither clamped in depth nor cut by the
// near plane; fixtures far from the stock cost depth precision.
// renderer_fit still frames the stock alone. The next frame is drawn
// whole. kBadArgument (nothing changes) for n < 0 or null boxes with n > 0;
// kBufferTooSmall for n > kFixturesMax: the first kFixturesMax are drawn,
// the rest not.
template <class H>
[[nodiscard]] Status renderer_set_fixtures(Renderer<H>* r, const BoxNm* boxes, int n);

// Takes the stock box and scene frame of `from` (a renderer of another grid
// of the same geometry): the two then map machine points to the same
// screen points and depths for any camera (display/overlay/overlay.h). Next frame whole.
// The frame includes the room `from`'s fixtures took; set fixtures on
// `from` before sharing, and none on r afterwards (they would widen r's
// frame again).
template <class H>
void renderer_share_frame(Renderer<H>* r, const Renderer<H>& from);

// A colour mode (null: off, the workpiece colour throughout). Its ramps are
// built with the next frame, which is drawn whole.
template <class H>
void renderer_set_colours(Renderer<H>* r, const SurfaceColours* c);

// Draws everything. Clears the grid's dirty rectangle.
template <class H>
RenderResult render_full(Renderer<H>* r, DexelGrid<H>* g, const CutterPose& cutter);
// Redraws what changed since the last render. Clears the grid's dirty
// rectangle.
template <class H>
RenderResult render_update(Renderer<H>* r, DexelGrid<H>* g, const CutterPose& cutter);

// Has the next render_update repaint `rect` too (what was drawn over the
// frame there changes: a backplot piece that turned from to come to done).
template <class H>
void renderer_invalidate(Renderer<H>* r, const ScreenRect& rect);

#define DEXMILL_RENDER_EXTERN(H)                                                                                   \
  extern template Status renderer_init<H>(Renderer<H>*, const DexelGrid<H>&, const FrameView&, const RenderOptions&, \
                                          void*, size_t);                                                          \
  extern template BoxNm renderer_stock_box<H>(const Renderer<H>&);                                                 \
  extern template Camera renderer_fit<H>(const Renderer<H>&, ViewPreset);                                          \
  extern template void renderer_set_camera<H>(Renderer<H>*, const Camera&);                                        \
  extern template void renderer_set_tool<H>(Renderer<H>*, const ToolProfile*);                                     \
  extern template void renderer_set_colours<H>(Renderer<H>*, const SurfaceColours*);                                \
  extern template Status renderer_set_fixtures<H>(Renderer<H>*, const BoxNm*, int);                                 \
  extern template void renderer_share_frame<H>(Renderer<H>*, const Renderer<H>&);                                   \
  extern template RenderResult render_full<H>(Renderer<H>*, DexelGrid<H>*, const CutterPose&);                     \
  extern template RenderResult render_update<H>(Renderer<H>*, DexelGrid<H>*, const CutterPose&);                   \
  extern template void renderer_invalidate<H>(Renderer<H>*, const ScreenRect&);
DEXMILL_RENDER_EXTERN(uint8_t)
DEXMILL_RENDER_EXTERN(uint16_t)
DEXMILL_RENDER_EXTERN(uint32_t)
#undef DEXMILL_RENDER_EXTERN

}  // namespace dexmill

#endif
