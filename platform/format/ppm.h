// Binary PPM (P6, maxval 255) images of a framebuffer view, written
// atomically (platform/os/output_file.h): complete or not at all.
#ifndef DEXMILL_PLATFORM_FORMAT_PPM_H
#define DEXMILL_PLATFORM_FORMAT_PPM_H

#include <cstddef>
#include <cstdint>

#include "display/raster/framebuffer.h"

namespace dexmill {

// Writes fb (either pixel format; RGB565 channels widened as pixel_unpack
// does) as `path`. On failure returns false with a message in err.
bool write_ppm(const char* path, const FrameView& fb, char* err, std::size_t errn);

// One row of fb as R, G, B bytes (3 * width of them).
void frame_row_rgb(const FrameView& fb, int32_t y, uint8_t* rgb);

}  // namespace dexmill

#endif
