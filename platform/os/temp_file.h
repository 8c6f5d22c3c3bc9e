// Temporary files that prove they are alive: each is held under an
// exclusive advisory lock (flock) for as long as its owner may still use
// it, so that a clean-up can tell debris from a file in use without
// trusting a process id (a run in another PID namespace, a container or
// another host on NFS has ids this process cannot check).
//
// - make_locked_temp() creates DIR/PREFIX + 8 random letters and digits
//   with O_EXCL (short whatever the file it stands for: an output named
//   with 255 bytes still has a temporary that fits), and takes the lock
//   through a second descriptor of the same open file before it returns.
//   The writer may close its own descriptor (and see the close's error)
//   while the lock stays.
// - remove_stale_temps() removes DIR/PREFIX* files whose lock it can take:
//   no live owner holds them. What a SIGKILL, a power cut or `ulimit -f`
//   left. A file being created is safe: its creator checks, once it holds
//   the lock, that its name is still its file, and starts again if not.
#ifndef DEXMILL_PLATFORM_OS_TEMP_FILE_H
#define DEXMILL_PLATFORM_OS_TEMP_FILE_H

#include <sys/types.h>

#include <string>

namespace dexmill {

struct LockedTemp {
  std::string path;
  int fd = -1;       // open for writing (O_WRONLY), the creator's to close
  int lock_fd = -1;  // holds the lock; release_locked_temp() closes it
};

// Creates the temporary (permission bits `mode` before the umask). False
// with errno set on failure (no file is left).
bool make_locked_temp(const std::string& dir, const char* prefix, mode_t mode, LockedTemp* t);

// Closes what is still open of t (the lock last); the file itself stays.
void release_locked_temp(LockedTemp* t);

// Removes the stale DIR/PREFIX* files as above; returns how many. Errors
// (an unreadable folder, a file that cannot be removed) are not reported:
// debris is left as it was.
int remove_stale_temps(const std::string& dir, const char* prefix);

}  // namespace dexmill

#endif
