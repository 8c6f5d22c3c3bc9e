#include "platform/output_file.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdarg>
#include <cstdlib>
#include <cstring>

#include "platform/process.h"

namespace dexmill {

namespace {

// Removes "<target>.tmp-PID" files whose process is gone: what a run killed
// by SIGKILL (which no handler sees) left of this output.
void remove_stale_temporaries(const std::string& target) {
  const size_t slash = target.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : target.substr(0, slash));
  const std::string prefix = (slash == std::string::npos ? target : target.substr(slash + 1)) + ".tmp-";
  DIR* d = opendir(dir.c_str());
  if (!d) return;
  while (const dirent* e = readdir(d)) {
    if (std::strncmp(e->d_name, prefix.c_str(), prefix.size()) != 0) continue;
    const char* digits = e->d_name + prefix.size();
    char* end = nullptr;
    const long pid = std::strtol(digits, &end, 10);
    if (end == digits || *end || pid <= 0 || pid == static_cast<long>(getpid())) continue;
    if (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    unlink((dir + "/" + e->d_name).c_str());
  }
  closedir(d);
}

}  // namespace

// Follows symbolic links (as the kernel would, up to its usual limit of
// 40): that name is replaced, the links stay.
bool output_target(const std::string& path, std::string* out) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st;
    if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
      *out = p;
      return true;
    }
    char buf[4096];
    const ssize_t n = readlink(p.c_str(), buf, sizeof buf - 1);
    if (n < 0) return false;
    buf[n] = 0;
    if (buf[0] == '/') {
      p = buf;
    } else {
      const size_t slash = p.rfind('/');
      p = (slash == std::string::npos ? std::string() : p.substr(0, slash + 1)) + buf;
    }
  }
  errno = ELOOP;
  return false;
}

OutputFile::~OutputFile() { abandon(); }

void OutputFile::set_error(const char* what, const char* path) {
  if (!failed_) std::snprintf(error_, sizeof error_, "cannot %s '%s': %s", what, path, std::strerror(errno));
  failed_ = true;
}

void OutputFile::abandon() {
  if (f_ && !stdout_) {
    std::fclose(f_);
    if (!tmp_.empty()) std::remove(tmp_.c_str());
  }
  cleanup_unregister(cleanup_slot_);
  cleanup_slot_ = -1;
  f_ = nullptr;
  stdout_ = false;
}

bool OutputFile::open(const char* path) {
  abandon();
  failed_ = false;
  error_[0] = 0;
  path_ = path;
  target_.clear();
  tmp_.clear();
  mode_ = -1;
  if (is_stdout_path(path_)) {
    f_ = stdout;
    stdout_ = true;
    return true;
  }
  std::string real;
  if (!output_target(path_, &real)) {
    set_error("write", path);
    return false;
  }
  struct stat st;
  const bool exists = stat(real.c_str(), &st) == 0;
  if (exists && !S_ISREG(st.st_mode)) {
    // A device, FIFO or socket is written to, never replaced by a file
    // (run as root, a rename over /dev/null would replace the device).
    f_ = std::fopen(real.c_str(), "wb");
    if (!f_) set_error("write", path);
    return f_ != nullptr;
  }
  target_ = real;
  if (exists) mode_ = static_cast<int>(st.st_mode & 07777);
  remove_stale_temporaries(real);
  tmp_ = real + ".tmp-" + std::to_string(static_cast<long>(getpid()));
  cleanup_slot_ = cleanup_register(tmp_.c_str());
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (!f_) {
    cleanup_unregister(cleanup_slot_);
    cleanup_slot_ = -1;
    tmp_.clear();
    set_error("write", path);
    return false;
  }
  return true;
}

void OutputFile::write(const void* data, std::size_t n) {
  if (!f_ || failed_) return;
  if (n && std::fwrite(data, 1, n, f_) != n) set_error("write", path_.c_str());
}

void OutputFile::printf(const char* fmt, ...) {
  if (!f_ || failed_) return;
  va_list ap;
  va_start(ap, fmt);
  if (std::vfprintf(f_, fmt, ap) < 0) set_error("write", path_.c_str());
  va_end(ap);
}

bool OutputFile::commit() {
  if (!f_) return false;
  if (!failed_ && std::fflush(f_) != 0) set_error("write", path_.c_str());
  if (stdout_) {
    f_ = nullptr;
    stdout_ = false;
    return !failed_;
  }
  if (mode_ >= 0 && !failed_ && fchmod(fileno(f_), static_cast<mode_t>(mode_)) != 0) set_error("write", path_.c_str());
  if (std::fclose(f_) != 0 && !failed_) set_error("write", path_.c_str());
  f_ = nullptr;
  if (tmp_.empty()) return !failed_;  // written in place
  if (!failed_ && std::rename(tmp_.c_str(), target_.c_str()) != 0) set_error("write", path_.c_str());
  if (failed_) std::remove(tmp_.c_str());
  cleanup_unregister(cleanup_slot_);
  cleanup_slot_ = -1;
  tmp_.clear();
  return !failed_;
}

bool write_output(const char* path, const void* data, std::size_t n, char* err, std::size_t errn) {
  OutputFile f;
  if (f.open(path)) {
    f.write(data, n);
    if (f.commit()) return true;
  }
  std::snprintf(err, errn, "%s", f.error());
  return false;
}

}  // namespace dexmill
