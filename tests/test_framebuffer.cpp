// display/raster/framebuffer.h: pixel formats, the view checks, fills, the frame hash.
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "core/math/hash.h"
#include "display/raster/framebuffer.h"
#include "display/overlay/overlay.h"
#include "tests/runner.h"

using namespace dexmill;

TEST(pixel_formats_pack_and_unpack) {
  CHECK_EQ(pixel_pack(PixelFormat::kXrgb8888, Rgb{0x12, 0x34, 0x56}), 0xFF123456u);
  CHECK_EQ(pixel_pack(PixelFormat::kRgb565, Rgb{0xFF, 0x00, 0x00}), 0xF800u);
  CHECK_EQ(pixel_pack(PixelFormat::kRgb565, Rgb{0x00, 0xFF, 0x00}), 0x07E0u);
  CHECK_EQ(pixel_pack(PixelFormat::kRgb565, Rgb{0x00, 0x00, 0xFF}), 0x001Fu);
  for (uint32_t v = 0; v < 65536; ++v) CHECK_EQ(pixel_pack(PixelFormat::kRgb565, pixel_unpack(PixelFormat::kRgb565, v)), v);
  const Rgb white = pixel_unpack(PixelFormat::kRgb565, 0xFFFF);
  CHECK(white.r == 255 && white.g == 255 && white.b == 255);
  const Rgb c = pixel_unpack(PixelFormat::kXrgb8888, 0xFFABCDEFu);
  CHECK(c.r == 0xAB && c.g == 0xCD && c.b == 0xEF);
  CHECK_EQ(pixel_bytes(PixelFormat::kRgb565), 2);
  CHECK_EQ(pixel_bytes(PixelFormat::kXrgb8888), 4);
}

TEST(frame_view_checks) {
  std::vector<uint32_t> mem(64 * 64);
  FrameView fb{mem.data(), 64, 48, 64 * 4, PixelFormat::kXrgb8888};
  CHECK_EQ(frame_check(fb), Status::kOk);
  FrameView bad = fb;
  bad.pixels = nullptr;
  CHECK_EQ(frame_check(bad), Status::kBadArgument);
  bad = fb;
  bad.stride_bytes = 63 * 4;
  CHECK_EQ(frame_check(bad), Status::kBadArgument);
  bad = fb;
  bad.format = PixelFormat::kRgb565;
  bad.stride_bytes = 129;  // not a whole number of pixels
  CHECK_EQ(frame_check(bad), Status::kBadArgument);
  bad = fb;
  bad.width = kFrameMaxSide + 1;
  CHECK_EQ(frame_check(bad), Status::kBadArgument);
  bad = fb;
  bad.height = 0;
  CHECK_EQ(frame_check(bad), Status::kBadArgument);
}

TEST(frame_fill_and_hash_ignore_stride) {
  // The same picture in a tight and a padded buffer: same hash, and the
  // padding untouched.
  std::vector<uint16_t> tight(10 * 6, 0), padded(16 * 6, 0x5555);
  FrameView a{tight.data(), 10, 6, 20, PixelFormat::kRgb565};
  FrameView b{padded.data(), 10, 6, 32, PixelFormat::kRgb565};
  for (FrameView* f : {&a, &b}) {
    frame_fill(*f, ScreenRect{0, 0, 10, 6}, 0x1234);
    frame_fill(*f, ScreenRect{3, 2, 20, 4}, 0xBEEF);  // clipped to the frame
  }
  CHECK_EQ(frame_hash(a), frame_hash(b));
  CHECK_EQ(frame_pixel(b, 9, 3), 0xBEEFu);
  CHECK_EQ(frame_pixel(b, 2, 3), 0x1234u);
  CHECK_EQ(padded[16 * 3 + 12], 0x5555);
  // The hash reads pixel values as little-endian bytes after a header of
  // width, height and format: spelled out here for one pixel.
  uint16_t one = 0xBEEF;
  FrameView p{&one, 1, 1, 2, PixelFormat::kRgb565};
  Hash64 h;
  h.uint_le(1, 4);
  h.uint_le(1, 4);
  h.byte(static_cast<uint8_t>(PixelFormat::kRgb565));
  h.uint_le(0xBEEF, 2);
  CHECK_EQ(frame_hash(p), h.value());
}

