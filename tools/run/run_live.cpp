// The live view of `dexmill run`; see run_live.h.
#include "tools/run/run_live.h"

#include <cstdio>

#include "core/math/fixed.h"
#include "display/overlay/font.h"
#include "display/view/pick.h"
#include "platform/os/clock.h"
#include "platform/live/fbdev.h"
#include "platform/report/report_json.h"
#include "platform/live/window.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {

// The screen under the live view, and its input (a panel has none).
class LiveScreen {
 public:
  virtual ~LiveScreen() = default;
  virtual Screen& screen() = 0;
  virtual bool interactive() const = 0;
  virtual WindowInput poll(double wait_s) = 0;
};

namespace {

class WindowScreen final : public LiveScreen {
 public:
  Window window;
  Screen& screen() override { return window; }
  bool interactive() const override { return true; }
  WindowInput poll(double wait_s) override { return window.poll(wait_s); }
};

class PanelScreen final : public LiveScreen {
 public:
  FbdevScreen fb;
  Screen& screen() override { return fb; }
  bool interactive() const override { return false; }
  WindowInput poll(double wait_s) override {
    clock_sleep_s(wait_s);
    return WindowInput();
  }
};

constexpr double kFrameS = 1.0 / 30;
constexpr int64_t kElevationLimitBam = 0x3fffffff;  // just under 90 degrees
constexpr int32_t kBamPerPixel = 5965232;  // 0.5 degree: a drag across 720 pixels turns once

int32_t band_scale(int32_t width) { return width >= 960 ? 2 : 1; }  // the status line fits up to 80 cells

constexpr double kClickTextS = 4;  // how long a click's heights stay on the status line
// The click's marker: cyan, apart from the gouges' red, the safety
// findings' magenta and the partial run's amber.

}  // namespace

int32_t status_band_height(int32_t width) { return kFontCellH * band_scale(width) + 4; }

ScreenRect status_band_draw(const FrameView& all, int32_t band_h, const std::string& text) {
  const int32_t scale = band_scale(all.width);
  const ScreenRect band{0, all.height - band_h, all.width, all.height};
  frame_fill(all, band, pixel_pack(all.format, Rgb{24, 28, 36}));
  font_draw(all, 2 * scale, band.y0 + 2, text.data(), text.size(), pixel_pack(all.format, Rgb{230, 232, 236}), scale);
  return band;
}

std::string status_text(const LiveStatus& s, int64_t speed_milli, bool paused, bool done) {
  char b[256];
  const int64_t sec = s.sim_us / 1000000;
  const std::string x = nm_to_mm_text(s.pos.x_nm, 3), y = nm_to_mm_text(s.pos.y_nm, 3), z = nm_to_mm_text(s.pos.z_nm, 3);
  const std::string speed =
      speed_milli > 0 ? " x" + nm_to_mm_text(speed_milli * 1000, 3 - (speed_milli >= 10000 ? 3 : 0)) : std::string();
  std::snprintf(b, sizeof b, "line %u X%s Y%s Z%s F%lld T%d %s %lld:%02lld:%02lld%s%s", static_cast<unsigned>(s.line),
                x.c_str(), y.c_str(), z.c_str(), static_cast<long long>(div_round(s.feed_nm_per_min, kNmPerMm)),
                static_cast<int>(s.tool), s.tool_spec.c_str(), static_cast<long long>(sec / 3600),
                static_cast<long long>(sec / 60 % 60), static_cast<long long>(sec % 60), speed.c_str(),
                done ? " DONE" : (paused ? " PAUSED" : ""));
  return b;
}

LiveView::LiveView() = default;
LiveView::~LiveView() = default;

