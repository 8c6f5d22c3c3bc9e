#include "tools/run_render.h"

namespace dexmill {
namespace cli {

RenderOutput::RenderOutput() : r_(new Renderer<height_t>()) {}
RenderOutput::~RenderOutput() = default;

bool RenderOutput::init(const DexelGrid<height_t>& g, const FrameView& fb, const CameraChoice& cam, std::string* err) {
  choice_ = cam;
  if (!resize(g, fb, err)) return false;
  set_camera(initial_camera());
  return true;
}

bool RenderOutput::resize(const DexelGrid<height_t>& g, const FrameView& fb, std::string* err) {
  const bool had_camera = r_->fb.pixels != nullptr;
  const Camera keep = r_->cam;
  RenderOptions opt;
  const size_t bytes = renderer_scratch_bytes(g, fb.width, fb.height, opt.zformat);
  scratch_.assign((bytes + 7) / 8, 0);
  const Status s = renderer_init(r_.get(), g, fb, opt, scratch_.data(), scratch_.size() * 8);
  if (!ok(s)) {
    *err = std::string("cannot draw a ") + std::to_string(fb.width) + "x" + std::to_string(fb.height) +
           " frame of this grid: " + status_message(s);
    return false;
  }
  fb_ = fb;
  if (had_camera) {
    Camera c = keep;
    // Keep direction and zoom; refit only the target to the new aspect.
    renderer_set_camera(r_.get(), c);
  }
  if (have_tool_) renderer_set_tool(r_.get(), &profile_);
  renderer_set_colours(r_.get(), colours_);
  if (fixtures_)  // at most kFixturesMax: run_options
    (void)renderer_set_fixtures(r_.get(), fixtures_->data(), static_cast<int>(fixtures_->size()));
  return true;
}

void RenderOutput::set_fixtures(const std::vector<BoxNm>* f) {
  fixtures_ = f;
  (void)renderer_set_fixtures(r_.get(), f->data(), static_cast<int>(f->size()));
  set_camera(initial_camera());  // framed with the stock
}

void RenderOutput::set_colours(const SurfaceColours* c) {
  colours_ = c;
  renderer_set_colours(r_.get(), c);
}

void RenderOutput::set_tool(const Tool& t) {
  profile_ = tool_profile(t);
  have_tool_ = true;
  renderer_set_tool(r_.get(), &profile_);
}

RenderResult RenderOutput::draw(DexelGrid<height_t>* g, const CutterPose& pose) {
  // Backplot pieces that turned to done since the last draw: the renderer
  // repaints where they lie, and draw_path draws the path there again.
  if (path_ && path_on_) {
    const uint32_t done = min_of<uint32_t>(*path_done_, static_cast<uint32_t>(path_->size()));
    if (done > path_drawn_done_)
      renderer_invalidate(r_.get(), backplot_bounds(fb_, r_->view, path_->data(), path_drawn_done_, done));
  }
  const GridRect saved = g->dirty;
  g->dirty = pending_;
  pending_ = GridRect::none();
  RenderResult res = render_update(r_.get(), g, pose);
  g->dirty = saved;
  if (path_ && path_on_) draw_path(&res);
  for (const Marks& m : marks_) {
    const int32_t radius = fb_.height >= 400 ? 8 : 4;
    const uint32_t value = pixel_pack(fb_.format, m.colour);
    ScreenRect all{0, 0, 0, 0};
    for (const PointNm& p : *m.points) all = rect_union(all, marker_draw(fb_, r_->view, p, radius, value));
    if (!all.empty()) {
      if (res.nrects < kMaxDirtyRects) res.rects[res.nrects++] = all;
      else res.rects[res.nrects - 1] = rect_union(res.rects[res.nrects - 1], all);
    }
  }
  if (legend_) {
    const char* labels[kLegendMaxSwatches];
    for (int32_t k = 0; k < legend_->n; ++k) labels[k] = legend_->labels[k].c_str();
    if (legend_->named) legend_draw_named(fb_, legend_->colour, legend_->n, labels);
    else legend_draw(fb_, legend_->colour, legend_->n, labels, legend_->title.c_str());
    const ScreenRect l = legend_rect(fb_);
    if (res.nrects < kMaxDirtyRects) res.rects[res.nrects++] = l;
    else res.rects[res.nrects - 1] = rect_union(res.rects[res.nrects - 1], l);
  }
  return res;
}

Camera RenderOutput::camera() const { return r_->cam; }

void RenderOutput::set_path(const std::vector<PathSegment>* path, const uint32_t* done) {
  path_ = path;
  path_done_ = done;
  path_drawn_done_ = 0;
  r_->need_full = true;
}

void RenderOutput::set_path_visible(bool on) {
  path_on_ = on;
  r_->need_full = true;
}

// The path over what render_update drew, inside each rectangle it
// repainted (the whole frame after a full redraw; where pieces turned to
// done, draw() had it repaint). Every piece is redrawn in order inside
// each, so the pixels equal a full redraw's (backplot.h).
void RenderOutput::draw_path(RenderResult* res) {
  const PathSegment* segs = path_->data();
  const uint32_t n = static_cast<uint32_t>(path_->size()), done = min_of(*path_done_, n);
  const BackplotColours colours;
  for (int k = 0; k < res->nrects; ++k) backplot_draw(fb_, depth(), r_->view, segs, n, done, res->rects[k], colours);
  path_drawn_done_ = done;
}

DepthView RenderOutput::depth() const {
  DepthView d;
  d.z = r_->target.z;
  d.stride_bytes = r_->target.z_stride;
  d.format = r_->target.zformat;
  return d;
}

void RenderOutput::share_view_of(const RenderOutput& other) {
  renderer_share_frame(r_.get(), *other.r_);
  renderer_set_camera(r_.get(), other.camera());
}

void RenderOutput::set_camera(const Camera& c) { renderer_set_camera(r_.get(), c); }

Camera RenderOutput::initial_camera() const {
  // The stock and the fixtures beside it (a clamp cut off at the frame's
  // edge hides what the check found there).
  BoxNm box = renderer_stock_box(*r_);
  if (fixtures_)
    for (const BoxNm& f : *fixtures_) {
      box.lo = PointNm{min_of(box.lo.x_nm, min_of(f.lo.x_nm, f.hi.x_nm)), min_of(box.lo.y_nm, min_of(f.lo.y_nm, f.hi.y_nm)),
                       min_of(box.lo.z_nm, min_of(f.lo.z_nm, f.hi.z_nm))};
      box.hi = PointNm{max_of(box.hi.x_nm, max_of(f.lo.x_nm, f.hi.x_nm)), max_of(box.hi.y_nm, max_of(f.lo.y_nm, f.hi.y_nm)),
                       max_of(box.hi.z_nm, max_of(f.lo.z_nm, f.hi.z_nm))};
    }
  Camera c = camera_preset(choice_.angles ? ViewPreset::kIso : choice_.preset);
  if (choice_.angles) {
    c.azimuth_bam = choice_.azimuth_bam;
    c.elevation_bam = choice_.elevation_bam;
  }
  camera_fit(&c, box, fb_.width, fb_.height);
  return c;
}

void fan_out_dirty(DexelGrid<height_t>* g, RenderOutput* const* outputs, int n) {
  for (int k = 0; k < n; ++k) outputs[k]->note_dirty(g->dirty);
  g->dirty = GridRect::none();
}

}  // namespace cli
}  // namespace dexmill
