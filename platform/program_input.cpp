#include "platform/program_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "platform/process.h"

namespace dexmill {

namespace {

std::string describe(const std::string& path) { return path == "-" ? "standard input" : "'" + path + "'"; }

}  // namespace

ProgramInput::~ProgramInput() {
  if (!spool_.empty()) unlink(spool_.c_str());
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
      mtime_ = st.st_mtim;
      return true;
    }
    if (S_ISDIR(st.st_mode)) {
      *err = "cannot read '" + path + "': Is a directory";
      return false;
    }
  }
  // One read into a temporary file.
  const int in = path == "-" ? 0 : ::open(path.c_str(), O_RDONLY);
  if (in < 0) {
    *err = "cannot open '" + path + "': " + std::strerror(errno);
    return false;
  }
  const char* tmpdir = std::getenv("TMPDIR");
  std::string templ = std::string(tmpdir && *tmpdir ? tmpdir : "/tmp") + "/dexmill-input-XXXXXX";
  std::vector<char> name(templ.begin(), templ.end());
  name.push_back(0);
  const int out = mkstemp(name.data());
  if (out < 0) {
    *err = "cannot keep " + describe(path) + " in '" + templ + "': " + std::strerror(errno);
    if (in != 0) close(in);
    return false;
  }
  spool_ = read_path_ = name.data();
  cleanup_slot_ = cleanup_register(spool_.c_str());
  bool ok = true;
  char chunk[65536];
  for (;;) {
    const ssize_t n = read(in, chunk, sizeof chunk);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      *err = "cannot read " + describe(path) + ": " + std::strerror(errno);
      ok = false;
      break;
    }
    if (write(out, chunk, static_cast<size_t>(n)) != n) {
      *err = "cannot keep " + describe(path) + " in '" + spool_ + "': " + std::strerror(errno);
      ok = false;
      break;
    }
  }
  close(out);
  if (in != 0) close(in);
  return ok;
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
