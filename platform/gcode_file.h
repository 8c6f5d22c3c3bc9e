// The hosted G-code reader: reads a file (or stdin, "-") line by line into a
// fixed buffer, feeds the interpreter (core/motion/interp.h), and reports errors as
// `FILE:LINE:COL: error: MESSAGE` and warnings as `FILE:LINE:COL: warning:
// MESSAGE` (../shared/CLI.md). Memory is fixed: a 64 KiB read buffer and one
// line of kGcodeMaxLine bytes, whatever the length of the file.
//
// What counts as text, decided on the first 64 KiB read (the file's start):
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
// kGcodeMaxSkip bytes (/dev/zero, a stuck pipe), reading stops there: the
// over-long line is the input's last error, not a read that never ends.
//
// Driving it (what `dexmill path`, `check` and `run` do):
//
//   GcodeFile file;
//   if (!file.open(path)) -> exit 3 with file.error()
//   GcodeStderrMessages msgs(file.name());        // or your own GcodeMessages
//   InterpOptions opt; opt.warnings = &msgs;      // opt.tools = your tool table
//   Interp interp(&my_canon_sink, opt);
//   GcodeRunner runner(&file, &interp, &msgs, /*stop_at_first_error=*/true);
//   while (runner.step()) show_progress(file.bytes_read(), file.total_bytes());
//   exit code: runner.io_error() ? 3 : msgs.errors() ? 1 : 0
#ifndef DEXMILL_PLATFORM_GCODE_FILE_H
#define DEXMILL_PLATFORM_GCODE_FILE_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/gcode/block.h"
#include "core/gcode/error.h"
#include "core/motion/interp.h"

namespace dexmill {

class GcodeFile {
 public:
  GcodeFile() = default;
  GcodeFile(const GcodeFile&) = delete;
  GcodeFile& operator=(const GcodeFile&) = delete;
  ~GcodeFile();

  // Opens `path`, or standard input for "-". False on failure (see error()).
  bool open(const char* path);

  enum class Read : uint8_t {
    kLine,     // *text/*len hold the line, without its line end
    kTooLong,  // the line exceeded kGcodeMaxLine bytes; the next call skips its rest
    kEof,
    kIoError,  // see error()
    kNotText,  // the input is not text (see not_text()); nothing is read
    kEndless,  // the rest of an over-long line had no end within kGcodeMaxSkip bytes; reading stopped
  };
  // The next line; *line_no is its 1-based number.
  Read next(const char** text, std::size_t* len, uint32_t* line_no);

  // Progress: bytes consumed so far, and the file size (-1 when unknown,
  // e.g. a pipe).
  uint64_t bytes_read() const { return consumed_; }
  // Where the line next() returned last begins: its first byte's offset
  // in the input (a UTF-8 byte-order mark before line 1 counts). What a
  // rewrite of the program (`dexmill optimize`) splices at.
  uint64_t line_offset() const { return line_start_; }
  int64_t total_bytes() const { return total_; }
  // Name for messages: the path, or "<stdin>".
  const char* name() const { return name_; }
  const char* error() const { return error_; }
  // After Read::kNotText: kNotText (binary data, with the first control byte
  // in word) or kUtf16Text, and the diagnostic's word.
  GcodeError not_text(char word[16]) const;
  // The line ends are CRs (an old Mac file).
  bool cr_line_ends() const { return cr_lines_; }

  // Bytes of an over-long line's rest read in search of its end.
  static constexpr std::size_t kGcodeMaxSkip = std::size_t(1) << 20;

 private:
  bool fill();
  void look_at_start();
  bool more();
  std::size_t find_eol() const;
  void take_eol();

