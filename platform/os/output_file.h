// Output files, written the way a careful Unix tool writes them:
// - a regular file (or a new name) is written completely or not at all:
//   the data goes to a temporary file beside it (.dexmill-tmp-XXXXXXXX,
//   held under a lock while it exists: platform/os/temp_file.h), renamed over
//   it on commit, keeping the old file's permission bits; the first output
//   a process writes into a folder removes the temporaries there that no
//   live process holds (what a SIGKILL left);
// - a symbolic link is written through: its target is replaced that way,
//   the link stays a link;
// - anything else that exists (a device such as /dev/null, a FIFO, a socket)
//   is opened and written straight through, never replaced by a file;
// - "-" is standard output.
#ifndef DEXMILL_PLATFORM_OS_OUTPUT_FILE_H
#define DEXMILL_PLATFORM_OS_OUTPUT_FILE_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "platform/os/temp_file.h"

namespace dexmill {

class OutputFile {
 public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();  // abandons (removes the temporary) unless committed

  // Opens `path` for writing as above. False on failure (see error()).
  bool open(const char* path);
  // Appends bytes; failures are remembered and reported by commit().
  void write(const void* data, std::size_t n);
  void printf(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
  // Flushes and closes; renames a temporary onto its target, or, while an
  // OutputSet is open, hands it to the set, which renames it with the
  // others (platform/os/output_set.h). False on any failure, in which case a
  // replaced target is untouched and the temporary removed (a device, FIFO
  // or standard output may have had part of it).
  bool commit();
  // Text of the first failure, e.g. "cannot write 'out/x.ppm': No space left on device".
  const char* error() const { return error_; }

 private:
  void set_error(const char* what, const char* path);
  void abandon();
  std::FILE* f_ = nullptr;
  bool stdout_ = false;      // f_ is stdout: flushed, never closed
  std::string path_;         // as given, for messages
  std::string target_;       // what the rename replaces (a link's target); empty: written in place
  LockedTemp tmp_;          // the temporary (path empty: none), locked while it exists
  int mode_ = -1;            // permission bits of the replaced file; -1: a new file
  int cleanup_slot_ = -1;    // the temporary's entry in the signal handler's list
  uint64_t bytes_ = 0;       // written so far
  char error_[1200] = {0};
  bool failed_ = false;
};

// The name a write to `path` lands on, following symbolic links (a
// dangling link's target included). False with errno set on a link loop.
bool output_target(const std::string& path, std::string* target);

// Writes n bytes as the whole of `path` (an OutputFile opened, written and
// committed). On failure returns false with the message in err.
bool write_output(const char* path, const void* data, std::size_t n, char* err, std::size_t errn);

// True when `path` is "-": the output goes to standard output.
inline bool is_stdout_path(const std::string& path) { return path == "-"; }

}  // namespace dexmill

#endif
