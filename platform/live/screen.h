// The platform seam (core/README.md, habit 10; LVGL's flush callback): a screen
// hands out a framebuffer view to draw into and shows the rectangles of it
// that a frame changed. image files (platform/live/frame_files.h), a GLFW window
// (platform/live/window.h) and a Linux framebuffer (platform/live/fbdev.h) implement
// it; the renderer does not know which one it draws for.
#ifndef DEXMILL_PLATFORM_LIVE_SCREEN_H
#define DEXMILL_PLATFORM_LIVE_SCREEN_H

#include "display/raster/framebuffer.h"

namespace dexmill {

class Screen {
 public:
  // Where to draw the next frame. The view stays valid until the next
  // present() (a window may change size between frames).
  virtual FrameView frame() = 0;
  // The frame is complete: show it. `rects` are the parts that changed
  // since the previous present (count 0: nothing changed). False on
  // failure, with the reason in error().
  virtual bool present(const ScreenRect* rects, int count) = 0;
  virtual const char* error() const = 0;

 protected:
  ~Screen() = default;
};

}  // namespace dexmill

#endif
