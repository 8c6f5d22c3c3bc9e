#include "platform/format/image_file.h"

#include <vector>

#include "platform/os/output_file.h"
#include "platform/format/pgm.h"
#include "platform/format/png.h"
#include "platform/format/ppm.h"

namespace dexmill {

const char* image_format_extension(ImageFormat f) {
  switch (f) {
    case ImageFormat::kPpm: return "ppm";
    case ImageFormat::kPgm: return "pgm";
    case ImageFormat::kPng: return "png";
  }
  return "";
}

void frame_png(const FrameView& fb, std::vector<uint8_t>* out) {
  std::vector<uint8_t> rgb(static_cast<std::size_t>(fb.width) * 3 * static_cast<std::size_t>(fb.height));
  for (int32_t y = 0; y < fb.height; ++y)
    frame_row_rgb(fb, y, rgb.data() + static_cast<std::size_t>(y) * 3 * static_cast<std::size_t>(fb.width));
  png_encode_rgb8(rgb.data(), fb.width, fb.height, out);
}

bool write_frame_image(const char* path, ImageFormat format, const FrameView& fb, char* err, std::size_t errn) {
  if (format != ImageFormat::kPng) return write_ppm(path, fb, err, errn);
  std::vector<uint8_t> png;
  frame_png(fb, &png);
  return write_output(path, png.data(), png.size(), err, errn);
}

bool write_grey16_image(const char* path, ImageFormat format, int32_t width, int32_t height, const uint16_t* samples,
                        char* err, std::size_t errn) {
  if (format != ImageFormat::kPng) return write_pgm16(path, width, height, samples, err, errn);
  std::vector<uint8_t> png;
  png_encode_gray16(samples, width, height, &png);
  return write_output(path, png.data(), png.size(), err, errn);
}

}  // namespace dexmill