TEST(screen_rects) {
  const ScreenRect a{0, 0, 10, 10}, b{5, 5, 20, 8}, e{3, 3, 3, 9};
  const ScreenRect i = rect_intersect(a, b), u = rect_union(a, b);
  CHECK(i.x0 == 5 && i.y0 == 5 && i.x1 == 10 && i.y1 == 8);
  CHECK(u.x0 == 0 && u.y0 == 0 && u.x1 == 20 && u.y1 == 10);
  CHECK(e.empty());
  CHECK_EQ(e.area(), 0);
  CHECK_EQ(rect_union(e, b).x1, 20);
  CHECK_EQ(a.area(), 100);
}

TEST(overlay_blends_the_nearer_surface_half_and_half) {
  // Two 4 x 2 frames in each format; the top frame is nearer at x < 2.
  for (PixelFormat pf : {PixelFormat::kXrgb8888, PixelFormat::kRgb565}) {
    for (ZFormat zf : {ZFormat::kZ16, ZFormat::kZ32}) {
      uint32_t base_px[8], top_px[8], base_z[8], top_z[8];
      const int bpp = pf == PixelFormat::kRgb565 ? 2 : 4, zb = zf == ZFormat::kZ16 ? 2 : 4;
      FrameView base{base_px, 4, 2, 4 * bpp, pf}, top{top_px, 4, 2, 4 * bpp, pf};
      const Rgb a{201, 100, 31}, b{50, 255, 0};
      for (int k = 0; k < 8; ++k) {
        uint8_t* bp = reinterpret_cast<uint8_t*>(base_px) + k * bpp;
        uint8_t* tp = reinterpret_cast<uint8_t*>(top_px) + k * bpp;
        const uint32_t va = pixel_pack(pf, a), vb = pixel_pack(pf, b);
        std::memcpy(bp, &va, static_cast<size_t>(bpp));  // little-endian hosts: the low bytes
        std::memcpy(tp, &vb, static_cast<size_t>(bpp));
        const uint32_t zbase = 1000, ztop = (k % 4) < 2 ? 500 : 1000;  // equal depth: not nearer
        std::memcpy(reinterpret_cast<uint8_t*>(base_z) + k * zb, &zbase, static_cast<size_t>(zb));
        std::memcpy(reinterpret_cast<uint8_t*>(top_z) + k * zb, &ztop, static_cast<size_t>(zb));
      }
      const DepthView bz{reinterpret_cast<uint8_t*>(base_z), 4 * zb, zf}, tz{reinterpret_cast<uint8_t*>(top_z), 4 * zb, zf};
      CHECK(overlay_blend(base, bz, top, tz, ScreenRect{0, 0, 4, 2}));
      const Rgb pa = pixel_unpack(pf, pixel_pack(pf, a)), pb = pixel_unpack(pf, pixel_pack(pf, b));
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
          const Rgb got = pixel_unpack(pf, frame_pixel(base, x, y));
          if (x < 2) {
            // The mean per channel, rounded down, in the format's own precision.
            const Rgb want = pixel_unpack(pf, pixel_pack(pf, Rgb{uint8_t((pa.r + pb.r) / 2), uint8_t((pa.g + pb.g) / 2),
                                                                 uint8_t((pa.b + pb.b) / 2)}));
            if (pf == PixelFormat::kXrgb8888) {
              CHECK(got.r == want.r && got.g == want.g && got.b == want.b);
            } else {  // per 5/6-bit channel of the stored values
              const uint32_t va = pixel_pack(pf, a), vb = pixel_pack(pf, b), v = frame_pixel(base, x, y);
              CHECK_EQ(v >> 11, ((va >> 11) + (vb >> 11)) / 2);
              CHECK_EQ((v >> 5) & 63, (((va >> 5) & 63) + ((vb >> 5) & 63)) / 2);
              CHECK_EQ(v & 31, ((va & 31) + (vb & 31)) / 2);
            }
          } else {
            CHECK(got.r == pa.r && got.g == pa.g && got.b == pa.b);
          }
        }
      FrameView other = top;
      other.width = 3;
      CHECK(!overlay_blend(base, bz, other, tz, ScreenRect{0, 0, 4, 2}));
    }
  }
}
