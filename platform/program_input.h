// The program of `dexmill run`, read by two passes (the scan that plans the
// stock, then the cut) as one and the same input:
// - a regular file is read where it is; before the second pass it must
//   still be the same file with the same size and time of change, else the
//   run stops with an I/O error (a cut that matches neither version would
//   be silently wrong);
// - anything that cannot be read twice (standard input "-", a pipe given by
//   name such as /dev/stdin or a shell's <(...), a FIFO, a device) is copied
//   once into a temporary file, which is removed at the end and on SIGINT,
//   SIGTERM or SIGHUP (platform/process.h).
#ifndef DEXMILL_PLATFORM_PROGRAM_INPUT_H
#define DEXMILL_PLATFORM_PROGRAM_INPUT_H

#include <sys/types.h>

#include <ctime>
#include <string>

namespace dexmill {

class ProgramInput {
 public:
  ProgramInput() = default;
  ProgramInput(const ProgramInput&) = delete;
  ProgramInput& operator=(const ProgramInput&) = delete;
  ~ProgramInput();

  // Takes `path` ("-": standard input). False with a message ("cannot read
  // 'x': ...") on failure: an I/O error.
  bool open(const std::string& path, std::string* err);
  // What the passes open: the file itself or the copy.
  const std::string& read_path() const { return read_path_; }
  // Before a second pass: false with a message when a regular file was
  // replaced or changed since open().
  bool unchanged(std::string* err) const;

 private:
  std::string path_, read_path_, spool_;
  int cleanup_slot_ = -1;
  bool regular_ = false;
  dev_t dev_ = 0;
  ino_t ino_ = 0;
  off_t size_ = 0;
  struct timespec mtime_ {};
};

}  // namespace dexmill

#endif
