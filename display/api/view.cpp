// The embedding API: a simulation drawn into the caller's framebuffer, as
// `dexmill run` draws it (display/view/stock_view.h; dexmill.h).
#include <new>

#include "core/math/trig.h"
#include "display/api/frame.h"
#include "display/api/handles.h"
#include "display/api/path_pieces.h"

using namespace dexmill;
using namespace dexmill::api;

static_assert(DM_RECTS_MAX == kMaxDirtyRects && DM_FRAME_MAX_SIDE == kFrameMaxSide, "the renderer's limits");

namespace dexmill {
namespace api {

void ViewFan::tool_loaded(const Tool& t) {
  current = t;
  for (dm_view* v = first; v; v = v->next) stock_view_set_tool(&v->v, t);
}

void ViewFan::record(const CanonRecord& r) {
  if (sim) run_marks_record(&marks, *sim);
  for (dm_view* v = first; v; v = v->next) {
    if (!v->path) continue;
    v->path_dropped += path_append(r, v->path, &v->path_n, v->path_cap);
    stock_view_path_progress(&v->v, v->path, v->path_n, v->path_n);  // each piece is cut as it comes
  }
}

void ViewFan::changed(const GridRect& r) {
  for (dm_view* v = first; v; v = v->next) stock_view_note(&v->v, r);
}

}  // namespace api
}  // namespace dexmill

namespace {

// The view's own part of its block; the renderer's scratch follows.
constexpr size_t kViewHead = (sizeof(dm_view) + 7) & ~size_t{7};

dm_status camera_of(const dm_camera* c, CameraChoice* out) {
  CameraChoice ch;
  if (c) {
    if (c->preset < DM_VIEW_ISO || c->preset > DM_VIEW_RIGHT || c->elevation_mdeg < -90000 || c->elevation_mdeg > 90000)
      return DM_E_ARGUMENT;
    ch.preset = static_cast<ViewPreset>(c->preset);
    ch.angles = c->angles != 0;
    ch.azimuth_bam = bam_from_mdeg(c->azimuth_mdeg);
    ch.elevation_bam = static_cast<int32_t>(bam_from_mdeg(c->elevation_mdeg));
  }
  *out = ch;
  return DM_OK;
}

ScreenRect screen_rect(const dm_rect& r) { return ScreenRect{r.x0, r.y0, r.x1, r.y1}; }

bool side_ok(int32_t n) { return n >= 1 && n <= kFrameMaxSide; }

constexpr uint32_t kKnownFlags = DM_VIEW_ANTIALIAS;

// The renderer's scratch in a view's block, a whole number of 8-byte words
// (the supersampled frame follows it).
size_t scratch_part(const DexelGrid<height_t>& g, int32_t width, int32_t height, bool supersampled) {
  return (stock_view_scratch_bytes(g, width, height, supersampled) + 7) & ~size_t{7};
}

bool finished(const Simulation& s) {
  return s.state() == SimState::kDone || s.state() == SimState::kStopped || s.state() == SimState::kIoError;
}

// The marks to draw: the run's (display/api/run_marks.h; after the cut,
// final), then dm_view_set_mark's. A gouge's mark that moved or went since
// the last render has the whole frame drawn.
void set_view_marks(dm_view* v, const Simulation& s) {
  ViewFan& fan = v->sim->views;
  if (finished(s) && !fan.marks_final) {
    run_marks_after_cut(&fan.marks, s, s.stop_reason() == SimStop::kInputError);
    fan.marks_final = true;
  }
  int32_t n = run_marks_lists(&fan.marks, s);
  for (int32_t k = 0; k < n; ++k) v->marks[k] = fan.marks.lists[k];
  if (v->has_mark) v->marks[n++] = ViewMarks{&v->mark_at, 1, kClickMarkColour};
  stock_view_set_marks(&v->v, v->marks, n);
  const RunMarks& m = fan.marks;
  bool kept = m.ngouges >= v->ndrawn_gouges;
  for (uint32_t k = 0; kept && k < v->ndrawn_gouges; ++k)
    kept = m.gouges[k].x_nm == v->drawn_gouges[k].x_nm && m.gouges[k].y_nm == v->drawn_gouges[k].y_nm &&
           m.gouges[k].z_nm == v->drawn_gouges[k].z_nm;
  if (!kept) v->v.r.need_full = true;
  for (uint32_t k = 0; k < m.ngouges; ++k) v->drawn_gouges[k] = m.gouges[k];
  v->ndrawn_gouges = m.ngouges;
}

}  // namespace

