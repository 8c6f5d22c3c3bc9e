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
#include "core/gcode/source.h"
#include "core/motion/interp.h"

namespace dexmill {

// Also the program's GcodeSource (core/gcode/source.h): o-word loops and
// calls seek back in it, and `o<name> call` opens NAME.ngc from the
// subroutine path. A pipe (standard input) is copied to an anonymous
// temporary file as it is read, so it can be read again too.
class GcodeFile final : public GcodeSource {
 public:
  GcodeFile() = default;
  GcodeFile(const GcodeFile&) = delete;
  GcodeFile& operator=(const GcodeFile&) = delete;
  ~GcodeFile();

  // Opens `path`, or standard input for "-". False on failure (see error()).
  // `shown` (when not null) is the name messages give it (ProgramInput's
  // copy of standard input is "<stdin>").
  bool open(const char* path, const char* shown = nullptr);

  // GcodeSource: positions of the line next() returned last.
  SourcePos line_start() const override { return SourcePos{line_start_, line_no_, cur_}; }
  SourcePos line_next() const override { return SourcePos{consumed_, line_no_ + 1, cur_}; }
  bool seek(const SourcePos& p) override;
  bool open_subroutine(const char* name, SourcePos* start) override;
  // Directories searched for NAME.ngc (LinuxCNC's SUBROUTINE_PATH), in order.
  void set_subroutine_path(std::vector<std::string> dirs) { sub_path_ = std::move(dirs); }
  // The program's name for messages (name() is the current file's).
  const char* program_name() const { return files_[0].name.c_str(); }
  // The file the last line came from (0: the program).
  uint16_t file_index() const { return cur_; }
  // Subroutine files open at once (each is opened once and kept).
  static constexpr int kSubFilesMax = 16;

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
  bool open_one(const char* path);
  void switch_to(uint16_t file);
  void restart_buffer(uint64_t offset, uint32_t line);

  // What is kept of each file while another is read.
  struct Opened {
    std::FILE* f = nullptr;
    bool owned = false;
    bool started = false;
    bool cr_lines = false;
    uint64_t read_off = 0;
    std::string name;
  };
  Opened files_[kSubFilesMax + 1];
  uint16_t nfiles_ = 1;
  uint16_t cur_ = 0;
  std::vector<std::string> sub_path_;
  // The program read from a pipe: its copy so far (see open()).
  std::FILE* tee_ = nullptr;
  uint64_t teed_ = 0;
  uint64_t read_off_ = 0;  // offset in the current file of the next byte fill() reads

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
  // Diagnostics from now on are of this file (a subroutine file's lines).
  virtual void set_file(const char* name) { (void)name; }
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
  void set_file(const char* name) override { file_ = name; }

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

// The memory of one run of a program (about 68 KB): its parameters
// (core/gcode/params.h) and its o-word control flow
// (core/motion/oword_store.h), for InterpOptions::params and ::control.
struct GcodeMemory {
  ParamStore params;
  OwordStore control;
  void attach(InterpOptions* opt) {
    opt->params = &params;
    opt->control = &control;
  }
};
std::unique_ptr<GcodeMemory> gcode_memory();

// Feeds a file to an interpreter one line per step(); the file is the
// interpreter's source (Interp::set_source), so loops and calls read it again.
class GcodeRunner {
 public:
  GcodeRunner(GcodeFile* file, Interp* interp, GcodeMessages* messages, bool stop_at_first_error)
      : file_(file), interp_(interp), messages_(messages), stop_at_first_error_(stop_at_first_error) {
    interp->set_source(file);
  }

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
  void show_file();

  GcodeFile* file_;
  Interp* interp_;
  GcodeMessages* messages_;
  bool stop_at_first_error_;
  bool done_ = false;
  bool io_error_ = false;
  uint32_t lines_ = 0;
  uint32_t last_line_ = 0;  // the program file's last line number read
  uint16_t shown_file_ = 0;  // the file messages name
  uint32_t follow_ons_ = 0;
  bool show_follow_ons_ = false;
};

}  // namespace dexmill

#endif
