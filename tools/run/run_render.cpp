#include "tools/run/run_render.h"

#include <algorithm>
#include <cstring>

namespace dexmill {
namespace cli {

RenderOutput::RenderOutput() : v_(new StockView()) {}
RenderOutput::~RenderOutput() = default;

namespace {

std::string cannot_draw(const FrameView& fb, Status s) {
  return std::string("cannot draw a ") + std::to_string(fb.width) + "x" + std::to_string(fb.height) +
         " frame of this grid: " + status_message(s);
}

}  // namespace

void* RenderOutput::scratch_for(const DexelGrid<height_t>& g, const FrameView& fb, size_t* bytes) {
  // Supersampled only where twice the size is a frame the renderer takes.
  const bool big = antialias_ && fb.width <= kFrameMaxSide / 2 && fb.height <= kFrameMaxSide / 2;
  if (big) big_.assign((stock_view_supersample_bytes(fb.width, fb.height, fb.format) + 7) / 8, 0);
  else big_.clear();
  stock_view_set_supersample(v_.get(), big ? big_.data() : nullptr);
  scratch_.assign((stock_view_scratch_bytes(g, fb.width, fb.height, big) + 7) / 8, 0);
  *bytes = scratch_.size() * 8;
  return scratch_.data();
}

bool RenderOutput::init(const DexelGrid<height_t>& g, const FrameView& fb, const CameraChoice& cam, std::string* err) {
  size_t bytes = 0;
  void* scratch = scratch_for(g, fb, &bytes);
  const Status s = stock_view_init(v_.get(), g, fb, cam, scratch, bytes);
  if (!ok(s)) *err = cannot_draw(fb, s);
  return ok(s);
}

bool RenderOutput::resize(const DexelGrid<height_t>& g, const FrameView& fb, std::string* err) {
  size_t bytes = 0;
  void* scratch = scratch_for(g, fb, &bytes);
  const Status s = stock_view_resize(v_.get(), g, fb, scratch, bytes);
  if (!ok(s)) *err = cannot_draw(fb, s);
  return ok(s);
}

void RenderOutput::set_fixtures(const std::vector<BoxNm>* f) {
  stock_view_set_fixtures(v_.get(), f->data(), static_cast<int32_t>(f->size()));  // at most kFixturesMax: run_options
}

void RenderOutput::set_colours(const SurfaceColours* c) { stock_view_set_colours(v_.get(), c); }

void RenderOutput::set_tool(const Tool& t) { stock_view_set_tool(v_.get(), t); }

RenderResult RenderOutput::draw(DexelGrid<height_t>* g, const CutterPose& pose) {
  // The lists as they are now: the view reads them by pointer.
  if (path_) stock_view_path_progress(v_.get(), path_->data(), static_cast<uint32_t>(path_->size()), *path_done_);
  view_marks_.clear();
  if (run_marks_) view_marks_.assign(run_marks_->lists, run_marks_->lists + run_marks_lists(run_marks_, *run_sim_));
  for (const Marks& m : marks_)
    view_marks_.push_back(ViewMarks{m.points->data(), static_cast<uint32_t>(m.points->size()), m.colour});
  stock_view_set_marks(v_.get(), view_marks_.data(), static_cast<int32_t>(view_marks_.size()));
  stock_view_set_legend(v_.get(), legend_);
  return stock_view_draw(v_.get(), g, pose);
}

Camera RenderOutput::camera() const { return stock_view_given_camera(*v_); }

void RenderOutput::zoom(int32_t steps, bool reset) {
  if (reset) stock_view_zoom_reset(v_.get());
  else (void)stock_view_zoom(v_.get(), steps, v_->fb.width / 2, v_->fb.height / 2);
}

void RenderOutput::set_path(const std::vector<PathSegment>* path, const uint32_t* done) {
  path_ = path;
  path_done_ = done;
  if (path) stock_view_set_path(v_.get(), path->data(), static_cast<uint32_t>(path->size()), *done);
  else stock_view_remove_path(v_.get());
}

void RenderOutput::set_path_visible(bool on) { stock_view_show_path(v_.get(), on); }

DepthView RenderOutput::depth() const { return stock_view_depth(*v_); }

void RenderOutput::share_view_of(const RenderOutput& other) { stock_view_share_frame(v_.get(), *other.v_); }

void RenderOutput::set_camera(const Camera& c) { stock_view_set_camera(v_.get(), c); }

Camera RenderOutput::initial_camera() const { return stock_view_initial_camera(*v_); }

void fan_out_dirty(DexelGrid<height_t>* g, RenderOutput* const* outputs, int n) {
  for (int k = 0; k < n; ++k) outputs[k]->note_dirty(g->dirty);
  g->dirty = GridRect::none();
}

}  // namespace cli
}  // namespace dexmill
