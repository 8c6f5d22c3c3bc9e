// The hosted G-code reader: reads a file (or stdin, "-") line by line
// (core/gcode/line_reader.h says what counts as text, how lines end and
// what happens to over-long lines), for the runner (core/sim/gcode_runner.h)
// to feed the interpreter (core/interp/interp.h); errors print as
// `FILE:LINE:COL: error: MESSAGE` and warnings as `FILE:LINE:COL: warning:
// MESSAGE`. Memory is fixed: a 64 KiB read buffer and one line of
// kGcodeMaxLine bytes, whatever the length of the file.
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
#ifndef DEXMILL_PLATFORM_INPUT_GCODE_FILE_H
#define DEXMILL_PLATFORM_INPUT_GCODE_FILE_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/gcode/block.h"
#include "core/gcode/error.h"
#include "core/gcode/line_reader.h"
#include "core/gcode/messages.h"
#include "core/gcode/source.h"
#include "core/interp/interp.h"
#include "core/sim/gcode_runner.h"
#include "platform/input/warning_fold.h"

namespace dexmill {

class FileGuard;

// The program's LineInput (core/gcode/line_reader.h), so also its
// GcodeSource: o-word loops and calls seek back in it, and `o<name> call`
// opens NAME.ngc from the subroutine path. A pipe (standard input) is copied
// to an anonymous temporary file as it is read, so it can be read again too;
// the copy keeps at most kDefaultMaxCopyBytes (the spool's limit,
// platform/input/program_input.h), past which it is dropped and a seek back fails
// with an error (the disk is never filled by a program read once).
class GcodeFile final : public LineInput, private ByteSource {
 public:
  GcodeFile();
  GcodeFile(const GcodeFile&) = delete;
  GcodeFile& operator=(const GcodeFile&) = delete;
  ~GcodeFile();

  // Opens `path`, or standard input for "-". False on failure (see error()).
  // `shown` (when not null) is the name messages give it (ProgramInput's
  // copy of standard input is "<stdin>").
  bool open(const char* path, const char* shown = nullptr);

  // GcodeSource: positions of the line next() returned last.
  SourcePos line_start() const override { return SourcePos{reader_.line_offset(), reader_.line_number(), cur_}; }
  SourcePos line_next() const override { return SourcePos{reader_.next_offset(), reader_.line_number() + 1, cur_}; }
  bool seek(const SourcePos& p) override;
  bool open_subroutine(const char* name, SourcePos* start) override;
  // The most of a pipe's copy kept (kDefaultMaxCopyBytes unless set).
  void set_pipe_copy_limit(uint64_t bytes) { tee_limit_ = bytes; }
  // Directories searched for NAME.ngc (LinuxCNC's SUBROUTINE_PATH), in order.
  void set_subroutine_path(std::vector<std::string> dirs) { sub_path_ = std::move(dirs); }
  // The command's guard (platform/input/file_guard.h): each subroutine file is
  // registered as an input when a call opens it. One that is an output
  // stops the reading there (an I/O error of the runner, with refused()
  // true and the guard's message in error(): a usage error).
  void set_guard(FileGuard* guard) { guard_ = guard; }
  bool refused() const { return refused_; }
  // The program's name for messages (name() is the current file's).
  const char* program_name() const override { return files_[0].name.c_str(); }
  // The file the last line came from (0: the program).
  uint16_t file_index() const override { return cur_; }
  // Subroutine files open at once (each is opened once and kept).
  static constexpr int kSubFilesMax = 16;

  using Read = LineReader::Read;  // a file never answers kWait
  // The next line; *line_no is its 1-based number.
  Read next(const char** text, std::size_t* len, uint32_t* line_no) override {
    return reader_.next(text, len, line_no);
  }

  // Progress: bytes consumed so far, and the file size (-1 when unknown,
  // e.g. a pipe).
  uint64_t bytes_read() const { return reader_.bytes_read(); }
  // Where the line next() returned last begins: its first byte's offset
  // in the input (a UTF-8 byte-order mark before line 1 counts). What a
  // rewrite of the program (`dexmill optimize`) splices at.
  uint64_t line_offset() const { return reader_.line_offset(); }
  int64_t total_bytes() const { return total_; }
  // Name for messages: the path, or "<stdin>".
  const char* name() const override { return name_; }
  const char* error() const { return error_; }
  // After Read::kNotText (LineReader::not_text).
  GcodeError not_text(char word[16]) const override { return reader_.not_text(word); }
  // The line ends are CRs (an old Mac file).
  bool cr_line_ends() const { return reader_.cr_line_ends(); }

