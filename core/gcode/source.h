// A program the interpreter can re-read (o-word loops and calls
// jump back by position, as LinuxCNC's interpreter does with ftell/fseek;
// no line is kept in memory). The host's is a file (platform/gcode_source.h),
// a panel's a pointer into flash (MemorySource below).
//
// Lines are read by the driver (`dexmill path`'s runner, interp_run_text);
// the interpreter only asks where the line it is given starts and ends, and
// moves the reading position.
#ifndef DEXMILL_CORE_GCODE_SOURCE_H
#define DEXMILL_CORE_GCODE_SOURCE_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

// A place in the program: the byte offset of a line's first byte in its
// file, its 1-based number, and which file (0: the program; others: the
// subroutine files opened for `o<name> call`).
struct SourcePos {
  uint64_t offset;
  uint32_t line;
  uint16_t file;
};

class GcodeSource {
 public:
  // Where the line last read starts, and where the one after it starts.
  virtual SourcePos line_start() const = 0;
  virtual SourcePos line_next() const = 0;
  // The next line read is the one at `p` (a position line_start or
  // line_next gave). False when the input cannot be re-read there.
  virtual bool seek(const SourcePos& p) = 0;
  // LinuxCNC's search for a subroutine file: `name`.ngc on the subroutine
  // path (name folded to lower case). True with *start at its first line,
  // which becomes the next line read; false when there is none (the
  // default: a panel has no files).
  virtual bool open_subroutine(const char* name, SourcePos* start) {
    (void)name;
    (void)start;
    return false;
  }

 protected:
  ~GcodeSource() = default;
};

// A program held in memory (a panel's flash, a test's string): lines split
// at '\n', a '\r' before it kept for the reader to drop.
class MemorySource final : public GcodeSource {
 public:
  MemorySource(const char* text, size_t len) : s_(text), n_(len) {}
  // The next line; false at the end. An empty last line after a final '\n'
  // is no line.
  bool next(const char** text, size_t* len, uint32_t* line);
  SourcePos line_start() const override { return SourcePos{start_, line_, 0}; }
  SourcePos line_next() const override { return SourcePos{pos_, line_ + 1, 0}; }
  bool seek(const SourcePos& p) override;

 private:
  const char* s_;
  size_t n_;
  size_t pos_ = 0;    // where the next line starts
  size_t start_ = 0;  // where the last line read starts
  uint32_t line_ = 0;  // its number
};

}  // namespace dexmill

#endif
