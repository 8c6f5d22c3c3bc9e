#include "platform/input/program_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "core/gcode/line_reader.h"
#include "platform/os/process.h"
#include "platform/os/temp_file.h"

namespace dexmill {

namespace {

constexpr const char* kSpoolPrefix = "dexmill-input-";
constexpr std::size_t kChunk = 65536;

std::string describe(const std::string& path) { return path == "-" ? "standard input" : "'" + path + "'"; }

// The copy as the line reader pulls it: each byte read from `in` goes to
// `out` before the reader sees it, so the copy holds every byte a reading
// of it needs to come to the same end (core/gcode/line_reader.h decides
// on bytes alone).
class SpoolSource final : public ByteSource {
 public:
  SpoolSource(int in, int out, uint64_t limit) : in_(in), out_(out), limit_(limit) {}
  Fill read_bytes(char* buf, std::size_t n, std::size_t* got) override {
    *got = 0;
    ssize_t k;
    do k = read(in_, buf, n); while (k < 0 && errno == EINTR);
    if (k < 0) return fail(&read_errno_);
    if (k == 0) return Fill::kEnd;
    copied_ += static_cast<uint64_t>(k);
    if (copied_ > limit_) {
      over_ = true;
      return Fill::kError;
    }
    for (std::size_t done = 0; done < static_cast<std::size_t>(k);) {
      // A short write is not an error: the rest is written again, and a
      // write that fails says why (ENOSPC, EFBIG past `ulimit -f`).
      const ssize_t w = write(out_, buf + done, static_cast<std::size_t>(k) - done);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) return fail(&write_errno_);
      done += static_cast<std::size_t>(w);
    }
    *got = static_cast<std::size_t>(k);
    return Fill::kBytes;
  }
  bool seek_bytes(uint64_t) override { return false; }
  bool over() const { return over_; }
  uint64_t copied() const { return copied_; }
  int read_errno() const { return read_errno_; }
  int write_errno() const { return write_errno_; }

 private:
  Fill fail(int* e) {
    *e = errno ? errno : EIO;
    return Fill::kError;
  }
  int in_, out_;
  uint64_t limit_, copied_ = 0;
  bool over_ = false;
  int read_errno_ = 0, write_errno_ = 0;
};

}  // namespace

ProgramInput::~ProgramInput() {
  if (!spool_.path.empty()) unlink(spool_.path.c_str());
  release_locked_temp(&spool_);  // after the unlink: a clean-up never finds it unlocked
  cleanup_unregister(cleanup_slot_);
}

bool ProgramInput::open(const std::string& path, std::string* err) {
  path_ = read_path_ = path;
  if (path == "-" && standard_input_closed()) {
    *err = "standard input is closed: there is no program to read";
    return false;
  }
  struct stat st;
  if (path != "-") {
    if (stat(path.c_str(), &st) != 0) {
      *err = "cannot open '" + path + "': " + std::strerror(errno);
      return false;
    }
    if (S_ISREG(st.st_mode)) {
      regular_ = true;
      dev_ = st.st_dev;
      ino_ = st.st_ino;
      size_ = st.st_size;
      bytes_ = static_cast<uint64_t>(st.st_size);
      mtime_ = st.st_mtim;
      return true;
    }
    if (S_ISDIR(st.st_mode)) {
      *err = "cannot read '" + path + "': Is a directory";
      return false;
    }
  }
  const int in = path == "-" ? 0 : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) {
    *err = "cannot open '" + path + "': " + std::strerror(errno);
    return false;
  }
  const bool ok = copy(in, err);
  if (in != 0) close(in);
  return ok;
}

bool ProgramInput::copy(int in, std::string* err) {
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string dir = tmpdir && *tmpdir ? tmpdir : "/tmp";
  remove_stale_temps(dir, kSpoolPrefix);  // what killed runs left (platform/os/temp_file.h)
  {
    const StopSignalsHeld held;  // no signal between the spool's creation and its registration
    if (!make_locked_temp(dir, kSpoolPrefix, 0600, &spool_)) {
      *err = "cannot keep " + describe(path_) + " in '" + dir + "/" + kSpoolPrefix + "...': " + std::strerror(errno);
      return false;
    }
    cleanup_slot_ = cleanup_register(spool_.path.c_str());
  }
  read_path_ = spool_.path;
  SpoolSource src(in, spool_.fd, limit_);
  std::unique_ptr<char[]> buf(new char[kChunk]);
  LineReader reader(buf.get(), kChunk);
  reader.set_source(&src);
  const char* text;
  std::size_t len;
  uint32_t line;
  LineReader::Read r;
  do r = reader.next(&text, &len, &line);
  while (r == LineReader::Read::kLine || r == LineReader::Read::kTooLong);
  // Not text, or a line with no end: the reading of the copy stops where
  // this one did, and says why (an input error); what follows is never read.
  bytes_ = src.copied();
  const int close_errno = close(spool_.fd) != 0 ? errno : 0;
  spool_.fd = -1;
  if (src.over()) {
    too_large_ = true;
    *err = describe(path_) + " is larger than " + std::to_string(limit_ >> 20) +
           " MiB, the most dexmill copies of a program it cannot read twice (a pipe, FIFO or device, into $TMPDIR); "
           "--max-input MIB raises it";
    return false;
  }
  if (src.read_errno()) {
    *err = "cannot read " + describe(path_) + ": " + std::strerror(src.read_errno());
    return false;
  }
  const int werr = src.write_errno() ? src.write_errno() : close_errno;
  if (werr) {
    *err = "cannot keep " + describe(path_) + " in '" + spool_.path + "': " + std::strerror(werr);
    return false;
  }
  return true;
}

bool ProgramInput::unchanged(std::string* err) const {
  if (!regular_) return true;
  struct stat st;
  if (stat(path_.c_str(), &st) != 0 || st.st_dev != dev_ || st.st_ino != ino_ || st.st_size != size_ ||
      st.st_mtim.tv_sec != mtime_.tv_sec || st.st_mtim.tv_nsec != mtime_.tv_nsec) {
    *err = "'" + path_ + "' changed while dexmill read it (between planning the stock and cutting); run again";
    return false;
  }
  return true;
}

}  // namespace dexmill
