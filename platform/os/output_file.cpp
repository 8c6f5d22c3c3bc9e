#include "platform/os/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <set>
#include <utility>

#include "platform/os/output_set.h"
#include "platform/os/path_name.h"
#include "platform/os/process.h"
#include "platform/os/temp_file.h"

namespace dexmill {

namespace {

// Temporaries are DIR/.dexmill-tmp-XXXXXXXX (platform/os/temp_file.h): 21
// bytes, whatever the length of the output's own name.
constexpr const char* kTempPrefix = ".dexmill-tmp-";

// What runs killed outright (SIGKILL, which no handler sees) left in the
// folder an output goes to: removed once per folder and process, when the
// first output goes there (a folder of 40 000 frames is read once, not
// once a frame), so before this process has a temporary of its own there:
// on NFS, where flock is emulated by POSIX locks, which never conflict
// within a process, it could not tell its own from a dead run's. The
// folder is known by device and inode ("out" and "./out" are one).
void remove_stale_temporaries(const std::string& dir) {
  static std::set<std::pair<dev_t, ino_t>> done;
  struct stat st;
  if (stat(dir.c_str(), &st) == 0 && done.insert({st.st_dev, st.st_ino}).second) remove_stale_temps(dir, kTempPrefix);
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
  if (failed_) return;  // the first failure is the cause
  if (is_stdout_path(path)) {
    std::snprintf(error_, sizeof error_, "cannot %s standard output: %s", what, std::strerror(errno));
  } else {
    std::snprintf(error_, sizeof error_, "cannot %s '%s': %s", what, path, std::strerror(errno));
  }
  failed_ = true;
}

void OutputFile::abandon() {
  if (f_ && !stdout_) std::fclose(f_);
  if (!tmp_.path.empty()) unlink(tmp_.path.c_str());
  release_locked_temp(&tmp_);
  tmp_.path.clear();
  cleanup_unregister(cleanup_slot_);
  cleanup_slot_ = -1;
  f_ = nullptr;
  stdout_ = false;
}

bool OutputFile::open(const char* path) {
  abandon();
  failed_ = false;
  bytes_ = 0;
  error_[0] = 0;
  path_ = path;
  target_.clear();
  mode_ = -1;
  if (is_stdout_path(path_)) {
    if (standard_output_closed()) {
      std::snprintf(error_, sizeof error_, "cannot write standard output: it is closed");
      failed_ = true;
      return false;
    }
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
  const std::string dir = folder_of(real);
  remove_stale_temporaries(dir);
  {
    const StopSignalsHeld held;  // no signal between the temporary's creation and its registration
    if (!make_locked_temp(dir, kTempPrefix, 0666, &tmp_)) {
      set_error("write", path);
      return false;
    }
    cleanup_slot_ = cleanup_register(tmp_.path.c_str());
  }
  f_ = fdopen(tmp_.fd, "wb");
  if (!f_) {
    set_error("write", path);
    abandon();
    return false;
  }
  tmp_.fd = -1;  // f_ has it now
  return true;
}

void OutputFile::write(const void* data, std::size_t n) {
  if (!f_ || failed_) return;
  if (n && std::fwrite(data, 1, n, f_) != n) set_error("write", path_.c_str());
  bytes_ += n;
}

void OutputFile::printf(const char* fmt, ...) {
  if (!f_ || failed_) return;
  va_list ap;
  va_start(ap, fmt);
  const int n = std::vfprintf(f_, fmt, ap);
  if (n < 0) set_error("write", path_.c_str());
  else bytes_ += static_cast<uint64_t>(n);
  va_end(ap);
}

bool OutputFile::commit() {
  if (!f_) return false;
  if (!failed_ && (std::fflush(f_) != 0 || std::ferror(f_))) set_error("write", path_.c_str());
  OutputSet* set = OutputSet::current();
  if (stdout_) {
    f_ = nullptr;
    stdout_ = false;
    if (set && !failed_) set->written(path_, bytes_);
    return !failed_;
  }
  if (mode_ >= 0 && !failed_ && fchmod(fileno(f_), static_cast<mode_t>(mode_)) != 0) set_error("write", path_.c_str());
  if (std::fclose(f_) != 0 && !failed_) set_error("write", path_.c_str());
  f_ = nullptr;
  if (tmp_.path.empty()) {  // written in place
    if (set && !failed_) set->written(path_, bytes_);
    return !failed_;
  }
  if (set && !failed_) {  // complete: the set renames it (platform/os/output_set.h)
    set->adopt(path_, bytes_, target_, &tmp_, cleanup_slot_);
    cleanup_slot_ = -1;
    return true;
  }
  const StopSignalsHeld held;  // renamed and unregistered together
  if (!failed_ && std::rename(tmp_.path.c_str(), target_.c_str()) != 0) set_error("write", path_.c_str());
  if (failed_) unlink(tmp_.path.c_str());
  release_locked_temp(&tmp_);  // the lock, after the rename: the file is never unlocked under its temporary name
  tmp_.path.clear();
  cleanup_unregister(cleanup_slot_);
  cleanup_slot_ = -1;
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
