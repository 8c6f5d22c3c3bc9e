// One drawing of a simulation's stock; see stock_view.h.
#include "display/view/stock_view.h"

#include "core/math/fixed.h"
#include "display/overlay/box_outline.h"
#include "display/overlay/decorations.h"
#include "display/overlay/marker.h"
#include "display/view/supersample.h"

namespace dexmill {

namespace {

// The renderer's defaults, as a constant (flash, not code that builds them).
constexpr RenderOptions kViewOptions{};

// A rectangle more to present: appended, or merged into the last one when
// the list is full.
void add_rect(RenderResult* res, const ScreenRect& r) {
  if (res->nrects < kMaxDirtyRects) res->rects[res->nrects++] = r;
  else res->rects[res->nrects - 1] = rect_union(res->rects[res->nrects - 1], r);
}

// The path's width in the renderer's pixels: one pixel of the picture.
int32_t path_width_px(const StockView& v) { return v.big_pixels ? 2 : 1; }

// The path over what render_update drew, inside each rectangle it
// repainted (the whole frame after a full redraw; where pieces turned to
// done, stock_view_draw had it repaint). Every piece is redrawn in order
// inside each, so the pixels equal a full redraw's (backplot.h).
void draw_path(StockView* v, RenderResult* res) {
  const uint32_t done = min_of(v->path_done, v->path_n);
  const BackplotColours colours;
  const DepthView depth = stock_view_depth(*v);
  for (int k = 0; k < res->nrects; ++k)
    backplot_draw(v->r.fb, depth, v->r.view, v->path, v->path_n, done, res->rects[k], colours, path_width_px(*v));
  v->path_drawn_done = done;
}

// Over the picture at its own size (view_1x): screen-space markers.
void draw_marks(StockView* v, RenderResult* res) {
  const int32_t radius = v->fb.height >= 400 ? 8 : 4;
  for (int32_t m = 0; m < v->nmarks; ++m) {
    const ViewMarks& list = v->marks[m];
    const uint32_t value = pixel_pack(v->fb.format, list.colour);
    ScreenRect all{0, 0, 0, 0};
    for (uint32_t k = 0; k < list.n; ++k)
      all = rect_union(all, marker_draw(v->fb, v->view_1x, list.points[k], radius, value));
    if (!all.empty()) add_rect(res, all);
  }
}

// The box the initial camera frames: the stock and the fixtures beside it.
BoxNm framed_box(const StockView& v) { return fixtures_box(renderer_stock_box(v.r), v.fixtures, v.nfixtures); }

// Where the decorations go in this view; empty when they are off or would
// cover the framed box (the part is never hidden: a thumbnail too small to
// hold both shows the part alone).
ScreenRect decorations_place(const StockView& v, const View& view, const ScreenRect& area) {
  if (!v.decorations) return ScreenRect{0, 0, 0, 0};
  const ScreenRect deco = decorations_rect(v.fb, view, renderer_stock_box(v.r), area);
  return box_outline_meets(view, framed_box(v), deco) ? ScreenRect{0, 0, 0, 0} : deco;
}

bool legend_has_captions(const ViewLegend* l) { return l && !l->named && (l->low_caption[0] || l->high_caption[0]); }

void draw_legend(StockView* v, RenderResult* res) {
  const ViewLegend& l = *v->legend;
  const char* labels[kLegendMaxSwatches];
  for (int32_t k = 0; k < l.n && k < kLegendMaxSwatches; ++k) labels[k] = l.labels[k];
  if (l.named) legend_draw_named(v->fb, l.colour, l.n, labels);
  else legend_draw(v->fb, l.colour, l.n, labels, l.title, l.low_caption[0] ? l.low_caption : nullptr,
                   l.high_caption[0] ? l.high_caption : nullptr);
  add_rect(res, legend_rect(v->fb, legend_has_captions(&l)));
}

// The rectangles the renderer and the path repainted in the supersampled
// frame, averaged into the picture; the result's rectangles become the
// picture's. The renderer's rectangles lie on its 4-pixel tile grid, so
// each covers whole 2x2 blocks and the picture is the same whether it was
// drawn whole or in parts.
void resolve(StockView* v, RenderResult* res) {
  for (int k = 0; k < res->nrects; ++k) {
    res->rects[k] = supersample_half_rect(res->rects[k]);
    downsample_2x2(v->big, v->fb, res->rects[k]);
  }
}

// What is drawn over the picture at its own size (view_1x), after the
// scene: the marks, the legend and the decorations.
void draw_layers(StockView* v, RenderResult* res) {
  draw_marks(v, res);
  if (v->legend) draw_legend(v, res);
  const ScreenRect area = stock_view_picture_area(*v);
  if (!decorations_place(*v, v->view_1x, area).empty())
    add_rect(res, decorations_draw(v->fb, v->view_1x, renderer_stock_box(v->r), area));
}

}  // namespace

size_t stock_view_scratch_bytes(const DexelGrid<height_t>& g, int32_t width, int32_t height, bool supersampled) {
  const int32_t k = supersampled ? 2 : 1;
  return renderer_scratch_bytes(g, k * width, k * height, kViewOptions.zformat);
}

void stock_view_set_supersample(StockView* v, void* pixels) { v->big_pixels = pixels; }

size_t stock_view_supersample_bytes(int32_t width, int32_t height, PixelFormat f) {
  return 4 * static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(pixel_bytes(f));
}

Status stock_view_init(StockView* v, const DexelGrid<height_t>& g, const FrameView& fb, const CameraChoice& cam,
                       void* scratch, size_t scratch_bytes) {
  const Status s = stock_view_resize(v, g, fb, scratch, scratch_bytes);
  if (ok(s)) stock_view_choose_camera(v, cam);
  return s;
}

void stock_view_choose_camera(StockView* v, const CameraChoice& cam) {
  v->choice = cam;
  stock_view_set_camera(v, stock_view_initial_camera(*v));
}

Status stock_view_resize(StockView* v, const DexelGrid<height_t>& g, const FrameView& fb, void* scratch,
                         size_t scratch_bytes) {
  Renderer<height_t>* r = &v->r;
  const bool had_camera = r->fb.pixels != nullptr;
  const Camera keep = v->given;
  FrameView scene = fb;
  if (v->big_pixels) {
    scene.pixels = v->big_pixels;
    scene.width = 2 * fb.width;
    scene.height = 2 * fb.height;
    scene.stride_bytes = scene.width * pixel_bytes(fb.format);
  }
  const Status s = ok(frame_check(fb)) ? renderer_init(r, g, scene, kViewOptions, scratch, scratch_bytes)
                                       : Status::kBadArgument;
  if (!ok(s)) return s;
  v->fb = fb;
  v->big = scene;
  // Keep direction and zoom; refit only the target to the new aspect.
  if (had_camera) renderer_set_camera(r, view_zoom_apply(keep, v->zoom, fb.height));
  if (v->have_tool) renderer_set_tool(r, &v->profile);
  renderer_set_colours(r, v->colours);
  if (v->fixtures) (void)renderer_set_fixtures(r, v->fixtures, v->nfixtures);
  return Status::kOk;
}

void stock_view_set_tool(StockView* v, const Tool& t) {
  v->profile = tool_profile(t);
  v->have_tool = true;
  renderer_set_tool(&v->r, &v->profile);
}

void stock_view_set_colours(StockView* v, const SurfaceColours* c) {
  v->colours = c;
  renderer_set_colours(&v->r, c);
}

void stock_view_set_legend(StockView* v, const ViewLegend* l) {
  v->legend = l;
  const bool rows = legend_has_captions(l);
  if ((l != nullptr) == v->legend_fitted && rows == v->legend_rows) return;
  stock_view_set_camera(v, stock_view_initial_camera(*v));  // framed above it
}

void stock_view_set_decorations(StockView* v, bool on) {
  if (on == v->decorations) return;
  v->decorations = on;
  stock_view_set_camera(v, stock_view_initial_camera(*v));  // framed clear of them
}

ScreenRect stock_view_picture_area(const StockView& v) {
  ScreenRect a{0, 0, v.fb.width, v.fb.height};
  if (v.legend) a.y1 = legend_rect(v.fb, legend_has_captions(v.legend)).y0;
  return a;
}

void stock_view_set_marks(StockView* v, const ViewMarks* lists, int32_t n) {
  v->marks = n > 0 ? lists : nullptr;
  v->nmarks = lists && n > 0 ? n : 0;
}

void stock_view_set_fixtures(StockView* v, const BoxNm* boxes, int32_t n) {
  v->fixtures = boxes;
  v->nfixtures = boxes && n > 0 ? n : 0;
  (void)renderer_set_fixtures(&v->r, boxes, v->nfixtures);  // the first kFixturesMax
  stock_view_set_camera(v, stock_view_initial_camera(*v));  // framed with the stock
}

void stock_view_set_path(StockView* v, const PathSegment* segs, uint32_t n, uint32_t done) {
  stock_view_path_progress(v, segs, n, done);
  v->has_path = true;
  v->path_drawn_done = 0;
  v->r.need_full = true;
}

void stock_view_remove_path(StockView* v) {
  stock_view_path_progress(v, nullptr, 0, 0);
  v->has_path = false;
  v->path_drawn_done = 0;
  v->r.need_full = true;
}

void stock_view_path_progress(StockView* v, const PathSegment* segs, uint32_t n, uint32_t done) {
  v->path = segs;
  v->path_n = segs ? n : 0;
  v->path_done = done;
}

void stock_view_show_path(StockView* v, bool on) {
  v->path_on = on;
  v->r.need_full = true;
}

RenderResult stock_view_draw(StockView* v, DexelGrid<height_t>* g, const CutterPose& pose) {
  const bool path = stock_view_path_visible(*v);
  // Backplot pieces that turned to done since the last draw: the renderer
  // repaints where they lie, and draw_path draws the path there again.
  if (path) {
    const uint32_t done = min_of(v->path_done, v->path_n);
    if (done > v->path_drawn_done)
      renderer_invalidate(&v->r,
                          backplot_bounds(v->r.fb, v->r.view, v->path, v->path_drawn_done, done, path_width_px(*v)));
  }
  const GridRect saved = g->dirty;
  g->dirty = v->pending;
  v->pending = GridRect::none();
  RenderResult res = render_update(&v->r, g, pose);
  g->dirty = saved;
  if (path) draw_path(v, &res);
  // The view at the frame's size, for what is drawn over the picture (the
  // renderer's own is built for its frame when it draws).
  if (v->big_pixels) {
    resolve(v, &res);
    view_build(v->r.cam, v->r.scene, v->fb.width, v->fb.height, &v->view_1x);
  } else {
    v->view_1x = v->r.view;
  }
  draw_layers(v, &res);
  return res;
}

bool stock_view_blend(StockView* base, const StockView& top) {
  const FrameView& scene = base->r.fb;
  if (!overlay_blend(scene, stock_view_depth(*base), top.r.fb, stock_view_depth(top),
                     ScreenRect{0, 0, scene.width, scene.height}))
    return false;
  if (!base->big_pixels) return true;  // blended over the picture as it is
  RenderResult res;
  res.nrects = 1;
  res.rects[0] = ScreenRect{0, 0, scene.width, scene.height};
  resolve(base, &res);
  draw_layers(base, &res);
  return true;
}

DepthView stock_view_depth(const StockView& v) {
  DepthView d;
  d.z = v.r.target.z;
  d.stride_bytes = v.r.target.z_stride;
  d.format = v.r.target.zformat;
  return d;
}

void stock_view_share_frame(StockView* v, const StockView& other) {
  renderer_share_frame(&v->r, other.r);
  v->given = stock_view_camera(other);
  v->zoom = ViewZoom{};
  renderer_set_camera(&v->r, v->given);
}

void stock_view_set_camera(StockView* v, const Camera& c) {
  v->given = c;
  renderer_set_camera(&v->r, view_zoom_apply(c, v->zoom, v->fb.height));
  v->legend_fitted = v->legend != nullptr;
  v->legend_rows = legend_has_captions(v->legend);
}

bool stock_view_zoom(StockView* v, int32_t steps, int32_t x_px, int32_t y_px) {
  if (!view_zoom_about(&v->zoom, steps, x_px, y_px, v->fb.width, v->fb.height)) return false;
  renderer_set_camera(&v->r, view_zoom_apply(v->given, v->zoom, v->fb.height));
  return true;
}

void stock_view_zoom_reset(StockView* v) {
  v->zoom = ViewZoom{};
  renderer_set_camera(&v->r, v->given);
}

Camera stock_view_initial_camera(const StockView& v) {
  // The stock and the fixtures beside it (a clamp cut off at the frame's
  // edge hides what the check found there).
  const BoxNm box = framed_box(v);
  const CameraChoice& ch = v.choice;
  Camera c = camera_preset(ch.angles ? ViewPreset::kIso : ch.preset);
  if (ch.angles) {
    c.azimuth_bam = ch.azimuth_bam;
    c.elevation_bam = ch.elevation_bam;
  }
  const ScreenRect area = stock_view_picture_area(v);
  camera_fit_inside(&c, box, v.fb.width, v.fb.height, area);
  if (!v.decorations) return c;
  // Decorations in a corner the stock reaches (a top view of a wide stock):
  // the stock framed above them instead, when that leaves it at least 60 %
  // of the height (else the decorations give way: decorations_place).
  View view;
  view_build(c, v.r.scene, v.fb.width, v.fb.height, &view);
  const ScreenRect deco = decorations_rect(v.fb, view, renderer_stock_box(v.r), area);
  if (!box_outline_meets(view, box, deco) || (deco.y0 - area.y0) * 5 < (area.y1 - area.y0) * 3) return c;
  ScreenRect above = area;
  above.y1 = deco.y0;
  camera_fit_inside(&c, box, v.fb.width, v.fb.height, above);
  return c;
}

}  // namespace dexmill
