// Image files for embedders; see dexmill_io.h.
#include "platform/api/dexmill_io.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include "display/api/frame.h"
#include "platform/format/image_file.h"

namespace {

bool ends_with(const char* s, const char* tail) {
  const size_t n = std::strlen(s), m = std::strlen(tail);
  return n >= m && std::strcmp(s + n - m, tail) == 0;
}

}  // namespace

extern "C" {

dm_status dm_io_write_image(const char* path, const dm_frame* frame, char* err, size_t errn) {
  using namespace dexmill;
  if (err && errn) err[0] = 0;
  if (!path) return DM_E_ARGUMENT;
  ImageFormat format;
  if (ends_with(path, ".ppm")) format = ImageFormat::kPpm;
  else if (ends_with(path, ".png")) format = ImageFormat::kPng;
  else return DM_E_ARGUMENT;
  FrameView fb;
  if (const dm_status s = api::frame_view_of(frame, &fb)) return s;
  char why[1300];
  if (write_frame_image(path, format, fb, why, sizeof why)) return DM_OK;
  if (err && errn) std::snprintf(err, errn, "%s", why);
  return DM_E_IO;
}

dm_status dm_io_png(const dm_frame* frame, uint8_t* out, size_t cap, size_t* bytes) {
  using namespace dexmill;
  if (!bytes || (cap && !out)) return DM_E_ARGUMENT;
  *bytes = 0;
  FrameView fb;
  if (const dm_status s = api::frame_view_of(frame, &fb)) return s;
  std::vector<uint8_t> png;
  frame_png(fb, &png);
  *bytes = png.size();
  if (png.size() > cap) return DM_E_MEMORY;
  std::memcpy(out, png.data(), png.size());
  return DM_OK;
}

}  // extern "C"
