// The hosted G-code reader; see gcode_file.h.
#include "platform/gcode_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "core/gcode/lex.h"
#include "platform/process.h"

namespace dexmill {

GcodeFile::~GcodeFile() {
  if (tee_) std::fclose(tee_);
  files_[cur_].f = f_;
  files_[cur_].owned = owned_;
  for (uint16_t k = 0; k < nfiles_; ++k)
    if (files_[k].f && files_[k].owned) std::fclose(files_[k].f);
}

bool GcodeFile::open(const char* path, const char* shown) {
  if (!open_one(path)) return false;
  if (shown) std::snprintf(name_, sizeof name_, "%s", shown);
  files_[0].name = name_;
  return true;
}

bool GcodeFile::open_one(const char* path) {
  if (!std::strcmp(path, "-")) {
    if (standard_input_closed()) {
      std::snprintf(error_, sizeof error_, "standard input is closed: there is no program to read");
      return false;
    }
    f_ = stdin;
    owned_ = false;
    std::snprintf(name_, sizeof name_, "<stdin>");
  } else {
    f_ = std::fopen(path, "rb");
    if (!f_) {
      std::snprintf(error_, sizeof error_, "cannot open '%s': %s", path, std::strerror(errno));
      return false;
    }
    owned_ = true;
    std::snprintf(name_, sizeof name_, "%s", path);
  }
  struct stat st;
  if (fstat(fileno(f_), &st) == 0) {
    if (S_ISREG(st.st_mode)) total_ = static_cast<int64_t>(st.st_size);
    // A pipe or a device cannot seek: what is read is copied (an anonymous
    // temporary file) as it is read, so a loop can go back. Memory stays
    // flat; the copy grows only as far as the program is read.
    else tee_ = std::tmpfile();
    if (S_ISDIR(st.st_mode)) {
      std::snprintf(error_, sizeof error_, "cannot read '%s': Is a directory", path);
      return false;
    }
  }
  return true;
}

bool GcodeFile::fill() {
  if (eof_) return false;
  if (cur_ == 0 && tee_ && read_off_ < teed_) {
    // Read again after a seek back: from the copy.
    const uint64_t want = teed_ - read_off_ < sizeof buf_ ? teed_ - read_off_ : sizeof buf_;
    end_ = std::fseek(tee_, static_cast<long>(read_off_), SEEK_SET) == 0
               ? std::fread(buf_, 1, static_cast<std::size_t>(want), tee_)
               : 0;
    if (end_ == 0) std::snprintf(error_, sizeof error_, "cannot read back '%s': %s", name_, std::strerror(errno));
  } else {
    end_ = std::fread(buf_, 1, sizeof buf_, f_);
    if (cur_ == 0 && tee_ && end_) {
      // Keep what a pipe gave, for loops and calls to read again.
      if (std::fseek(tee_, 0, SEEK_END) != 0 || std::fwrite(buf_, 1, end_, tee_) != end_) {
        std::fclose(tee_);
        tee_ = nullptr;  // a later seek back fails with an error naming the line
      } else {
        teed_ += end_;
      }
    }
  }
  read_off_ += end_;
  pos_ = 0;
  if (end_ == 0) {
    eof_ = true;
    if (std::ferror(f_)) std::snprintf(error_, sizeof error_, "cannot read '%s': %s", name_, std::strerror(errno));
    return false;
  }
  return true;
}

namespace {

// A byte that text never holds; see the top of gcode_file.h for the ones
// left out (NUL, white space, SUB).
bool is_binary_byte(unsigned char c) {
  return (c < 0x20 && c != 0 && c != '\t' && c != '\n' && c != '\v' && c != '\f' && c != '\r' && c != 0x1a) ||
         c == 0x7f;
}

}  // namespace

// Decides, on the first buffer, what the input is (gcode_file.h).
void GcodeFile::look_at_start() {
  started_ = true;
  if (!fill()) return;
  const unsigned char* b = reinterpret_cast<const unsigned char*>(buf_);
  if (end_ >= 2 && ((b[0] == 0xff && b[1] == 0xfe) || (b[0] == 0xfe && b[1] == 0xff))) {
    not_text_ = GcodeError::kUtf16Text;
    return;
  }
  std::size_t binary = 0;
  for (std::size_t i = 0; i < end_; ++i) {
    if (!is_binary_byte(b[i])) continue;
    if (binary++ == 0) not_text_byte_ = b[i];
  }
  if (binary && binary * 32 >= end_) {
    not_text_ = GcodeError::kNotText;
    return;
  }
  if (end_ >= 3 && b[0] == 0xef && b[1] == 0xbb && b[2] == 0xbf) {
    pos_ = 3;
    consumed_ = 3;
  }
  cr_lines_ = !std::memchr(buf_, '\n', end_) && std::memchr(buf_, '\r', end_);
}

GcodeError GcodeFile::not_text(char word[16]) const {
  word[0] = 0;
  if (not_text_ == GcodeError::kNotText) {
    GcodeDiag d{};
    const char c = static_cast<char>(not_text_byte_);
    gcode_set_word(&d, &c, 1);
    std::memcpy(word, d.word, sizeof d.word);
  }
  return not_text_;
}

// True when buf_[pos_] is a byte to read (the LF of a CRLF whose CR ended
// the last line is skipped here, even across a refill).
bool GcodeFile::more() {
  for (;;) {
    if (pos_ >= end_ && !fill()) return false;
    if (!pending_lf_) return true;
    pending_lf_ = false;
    if (buf_[pos_] == '\n') {
      ++pos_;
      ++consumed_;
    }
  }
}

// Index of the first line end in buf_[pos_, end_), or end_.
std::size_t GcodeFile::find_eol() const {
  if (!cr_lines_) {
    const void* nl = std::memchr(buf_ + pos_, '\n', end_ - pos_);
    return nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - buf_) : end_;
  }
  for (std::size_t i = pos_; i < end_; ++i)
    if (buf_[i] == '\n' || buf_[i] == '\r') return i;
  return end_;
}

