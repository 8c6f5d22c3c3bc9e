// A dm_frame (display/api/dexmill.h) as the display's FrameView: what the
// API's views draw into and what dexmill_io.h writes out.
#ifndef DEXMILL_DISPLAY_API_FRAME_H
#define DEXMILL_DISPLAY_API_FRAME_H

#include "display/api/dexmill.h"
#include "display/raster/framebuffer.h"

namespace dexmill {
namespace api {

static_assert(DM_XRGB8888 == static_cast<int>(PixelFormat::kXrgb8888) &&
                  DM_RGB565 == static_cast<int>(PixelFormat::kRgb565),
              "DM_ pixel formats are the display's numbers");

// DM_E_ARGUMENT for no frame, DM_E_FRAME for one the renderer cannot use
// (frame_check).
inline dm_status frame_view_of(const dm_frame* f, FrameView* out) {
  if (!f) return DM_E_ARGUMENT;
  if (f->format != DM_XRGB8888 && f->format != DM_RGB565) return DM_E_FRAME;
  FrameView fb;
  fb.pixels = f->pixels;
  fb.width = f->width;
  fb.height = f->height;
  fb.stride_bytes = f->stride_bytes;
  fb.format = static_cast<PixelFormat>(f->format);
  if (!ok(frame_check(fb))) return DM_E_FRAME;
  *out = fb;
  return DM_OK;
}

}  // namespace api
}  // namespace dexmill

#endif
