#include "platform/live/frame_files.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>


namespace dexmill {

FrameFiles::FrameFiles(const std::string& dir, ImageFormat format, int32_t width, int32_t height)
    : dir_(dir), format_(format), pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
  view_.pixels = pixels_.data();
  view_.width = width;
  view_.height = height;
  view_.stride_bytes = width * 4;
  view_.format = PixelFormat::kXrgb8888;
}

bool FrameFiles::present(const ScreenRect*, int) {
  // A file holds a whole frame, whatever changed.
  char path[1100];
  std::snprintf(path, sizeof path, "%s/frame-%06u.%s", dir_.c_str(), static_cast<unsigned>(written_ + 1),
                image_format_extension(format_));
  if (!write_frame_image(path, format_, view_, error_, sizeof error_)) return false;
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

bool is_frame_name(const char* name) {
  if (std::strncmp(name, "frame-", 6) != 0) return false;
  for (int k = 6; k < 12; ++k)
    if (name[k] < '0' || name[k] > '9') return false;
  return std::strcmp(name + 12, ".png") == 0 || std::strcmp(name + 12, ".ppm") == 0;
}

bool find_old_frames(const std::string& dir, std::vector<std::string>* paths, std::string* err) {
  paths->clear();
  DIR* d = opendir(dir.c_str());
  if (!d) {
    *err = "cannot read directory '" + dir + "': " + std::strerror(errno);
    return false;
  }
  while (const dirent* e = readdir(d))
    if (is_frame_name(e->d_name)) paths->push_back(dir + "/" + e->d_name);
  closedir(d);
  return true;
}

bool remove_old_frames(const std::vector<std::string>& paths, std::string* err) {
  for (const std::string& path : paths)
    if (unlink(path.c_str()) != 0 && errno != ENOENT) {
      *err = "cannot remove the earlier frame '" + path + "': " + std::strerror(errno);
      return false;
    }
  return true;
}

}  // namespace dexmill