int LiveView::open(const RunOptions& o, const DexelGrid<height_t>& g, const CameraChoice& cam, int64_t total_us,
                   std::string* err) {
  exit_when_done_ = o.view.exit_when_done || !o.view.window;
  hold_ms_ = o.view.hold_ms;
  // By default the whole job in about 20 s, but never faster than real time...
  // slower than real time is never wanted either: at least x1.
  speed_milli_ = o.view.speed_milli ? o.view.speed_milli : max_of<int64_t>(1000, total_us / 20000);
  if (o.view.window) {
    if (!Window::available()) {
      Window w;
      *err = w.error();
      return kExitUsage;
    }
    std::unique_ptr<WindowScreen> ws(new WindowScreen());
    if (!ws->window.open(o.view.width, o.view.height + status_band_height(o.view.width), "dexmill")) {
      *err = ws->window.error();
      return kExitIo;
    }
    screen_ = std::move(ws);
  } else {
    std::unique_ptr<PanelScreen> ps(new PanelScreen());
    if (!ps->fb.open(o.view.fbdev.c_str())) {
      *err = ps->fb.error();
      return kExitIo;
    }
    screen_ = std::move(ps);
  }
  interactive_ = screen_->interactive();
  FrameView all = screen_->screen().frame();
  band_h_ = status_band_height(all.width);
  if (all.height <= band_h_ + 16) {
    *err = "the screen is too small for the picture and its status line";
    return kExitIo;
  }
  FrameView pic = all;
  pic.height = all.height - band_h_;
  out_.set_antialias(o.view.live_antialiased());
  if (!out_.init(g, pic, cam, err)) return kExitIo;
  out_.add_marks(&click_mark_, kClickMarkColour);
  base_wall_s_ = clock_now_s();
  next_frame_s_ = base_wall_s_;
  return kExitOk;
}

void LiveView::layout(const DexelGrid<height_t>& g) {
  FrameView all = screen_->screen().frame();
  band_h_ = status_band_height(all.width);
  FrameView pic = all;
  pic.height = max_of<int32_t>(1, all.height - band_h_);
  std::string err;
  if (!out_.resize(g, pic, &err)) {
    failed_ = true;
    error_ = err;
  }
}

bool LiveView::frame(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st, bool done, bool) {
  if (before_draw_) before_draw_();
  RenderResult res = out_.draw(g, pose);
  const bool clicked = !click_text_.empty() && clock_now_s() < click_until_s_;
  const ScreenRect band = status_band_draw(screen_->screen().frame(), band_h_,
                                           clicked ? click_text_ : status_text(st, speed_milli_, paused_, done));
  ScreenRect rects[kMaxDirtyRects + 1];
  int n = 0;
  for (int k = 0; k < res.nrects; ++k) rects[n++] = res.rects[k];
  rects[n++] = band;
  if (!screen_->screen().present(rects, n)) {
    failed_ = true;
    error_ = screen_->screen().error();
    return false;
  }
  return true;
}

bool LiveView::click(const DexelGrid<height_t>& g, int32_t x, int32_t y) {
  if (!measure_.grid) return false;
  // The picture is the frame's top rows, so its pixels are the screen's.
  const PickHit h = pick_dexel(out_.picture_view(), g, x, y);
  std::string text;
  MeasureAt r;
  if (!h.hit || !measure_dexel_text(measure_, h.i, h.j, &text, &r)) {
    click_text_ = "no part under the cursor";
  } else {
    std::printf("%s\n", text.c_str());
    std::fflush(stdout);
    click_mark_.assign(1, PointNm{r.column_x_nm, r.column_y_nm, r.top_nm});
    out_.repaint();  // the old marker off
    click_text_ = "measured X" + nm_to_mm_text(r.column_x_nm, 3) + " Y" + nm_to_mm_text(r.column_y_nm, 3) + ": top Z" +
                  nm_to_mm_text(r.top_nm, 4) + ", bottom Z" + nm_to_mm_text(r.bottom_nm, 4);
    if (measure_.lines) click_text_ += r.line ? ", line " + std::to_string(r.line) : ", uncut";
  }
  click_until_s_ = clock_now_s() + kClickTextS;
  return true;
}

