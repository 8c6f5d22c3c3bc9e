// The window with GLFW and OpenGL 1.1's glDrawPixels: the frame is ours,
// GL only copies it to the screen (see window.h).
#ifdef DEXMILL_GLFW
#include "platform/live/window.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#ifndef GL_BGRA
#define GL_BGRA 0x80E1
#endif

namespace dexmill {

struct Window::Impl {
  GLFWwindow* win = nullptr;
  std::vector<uint32_t> pixels;
  int32_t width = 0, height = 0;
  WindowInput pending;
  bool dragging = false;
  double last_x = 0, last_y = 0;
  // The left press that may become a click: where it was, and the farthest
  // the mouse has gone from there since.
  bool left_down = false;
  double press_x = 0, press_y = 0, strayed = 0;
  std::string error;

  void fit_to_framebuffer() {
    int w = 0, h = 0;
    glfwGetFramebufferSize(win, &w, &h);
    if (w < 1) w = 1;
    if (h < 1) h = 1;
    if (w == width && h == height) return;
    width = w;
    height = h;
    pixels.assign(static_cast<size_t>(w) * static_cast<size_t>(h), 0xff000000u);
    pending.resized = true;
  }
};

namespace {

Window::Impl* impl_of(GLFWwindow* w) { return static_cast<Window::Impl*>(glfwGetWindowUserPointer(w)); }

void on_char(GLFWwindow* w, unsigned int c) {
  WindowInput& in = impl_of(w)->pending;
  switch (c) {
    case '+': case '=': ++in.speed_steps; break;
    case '-': case '_': --in.speed_steps; break;
    case ' ': in.toggle_pause = true; break;
    case 'r': case 'R': in.reset_view = true; break;
    case 'p': case 'P': in.toggle_path = true; break;
    case 'q': case 'Q': in.quit = true; break;
    default: break;
  }
}

void on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  WindowInput& in = impl_of(w)->pending;
  if (key == GLFW_KEY_ESCAPE) in.quit = true;
  if (key == GLFW_KEY_KP_ADD) ++in.speed_steps;
  if (key == GLFW_KEY_KP_SUBTRACT) --in.speed_steps;
}

// The cursor (window coordinates) as a pixel of the frame, which is
// larger on a display that scales windows.
void frame_pixel(GLFWwindow* w, const Window::Impl& p, double x, double y, int32_t* px, int32_t* py) {
  int ww = 0, wh = 0;
  glfwGetWindowSize(w, &ww, &wh);
  const double sx = ww > 0 ? static_cast<double>(p.width) / ww : 1.0, sy = wh > 0 ? static_cast<double>(p.height) / wh : 1.0;
  *px = static_cast<int32_t>(x * sx);
  *py = static_cast<int32_t>(y * sy);
}

void on_button(GLFWwindow* w, int button, int action, int) {
  Window::Impl* p = impl_of(w);
  p->dragging = action == GLFW_PRESS;
  glfwGetCursorPos(w, &p->last_x, &p->last_y);
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  if (action == GLFW_PRESS) {
    p->left_down = true;
    p->press_x = p->last_x;
    p->press_y = p->last_y;
    p->strayed = 0;
  } else if (action == GLFW_RELEASE && p->left_down) {
    p->left_down = false;
    if (p->strayed <= kClickSlopPx) {
      p->pending.click = true;
      frame_pixel(w, *p, p->press_x, p->press_y, &p->pending.click_x, &p->pending.click_y);
    }
  }
}

void on_cursor(GLFWwindow* w, double x, double y) {
  Window::Impl* p = impl_of(w);
  if (!p->dragging) return;
  if (p->left_down) {
    const double dx = x - p->press_x, dy = y - p->press_y;
    p->strayed = std::max(p->strayed, std::max(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy));
  }
  p->pending.drag_dx += static_cast<int32_t>(x - p->last_x);
  p->pending.drag_dy += static_cast<int32_t>(y - p->last_y);
  p->last_x = x;
  p->last_y = y;
}

void on_scroll(GLFWwindow* w, double, double dy) {
  impl_of(w)->pending.zoom_steps += dy > 0 ? 1 : (dy < 0 ? -1 : 0);
}

void on_close(GLFWwindow* w) { impl_of(w)->pending.quit = true; }

}  // namespace

Window::Window() : impl_(new Impl()) {}

Window::~Window() {
  if (impl_->win) {
    glfwDestroyWindow(impl_->win);
    glfwTerminate();
  }
}

bool Window::available() { return true; }

bool Window::open(int32_t width, int32_t height, const char* title) {
  if (!glfwInit()) {
    const char* why = nullptr;
    glfwGetError(&why);
    impl_->error = std::string("cannot open a window: ") + (why ? why : "GLFW could not start (no display?)");
    return false;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 1);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  impl_->win = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (!impl_->win) {
    const char* why = nullptr;
    glfwGetError(&why);
    impl_->error = std::string("cannot open a window: ") + (why ? why : "unknown GLFW error");
    glfwTerminate();
    return false;
  }
  glfwSetWindowUserPointer(impl_->win, impl_.get());
  glfwSetCharCallback(impl_->win, on_char);
  glfwSetKeyCallback(impl_->win, on_key);
  glfwSetMouseButtonCallback(impl_->win, on_button);
  glfwSetCursorPosCallback(impl_->win, on_cursor);
  glfwSetScrollCallback(impl_->win, on_scroll);
  glfwSetWindowCloseCallback(impl_->win, on_close);
  glfwMakeContextCurrent(impl_->win);
  glfwSwapInterval(0);  // the live view paces itself
  impl_->fit_to_framebuffer();
  impl_->pending.resized = false;
  return true;
}

FrameView Window::frame() {
  FrameView v;
  v.pixels = impl_->pixels.data();
  v.width = impl_->width;
  v.height = impl_->height;
  v.stride_bytes = impl_->width * 4;
  v.format = PixelFormat::kXrgb8888;
  return v;
}

bool Window::present(const ScreenRect*, int) {
  // The back buffer is undefined after a swap, so the whole frame goes up
  // each time; 0xFFRRGGBB in memory is B, G, R, A bytes on a little-endian
  // CPU, which GL_BGRA reads as such.
  glViewport(0, 0, impl_->width, impl_->height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, impl_->width);
  glRasterPos2f(-1.0f, 1.0f);
  glPixelZoom(1.0f, -1.0f);  // row 0 of the frame at the top
  glDrawPixels(impl_->width, impl_->height, GL_BGRA, GL_UNSIGNED_BYTE, impl_->pixels.data());
  glfwSwapBuffers(impl_->win);
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char b[64];
    std::snprintf(b, sizeof b, "OpenGL error 0x%x while drawing the window", static_cast<unsigned>(e));
    impl_->error = b;
    return false;
  }
  return true;
}

const char* Window::error() const { return impl_->error.c_str(); }

WindowInput Window::poll(double wait_s) {
  if (wait_s > 0) glfwWaitEventsTimeout(wait_s);
  else glfwPollEvents();
  impl_->fit_to_framebuffer();
  WindowInput in = impl_->pending;
  impl_->pending = WindowInput();
  return in;
}

}  // namespace dexmill
#endif
