// Locked temporaries; see temp_file.h.
#include "platform/os/temp_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <ctime>

namespace dexmill {

namespace {

constexpr int kNameLetters = 8;

// Eight letters and digits, different on every call (a collision only
// costs a retry: the file is made with O_EXCL).
std::string random_letters() {
  static uint64_t counter = 0;
  struct timespec ts;
  clock_gettime(CLOCK_REALTIME, &ts);
  uint64_t x = static_cast<uint64_t>(ts.tv_nsec) ^ (static_cast<uint64_t>(ts.tv_sec) << 30) ^
               (static_cast<uint64_t>(getpid()) << 17) ^ (++counter * 0x9E3779B97F4A7C15ULL);
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  std::string s;
  for (int k = 0; k < kNameLetters; ++k) {
    x ^= x >> 33;  // splitmix64's finaliser
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    s += kAlphabet[x % (sizeof kAlphabet - 1)];
  }
  return s;
}

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

void close_keep_errno(int fd) {
  const int e = errno;
  if (fd >= 0) close(fd);
  errno = e;
}

// The name still denotes the file fd has open (a clean-up may have taken
// the file between its making and its lock).
bool still_named(int fd, const std::string& path) {
  struct stat mine, named;
  return fstat(fd, &mine) == 0 && stat(path.c_str(), &named) == 0 && same_file(mine, named);
}

}  // namespace

bool make_locked_temp(const std::string& dir, const char* prefix, mode_t mode, LockedTemp* t) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string path = dir + "/" + prefix + random_letters();
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      return false;
    }
    // The lock is on the file's open description, through a descriptor of
    // its own: closing the writer's (and seeing that close's error) leaves
    // it held.
    const int lock_fd = fcntl(fd, F_DUPFD_CLOEXEC, 0);
    if (lock_fd < 0) {
      close_keep_errno(fd);
      const int e = errno;
      unlink(path.c_str());
      errno = e;
      return false;
    }
    // Blocking: a clean-up holds a lock only to remove the file. A file
    // system without flock (some FUSE ones) fails it: the file is then
    // written unlocked, and no clean-up can lock it to remove it either.
    (void)flock(lock_fd, LOCK_EX);
    if (!still_named(lock_fd, path)) {  // a clean-up took it first: another name
      close(lock_fd);
      close(fd);
      continue;
    }
    t->path = path;
    t->fd = fd;
    t->lock_fd = lock_fd;
    return true;
  }
  errno = EEXIST;
  return false;
}

void release_locked_temp(LockedTemp* t) {
  if (t->fd >= 0) close(t->fd);
  if (t->lock_fd >= 0) close(t->lock_fd);
  t->fd = t->lock_fd = -1;
}

int remove_stale_temps(const std::string& dir, const char* prefix) {
  DIR* d = opendir(dir.c_str());
  if (!d) return 0;
  const size_t plen = std::strlen(prefix);
  int removed = 0;
  while (const dirent* e = readdir(d)) {
    if (std::strncmp(e->d_name, prefix, plen) != 0 || std::strlen(e->d_name) != plen + kNameLetters) continue;
    const std::string path = dir + "/" + e->d_name;
    // O_NONBLOCK: a FIFO of that name must not hang the run; O_NOFOLLOW: a
    // link is not ours.
    const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat held, named;
    if (fstat(fd, &held) == 0 && S_ISREG(held.st_mode) && flock(fd, LOCK_EX | LOCK_NB) == 0 &&
        stat(path.c_str(), &named) == 0 && same_file(held, named) && unlink(path.c_str()) == 0)
      ++removed;
    close(fd);
  }
  closedir(d);
  return removed;
}

}  // namespace dexmill
