#include "platform/atomic_file.h"

#include <cerrno>
#include <cstdarg>
#include <cstring>
#include <unistd.h>

namespace dexmill {

AtomicFile::~AtomicFile() { abandon(); }

void AtomicFile::set_error(const char* what, const char* path) {
  if (!failed_) std::snprintf(error_, sizeof error_, "cannot %s '%s': %s", what, path, std::strerror(errno));
  failed_ = true;
}

void AtomicFile::abandon() {
  if (f_) {
    std::fclose(f_);
    f_ = nullptr;
    std::remove(tmp_);
  }
}

bool AtomicFile::open(const char* path) {
  abandon();
  failed_ = false;
  error_[0] = 0;
  if (std::strlen(path) >= sizeof path_) {
    std::snprintf(error_, sizeof error_, "cannot write '%s': path too long", path);
    failed_ = true;
    return false;
  }
  std::snprintf(path_, sizeof path_, "%s", path);
  std::snprintf(tmp_, sizeof tmp_, "%s.tmp-%ld", path, static_cast<long>(getpid()));
  f_ = std::fopen(tmp_, "wb");
  if (!f_) {
    set_error("write", path_);
    return false;
  }
  return true;
}

void AtomicFile::write(const void* data, std::size_t n) {
  if (!f_ || failed_) return;
  if (n && std::fwrite(data, 1, n, f_) != n) set_error("write", path_);
}

void AtomicFile::printf(const char* fmt, ...) {
  if (!f_ || failed_) return;
  va_list ap;
  va_start(ap, fmt);
  if (std::vfprintf(f_, fmt, ap) < 0) set_error("write", path_);
  va_end(ap);
}

bool AtomicFile::commit() {
  if (!f_) return false;
  if (!failed_ && std::fflush(f_) != 0) set_error("write", path_);
  if (std::fclose(f_) != 0 && !failed_) set_error("write", path_);
  f_ = nullptr;
  if (!failed_ && std::rename(tmp_, path_) != 0) set_error("write", path_);
  if (failed_) std::remove(tmp_);
  return !failed_;
}

}  // namespace dexmill