extern "C" {

dm_status dm_view_bytes(const dm_sim* sim, int32_t width, int32_t height, size_t* bytes) {
  return dm_view_bytes_flags(sim, width, height, DM_XRGB8888, 0, bytes);
}

dm_status dm_view_bytes_flags(const dm_sim* sim, int32_t width, int32_t height, int32_t format, uint32_t flags,
                              size_t* bytes) {
  if (!live(sim) || !bytes || (flags & ~kKnownFlags) != 0) return DM_E_ARGUMENT;
  *bytes = 0;
  const bool aa = (flags & DM_VIEW_ANTIALIAS) != 0;
  if (!side_ok(width) || !side_ok(height) || (format != DM_XRGB8888 && format != DM_RGB565)) return DM_E_FRAME;
  if (aa && (!side_ok(2 * width) || !side_ok(2 * height))) return DM_E_FRAME;
  *bytes = kViewHead + scratch_part(sim->sim->grid(), width, height, aa) +
           (aa ? stock_view_supersample_bytes(width, height, static_cast<PixelFormat>(format)) : 0);
  return DM_OK;
}

dm_status dm_view_create(dm_sim* sim, const dm_frame* frame, const dm_camera* camera, void* mem, size_t bytes,
                         dm_view** out) {
  return dm_view_create_flags(sim, frame, camera, 0, mem, bytes, out);
}

dm_status dm_view_create_flags(dm_sim* sim, const dm_frame* frame, const dm_camera* camera, uint32_t flags,
                               void* mem, size_t bytes, dm_view** out) {
  if (!live(sim) || !out || (flags & ~kKnownFlags) != 0) return DM_E_ARGUMENT;
  *out = nullptr;
  FrameView fb;
  CameraChoice choice;
  if (const dm_status s = frame_view_of(frame, &fb)) return s;
  if (const dm_status s = camera_of(camera, &choice)) return s;
  size_t need = 0;
  if (const dm_status s = dm_view_bytes_flags(sim, fb.width, fb.height, frame->format, flags, &need)) return s;
  if (!mem || (reinterpret_cast<uintptr_t>(mem) & 7) != 0 || bytes < need) return DM_E_MEMORY;
  dm_view* v = new (mem) dm_view();
  DexelGrid<height_t>& grid = sim->sim->grid();
  // The block: the dm_view, the renderer's scratch, the supersampled frame.
  const bool aa = (flags & DM_VIEW_ANTIALIAS) != 0;
  const size_t scratch = scratch_part(grid, fb.width, fb.height, aa);
  if (aa) stock_view_set_supersample(&v->v, static_cast<char*>(mem) + kViewHead + scratch);
  const Status st = stock_view_init(&v->v, grid, fb, choice, static_cast<char*>(mem) + kViewHead, scratch);
  if (!ok(st)) {
    v->tag = 0;
    return st == Status::kBufferTooSmall ? DM_E_MEMORY : DM_E_FRAME;
  }
  stock_view_set_tool(&v->v, sim->views.current);
  const SimChecks& checks = sim->sim->job().checks;
  if (checks.nfixtures > 0) stock_view_set_fixtures(&v->v, checks.fixtures, checks.nfixtures);
  stock_view_note(&v->v, grid.bounds());
  v->sim = sim;
  v->next = sim->views.first;
  sim->views.first = v;
  v->tag = kViewTag;
  *out = v;
  return DM_OK;
}

dm_status dm_render(dm_view* view, dm_rect* rects, int32_t max_rects, int32_t* nrects) {
  if (!view || view->tag != kViewTag || !nrects || max_rects < 0 || (max_rects > 0 && !rects)) return DM_E_ARGUMENT;
  *nrects = 0;
  if (!live(view)) return DM_E_STATE;
  Simulation& s = *view->sim->sim;
  // The cut so far, the deferred end cap shown (after the end it is cut).
  if (!finished(s)) s.sync();
  view_colour_update(view);
  set_view_marks(view, s);
  const RenderResult res = stock_view_draw(&view->v, &s.grid(), CutterPose{true, s.mill().position()});
  int32_t n = 0;
  for (int k = 0; k < res.nrects && max_rects > 0; ++k) {
    ScreenRect r = res.rects[k];
    if (n == max_rects) r = rect_union(r, screen_rect(rects[--n]));  // the rest merged into the last
    rects[n++] = dm_rect{r.x0, r.y0, r.x1, r.y1};
  }
  *nrects = n;
  return DM_OK;
}

dm_status dm_view_set_camera(dm_view* view, const dm_camera* camera) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  CameraChoice choice;
  if (const dm_status s = camera_of(camera, &choice)) return s;
  stock_view_choose_camera(&view->v, choice);
  return DM_OK;
}

