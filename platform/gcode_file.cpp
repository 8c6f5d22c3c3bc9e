// The hosted G-code reader; see gcode_file.h.
#include "platform/gcode_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace dexmill {

GcodeFile::~GcodeFile() {
  if (f_ && owned_) std::fclose(f_);
}

bool GcodeFile::open(const char* path) {
  if (!std::strcmp(path, "-")) {
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
    if (S_ISDIR(st.st_mode)) {
      std::snprintf(error_, sizeof error_, "cannot read '%s': Is a directory", path);
      return false;
    }
  }
  return true;
}

bool GcodeFile::fill() {
  if (eof_) return false;
  end_ = std::fread(buf_, 1, sizeof buf_, f_);
  pos_ = 0;
  if (end_ == 0) {
    eof_ = true;
    if (std::ferror(f_)) std::snprintf(error_, sizeof error_, "cannot read '%s': %s", name_, std::strerror(errno));
    return false;
  }
  return true;
}

GcodeFile::Read GcodeFile::next(const char** text, std::size_t* len, uint32_t* line_no) {
  std::size_t n = 0;
  bool too_long = false, any = false;
  for (;;) {
    if (pos_ >= end_ && !fill()) {
      if (error_[0]) return Read::kIoError;
      if (!any) return Read::kEof;
      break;  // a last line with no line end
    }
    any = true;
    // Copy up to the next '\n' in one go.
    const char* start = buf_ + pos_;
    const void* nl = std::memchr(start, '\n', end_ - pos_);
    std::size_t chunk = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - start) : end_ - pos_;
    if (!too_long) {
      if (n + chunk <= kGcodeMaxLine + 1) {
        std::memcpy(line_ + n, start, chunk);
        n += chunk;
      } else {
        too_long = true;
      }
    }
    pos_ += chunk;
    consumed_ += chunk;
    if (nl) {
      ++pos_;
      ++consumed_;
      break;
    }
  }
  *line_no = ++line_no_;
  if (!too_long && n > 0 && line_[n - 1] == '\r') --n;  // CRLF
  if (too_long || n > kGcodeMaxLine) return Read::kTooLong;
  *text = line_;
  *len = n;
  return Read::kLine;
}

std::size_t gcode_format_diag(const char* file, const GcodeDiag& d, bool is_error, char* buf, std::size_t n) {
  char msg[400];
  gcode_format_message(d, msg, sizeof msg);
  int k = std::snprintf(buf, n, "%s:%u:%u: %s: %s", file, static_cast<unsigned>(d.line), static_cast<unsigned>(d.col),
                        is_error ? "error" : "warning", msg);
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

bool GcodeRunner::step() {
  if (done_) return false;
  const char* text = nullptr;
  std::size_t len = 0;
  uint32_t line_no = 0;
  GcodeFile::Read r = file_->next(&text, &len, &line_no);
  if (r == GcodeFile::Read::kEof) {
    done_ = true;
    return false;
  }
  if (r == GcodeFile::Read::kIoError) {
    io_error_ = true;
    done_ = true;
    return false;
  }
  ++lines_;
  GcodeDiag d{};
  GcodeError e;
  if (r == GcodeFile::Read::kTooLong) {
    e = GcodeError::kLineTooLong;
    d.code = e;
    d.line = line_no;
    d.col = static_cast<uint16_t>(kGcodeMaxLine + 1);
    d.a_nm = static_cast<int64_t>(kGcodeMaxLine);
    if (interp_->ended()) e = GcodeError::kOk;  // nothing after the end is read
  } else {
    e = interp_->execute_line(text, len, line_no, &d);
  }
  if (e != GcodeError::kOk) {
    d.line = line_no;
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
