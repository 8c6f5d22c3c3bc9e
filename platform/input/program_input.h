// The program of `dexmill run`, read by two passes (the scan that plans the
// stock, then the cut) as one and the same input:
// - a regular file is read where it is; before the second pass it must
//   still be the same file with the same size and time of change, else the
//   run stops with an I/O error (a cut that matches neither version would
//   be silently wrong);
// - anything that cannot be read twice (standard input "-", a pipe given by
//   name such as /dev/stdin or a shell's <(...), a FIFO, a device) is copied
//   once into a temporary file, $TMPDIR/dexmill-input-XXXXXXXX, which is
//   removed at the end and on SIGINT, SIGTERM or SIGHUP (platform/os/process.h)
//   and is held under a lock while it is used, so that the next copy's
//   clean-up removes what a killed run left and nothing else
//   (platform/os/temp_file.h). The copy is bounded: it stops where the reading
//   of it would (input that is not text after its first 64 KiB, a line with
//   no end within 1 MiB: core/gcode/line_reader.h), and an input longer than
//   the limit (kDefaultMaxCopyBytes, `--max-input`) is refused.
#ifndef DEXMILL_PLATFORM_INPUT_PROGRAM_INPUT_H
#define DEXMILL_PLATFORM_INPUT_PROGRAM_INPUT_H

#include <sys/types.h>

#include <cstdint>
#include <ctime>
#include <string>

#include "platform/os/temp_file.h"

namespace dexmill {

// The most bytes copied by default (1 GiB, the most `dexmill optimize`
// holds of a program).
constexpr uint64_t kDefaultMaxCopyBytes = uint64_t(1) << 30;

class ProgramInput {
 public:
  ProgramInput() = default;
  ProgramInput(const ProgramInput&) = delete;
  ProgramInput& operator=(const ProgramInput&) = delete;
  ~ProgramInput();

  // The most bytes a copy may hold; before open().
  void set_copy_limit(uint64_t bytes) { limit_ = bytes; }
  // Takes `path` ("-": standard input). False with a message ("cannot read
  // 'x': ...") on failure: an I/O error, or an input error when
  // too_large().
  bool open(const std::string& path, std::string* err);
  // open() failed because the input is longer than the copy limit.
  bool too_large() const { return too_large_; }
  // The bytes there are to read: the file's size, or the copy's.
  uint64_t bytes() const { return bytes_; }
  // What the passes open: the file itself or the copy.
  const std::string& read_path() const { return read_path_; }
  // Before a second pass: false with a message when a regular file was
  // replaced or changed since open().
  bool unchanged(std::string* err) const;

 private:
  bool copy(int in, std::string* err);
  std::string path_, read_path_;
  LockedTemp spool_;
  uint64_t limit_ = kDefaultMaxCopyBytes;
  bool too_large_ = false;
  uint64_t bytes_ = 0;
  int cleanup_slot_ = -1;
  bool regular_ = false;
  dev_t dev_ = 0;
  ino_t ino_ = 0;
  off_t size_ = 0;
  struct timespec mtime_ {};
};

}  // namespace dexmill

#endif
