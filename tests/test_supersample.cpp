// display/view/supersample.h: the 2x2 resolve against a per-channel reference,
// both formats, rectangles and clipping.
#include <cstdint>
#include <vector>

#include "display/raster/framebuffer.h"
#include "display/view/supersample.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

// The filter written out field by field, as the format stores them.
uint32_t reference(PixelFormat f, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  const int shift[3] = {0, f == PixelFormat::kRgb565 ? 5 : 8, f == PixelFormat::kRgb565 ? 11 : 16};
  const uint32_t mask[3] = {f == PixelFormat::kRgb565 ? 0x1Fu : 0xFFu, f == PixelFormat::kRgb565 ? 0x3Fu : 0xFFu,
                            f == PixelFormat::kRgb565 ? 0x1Fu : 0xFFu};
  uint32_t out = f == PixelFormat::kXrgb8888 ? 0xFF000000u : 0u;
  for (int k = 0; k < 3; ++k) {
    const uint32_t s = ((a >> shift[k]) & mask[k]) + ((b >> shift[k]) & mask[k]) + ((c >> shift[k]) & mask[k]) +
                       ((d >> shift[k]) & mask[k]);
    out |= ((s + 2) >> 2) << shift[k];
  }
  return out;
}

void check_format(PixelFormat f) {
  const int32_t w = 13, h = 9;  // odd sides: the last half pixel row and column are left out
  const int32_t bpp = pixel_bytes(f);
  std::vector<uint8_t> big_mem(static_cast<size_t>(2 * w + 3) * (2 * h + 1) * 4, 0);
  std::vector<uint8_t> out_mem(static_cast<size_t>(w + 2) * h * 4, 0);
  FrameView big{big_mem.data(), 2 * w + 1, 2 * h + 1, (2 * w + 3) * bpp, f};
  FrameView out{out_mem.data(), w, h, (w + 2) * bpp, f};
  t::Rng rng(7);
  for (int32_t y = 0; y < big.height; ++y)
    for (int32_t x = 0; x < big.width; ++x) {
      const uint32_t v = f == PixelFormat::kRgb565 ? rng.next() & 0xFFFFu : 0xFF000000u | (rng.next() & 0xFFFFFFu);
      frame_fill(big, ScreenRect{x, y, x + 1, y + 1}, v);
    }
  frame_fill(out, ScreenRect{0, 0, w, h}, 0x1234u);
  const ScreenRect r{2, 1, 11, 7};
  downsample_2x2(big, out, r);
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      const bool inside = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
      const uint32_t want = inside ? reference(f, frame_pixel(big, 2 * x, 2 * y), frame_pixel(big, 2 * x + 1, 2 * y),
                                               frame_pixel(big, 2 * x, 2 * y + 1), frame_pixel(big, 2 * x + 1, 2 * y + 1))
                                   : 0x1234u;
      CHECK_EQ(frame_pixel(out, x, y), want);
    }
  // The whole frame and more: clipped, every pixel resolved.
  downsample_2x2(big, out, ScreenRect{-5, -5, 100, 100});
  CHECK_EQ(frame_pixel(out, w - 1, h - 1), reference(f, frame_pixel(big, 2 * w - 2, 2 * h - 2), frame_pixel(big, 2 * w - 1, 2 * h - 2),
                                                    frame_pixel(big, 2 * w - 2, 2 * h - 1), frame_pixel(big, 2 * w - 1, 2 * h - 1)));
}

}  // namespace

TEST(supersample_resolve_matches_reference) {
  check_format(PixelFormat::kXrgb8888);
  check_format(PixelFormat::kRgb565);
}

TEST(supersample_rounding_and_flat_colours) {
  // RGB565 fields rounded half up: red 1+1+1+0 = 3 -> (3+2)>>2 = 1; 1+0+0+0 -> 0;
  // green 2+1+1+1 = 5 -> 1; 63 x4 stays 63.
  std::vector<uint16_t> big(4), one(1);
  FrameView b{big.data(), 2, 2, 4, PixelFormat::kRgb565};
  FrameView o{one.data(), 1, 1, 2, PixelFormat::kRgb565};
  big = {0x0800 | (2 << 5), 0x0800 | (1 << 5), 0x0800 | (1 << 5), 1 << 5};
  downsample_2x2(b, o, ScreenRect{0, 0, 1, 1});
  CHECK_EQ(one[0], static_cast<uint16_t>(0x0800 | (1 << 5)));
  big = {0x0800, 0, 0, 0};
  downsample_2x2(b, o, ScreenRect{0, 0, 1, 1});
  CHECK_EQ(one[0], 0u);
  // A flat colour resolves to itself, in both formats.
  for (const uint32_t v : {0xFFFFu, 0x07E0u, 0xA5A5u}) {
    big = {static_cast<uint16_t>(v), static_cast<uint16_t>(v), static_cast<uint16_t>(v), static_cast<uint16_t>(v)};
    downsample_2x2(b, o, ScreenRect{0, 0, 1, 1});
    CHECK_EQ(one[0], static_cast<uint16_t>(v));
  }
  std::vector<uint32_t> big32(4, 0xFFC4CCD6u), one32(1, 0);
  downsample_2x2(FrameView{big32.data(), 2, 2, 8, PixelFormat::kXrgb8888},
                 FrameView{one32.data(), 1, 1, 4, PixelFormat::kXrgb8888}, ScreenRect{0, 0, 1, 1});
  CHECK_EQ(one32[0], 0xFFC4CCD6u);
  // 8-bit channel sums carry into no neighbour: red 255 x 4 stays 255, green 1 rounds to 0, blue 3 to 1.
  big32 = {0xFFFF0102u, 0xFFFF0001u, 0xFFFF0000u, 0xFFFF0000u};
  downsample_2x2(FrameView{big32.data(), 2, 2, 8, PixelFormat::kXrgb8888},
                 FrameView{one32.data(), 1, 1, 4, PixelFormat::kXrgb8888}, ScreenRect{0, 0, 1, 1});
  CHECK_EQ(one32[0], 0xFFFF0001u);
}

TEST(supersample_half_rect_widens) {
  const ScreenRect r = supersample_half_rect(ScreenRect{3, 4, 9, 8});
  CHECK(r.x0 == 1 && r.y0 == 2 && r.x1 == 5 && r.y1 == 4);
  CHECK(supersample_half_rect(ScreenRect{4, 4, 4, 9}).empty());
}