dm_status dm_view_set_decorations(dm_view* view, int32_t on) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  stock_view_set_decorations(&view->v, on != 0);
  return DM_OK;
}

size_t dm_path_bytes(uint32_t segments) { return static_cast<size_t>(segments) * sizeof(PathSegment); }

dm_status dm_view_set_path(dm_view* view, void* mem, size_t bytes) {
  if (!view || view->tag != kViewTag || (mem && (reinterpret_cast<uintptr_t>(mem) & 7) != 0)) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  const size_t cap = mem ? bytes / sizeof(PathSegment) : 0;
  view->path = cap > 0 ? static_cast<PathSegment*>(mem) : nullptr;
  view->path_cap = static_cast<uint32_t>(cap < UINT32_MAX ? cap : UINT32_MAX);
  view->path_n = 0;
  view->path_dropped = 0;
  if (view->path) stock_view_set_path(&view->v, view->path, 0, 0);
  else stock_view_remove_path(&view->v);
  return DM_OK;
}

dm_status dm_view_show_path(dm_view* view, int32_t on) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  stock_view_show_path(&view->v, on != 0);
  return DM_OK;
}

dm_status dm_view_path_info(const dm_view* view, uint32_t* segments, uint32_t* capacity, uint64_t* dropped) {
  if (!view || view->tag != kViewTag || !segments || !capacity || !dropped) return DM_E_ARGUMENT;
  *segments = view->path_n;
  *capacity = view->path_cap;
  *dropped = view->path_dropped;
  return DM_OK;
}

dm_status dm_view_set_mark(dm_view* view, const int64_t* at_nm) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  if (at_nm) view->mark_at = PointNm{at_nm[0], at_nm[1], at_nm[2]};
  view->has_mark = at_nm != nullptr;  // drawn over the run's own marks (dm_render)
  view->v.r.need_full = true;  // a mark taken away leaves the picture under it to draw
  return DM_OK;
}

dm_status dm_view_zoom(dm_view* view, int32_t steps, int32_t x_px, int32_t y_px) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  if (steps < -1000 || steps > 1000 || x_px < 0 || y_px < 0 || x_px >= view->v.fb.width || y_px >= view->v.fb.height)
    return DM_E_ARGUMENT;
  (void)stock_view_zoom(&view->v, steps, x_px, y_px);
  return DM_OK;
}

dm_status dm_view_zoom_reset(dm_view* view) {
  if (!view || view->tag != kViewTag) return DM_E_ARGUMENT;
  if (!live(view)) return DM_E_STATE;
  stock_view_zoom_reset(&view->v);
  return DM_OK;
}

void dm_view_destroy(dm_view* view) {
  if (!view || view->tag != kViewTag) return;
  if (live(view->sim))
    for (dm_view** at = &view->sim->views.first; *at; at = &(*at)->next)
      if (*at == view) {
        *at = view->next;
        break;
      }
  view->tag = 0;  // a dm_view has nothing else to end (handles.h)
}

}  // extern "C"
