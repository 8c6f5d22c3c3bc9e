// The Linux framebuffer screen against a file-backed fake device, in both
// pixel formats: the screen info comes from the test (the ioctl seam), the
// device's line length is longer than a row and the visible area sits at an
// offset, and present() must copy exactly the rectangles it is given.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "display/raster/framebuffer.h"
#include "platform/live/fbdev.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

FbInfo fake_info(int bpp) {
  FbInfo i;
  i.width = 20;
  i.height = 10;
  i.bits_per_pixel = bpp;
  i.xoffset = 3;
  i.yoffset = 2;
  i.line_length = (i.xoffset + i.width) * bpp / 8 + 24;  // padding at each line's end
  if (bpp == 16) {
    i.red_offset = 11; i.red_length = 5; i.green_offset = 5; i.green_length = 6; i.blue_offset = 0; i.blue_length = 5;
  } else {
    i.red_offset = 16; i.red_length = 8; i.green_offset = 8; i.green_length = 8; i.blue_offset = 0; i.blue_length = 8;
  }
  i.mem_bytes = static_cast<uint64_t>(i.yoffset + i.height) * static_cast<uint64_t>(i.line_length);
  return i;
}

std::string make_device(const FbInfo& i, size_t bytes) {
  char path[] = "/tmp/dexmill-fb-XXXXXX";
  const int fd = mkstemp(path);
  std::vector<uint8_t> fill(bytes, 0xab);
  if (fd >= 0) {
    if (write(fd, fill.data(), fill.size()) != static_cast<ssize_t>(fill.size())) std::printf("  short write\n");
    close(fd);
  }
  (void)i;
  return path;
}

std::vector<uint8_t> read_all(const std::string& path) {
  std::vector<uint8_t> v;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return v;
  uint8_t b[4096];
  size_t n;
  while ((n = std::fread(b, 1, sizeof b, f)) > 0) v.insert(v.end(), b, b + n);
  std::fclose(f);
  return v;
}

// Every pixel of the device file: frame pixel (x, y) inside `shown`, 0xab
// bytes everywhere else.
void check_device(const std::string& path, const FbInfo& i, const FrameView& fb, const ScreenRect& shown) {
  const std::vector<uint8_t> mem = read_all(path);
  const int bpp = i.bits_per_pixel / 8;
  long bad = 0;
  for (size_t off = 0; off < mem.size(); ++off) {
    const int64_t line = static_cast<int64_t>(off) / i.line_length;
    const int64_t col = (static_cast<int64_t>(off) % i.line_length) / bpp;
    const int32_t y = static_cast<int32_t>(line - i.yoffset), x = static_cast<int32_t>(col - i.xoffset);
    const bool in = x >= shown.x0 && x < shown.x1 && y >= shown.y0 && y < shown.y1 &&
                    (static_cast<int64_t>(off) % i.line_length) < static_cast<int64_t>(i.xoffset + i.width) * bpp;
    uint8_t want = 0xab;
    if (in) {
      const uint8_t* row = static_cast<const uint8_t*>(fb.pixels) + static_cast<size_t>(y) * fb.stride_bytes;
      want = row[static_cast<size_t>(x) * bpp + (off % i.line_length) % bpp];
    }
    if (mem[off] != want && ++bad <= 3)
      std::printf("  byte %zu (x %d, y %d): 0x%02x, want 0x%02x\n", off, static_cast<int>(x), static_cast<int>(y), mem[off], want);
  }
  CHECK_EQ(bad, 0L);
}

void exercise(int bpp, PixelFormat want_format) {
  const FbInfo info = fake_info(bpp);
  const std::string dev = make_device(info, info.mem_bytes);
  FbdevScreen s;
  CHECK(s.open_with(dev.c_str(), info));
  FrameView fb = s.frame();
  CHECK_EQ(fb.format, want_format);
  CHECK_EQ(fb.width, 20);
  CHECK_EQ(fb.height, 10);
  for (int32_t y = 0; y < fb.height; ++y)
    for (int32_t x = 0; x < fb.width; ++x)
      frame_fill(fb, ScreenRect{x, y, x + 1, y + 1},
                 pixel_pack(fb.format, Rgb{static_cast<uint8_t>(x * 12), static_cast<uint8_t>(y * 25), static_cast<uint8_t>(x ^ y)}));
  const ScreenRect part{2, 1, 7, 4};
  CHECK(s.present(&part, 1));
  check_device(dev, info, fb, part);
  const ScreenRect all{-5, -5, 100, 100};  // clipped to the screen
  CHECK(s.present(&all, 1));
  check_device(dev, info, fb, ScreenRect{0, 0, 20, 10});
  std::remove(dev.c_str());
}

}  // namespace

TEST(fbdev_formats_from_screen_info) {
  PixelFormat f;
  CHECK(fbdev_format(fake_info(16), &f));
  CHECK_EQ(f, PixelFormat::kRgb565);
  CHECK(fbdev_format(fake_info(32), &f));
  CHECK_EQ(f, PixelFormat::kXrgb8888);
  FbInfo bgr = fake_info(32);
  bgr.red_offset = 0;
  bgr.blue_offset = 16;
  CHECK(!fbdev_format(bgr, &f));
  FbInfo b24 = fake_info(32);
  b24.bits_per_pixel = 24;
  CHECK(!fbdev_format(b24, &f));
}

TEST(fbdev_rgb565_file_device) { exercise(16, PixelFormat::kRgb565); }
TEST(fbdev_xrgb8888_file_device) { exercise(32, PixelFormat::kXrgb8888); }

TEST(fbdev_rejects_short_and_non_devices) {
  const FbInfo info = fake_info(32);
  const std::string dev = make_device(info, info.mem_bytes - 1);
  FbdevScreen s;
  CHECK(!s.open_with(dev.c_str(), info));
  CHECK(std::string(s.error()).find("the screen needs") != std::string::npos);
  FbdevScreen q;
  CHECK(!q.open(dev.c_str()));  // a regular file answers no framebuffer ioctl
  CHECK(std::string(q.error()).find("not a framebuffer device") != std::string::npos);
  const int fd = open(dev.c_str(), O_RDONLY);
  FbInfo got;
  std::string err;
  CHECK(!fbdev_query(fd, &got, &err));
  close(fd);
  std::remove(dev.c_str());
  FbdevScreen missing;
  CHECK(!missing.open("/nonexistent/fb0"));
}