// Consumes the line end at pos_.
void GcodeFile::take_eol() {
  pending_lf_ = buf_[pos_] == '\r';
  ++pos_;
  ++consumed_;
}

GcodeFile::Read GcodeFile::next(const char** text, std::size_t* len, uint32_t* line_no) {
  if (!started_) look_at_start();
  if (not_text_ != GcodeError::kOk) {
    if (not_text_done_) return Read::kEof;
    not_text_done_ = true;
    return Read::kNotText;
  }
  if (skipping_) {
    // The rest of an over-long line, already reported.
    skipping_ = false;
    for (std::size_t skipped = 0;;) {
      if (!more()) return error_[0] ? Read::kIoError : Read::kEof;
      const std::size_t e = find_eol();
      skipped += e - pos_;
      consumed_ += e - pos_;
      pos_ = e;
      if (e < end_) {
        take_eol();
        break;
      }
      if (skipped > kGcodeMaxSkip) return Read::kEndless;
    }
  }
  std::size_t n = 0;
  bool any = false;
  for (;;) {
    if (!more()) {
      if (error_[0]) return Read::kIoError;
      if (!any) return Read::kEof;
      break;  // a last line with no line end
    }
    if (!any) line_start_ = consumed_;
    any = true;
    const std::size_t e = find_eol();
    const std::size_t chunk = e - pos_;
    if (n + chunk > kGcodeMaxLine + 1) {
      // Longer than any line, even with the CR of a CRLF: say so now, and
      // skip the rest on the next call (which may never find a line end).
      pos_ = e;
      consumed_ += chunk;
      if (e < end_) take_eol();
      else skipping_ = true;
      *line_no = ++line_no_;
      return Read::kTooLong;
    }
    std::memcpy(line_ + n, buf_ + pos_, chunk);
    n += chunk;
    pos_ = e;
    consumed_ += chunk;
    if (e < end_) {
      take_eol();
      break;
    }
  }
  *line_no = ++line_no_;
  // The LF of a CRLF whose CR ended the line is taken now, so that
  // line_next() is where the next line starts.
  if (pending_lf_) (void)more();
  if (n > 0 && line_[n - 1] == '\r') --n;  // CRLF
  if (n > kGcodeMaxLine) return Read::kTooLong;
  *text = line_;
  *len = n;
  return Read::kLine;
}

// Makes `file` the one read (its reading state is set by the caller).
void GcodeFile::switch_to(uint16_t file) {
  if (file == cur_) return;
  Opened& was = files_[cur_];
  was.f = f_;
  was.owned = owned_;
  was.started = started_;
  was.cr_lines = cr_lines_;
  was.read_off = read_off_;
  const Opened& to = files_[file];
  f_ = to.f;
  owned_ = to.owned;
  started_ = to.started;
  cr_lines_ = to.cr_lines;
  read_off_ = to.read_off;
  std::snprintf(name_, sizeof name_, "%s", to.name.c_str());
  cur_ = file;
}

void GcodeFile::restart_buffer(uint64_t offset, uint32_t line) {
  pos_ = end_ = 0;
  eof_ = false;
  pending_lf_ = false;
  skipping_ = false;
  consumed_ = offset;
  line_start_ = offset;
  line_no_ = line;
}

bool GcodeFile::seek(const SourcePos& p) {
  if (p.file >= nfiles_ || p.line == 0) return false;
  // A loop's head is usually still in the buffer: no read at all.
  const uint64_t base = consumed_ - pos_;
  if (p.file == cur_ && end_ > 0 && p.offset >= base && p.offset <= base + end_) {
    pos_ = static_cast<std::size_t>(p.offset - base);
    consumed_ = line_start_ = p.offset;
    line_no_ = p.line - 1;
    pending_lf_ = skipping_ = false;
    return true;
  }
  switch_to(p.file);
  if (p.file == 0 && tee_) {
    if (p.offset > teed_) return false;
  } else if (std::fseek(f_, static_cast<long>(p.offset), SEEK_SET) != 0) {
    return false;
  }
  read_off_ = p.offset;
  restart_buffer(p.offset, p.line - 1);
  return true;
}

