#include "platform/ppm_frames.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "platform/ppm.h"

namespace dexmill {

PpmFrames::PpmFrames(const std::string& dir, int32_t width, int32_t height)
    : dir_(dir), pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
  view_.pixels = pixels_.data();
  view_.width = width;
  view_.height = height;
  view_.stride_bytes = width * 4;
  view_.format = PixelFormat::kXrgb8888;
}

bool PpmFrames::present(const ScreenRect*, int) {
  // A file holds a whole frame, whatever changed.
  char path[1100];
  std::snprintf(path, sizeof path, "%s/frame-%06u.ppm", dir_.c_str(), static_cast<unsigned>(written_ + 1));
  if (!write_ppm(path, view_, error_, sizeof error_)) return false;
  ++written_;
  return true;
}

bool make_dirs(const std::string& dir, std::string* err) {
  std::string part;
  std::size_t at = 0;
  while (at <= dir.size()) {
    std::size_t slash = dir.find('/', at);
    if (slash == std::string::npos) slash = dir.size();
    part = dir.substr(0, slash);
    at = slash + 1;
    if (part.empty() || part == "." || part == "..") continue;
    struct stat st;
    if (stat(part.c_str(), &st) == 0) {
      if (!S_ISDIR(st.st_mode)) {
        *err = "cannot create directory '" + dir + "': '" + part + "' is not a directory";
        return false;
      }
      continue;
    }
    if (mkdir(part.c_str(), 0777) != 0 && errno != EEXIST) {
      *err = "cannot create directory '" + dir + "': " + std::strerror(errno);
      return false;
    }
  }
  return true;
}

}  // namespace dexmill
