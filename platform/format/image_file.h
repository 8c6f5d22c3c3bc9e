// Images out in the format their name asks for: a frame (RGB) as PPM or
// PNG, a height image (16-bit grey) as PGM or PNG. Written through
// OutputFile (platform/os/output_file.h): complete or not at all.
#ifndef DEXMILL_PLATFORM_FORMAT_IMAGE_FILE_H
#define DEXMILL_PLATFORM_FORMAT_IMAGE_FILE_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "display/raster/framebuffer.h"

namespace dexmill {

enum class ImageFormat : uint8_t { kPpm, kPgm, kPng };

// The file name extension of a format, without the dot.
const char* image_format_extension(ImageFormat f);

// fb as a PNG file in memory (replacing *out).
void frame_png(const FrameView& fb, std::vector<uint8_t>* out);

// Writes fb as `path` in `format` (kPpm or kPng). On failure returns false
// with a message in err.
bool write_frame_image(const char* path, ImageFormat format, const FrameView& fb, char* err, std::size_t errn);

// Writes width x height 16-bit samples (row 0 the top of the picture) as
// `path` in `format` (kPgm or kPng).
bool write_grey16_image(const char* path, ImageFormat format, int32_t width, int32_t height, const uint16_t* samples,
                        char* err, std::size_t errn);

}  // namespace dexmill

#endif
