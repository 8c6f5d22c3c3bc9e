// The framebuffer view (core/README.md habit 10; olive.c's canvas): pixels in caller
// memory, described by `pixels, width, height, stride, format`. The renderer
// writes straight into it; the platform layer presents rectangles of it.
#ifndef DEXMILL_DISPLAY_RASTER_FRAMEBUFFER_H
#define DEXMILL_DISPLAY_RASTER_FRAMEBUFFER_H

#include <stddef.h>
#include <stdint.h>

#include "core/status.h"

namespace dexmill {

enum class PixelFormat : uint8_t {
  kXrgb8888 = 0,  // uint32 per pixel: 0xFFRRGGBB (X written as 0xFF)
  kRgb565 = 1,    // uint16 per pixel: rrrrrggg gggbbbbb
};

// Largest frame the renderer accepts: screen coordinates then fit 16 bits of
// pixels with 4 sub-pixel bits and a guard band (display/raster/raster.h).
constexpr int32_t kFrameMaxSide = 4096;

struct FrameView {
  void* pixels = nullptr;      // row 0 is the top row of the image
  int32_t width = 0;           // pixels, 1..kFrameMaxSide
  int32_t height = 0;          // pixels, 1..kFrameMaxSide
  int32_t stride_bytes = 0;    // bytes from one row to the next (>= width * pixel size)
  PixelFormat format = PixelFormat::kXrgb8888;
};

// A half-open rectangle of pixels [x0, x1) x [y0, y1); empty when x0 >= x1 or
// y0 >= y1.
struct ScreenRect {
  int32_t x0, y0, x1, y1;

  bool empty() const { return x0 >= x1 || y0 >= y1; }
  int64_t area() const { return empty() ? 0 : static_cast<int64_t>(x1 - x0) * (y1 - y0); }
};
ScreenRect rect_intersect(const ScreenRect& a, const ScreenRect& b);
ScreenRect rect_union(const ScreenRect& a, const ScreenRect& b);  // bounding rectangle

struct Rgb {
  uint8_t r, g, b;
};

// Bytes per pixel of a format: 4 or 2.
int32_t pixel_bytes(PixelFormat f);
// A colour as the format stores it (RGB565 truncates each channel).
uint32_t pixel_pack(PixelFormat f, Rgb c);
// The colour of a stored pixel value; RGB565 channels are widened by
// replicating their top bits, so 0x1f becomes 0xff.
Rgb pixel_unpack(PixelFormat f, uint32_t v);
// The stored value of pixel (x, y).
uint32_t frame_pixel(const FrameView& fb, int32_t x, int32_t y);

// kBadArgument when the view is unusable: null pixels, a side outside
// 1..kFrameMaxSide, a stride shorter than a row or not a multiple of the
// pixel size, an unknown format.
Status frame_check(const FrameView& fb);

// Fills a rectangle (clipped to the frame) with one stored value.
void frame_fill(const FrameView& fb, const ScreenRect& r, uint32_t value);

// FNV-1a 64 of width, height (4 bytes each), format (1 byte), then every
// pixel value row by row from the top, as pixel_bytes(format) little-endian
// bytes: the same on every CPU, whatever its byte order or stride.
uint64_t frame_hash(const FrameView& fb);

}  // namespace dexmill

#endif