bool LiveView::handle_input(DexelGrid<height_t>* g, double wait_s, bool* redraw) {
  const WindowInput in = screen_->poll(wait_s);
  if (in.quit) return false;
  if (!click_text_.empty() && clock_now_s() >= click_until_s_) {
    click_text_.clear();  // the status line back
    *redraw = true;
  }
  // Before any orbit: the pixel is of the picture as it is on the screen.
  if (in.click && click(*g, in.click_x, in.click_y)) *redraw = true;
  if (in.resized) {
    layout(*g);
    *redraw = true;
  }
  if (in.toggle_path) {
    out_.set_path_visible(!out_.path_visible());
    *redraw = true;
  }
  if (in.toggle_pause) {
    paused_ = !paused_;
    *redraw = true;
  }
  if (in.speed_steps) {
    const double now = clock_now_s();
    const double sim_s = static_cast<double>(last_sim_us_) / 1e6;
    for (int k = 0; k < in.speed_steps; ++k) speed_milli_ = min_of<int64_t>(speed_milli_ * 2, 1000000000);
    for (int k = 0; k > in.speed_steps; --k) speed_milli_ = max_of<int64_t>(speed_milli_ / 2, 1);
    base_wall_s_ = now - sim_s * 1000.0 / static_cast<double>(speed_milli_);  // no jump in simulated time
    *redraw = true;
  }
  if (in.drag_dx || in.drag_dy || in.zoom_steps || in.reset_view) {
    Camera c = out_.camera();
    if (in.reset_view) {
      c = out_.initial_camera();
    } else {
      c.azimuth_bam -= static_cast<uint32_t>(in.drag_dx) * static_cast<uint32_t>(kBamPerPixel);
      const int64_t el = static_cast<int64_t>(c.elevation_bam) + static_cast<int64_t>(in.drag_dy) * kBamPerPixel;
      c.elevation_bam = static_cast<int32_t>(clamp<int64_t>(el, -kElevationLimitBam, kElevationLimitBam));
    }
    out_.zoom(in.zoom_steps, in.reset_view);  // the API's zoom too (display/view/view_zoom.h)
    out_.set_camera(c);
    *redraw = true;
  }
  return true;
}

bool LiveView::tick(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st) {
  if (failed_) return false;
  last_sim_us_ = st.sim_us;
  double now = clock_now_s();
  // Where the wall clock should be for this simulated time.
  const double target = base_wall_s_ + static_cast<double>(st.sim_us) / (1000.0 * static_cast<double>(speed_milli_));
  if (now < next_frame_s_ && target <= now + kFrameS) return true;  // keep cutting
  if (!frame(g, pose, st, false, false)) return false;
  next_frame_s_ = now + kFrameS;
  // Ahead of the clock (or paused): show this frame while time catches up.
  for (;;) {
    bool redraw = false;
    now = clock_now_s();
    const double t = base_wall_s_ + static_cast<double>(st.sim_us) / (1000.0 * static_cast<double>(speed_milli_));
    const double wait = paused_ ? kFrameS : min_of(t - now, kFrameS);
    if (!paused_ && wait <= 0) {
      if (!handle_input(g, 0, &redraw)) return false;
      if (redraw && !frame(g, pose, st, false, true)) return false;
      return true;
    }
    const double t0 = clock_now_s();
    if (!handle_input(g, wait, &redraw)) return false;
    if (paused_) base_wall_s_ += clock_now_s() - t0;  // paused time does not count
    if (redraw && !frame(g, pose, st, false, true)) return false;
  }
}

bool LiveView::last_frame(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st) {
  paused_ = false;
  return frame(g, pose, st, true, false);
}

bool LiveView::wait_done(DexelGrid<height_t>* g, const CutterPose& pose, const LiveStatus& st) {
  const double until = clock_now_s() + static_cast<double>(hold_ms_) / 1000.0;
  for (;;) {
    const double now = clock_now_s();
    const bool holding = now < until;
    if (!holding && exit_when_done_) return !failed_;
    bool redraw = false;
    if (!handle_input(g, holding ? min_of(until - now, kFrameS) : kFrameS, &redraw)) return !failed_;
    if (redraw && !frame(g, pose, st, true, true)) return false;
  }
}

}  // namespace cli
}  // namespace dexmill
