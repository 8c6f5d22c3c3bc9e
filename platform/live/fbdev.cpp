// Linux framebuffer output; see fbdev.h.
#include "platform/live/fbdev.h"

#include <fcntl.h>
#include <linux/fb.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace dexmill {

bool fbdev_query(int fd, FbInfo* out, std::string* err) {
  fb_var_screeninfo var;
  fb_fix_screeninfo fix;
  std::memset(&var, 0, sizeof var);
  std::memset(&fix, 0, sizeof fix);
  if (ioctl(fd, FBIOGET_VSCREENINFO, &var) != 0 || ioctl(fd, FBIOGET_FSCREENINFO, &fix) != 0) {
    *err = std::string("not a framebuffer device (") + std::strerror(errno) + ")";
    return false;
  }
  FbInfo i;
  i.width = static_cast<int32_t>(var.xres);
  i.height = static_cast<int32_t>(var.yres);
  i.bits_per_pixel = static_cast<int32_t>(var.bits_per_pixel);
  i.line_length = static_cast<int32_t>(fix.line_length);
  i.xoffset = static_cast<int32_t>(var.xoffset);
  i.yoffset = static_cast<int32_t>(var.yoffset);
  i.red_offset = var.red.offset;
  i.red_length = var.red.length;
  i.green_offset = var.green.offset;
  i.green_length = var.green.length;
  i.blue_offset = var.blue.offset;
  i.blue_length = var.blue.length;
  i.mem_bytes = fix.smem_len;
  *out = i;
  return true;
}

bool fbdev_format(const FbInfo& i, PixelFormat* out) {
  // A zero length means the driver did not say; take the usual layout then.
  auto field = [](uint32_t off, uint32_t len, uint32_t want_off, uint32_t want_len) {
    return len == 0 || (off == want_off && len == want_len);
  };
  if (i.bits_per_pixel == 16 && field(i.red_offset, i.red_length, 11, 5) && field(i.green_offset, i.green_length, 5, 6) &&
      field(i.blue_offset, i.blue_length, 0, 5)) {
    *out = PixelFormat::kRgb565;
    return true;
  }
  if (i.bits_per_pixel == 32 && field(i.red_offset, i.red_length, 16, 8) && field(i.green_offset, i.green_length, 8, 8) &&
      field(i.blue_offset, i.blue_length, 0, 8)) {
    *out = PixelFormat::kXrgb8888;
    return true;
  }
  return false;
}

FbdevScreen::~FbdevScreen() { close_all(); }

void FbdevScreen::close_all() {
  if (mem_) munmap(mem_, mapped_);
  mem_ = nullptr;
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

bool FbdevScreen::open(const char* path) {
  const int fd = ::open(path, O_RDWR);
  if (fd < 0) {
    error_ = std::string("cannot open the framebuffer '") + path + "': " + std::strerror(errno);
    return false;
  }
  std::string why;
  if (!fbdev_query(fd, &info_, &why)) {
    error_ = std::string("cannot use '") + path + "': " + why;
    close(fd);
    return false;
  }
  return map(fd, path);
}

bool FbdevScreen::open_with(const char* path, const FbInfo& info) {
  const int fd = ::open(path, O_RDWR);
  if (fd < 0) {
    error_ = std::string("cannot open the framebuffer '") + path + "': " + std::strerror(errno);
    return false;
  }
  info_ = info;
  return map(fd, path);
}

bool FbdevScreen::map(int fd, const char* path) {
  close_all();
  fd_ = fd;
  const std::string name = std::string("the framebuffer '") + path + "'";
  if (!fbdev_format(info_, &format_)) {
    error_ = "cannot use " + name + ": " + std::to_string(info_.bits_per_pixel) +
             " bits per pixel in this channel order is not supported (RGB565 and XRGB8888 are)";
    return false;
  }
  const int32_t bpp = pixel_bytes(format_);
  if (info_.width < 1 || info_.height < 1 || info_.width > kFrameMaxSide || info_.height > kFrameMaxSide ||
      info_.xoffset < 0 || info_.yoffset < 0 || info_.line_length < (info_.xoffset + info_.width) * bpp) {
    error_ = "cannot use " + name + ": its screen info is inconsistent (size, offset or line length)";
    return false;
  }
  const uint64_t need = static_cast<uint64_t>(info_.yoffset + info_.height) * static_cast<uint64_t>(info_.line_length);
  uint64_t have = info_.mem_bytes;
  struct stat st;
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) have = static_cast<uint64_t>(st.st_size);
  if (have < need) {
    error_ = "cannot use " + name + ": it holds " + std::to_string(have) + " bytes, the screen needs " +
             std::to_string(need);
    return false;
  }
  void* m = mmap(nullptr, need, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (m == MAP_FAILED) {
    error_ = "cannot map " + name + ": " + std::strerror(errno);
    return false;
  }
  mem_ = static_cast<uint8_t*>(m);
  mapped_ = need;
  back_.assign(static_cast<size_t>(info_.width) * static_cast<size_t>(info_.height) * static_cast<size_t>(bpp), 0);
  return true;
}

FrameView FbdevScreen::frame() {
  FrameView v;
  v.pixels = back_.data();
  v.width = info_.width;
  v.height = info_.height;
  v.stride_bytes = info_.width * pixel_bytes(format_);
  v.format = format_;
  return v;
}

bool FbdevScreen::present(const ScreenRect* rects, int count) {
  if (!mem_) {
    error_ = "the framebuffer is not open";
    return false;
  }
  const int32_t bpp = pixel_bytes(format_);
  const ScreenRect all{0, 0, info_.width, info_.height};
  for (int k = 0; k < count; ++k) {
    const ScreenRect r = rect_intersect(rects[k], all);
    if (r.empty()) continue;
    const size_t row_bytes = static_cast<size_t>(r.x1 - r.x0) * static_cast<size_t>(bpp);
    for (int32_t y = r.y0; y < r.y1; ++y) {
      const uint8_t* src = back_.data() + (static_cast<size_t>(y) * info_.width + r.x0) * bpp;
      uint8_t* dst = mem_ + static_cast<size_t>(info_.yoffset + y) * static_cast<size_t>(info_.line_length) +
                     static_cast<size_t>(info_.xoffset + r.x0) * static_cast<size_t>(bpp);
      std::memcpy(dst, src, row_bytes);
    }
  }
  return true;
}

}  // namespace dexmill
