// A desktop window showing a framebuffer (the Screen seam), with the input
// the live view needs. Built with GLFW (`make GLFW=1`, Debian package
// libglfw3-dev): window_glfw.cpp. Without it, window_none.cpp says so.
//
// The frame is XRGB8888 at the window's framebuffer size, drawn 1:1 (no
// scaling), so a screenshot of the window holds the very pixels of frame().
#ifndef DEXMILL_PLATFORM_LIVE_WINDOW_H
#define DEXMILL_PLATFORM_LIVE_WINDOW_H

#include <cstdint>
#include <memory>

#include "platform/live/screen.h"

namespace dexmill {

// How far (pixels, each way) the mouse may move between a left press and
// its release for the two to be a click rather than a drag.
constexpr int32_t kClickSlopPx = 3;

// Input since the last poll.
struct WindowInput {
  bool quit = false;          // q, Esc, or the window closed
  bool toggle_pause = false;  // space
  int speed_steps = 0;        // + and - presses (+1 / -1 each)
  int32_t drag_dx = 0, drag_dy = 0;  // pixels the mouse moved with a button held
  // A left click: pressed and released within kClickSlopPx of where it was
  // pressed (a drag further than that only orbits); the pixel of frame()
  // it was pressed at.
  bool click = false;
  int32_t click_x = 0, click_y = 0;
  int32_t zoom_steps = 0;     // wheel notches, > 0 towards the scene
  bool reset_view = false;    // r
  bool toggle_path = false;   // p: the toolpath over the part
  bool resized = false;       // frame() has a new size
};

class Window final : public Screen {
 public:
  Window();
  ~Window();

  // True in a build with GLFW.
  static bool available();
  // Opens a width x height window; false with error() (no GLFW, no display).
  bool open(int32_t width, int32_t height, const char* title);

  FrameView frame() override;
  bool present(const ScreenRect* rects, int count) override;
  const char* error() const override;

  // Handles events, waiting up to wait_s seconds for one (0: just look).
  WindowInput poll(double wait_s);

  struct Impl;  // the toolkit's state (window_glfw.cpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace dexmill

#endif
