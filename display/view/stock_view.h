// One drawing of a simulation's stock: what `dexmill run` draws into each
// of its frames, windows and images, and what the embedding API
// (display/api/dexmill.h) draws into an embedder's framebuffer. A renderer
// (display/surface/render.h) with a camera chosen as a preset or as angles and
// fitted to the stock and the fixtures beside it, the tool, a colour mode
// and its legend, marks over the picture, fixtures and the backplot path,
// drawn in one order: the grid's changes (incremental), the path inside
// every rectangle that was repainted, the marks, the legend.
//
// Several views can watch one grid (a frame sequence and a window at its
// own size): each keeps the grid changes it has not drawn yet
// (stock_view_note), since a render consumes the grid's dirty rectangle.
//
// Everything a view draws from is caller memory, read by pointer at each
// draw (colours, legend, marks, fixtures, path): a caller whose lists move
// or grow passes them again before drawing. The renderer's scratch is the
// caller's too (stock_view_scratch_bytes). Integer only, no heap.
#ifndef DEXMILL_DISPLAY_VIEW_STOCK_VIEW_H
#define DEXMILL_DISPLAY_VIEW_STOCK_VIEW_H

#include <stddef.h>
#include <stdint.h>

#include "core/config.h"
#include "core/grid/grid.h"
#include "core/point.h"
#include "core/status.h"
#include "core/tool/tool.h"
#include "display/overlay/backplot.h"
#include "display/overlay/legend.h"
#include "display/overlay/overlay.h"
#include "display/surface/render.h"
#include "display/view/view_zoom.h"

