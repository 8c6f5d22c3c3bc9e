// Framebuffer view: pixel formats, fills and the frame hash.
#include "display/raster/framebuffer.h"

#include "core/math/fixed.h"
#include "core/math/hash.h"

namespace dexmill {

ScreenRect rect_intersect(const ScreenRect& a, const ScreenRect& b) {
  return ScreenRect{max_of(a.x0, b.x0), max_of(a.y0, b.y0), min_of(a.x1, b.x1), min_of(a.y1, b.y1)};
}

ScreenRect rect_union(const ScreenRect& a, const ScreenRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return ScreenRect{min_of(a.x0, b.x0), min_of(a.y0, b.y0), max_of(a.x1, b.x1), max_of(a.y1, b.y1)};
}

int32_t pixel_bytes(PixelFormat f) { return f == PixelFormat::kRgb565 ? 2 : 4; }

uint32_t pixel_pack(PixelFormat f, Rgb c) {
  if (f == PixelFormat::kRgb565)
    return (static_cast<uint32_t>(c.r >> 3) << 11) | (static_cast<uint32_t>(c.g >> 2) << 5) | (c.b >> 3);
  return 0xFF000000u | (static_cast<uint32_t>(c.r) << 16) | (static_cast<uint32_t>(c.g) << 8) | c.b;
}

Rgb pixel_unpack(PixelFormat f, uint32_t v) {
  if (f == PixelFormat::kRgb565) {
    const uint32_t r = (v >> 11) & 31, g = (v >> 5) & 63, b = v & 31;
    return Rgb{static_cast<uint8_t>((r << 3) | (r >> 2)), static_cast<uint8_t>((g << 2) | (g >> 4)),
               static_cast<uint8_t>((b << 3) | (b >> 2))};
  }
  return Rgb{static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

uint32_t frame_pixel(const FrameView& fb, int32_t x, int32_t y) {
  const uint8_t* row = static_cast<const uint8_t*>(fb.pixels) + static_cast<ptrdiff_t>(y) * fb.stride_bytes;
  if (fb.format == PixelFormat::kRgb565) return reinterpret_cast<const uint16_t*>(row)[x];
  return reinterpret_cast<const uint32_t*>(row)[x];
}

Status frame_check(const FrameView& fb) {
  if (!fb.pixels) return Status::kBadArgument;
  if (fb.format != PixelFormat::kXrgb8888 && fb.format != PixelFormat::kRgb565) return Status::kBadArgument;
  if (fb.width < 1 || fb.height < 1 || fb.width > kFrameMaxSide || fb.height > kFrameMaxSide)
    return Status::kBadArgument;
  const int32_t bpp = pixel_bytes(fb.format);
  if (fb.stride_bytes < fb.width * bpp || fb.stride_bytes % bpp != 0) return Status::kBadArgument;
  return Status::kOk;
}

void frame_fill(const FrameView& fb, const ScreenRect& r0, uint32_t value) {
  const ScreenRect r = rect_intersect(r0, ScreenRect{0, 0, fb.width, fb.height});
  if (r.empty()) return;
  uint8_t* base = static_cast<uint8_t*>(fb.pixels);
  for (int32_t y = r.y0; y < r.y1; ++y) {
    uint8_t* row = base + static_cast<ptrdiff_t>(y) * fb.stride_bytes;
    if (fb.format == PixelFormat::kRgb565) {
      uint16_t* p = reinterpret_cast<uint16_t*>(row);
      for (int32_t x = r.x0; x < r.x1; ++x) p[x] = static_cast<uint16_t>(value);
    } else {
      uint32_t* p = reinterpret_cast<uint32_t*>(row);
      for (int32_t x = r.x0; x < r.x1; ++x) p[x] = value;
    }
  }
}

uint64_t frame_hash(const FrameView& fb) {
  Hash64 h;
  h.uint_le(static_cast<uint32_t>(fb.width), 4);
  h.uint_le(static_cast<uint32_t>(fb.height), 4);
  h.byte(static_cast<uint8_t>(fb.format));
  const int nbytes = pixel_bytes(fb.format);
  for (int32_t y = 0; y < fb.height; ++y)
    for (int32_t x = 0; x < fb.width; ++x) h.uint_le(frame_pixel(fb, x, y), nbytes);
  return h.value();
}

}  // namespace dexmill
