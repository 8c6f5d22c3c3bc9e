// The window in a build without GLFW: it cannot open (see window.h).
#ifndef DEXMILL_GLFW
#include "platform/live/window.h"

namespace dexmill {

struct Window::Impl {};

Window::Window() = default;
Window::~Window() = default;
bool Window::available() { return false; }
bool Window::open(int32_t, int32_t, const char*) { return false; }
FrameView Window::frame() { return FrameView(); }
bool Window::present(const ScreenRect*, int) { return false; }
const char* Window::error() const {
  return "this dexmill was built without GLFW: install libglfw3-dev (tools/scripts/install-deps.sh window) and "
         "build with make GLFW=1, then run build/glfw/dexmill";
}
WindowInput Window::poll(double) {
  WindowInput in;
  in.quit = true;
  return in;
}

}  // namespace dexmill
#endif
