// Program text into lines, the one way every input is split (a file on the
// host, platform/input/gcode_file.h; chunks an embedder feeds, core/sim/chunk_input.h):
//
// What counts as text, decided on the input's first bytes (the first
// buffer: up to kStartBytes, fewer only when the buffer is smaller or the
// input ends sooner):
//   - a UTF-8 byte-order mark (EF BB BF, which Windows editors write) is
//     skipped;
//   - a UTF-16 byte-order mark, or control bytes making up 1/32 or more of
//     those bytes, make the input "not a text file": one error, nothing read
//     (an image or an executable would give an error per line otherwise). A
//     few stray control bytes are typos, reported on their lines. NUL does
//     not count (tape leaders and padding are NUL runs; /dev/zero is one
//     endless line), nor do white space and SUB (0x1A, DOS's end-of-file);
//   - a line ends at LF (a CR before it belongs to CRLF). A start with no
//     LF but some CR is an old Mac file: then CR, LF and CRLF each end a line.
//     Elsewhere a CR is white space, as in LinuxCNC.
// A line longer than kGcodeMaxLine is reported as soon as it is; its rest is
// skipped up to its line end. When that end does not come within the next
// kMaxSkip bytes (/dev/zero, a stuck pipe), reading stops there: the
// over-long line is the input's last error, not a read that never ends.
//
// The reader pulls bytes from a ByteSource into a buffer of caller memory.
// A source that has no bytes yet but has not ended (text still being fed)
// makes next() return kWait with everything read so far kept; the next call
// goes on where it stopped, so lines come out the same however the bytes
// were cut into pieces.
#ifndef DEXMILL_CORE_GCODE_LINE_READER_H
#define DEXMILL_CORE_GCODE_LINE_READER_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/block.h"
#include "core/gcode/error.h"
#include "core/gcode/source.h"

namespace dexmill {

class ByteSource {
 public:
  enum class Fill : uint8_t {
    kBytes,  // *got > 0 bytes were read
    kWait,   // none now; more may come (a chunked input not yet closed)
    kEnd,    // the input ended
    kError,  // it cannot be read (the source keeps the reason)
  };
  // Up to n bytes at the reading position into buf.
  virtual Fill read_bytes(char* buf, size_t n, size_t* got) = 0;
  // The next read starts at byte `offset` of the input; false: it cannot.
  virtual bool seek_bytes(uint64_t offset) = 0;

 protected:
  ~ByteSource() = default;
};

class LineReader {
 public:
  enum class Read : uint8_t {
    kLine,     // *text/*len hold the line, without its line end
    kTooLong,  // the line exceeded kGcodeMaxLine bytes; the next call skips its rest
    kEof,
    kIoError,  // the source's read failed
    kNotText,  // the input is not text (see not_text()); nothing is read
    kEndless,  // the rest of an over-long line had no end within kMaxSkip bytes; reading stopped
    kWait,     // the source has no bytes yet: call again when it has
  };
  // The sample the text decision is made on, at most.
  static constexpr size_t kStartBytes = 65536;
  // Bytes of an over-long line's rest read in search of its end.
  static constexpr size_t kMaxSkip = size_t(1) << 20;

  // buf: caller memory of `bytes` (at least 1) that holds what is read.
  LineReader(char* buf, size_t bytes) : buf_(buf), cap_(bytes) {}
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  void set_source(ByteSource* s) { src_ = s; }
  // The next line; *line_no is its 1-based number.
  Read next(const char** text, size_t* len, uint32_t* line_no);

  // Where the line next() returned last begins, where the one after it
  // begins (byte offsets in the input; a UTF-8 byte-order mark before line 1
  // counts), and its number.
  uint64_t line_offset() const { return line_start_; }
  uint64_t next_offset() const { return consumed_; }
  uint32_t line_number() const { return line_no_; }
  // Bytes consumed so far.
  uint64_t bytes_read() const { return consumed_; }
  // Reads on at `offset`, the start of line `line`, when those bytes are
  // still in the buffer (a loop's head usually is): true. False otherwise,
  // and nothing changed.
  bool seek_in_buffer(uint64_t offset, uint32_t line);
  // Reads on at `offset`, the start of line `line`, where the source was
  // just moved (ByteSource::seek_bytes): the buffer starts empty.
  void restart(uint64_t offset, uint32_t line);

  // After Read::kNotText: kNotText (binary data, with the first control byte
  // in word) or kUtf16Text, and the diagnostic's word.
  GcodeError not_text(char word[16]) const;
  // The line ends are CRs (an old Mac file).
  bool cr_line_ends() const { return cr_lines_; }

  // What is decided at a file's start, kept while another file is read
  // (subroutine files share one reader): restore it with restart().
  struct FileState {
    bool started = false;
    bool cr_lines = false;
  };
  FileState file_state() const { return FileState{started_, cr_lines_}; }
  void set_file_state(const FileState& s) {
    started_ = s.started;
    cr_lines_ = s.cr_lines;
  }

 private:
  enum class Avail : uint8_t { kYes, kNo, kWait };
  Avail fill();
  Avail start();
  Avail more();
  size_t find_eol() const;
  void take_eol();
  void reset_line();

  char* buf_;
  size_t cap_;
  ByteSource* src_ = nullptr;
  size_t pos_ = 0, end_ = 0;   // buf_[pos_, end_) is still to read; buf_[0] is at offset consumed_ - pos_
  bool eof_ = false;           // the source ended (or failed: err_)
  bool err_ = false;
  bool started_ = false;       // the first bytes were looked at
  bool cr_lines_ = false;      // CR ends lines (see the top of this file)
  bool pending_lf_ = false;    // a CR ended the last line: an LF right after it is part of it
  bool skipping_ = false;      // the last line was over-long: skip its rest first
  size_t skipped_ = 0;         // of that rest, so far
  bool finishing_ = false;     // a line is read, its CRLF's LF still to look for
  bool any_ = false;           // the line being read has begun
  size_t n_ = 0;               // its bytes in line_ so far
  bool not_text_done_ = false;
  GcodeError not_text_ = GcodeError::kOk;
  unsigned char not_text_byte_ = 0;
  char line_[kGcodeMaxLine + 1];
  uint32_t line_no_ = 0;
  uint64_t consumed_ = 0;
  uint64_t line_start_ = 0;
};

// What a runner reads lines from (core/sim/gcode_runner.h): the program,
// and the subroutine files it may open, as one source the interpreter can
// seek in.
class LineInput : public GcodeSource {
 public:
  virtual LineReader::Read next(const char** text, size_t* len, uint32_t* line_no) = 0;
  // The file the last line came from (0: the program) and its name for
  // messages; the program's name.
  virtual uint16_t file_index() const { return 0; }
  virtual const char* name() const = 0;
  virtual const char* program_name() const { return name(); }
  // After Read::kNotText (LineReader::not_text).
  virtual GcodeError not_text(char word[16]) const = 0;

 protected:
  ~LineInput() = default;
};

}  // namespace dexmill

#endif
