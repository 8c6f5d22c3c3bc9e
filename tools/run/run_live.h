// The live outputs of `dexmill run`: a GLFW window (--window) or a Linux
// framebuffer (--fbdev DEV). Both show the simulation as it runs, paced so
// that simulated time passes at --speed simulated seconds per second (by
// default the whole job in about 20 s), with a status line under the
// picture: program line, X Y Z, feed, tool, simulated time.
//
// The window also takes input: drag orbits, the wheel zooms, space pauses,
// + and - double or halve the speed, r resets the view, q or Esc quits, and
// a left click (no drag) on the part measures it there: the line
// `dexmill measure --at` would print for that column on standard output, a
// marker on the place and the heights on the status line for a while.
#ifndef DEXMILL_TOOLS_RUN_RUN_LIVE_H
#define DEXMILL_TOOLS_RUN_RUN_LIVE_H

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/grid/grid.h"
#include "display/surface/render.h"
#include "tools/cli/measure_text.h"
#include "tools/run/run_options.h"
#include "tools/run/run_render.h"

namespace dexmill {
namespace cli {

// What the status line shows.
struct LiveStatus {
  uint32_t line = 0;
  PointNm pos{0, 0, 0};
  int64_t feed_nm_per_min = 0;
  int32_t tool = 0;
  std::string tool_spec;
  int64_t sim_us = 0;
  bool inch = false;
};

// The status line's text, e.g.
// "line 123 X12.345 Y-3.000 Z1.000 F1200 T2 ball:6 0:01:23 x4.000 PAUSED";
// speed_milli 0 leaves the speed out (saved frames have no pace).
std::string status_text(const LiveStatus& s, int64_t speed_milli, bool paused, bool done);

// The strip the status line takes under a picture `width` pixels wide
// (the font doubled from 960 pixels, where 80 cells fit).
int32_t status_band_height(int32_t width);
// Draws the strip with `text` at the bottom band_h rows of `all`; the
// rectangle it covers.
ScreenRect status_band_draw(const FrameView& all, int32_t band_h, const std::string& text);

class LiveScreen;

class LiveView {
 public:
  LiveView();
  ~LiveView();

  // Opens the output the options ask for. Returns kExitOk, kExitUsage
  // (--window in a build without GLFW) or kExitIo (no display, no device),
  // with a message in *err.
  int open(const RunOptions& o, const DexelGrid<height_t>& g, const CameraChoice& cam, int64_t total_us,
           std::string* err);
  RenderOutput* output() { return &out_; }
  // Runs before every frame is drawn: completes the cut so far (the Mill
  // defers a move's end cap) and passes its dirty rectangle on.
  void set_before_draw(std::function<void()> f) { before_draw_ = std::move(f); }
  // What a click measures (its grid the one drawn; the layers and the
  // design as the run keeps them). Without it clicks are ignored.
  void set_measure(const MeasureSource& s) { measure_ = s; }

  // Called after every interpreted line, with the simulated time so far:
  // draws and presents a frame when the pacing says so, handles input
  // (and waits while paused). False when the user quit or presenting failed
  // (see failed()).
  bool tick(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st);
  // After the program: draws and shows the last frame (status "DONE").
  bool last_frame(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st);
  // Then keeps it on screen for --hold, and (a window without
  // --exit-when-done) until the user quits, still answering the view keys.
  bool wait_done(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st);

  bool failed() const { return failed_; }
  const std::string& error() const { return error_; }

 private:
  bool frame(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st, bool done, bool force_full);
  // Polls input for up to wait_s seconds; false when the user quit.
  bool handle_input(DexelGrid<height_t>* g, double wait_s, bool* redraw);
  void layout(const DexelGrid<height_t>& g);
  // A click at pixel (x, y) of the screen: measured and marked, or said to
  // miss. True when the picture changes (the marker, the status line).
  bool click(const DexelGrid<height_t>& g, int32_t x, int32_t y);

  std::unique_ptr<LiveScreen> screen_;
  RenderOutput out_;
  std::function<void()> before_draw_;
  bool interactive_ = false;
  bool exit_when_done_ = false;
  int64_t hold_ms_ = 0;
  int64_t speed_milli_ = 1000;
  bool paused_ = false;
  double next_frame_s_ = 0;  // wall clock of the next frame
  double base_wall_s_ = 0;   // wall clock at simulated time 0 (moves on with pauses and speed changes)
  int64_t last_sim_us_ = 0;
  bool failed_ = false;
  std::string error_;
  int32_t band_h_ = 0;
  MeasureSource measure_;
  std::vector<PointNm> click_mark_;  // the last click's place (one point, or none)
  std::string click_text_;           // shown on the status line until click_until_s_
  double click_until_s_ = 0;
};

}  // namespace cli
}  // namespace dexmill

#endif
