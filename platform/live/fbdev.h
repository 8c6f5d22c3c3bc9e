// A Linux framebuffer device (/dev/fb0) as a Screen: the frame is drawn in
// memory of the device's own pixel format (RGB565 or XRGB8888), and
// present() copies the changed rectangles into the mapped device, honouring
// its line length (stride) and the visible area's offset; drawing off-screen
// first means a half-drawn frame is never seen (LVGL's fbdev driver does
// the same with its draw buffers).
//
// The ioctl part (FBIOGET_VSCREENINFO, FBIOGET_FSCREENINFO) sits behind
// fbdev_query(), so a test can hand open_with() the screen info and use a
// regular file of the right size as the device.
#ifndef DEXMILL_PLATFORM_LIVE_FBDEV_H
#define DEXMILL_PLATFORM_LIVE_FBDEV_H

#include <cstdint>
#include <string>
#include <vector>

#include "platform/live/screen.h"

namespace dexmill {

// What dexmill needs of a framebuffer's screen info.
struct FbInfo {
  int32_t width = 0, height = 0;    // visible resolution (xres, yres)
  int32_t bits_per_pixel = 0;       // 16 or 32
  int32_t line_length = 0;          // bytes from one line to the next
  int32_t xoffset = 0, yoffset = 0; // the visible area's corner in memory
  uint32_t red_offset = 0, red_length = 0;
  uint32_t green_offset = 0, green_length = 0;
  uint32_t blue_offset = 0, blue_length = 0;
  uint64_t mem_bytes = 0;           // bytes that can be mapped (smem_len)
};

// The screen info of an open framebuffer device, by ioctl.
bool fbdev_query(int fd, FbInfo* out, std::string* err);

// The frame format matching the device: RGB565 (16 bpp, red at bit 11,
// green at 5, blue at 0) or XRGB8888 (32 bpp, red at 16, green at 8, blue at
// 0). False for anything else (e.g. BGR order, 24 bpp, 8 bpp palettes).
bool fbdev_format(const FbInfo& info, PixelFormat* out);

class FbdevScreen final : public Screen {
 public:
  FbdevScreen() = default;
  FbdevScreen(const FbdevScreen&) = delete;
  FbdevScreen& operator=(const FbdevScreen&) = delete;
  ~FbdevScreen();

  // Opens a device and asks it for its screen info.
  bool open(const char* path);
  // Opens `path` (a device or a regular file) with the given screen info.
  bool open_with(const char* path, const FbInfo& info);

  FrameView frame() override;
  bool present(const ScreenRect* rects, int count) override;
  const char* error() const override { return error_.c_str(); }
  const FbInfo& info() const { return info_; }

 private:
  bool map(int fd, const char* path);
  void close_all();

  int fd_ = -1;
  uint8_t* mem_ = nullptr;
  uint64_t mapped_ = 0;
  FbInfo info_;
  PixelFormat format_ = PixelFormat::kXrgb8888;
  std::vector<uint8_t> back_;
  std::string error_;
};

}  // namespace dexmill

#endif
