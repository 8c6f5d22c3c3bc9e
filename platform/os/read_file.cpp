// Whole-file input; see read_file.h.
#include "platform/os/read_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace dexmill {

ReadFile read_whole_file(const std::string& path, std::size_t max_bytes, std::vector<unsigned char>* out,
                         std::string* err) {
  out->clear();
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    *err = "dexmill: error: cannot read '" + path + "': " + std::strerror(errno);
    return ReadFile::kIoError;
  }
  std::vector<unsigned char> buf(65536);  // not on the stack (README, "Limits")
  unsigned char* chunk = buf.data();
  std::size_t n;
  while ((n = std::fread(chunk, 1, buf.size(), f)) > 0) {
    if (out->size() + n > max_bytes) {
      std::fclose(f);
      *err = path + ": error: larger than " + std::to_string(max_bytes >> 20) + " MB";
      return ReadFile::kTooLarge;
    }
    out->insert(out->end(), chunk, chunk + n);
  }
  const int e = std::ferror(f) ? errno : 0;
  std::fclose(f);
  if (e) {
    *err = "dexmill: error: cannot read '" + path + "': " + std::strerror(e);
    return ReadFile::kIoError;
  }
  return ReadFile::kOk;
}

}  // namespace dexmill