  std::FILE* f_ = nullptr;
  bool owned_ = false;
  char name_[512] = {0};
  char error_[640] = {0};
  char buf_[65536];
  std::size_t pos_ = 0, end_ = 0;
  bool eof_ = false;
  bool started_ = false;     // the first buffer was read and looked at
  bool cr_lines_ = false;    // CR ends lines (see the top of this file)
  bool pending_lf_ = false;  // a CR ended the last line: an LF right after it is part of it
  bool skipping_ = false;    // the last line was over-long: skip its rest first
  bool not_text_done_ = false;
  GcodeError not_text_ = GcodeError::kOk;
  unsigned char not_text_byte_ = 0;
  char line_[kGcodeMaxLine + 1];
  uint32_t line_no_ = 0;
  uint64_t consumed_ = 0;
  uint64_t line_start_ = 0;
  int64_t total_ = -1;
};

// Where diagnostics go; counts them.
class GcodeMessages : public GcodeDiagSink {
 public:
  virtual void error(const GcodeDiag& d) = 0;
  uint32_t errors() const { return errors_; }
  uint32_t warnings() const { return warnings_; }

 protected:
  ~GcodeMessages() = default;
  uint32_t errors_ = 0;
  uint32_t warnings_ = 0;
};

// `FILE:LINE:COL: error: MESSAGE` into buf (NUL-terminated, truncated to n);
// a follow-on error says so after its message.
std::size_t gcode_format_diag(const char* file, const GcodeDiag& d, bool is_error, char* buf, std::size_t n);

// Prints diagnostics to a stdio stream (stderr by default).
class GcodeStderrMessages final : public GcodeMessages {
 public:
  explicit GcodeStderrMessages(const char* file_name, std::FILE* out = stderr) : file_(file_name), out_(out) {}
  void error(const GcodeDiag& d) override;
  void warning(const GcodeDiag& d) override;

 private:
  const char* file_;
  std::FILE* out_;
};

// A program's message comments (issue 21: DEBUG, PRINT, MSG, with their
// parameters substituted), printed as `FILE:LINE: debug|print|message: TEXT`
// on stderr when `print`, and kept for the report.
class GcodeNotes final : public GcodeMessageSink {
 public:
  explicit GcodeNotes(const char* file_name, bool print = true) : file_(file_name), print_(print) {}
  void message(uint32_t line, int kind, const char* text) override;
  struct Note {
    uint32_t line;
    const char* kind;  // "debug", "print", "message"
    std::string text;
  };
  std::vector<Note> kept;

 private:
  const char* file_;
  bool print_;
};

// The parameters of one run of a program (core/gcode/params.h, about
// 57 KB), for InterpOptions::params.
std::unique_ptr<ParamStore> gcode_param_store();

// Feeds a file to an interpreter one line per step().
class GcodeRunner {
 public:
  GcodeRunner(GcodeFile* file, Interp* interp, GcodeMessages* messages, bool stop_at_first_error)
      : file_(file), interp_(interp), messages_(messages), stop_at_first_error_(stop_at_first_error) {}

  // Reads and interprets one line. False when there is nothing more to do:
  // end of file, an I/O error, an input that is not text (one error for it
  // all), an over-long line with no end in reach, or the first error when
  // stopping at it. After the end of the program (M2, M30, closing %) lines
  // are still read, to warn once about code after it.
  bool step();
  // Runs step() until it returns false.
  void run_all() {
    while (step()) {
    }
  }
  bool io_error() const { return io_error_; }
  uint32_t lines() const { return lines_; }
  // Errors not passed to the messages because they may be only consequences
  // of earlier ones (GcodeDiag::follow_on); when not stopping at the first.
  uint32_t follow_ons() const { return follow_ons_; }
  // Passes follow-ons to the messages too (marked in their text).
  void show_follow_ons(bool on) { show_follow_ons_ = on; }

 private:
  GcodeFile* file_;
  Interp* interp_;
  GcodeMessages* messages_;
  bool stop_at_first_error_;
  bool done_ = false;
  bool io_error_ = false;
  uint32_t lines_ = 0;
  uint32_t follow_ons_ = 0;
  bool show_follow_ons_ = false;
};

}  // namespace dexmill

#endif