bool GcodeFile::open_subroutine(const char* name, SourcePos* start) {
  if (nfiles_ > kSubFilesMax) return false;
  for (const std::string& dir : sub_path_) {
    const std::string path = dir + "/" + name + ".ngc";
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) continue;
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
      std::fclose(f);
      continue;
    }
    const uint16_t k = nfiles_++;
    files_[k] = Opened{f, true, false, false, 0, path};
    switch_to(k);
    restart_buffer(0, 0);
    *start = SourcePos{0, 1, k};
    return true;
  }
  return false;
}

std::size_t gcode_format_diag(const char* file, const GcodeDiag& d, bool is_error, char* buf, std::size_t n) {
  char msg[400];
  gcode_format_message(d, msg, sizeof msg);
  int k = std::snprintf(buf, n, "%s:%u:%u: %s: %s%s", file, static_cast<unsigned>(d.line), static_cast<unsigned>(d.col),
                        is_error ? "error" : "warning", msg, d.follow_on ? " (may follow from an earlier error)" : "");
  return k < 0 ? 0 : (static_cast<std::size_t>(k) < n ? static_cast<std::size_t>(k) : n - 1);
}

void GcodeStderrMessages::error(const GcodeDiag& d) {
  ++errors_;
  char line[600];
  gcode_format_diag(file_, d, true, line, sizeof line);
  std::fprintf(out_, "%s\n", line);
}

void GcodeStderrMessages::warning(const GcodeDiag& d) {
  ++warnings_;
  char line[600];
  gcode_format_diag(file_, d, false, line, sizeof line);
  std::fprintf(out_, "%s\n", line);
}

void GcodeNotes::message(uint32_t line, int kind, const char* text) {
  static const char* const kKinds[] = {"note", "debug", "print", "message"};
  const char* k = kKinds[kind >= 1 && kind <= 3 ? kind : 0];
  kept.push_back(Note{line, k, text});
  if (print_) std::fprintf(stderr, "%s:%u: %s: %s\n", file_, line, k, text);
}

std::unique_ptr<GcodeMemory> gcode_memory() { return std::unique_ptr<GcodeMemory>(new GcodeMemory()); }

void GcodeRunner::show_file() {
  shown_file_ = file_->file_index();
  messages_->set_file(file_->name());
}

bool GcodeRunner::step() {
  if (done_) return false;
  const char* text = nullptr;
  std::size_t len = 0;
  uint32_t line_no = 0;
  GcodeFile::Read r = file_->next(&text, &len, &line_no);
  if (r == GcodeFile::Read::kEof) {
    done_ = true;
    GcodeDiag d{};
    // What is left unclosed is reported at its line in the program (a
    // subroutine file may have ended before its sub was found).
    if (shown_file_ != 0) messages_->set_file(file_->program_name());
    if (interp_->end_of_input(last_line_, &d) != GcodeError::kOk) messages_->error(d);
    return false;
  }
  if (r == GcodeFile::Read::kIoError) {
    io_error_ = true;
    done_ = true;
    return false;
  }
  if (r == GcodeFile::Read::kEndless) {
    done_ = true;  // its over-long line was the error
    return false;
  }
  GcodeDiag d{};
  if (r == GcodeFile::Read::kNotText) {
    // One error for the whole input, however many lines it would make.
    d.code = file_->not_text(d.word);
    d.line = 1;
    d.col = 1;
    messages_->error(d);
    done_ = true;
    return false;
  }
  ++lines_;
  if (file_->file_index() == 0 && line_no > last_line_) last_line_ = line_no;
  if (file_->file_index() != shown_file_) show_file();
  GcodeError e;
  if (r == GcodeFile::Read::kTooLong) {
    e = GcodeError::kLineTooLong;
    d.code = e;
    d.line = line_no;
    d.col = static_cast<uint16_t>(kGcodeMaxLine + 1);
    d.a_nm = static_cast<int64_t>(kGcodeMaxLine);
    if (interp_->ended()) e = GcodeError::kOk;  // nothing after the end is read
    interp_->line_not_read();
  } else {
    e = interp_->execute_line(text, len, line_no, &d);
  }
  if (e != GcodeError::kOk && d.follow_on) ++follow_ons_;  // maybe a consequence of an error already reported
  if (e != GcodeError::kOk && (!d.follow_on || show_follow_ons_)) {
    if (!d.line) d.line = line_no;  // the interpreter names another line for an endless loop
    messages_->error(d);
    if (stop_at_first_error_) {
      done_ = true;
      return false;
    }
  }
  // After M2/M30 the interpreter ignores lines (warning once if they hold
  // code), so reading on is cheap and tells the user what was skipped.
  return true;
}

}  // namespace dexmill
