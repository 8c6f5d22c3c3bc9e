// Translucent overlay; see overlay.h.
#include "display/overlay/overlay.h"


namespace dexmill {

namespace {

// The mean of two pixels per channel, rounded down: halve each channel
// without its low bit, add, and add back the carry of the two low bits.
inline uint32_t mean_xrgb(uint32_t a, uint32_t b) { return ((a & 0xFEFEFEu) >> 1) + ((b & 0xFEFEFEu) >> 1) + (a & b & 0x010101u); }
inline uint16_t mean_565(uint16_t a, uint16_t b) {
  return static_cast<uint16_t>(((a & 0xF7DEu) >> 1) + ((b & 0xF7DEu) >> 1) + (a & b & 0x0821u));
}

inline uint32_t depth_at(const DepthView& d, int32_t x, int32_t y) {
  const uint8_t* row = d.z + static_cast<ptrdiff_t>(y) * d.stride_bytes;
  return d.format == ZFormat::kZ16 ? reinterpret_cast<const uint16_t*>(row)[x] : reinterpret_cast<const uint32_t*>(row)[x];
}

}  // namespace

bool overlay_blend(const FrameView& base, const DepthView& base_z, const FrameView& top, const DepthView& top_z,
                   ScreenRect r) {
  if (base.format != top.format || base.width != top.width || base.height != top.height ||
      base_z.format != top_z.format || !base.pixels || !top.pixels || !base_z.z || !top_z.z)
    return false;
  r = rect_intersect(r, ScreenRect{0, 0, base.width, base.height});
  for (int32_t y = r.y0; y < r.y1; ++y) {
    uint8_t* brow = static_cast<uint8_t*>(base.pixels) + static_cast<ptrdiff_t>(y) * base.stride_bytes;
    const uint8_t* trow = static_cast<const uint8_t*>(top.pixels) + static_cast<ptrdiff_t>(y) * top.stride_bytes;
    for (int32_t x = r.x0; x < r.x1; ++x) {
      if (depth_at(top_z, x, y) >= depth_at(base_z, x, y)) continue;
      if (base.format == PixelFormat::kRgb565) {
        uint16_t* b = reinterpret_cast<uint16_t*>(brow) + x;
        *b = mean_565(*b, reinterpret_cast<const uint16_t*>(trow)[x]);
      } else {
        uint32_t* b = reinterpret_cast<uint32_t*>(brow) + x;
        *b = mean_xrgb(*b, reinterpret_cast<const uint32_t*>(trow)[x]);
      }
    }
  }
  return true;
}

}  // namespace dexmill
