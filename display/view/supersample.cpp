// 2x2 supersampling's resolve; see supersample.h.
#include "display/view/supersample.h"

#include "core/math/fixed.h"

namespace dexmill {

namespace {

// (a + b + c + d + 2) >> 2 of each field of packed pixels: the fields sit
// under `mask`'s runs of ones, with room for two more bits above each (the
// caller spreads them apart first).
inline uint64_t average4(uint64_t a, uint64_t b, uint64_t c, uint64_t d, uint64_t round_bits, uint64_t mask) {
  return ((a + b + c + d + round_bits) >> 2) & mask;
}

// XRGB8888: the three channels spread 16 bits apart (0x00RR00GG... as two
// words would be) so sums of four cannot carry into a neighbour.
inline uint64_t spread8888(uint32_t v) {
  const uint64_t x = v;
  return (x & 0xFF) | ((x & 0xFF00) << 8) | ((x & 0xFF0000) << 16);
}
inline uint32_t pack8888(uint64_t s) {
  return 0xFF000000u | static_cast<uint32_t>((s & 0xFF) | ((s >> 8) & 0xFF00) | ((s >> 16) & 0xFF0000));
}
constexpr uint64_t kRound8888 = 2ull | (2ull << 16) | (2ull << 32);
constexpr uint64_t kMask8888 = 0xFFull | (0xFFull << 16) | (0xFFull << 32);

// RGB565: blue 5 bits at 0, green 6 bits at 16, red 5 bits at 32.
inline uint64_t spread565(uint32_t v) {
  const uint64_t x = v;
  return (x & 0x1F) | (((x >> 5) & 0x3F) << 16) | (((x >> 11) & 0x1F) << 32);
}
inline uint32_t pack565(uint64_t s) {
  return static_cast<uint32_t>((s & 0x1F) | (((s >> 16) & 0x3F) << 5) | (((s >> 32) & 0x1F) << 11));
}
constexpr uint64_t kRound565 = 2ull | (2ull << 16) | (2ull << 32);
constexpr uint64_t kMask565 = 0x1Full | (0x3Full << 16) | (0x1Full << 32);

}  // namespace

ScreenRect supersample_half_rect(const ScreenRect& r) {
  if (r.empty()) return ScreenRect{0, 0, 0, 0};
  // Floor and ceiling halves; screen coordinates are never negative here,
  // but the arithmetic shift floors either way.
  return ScreenRect{r.x0 >> 1, r.y0 >> 1, (r.x1 + 1) >> 1, (r.y1 + 1) >> 1};
}

void downsample_2x2(const FrameView& big, const FrameView& out, const ScreenRect& r) {
  if (big.format != out.format || !ok(frame_check(big)) || !ok(frame_check(out))) return;
  const ScreenRect c = rect_intersect(rect_intersect(r, ScreenRect{0, 0, out.width, out.height}),
                                      ScreenRect{0, 0, big.width >> 1, big.height >> 1});
  if (c.empty()) return;
  const uint8_t* bp = static_cast<const uint8_t*>(big.pixels);
  uint8_t* op = static_cast<uint8_t*>(out.pixels);
  for (int32_t y = c.y0; y < c.y1; ++y) {
    const uint8_t* row0 = bp + static_cast<ptrdiff_t>(2 * y) * big.stride_bytes;
    const uint8_t* row1 = row0 + big.stride_bytes;
    uint8_t* orow = op + static_cast<ptrdiff_t>(y) * out.stride_bytes;
    if (out.format == PixelFormat::kXrgb8888) {
      const uint32_t* a = reinterpret_cast<const uint32_t*>(row0);
      const uint32_t* b = reinterpret_cast<const uint32_t*>(row1);
      uint32_t* o = reinterpret_cast<uint32_t*>(orow);
      for (int32_t x = c.x0; x < c.x1; ++x)
        o[x] = pack8888(average4(spread8888(a[2 * x]), spread8888(a[2 * x + 1]), spread8888(b[2 * x]),
                                 spread8888(b[2 * x + 1]), kRound8888, kMask8888));
    } else {
      const uint16_t* a = reinterpret_cast<const uint16_t*>(row0);
      const uint16_t* b = reinterpret_cast<const uint16_t*>(row1);
      uint16_t* o = reinterpret_cast<uint16_t*>(orow);
      for (int32_t x = c.x0; x < c.x1; ++x)
        o[x] = static_cast<uint16_t>(pack565(average4(spread565(a[2 * x]), spread565(a[2 * x + 1]),
                                                      spread565(b[2 * x]), spread565(b[2 * x + 1]), kRound565, kMask565)));
    }
  }
}

}  // namespace dexmill