namespace dexmill {

// The camera a front end asks for: a preset, or azimuth and elevation
// (then the iso preset's projection); fitted to the stock either way.
struct CameraChoice {
  ViewPreset preset = ViewPreset::kIso;
  bool angles = false;
  uint32_t azimuth_bam = 0;
  int32_t elevation_bam = 0;
};

// A legend strip (display/overlay/legend.h): limits between the swatches
// (labels[0, n - 1)) and a title, or a name for each swatch (named:
// labels[0, n)). A label holds what any legend of dexmill writes (the tool
// legend's longest: ten tool numbers of 11 characters with 9 slashes).
constexpr size_t kViewLabelBytes = 136;
struct ViewLegend {
  Rgb colour[kLegendMaxSwatches];
  int32_t n = 0;
  char labels[kLegendMaxSwatches][kViewLabelBytes];
  char title[kViewLabelBytes];
  bool named = false;
  // Limits only: what the ends mean, in a row above (display/overlay/legend.h;
  // empty: none).
  char low_caption[kViewLabelBytes] = {};
  char high_caption[kViewLabelBytes] = {};
};

// Points marked in one colour over every frame (display/overlay/marker.h).
struct ViewMarks {
  const PointNm* points;
  uint32_t n;
  Rgb colour;
};

// The view's state; fields are internal.
struct StockView {
  Renderer<height_t> r;
  FrameView fb;
  CameraChoice choice;
  bool have_tool = false;
  ToolProfile profile{};
  GridRect pending = GridRect::none();  // grid changes not drawn yet
  const SurfaceColours* colours = nullptr;
  const ViewLegend* legend = nullptr;
  bool legend_rows = false;  // the camera was fitted above a legend with captions...
  bool legend_fitted = false;  // ... or above one without
  bool decorations = false;  // the axis triad and the scale bar (display/overlay/decorations.h)
  // 2x2 supersampling (display/view/supersample.h): the renderer draws into `big`
  // (caller memory, twice fb's size each way; null pixels: off) and each
  // draw resolves what it repainted into fb. `view_1x` is the camera's view
  // at fb's size, for what is drawn over the resolved picture.
  void* big_pixels = nullptr;
  FrameView big;
  View view_1x;
  const ViewMarks* marks = nullptr;
  int32_t nmarks = 0;
  const BoxNm* fixtures = nullptr;
  int32_t nfixtures = 0;
  bool has_path = false;
  bool path_on = true;
  const PathSegment* path = nullptr;
  uint32_t path_n = 0;
  uint32_t path_done = 0;        // pieces cut so far
  uint32_t path_drawn_done = 0;  // path_done when the path was last drawn
  Camera given{};   // the camera last set, before the zoom (display/view/view_zoom.h)
  ViewZoom zoom{};  // applied to `given`: kept across camera changes
};

// Scratch bytes for drawing grid g into a width x height frame; supersampled,
// the renderer's scratch at twice the size each way (4x the depth buffer).
size_t stock_view_scratch_bytes(const DexelGrid<height_t>& g, int32_t width, int32_t height,
                                bool supersampled = false);

// Edge anti-aliasing, set before stock_view_init or stock_view_resize (off
// after a zeroed StockView): `pixels` (null: off) holds a frame of twice the
// frame's width and height in its format, 4 x width x height x pixel size
// bytes (stock_view_supersample_bytes), caller memory; the scratch must then
// be the supersampled size. The scene, the path and the depth are drawn at
// that size and averaged 2x2 into the frame; the marks, the legend and the
// decorations are drawn over the frame at its own size, crisp.
void stock_view_set_supersample(StockView* v, void* pixels);
size_t stock_view_supersample_bytes(int32_t width, int32_t height, PixelFormat f);

// (Re)starts drawing g into fb with the chosen camera; scratch (8-byte
// aligned) of at least stock_view_scratch_bytes. The renderer's status
// (kBadArgument for a frame or grid it cannot draw, kBufferTooSmall).
Status stock_view_init(StockView* v, const DexelGrid<height_t>& g, const FrameView& fb, const CameraChoice& cam,
                       void* scratch, size_t scratch_bytes);
// A new frame size (a window resized), with scratch for it: keeps the
// camera's direction and zoom, the tool, the colours and the fixtures.
Status stock_view_resize(StockView* v, const DexelGrid<height_t>& g, const FrameView& fb, void* scratch,
                         size_t scratch_bytes);

void stock_view_set_tool(StockView* v, const Tool& t);
// A colour mode (null: the workpiece colour), kept across resizes.
void stock_view_set_colours(StockView* v, const SurfaceColours* c);
// Drawn over every frame (null: none). The initial camera frames the stock
// above it: a legend that comes, goes or gains captions fits the camera
// again.
void stock_view_set_legend(StockView* v, const ViewLegend* l);
// The axis triad and the scale bar in the picture's bottom-left corner (off
// after init), drawn in every view where they do not cover the stock and
// its fixtures; the camera is fitted again, clear of them, and the next
// frame is drawn whole.
void stock_view_set_decorations(StockView* v, bool on);
// The part of the frame the picture has to itself: all of it, less the
// legend's strip.
ScreenRect stock_view_picture_area(const StockView& v);
// lists[0, n) of marks drawn over every frame, in order.
void stock_view_set_marks(StockView* v, const ViewMarks* lists, int32_t n);
// Boxes drawn in every frame (at most kFixturesMax); the camera is framed
// again to hold them with the stock.
void stock_view_set_fixtures(StockView* v, const BoxNm* boxes, int32_t n);

// The toolpath over every frame (display/overlay/backplot.h): a new path (n may be
// 0), drawn whole with the next frame; segs[0, done) as done.
void stock_view_set_path(StockView* v, const PathSegment* segs, uint32_t n, uint32_t done);
// No path any more; the next frame is drawn whole.
void stock_view_remove_path(StockView* v);
// The same path as it is now (moved, longer, more of it done).
void stock_view_path_progress(StockView* v, const PathSegment* segs, uint32_t n, uint32_t done);
// Shows or hides the path; the next frame is drawn whole.
void stock_view_show_path(StockView* v, bool on);
inline bool stock_view_path_visible(const StockView& v) { return v.has_path && v.path_on; }

// A change of the grid to draw with the next frame.
inline void stock_view_note(StockView* v, const GridRect& r) { v->pending.include(r); }
// Draws what changed (everything after init, a resize or a camera, tool,
// colour, fixture or path change) into the frame; the rectangles say where.
RenderResult stock_view_draw(StockView* v, DexelGrid<height_t>* g, const CutterPose& pose);

// The depth of the scene as drawn: at twice the frame's size when
// supersampled (stock_view_scene_frame has the matching colours).
DepthView stock_view_depth(const StockView& v);
// The frame the renderer draws into: the frame, or the supersampled one.
inline const FrameView& stock_view_scene_frame(const StockView& v) { return v.r.fb; }
// Draws with the scene frame and camera of `other` (a grid of the same
// geometry): the two frames can be overlaid (display/overlay/overlay.h).
void stock_view_share_frame(StockView* v, const StockView& other);
// The paper's translucent overlay (display/overlay/overlay.h): top's scene, as it
// was last drawn through the frame v shares (stock_view_share_frame),
// blended over v's where it is nearer. Supersampled (both views must be),
// at twice the size, then v's picture is averaged again and its marks,
// legend and decorations drawn over it; else over v's picture as it is.
// False (nothing drawn) when the frames or depths do not match.
bool stock_view_blend(StockView* v, const StockView& top);
inline Camera stock_view_camera(const StockView& v) { return v.r.cam; }
// The view of the last draw at the frame's own size (the supersampled
// scene's camera and scene frame at 1x): what turns a pixel of the picture
// back into the dexel drawn there (display/view/pick.h).
inline const View& stock_view_picture_view(const StockView& v) { return v.view_1x; }
// The camera, zoomed by the view's zoom (stock_view_zoom) before it is drawn.
void stock_view_set_camera(StockView* v, const Camera& c);
// The camera last set, without the zoom (what an orbit turns).
inline const Camera& stock_view_given_camera(const StockView& v) { return v.given; }
// `steps` zoom steps (> 0 towards the scene) about the frame's pixel
// (x_px, y_px): the point drawn there stays (display/view/view_zoom.h); the
// next frame is drawn whole. False when at the zoom's limit.
bool stock_view_zoom(StockView* v, int32_t steps, int32_t x_px, int32_t y_px);
// No zoom (the camera as it was set).
void stock_view_zoom_reset(StockView* v);
// The chosen camera fitted to the stock and the fixtures, inside the
// picture's area (stock_view_picture_area) with a margin and, with
// decorations on, above them when they would cover it and that leaves the
// stock 60 % of the height (else they are not drawn while they would cover
// it): the tool may be cut off at the frame's edge, the stock never is.
Camera stock_view_initial_camera(const StockView& v);
// Another choice, taken as the camera now.
void stock_view_choose_camera(StockView* v, const CameraChoice& cam);

}  // namespace dexmill

#endif
