#include "platform/format/ppm.h"

#include <cstdio>
#include <vector>

#include "platform/os/output_file.h"

namespace dexmill {

void frame_row_rgb(const FrameView& fb, int32_t y, uint8_t* rgb) {
  const uint8_t* row = static_cast<const uint8_t*>(fb.pixels) + static_cast<std::size_t>(y) * fb.stride_bytes;
  for (int32_t x = 0; x < fb.width; ++x) {
    uint32_t v;
    if (fb.format == PixelFormat::kXrgb8888) v = reinterpret_cast<const uint32_t*>(row)[x];
    else v = reinterpret_cast<const uint16_t*>(row)[x];
    const Rgb c = pixel_unpack(fb.format, v);
    rgb[3 * x] = c.r;
    rgb[3 * x + 1] = c.g;
    rgb[3 * x + 2] = c.b;
  }
}

bool write_ppm(const char* path, const FrameView& fb, char* err, std::size_t errn) {
  OutputFile f;
  if (f.open(path)) {
    f.printf("P6\n%d %d\n255\n", static_cast<int>(fb.width), static_cast<int>(fb.height));
    std::vector<uint8_t> rgb(static_cast<std::size_t>(fb.width) * 3);
    for (int32_t y = 0; y < fb.height; ++y) {
      frame_row_rgb(fb, y, rgb.data());
      f.write(rgb.data(), rgb.size());
    }
    if (f.commit()) return true;
  }
  std::snprintf(err, errn, "%s", f.error());
  return false;
}

}  // namespace dexmill
