// One drawing of the simulation for `dexmill run`: the display's view of
// the stock (display/view/stock_view.h: camera, tool, colours, legend, marks,
// fixtures, path, the draw sequence) with the memory it needs, over a
// framebuffer view that a Screen owns. Several can watch one grid (PPM
// frames at --size and a window at its own size): each keeps the grid
// changes it has not drawn yet, since a render consumes the grid's dirty
// rectangle. What it adds to the view is hosted: the renderer's scratch,
// and the legend's and marks' lists as std::string and std::vector, handed
// to the view before each draw.
#ifndef DEXMILL_TOOLS_RUN_RUN_RENDER_H
#define DEXMILL_TOOLS_RUN_RUN_RENDER_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/grid/grid.h"
#include "core/tool/tool.h"
#include "display/api/run_marks.h"
#include "display/overlay/backplot.h"
#include "display/overlay/legend.h"
#include "display/overlay/overlay.h"
#include "display/surface/render.h"
#include "display/view/stock_view.h"

namespace dexmill {
namespace cli {

// The camera the options ask for: a preset, or azimuth and elevation.
using ::dexmill::CameraChoice;

class RenderOutput {
 public:
  RenderOutput();
  ~RenderOutput();

  // Edge anti-aliasing (display/view/supersample.h) from the next init or
  // resize on: the scene drawn into a frame of twice fb's size each way,
  // held here, then averaged into fb (4x the colour and depth memory).
  void set_antialias(bool on) { antialias_ = on; }
  // (Re)starts drawing `g` into `fb` with the chosen camera. False with a
  // message if the renderer rejects the view.
  bool init(const DexelGrid<height_t>& g, const FrameView& fb, const CameraChoice& cam, std::string* err);
  // A new frame size (a window resized), keeping the camera and tool.
  bool resize(const DexelGrid<height_t>& g, const FrameView& fb, std::string* err);
  void set_tool(const Tool& t);
  // A colour mode (null: the workpiece colour), kept across resizes.
  void set_colours(const SurfaceColours* c);
  // A legend drawn over every frame (null: none; display/view/stock_view.h,
  // the modes' own display/view/colour_legend.h), kept by the caller.
  using Legend = ViewLegend;
  void set_legend(const Legend* l) { legend_ = l; }
  // The axis triad and the scale bar over every frame (display/overlay/decorations.h).
  void set_decorations(bool on) { stock_view_set_decorations(v_.get(), on); }
  // Points marked over every frame in `colour` (the gouges found so far in
  // red, the block a partial run stopped at in amber); kept by the caller.
  void add_marks(const std::vector<PointNm>* m, Rgb colour) { marks_.push_back(Marks{m, colour}); }
  // A run's own marks (display/api/run_marks.h: gouges, findings, where it
  // stopped), drawn before those added; both kept by the caller.
  void set_run_marks(RunMarks* m, const Simulation* s) {
    run_marks_ = m;
    run_sim_ = s;
  }
  // Boxes drawn in every frame (--fixture; caller memory, kept by pointer:
  // the vector must not change while it is set).
  void set_fixtures(const std::vector<BoxNm>* f);

  // The toolpath drawn over every frame (display/overlay/backplot.h): path[0, *done)
  // as done, the rest as to come; null: none. Both are the caller's.
  void set_path(const std::vector<PathSegment>* path, const uint32_t* done);
  // Shows or hides the path (the live view's p key); the next draw is full.
  void set_path_visible(bool on);
  bool path_visible() const { return stock_view_path_visible(*v_); }
  // A grid change to draw with the next frame (every output gets them).
  void note_dirty(const GridRect& r) { stock_view_note(v_.get(), r); }
  // Draws what changed (everything after init, resize or a camera change).
  RenderResult draw(DexelGrid<height_t>* g, const CutterPose& pose);

  const FrameView& view() const { return v_->fb; }
  DepthView depth() const;
  // Draws with the scene frame and camera of `other` (a grid of the same
  // geometry): the two frames can be overlaid (display/overlay/overlay.h).
  void share_view_of(const RenderOutput& other);
  bool antialias() const { return antialias_; }
  // top's last drawing blended over this one's where it is nearer
  // (display/view/stock_view.h stock_view_blend); false if they do not match.
  bool blend(const RenderOutput& top) { return stock_view_blend(v_.get(), *top.v_); }
  // The camera as set (an orbit turns it), before the zoom.
  Camera camera() const;
  void set_camera(const Camera& c);
  // Zoom steps about the frame's centre (display/view/view_zoom.h), or none (reset).
  void zoom(int32_t steps, bool reset);
  // The view the last frame was drawn with, at the picture's size (for
  // picking what a pixel shows).
  const View& picture_view() const { return stock_view_picture_view(*v_); }
  // Has the next draw repaint the whole picture (a mark moved off a place).
  void repaint() { renderer_invalidate(&v_->r, ScreenRect{0, 0, v_->r.fb.width, v_->r.fb.height}); }
  // The chosen camera fitted to the stock (what `r` resets the window to).
  Camera initial_camera() const;

 private:
  std::unique_ptr<StockView> v_;
  std::vector<uint64_t> scratch_;
  bool antialias_ = false;
  std::vector<uint64_t> big_;  // the supersampled frame (antialias_)
  const Legend* legend_ = nullptr;
  struct Marks {
    const std::vector<PointNm>* points;
    Rgb colour;
  };
  std::vector<Marks> marks_;
  RunMarks* run_marks_ = nullptr;
  const Simulation* run_sim_ = nullptr;
  std::vector<ViewMarks> view_marks_;  // marks_ as the view draws them
  const std::vector<PathSegment>* path_ = nullptr;
  const uint32_t* path_done_ = nullptr;

  // The renderer's scratch for drawing g into fb (replaced).
  void* scratch_for(const DexelGrid<height_t>& g, const FrameView& fb, size_t* bytes);
};

// Moves the grid's dirty rectangle into every output (then clears it).
void fan_out_dirty(DexelGrid<height_t>* g, RenderOutput* const* outputs, int n);

}  // namespace cli
}  // namespace dexmill

#endif