  // Bytes of an over-long line's rest read in search of its end.
  static constexpr std::size_t kGcodeMaxSkip = LineReader::kMaxSkip;

 private:
  // ByteSource: the current file, or the copy of a pipe read again.
  Fill read_bytes(char* buf, std::size_t n, std::size_t* got) override;
  bool seek_bytes(uint64_t offset) override;
  bool open_one(const char* path);
  void switch_to(uint16_t file);

  // What is kept of each file while another is read.
  struct Opened {
    std::FILE* f = nullptr;
    bool owned = false;
    LineReader::FileState state;
    uint64_t read_off = 0;
    std::string name;
  };
  Opened files_[kSubFilesMax + 1];
  uint16_t nfiles_ = 1;
  uint16_t cur_ = 0;
  std::vector<std::string> sub_path_;
  FileGuard* guard_ = nullptr;
  bool refused_ = false;
  // The program read from a pipe: its copy so far (see open()).
  std::FILE* tee_ = nullptr;
  uint64_t teed_ = 0;
  uint64_t tee_limit_;  // set in the constructor (gcode_file.cpp): the spool's limit
  uint64_t read_off_ = 0;  // offset in the current file of the next byte read() reads

  std::FILE* f_ = nullptr;
  bool owned_ = false;
  char name_[512] = {0};
  char error_[640] = {0};
  // The read buffer on the heap: a GcodeFile is often a local, and the
  // stack the host binary needs is stated small (README, "Limits").
  static constexpr std::size_t kBufBytes = 65536;
  std::unique_ptr<char[]> buf_{new char[kBufBytes]};
  LineReader reader_{buf_.get(), kBufBytes};
  int64_t total_ = -1;
};

// `FILE:LINE:COL: error: MESSAGE` into buf (NUL-terminated, truncated to n);
// a follow-on error says so after its message.
std::size_t gcode_format_diag(const char* file, const GcodeDiag& d, bool is_error, char* buf, std::size_t n);

// The text of a diagnostic after `FILE:LINE:COL: error: ` or `warning: `
// (a follow-on one says so), as gcode_format_diag prints it.
std::string gcode_diag_message(const GcodeDiag& d);

// Prints diagnostics to a stdio stream (stderr by default): errors as they
// come, warnings folded (platform/input/warning_fold.h: a repeated one once, with
// its count and last line) until an error or finish().
class GcodeStderrMessages final : public GcodeMessages {
 public:
  explicit GcodeStderrMessages(const char* file_name, std::FILE* out = stderr)
      : file_(file_name), out_(out), fold_(out) {}
  void error(const GcodeDiag& d) override;
  void warning(const GcodeDiag& d) override;
  void set_file(const char* name) override { file_ = name; }
  // Prints the warnings held: before what the caller prints at the end.
  void finish() { fold_.flush(); }

 private:
  const char* file_;
  std::FILE* out_;
  WarningFold fold_;
};

// A program's message comments (DEBUG, PRINT, MSG, with their
// parameters substituted), printed as `FILE:LINE: debug|print|message: TEXT`
// on stderr when `print`, and kept for the report.
class GcodeNotes final : public GcodeMessageSink {
 public:
  explicit GcodeNotes(const char* file_name, bool print = true) : file_(file_name), print_(print) {}
  void message(uint32_t line, int kind, const char* text) override;
  // Prints the notes kept (made with print false: printed once known to be right).
  void print_kept() const;
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
// (core/interp/oword_store.h), for InterpOptions::params and ::control.
struct GcodeMemory {
  ParamStore params;
  OwordStore control;
  void attach(InterpOptions* opt) {
    opt->params = &params;
    opt->control = &control;
  }
};
std::unique_ptr<GcodeMemory> gcode_memory();

}  // namespace dexmill

#endif
