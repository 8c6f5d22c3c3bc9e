// Program text into lines; see line_reader.h.
#include "core/gcode/line_reader.h"

#include <string.h>

#include "core/gcode/lex.h"

namespace dexmill {

namespace {

// A byte that text never holds; see the top of line_reader.h for the ones
// left out (NUL, white space, SUB).
bool is_binary_byte(unsigned char c) {
  return (c < 0x20 && c != 0 && c != '\t' && c != '\n' && c != '\v' && c != '\f' && c != '\r' && c != 0x1a) ||
         c == 0x7f;
}

}  // namespace

// More bytes: appended while the buffer has room (what a loop may seek
// back to stays), else in a buffer started afresh.
LineReader::Avail LineReader::fill() {
  if (eof_) return Avail::kNo;
  if (!src_) {
    eof_ = true;
    return Avail::kNo;
  }
  if (end_ == cap_) {
    pos_ = end_ = 0;
  }
  size_t got = 0;
  const ByteSource::Fill f = src_->read_bytes(buf_ + end_, cap_ - end_, &got);
  if (f == ByteSource::Fill::kWait) return Avail::kWait;
  if (f != ByteSource::Fill::kBytes || got == 0) {
    eof_ = true;
    err_ = f == ByteSource::Fill::kError;
    return Avail::kNo;
  }
  end_ += got;
  return Avail::kYes;
}

// Decides, on the first bytes, what the input is (line_reader.h).
LineReader::Avail LineReader::start() {
  const size_t want = cap_ < kStartBytes ? cap_ : kStartBytes;
  while (end_ < want) {
    const Avail a = fill();
    if (a == Avail::kWait) return a;
    if (a == Avail::kNo) break;
  }
  started_ = true;
  if (end_ == 0) return Avail::kNo;
  const unsigned char* b = reinterpret_cast<const unsigned char*>(buf_);
  if (end_ >= 2 && ((b[0] == 0xff && b[1] == 0xfe) || (b[0] == 0xfe && b[1] == 0xff))) {
    not_text_ = GcodeError::kUtf16Text;
    return Avail::kYes;
  }
  size_t binary = 0;
  for (size_t i = 0; i < end_; ++i) {
    if (!is_binary_byte(b[i])) continue;
    if (binary++ == 0) not_text_byte_ = b[i];
  }
  if (binary && binary * 32 >= end_) {
    not_text_ = GcodeError::kNotText;
    return Avail::kYes;
  }
  if (end_ >= 3 && b[0] == 0xef && b[1] == 0xbb && b[2] == 0xbf && pos_ == 0) {
    pos_ = 3;
    consumed_ += 3;
  }
  cr_lines_ = !memchr(buf_ + pos_, '\n', end_ - pos_) && memchr(buf_ + pos_, '\r', end_ - pos_);
  return Avail::kYes;
}

GcodeError LineReader::not_text(char word[16]) const {
  word[0] = 0;
  if (not_text_ == GcodeError::kNotText) {
    GcodeDiag d{};
    const char c = static_cast<char>(not_text_byte_);
    gcode_set_word(&d, &c, 1);
    memcpy(word, d.word, sizeof d.word);
  }
  return not_text_;
}

// kYes when buf_[pos_] is a byte to read (the LF of a CRLF whose CR ended
// the last line is skipped here, even across a refill).
LineReader::Avail LineReader::more() {
  for (;;) {
    if (pos_ >= end_) {
      const Avail a = fill();
      if (a != Avail::kYes) return a;
    }
    if (!pending_lf_) return Avail::kYes;
    pending_lf_ = false;
    if (buf_[pos_] == '\n') {
      ++pos_;
      ++consumed_;
    }
  }
}

// Index of the first line end in buf_[pos_, end_), or end_.
size_t LineReader::find_eol() const {
  if (!cr_lines_) {
    const void* nl = memchr(buf_ + pos_, '\n', end_ - pos_);
    return nl ? static_cast<size_t>(static_cast<const char*>(nl) - buf_) : end_;
  }
  for (size_t i = pos_; i < end_; ++i)
    if (buf_[i] == '\n' || buf_[i] == '\r') return i;
  return end_;
}

// Consumes the line end at pos_.
void LineReader::take_eol() {
  pending_lf_ = buf_[pos_] == '\r';
  ++pos_;
  ++consumed_;
}

void LineReader::reset_line() {
  any_ = false;
  n_ = 0;
  finishing_ = false;
}

LineReader::Read LineReader::next(const char** text, size_t* len, uint32_t* line_no) {
  if (!started_ && start() == Avail::kWait) return Read::kWait;
  if (not_text_ != GcodeError::kOk) {
    if (not_text_done_) return Read::kEof;
    not_text_done_ = true;
    return Read::kNotText;
  }
  if (!finishing_) {
    if (skipping_) {
      // The rest of an over-long line, already reported.
      for (;;) {
        const Avail a = more();
        if (a == Avail::kWait) return Read::kWait;
        if (a == Avail::kNo) {
          skipping_ = false;
          return err_ ? Read::kIoError : Read::kEof;
        }
        const size_t e = find_eol();
        skipped_ += e - pos_;
        consumed_ += e - pos_;
        pos_ = e;
        if (e < end_) {
          take_eol();
          break;
        }
        if (skipped_ > kMaxSkip) {
          skipping_ = false;
          return Read::kEndless;
        }
      }
      skipping_ = false;
      skipped_ = 0;
    }
    for (;;) {
      const Avail a = more();
      if (a == Avail::kWait) return Read::kWait;
      if (a == Avail::kNo) {
        if (err_) return Read::kIoError;
        if (!any_) return Read::kEof;
        break;  // a last line with no line end
      }
      if (!any_) line_start_ = consumed_;
      any_ = true;
      const size_t e = find_eol();
      const size_t chunk = e - pos_;
      if (n_ + chunk > kGcodeMaxLine + 1) {
        // Longer than any line, even with the CR of a CRLF: say so now, and
        // skip the rest on the next call (which may never find a line end).
        pos_ = e;
        consumed_ += chunk;
        if (e < end_) take_eol();
        else skipping_ = true;
        skipped_ = 0;
        reset_line();
        *line_no = ++line_no_;
        return Read::kTooLong;
      }
      memcpy(line_ + n_, buf_ + pos_, chunk);
      n_ += chunk;
      pos_ = e;
      consumed_ += chunk;
      if (e < end_) {
        take_eol();
        break;
      }
    }
    ++line_no_;
    finishing_ = true;
  }
  // The LF of a CRLF whose CR ended the line is taken now, so that
  // next_offset() is where the next line starts.
  if (pending_lf_ && more() == Avail::kWait) return Read::kWait;
  size_t n = n_;
  reset_line();
  *line_no = line_no_;
  if (n > 0 && line_[n - 1] == '\r') --n;  // CRLF
  if (n > kGcodeMaxLine) return Read::kTooLong;
  *text = line_;
  *len = n;
  return Read::kLine;
}

bool LineReader::seek_in_buffer(uint64_t offset, uint32_t line) {
  const uint64_t base = consumed_ - pos_;
  if (end_ == 0 || offset < base || offset > base + end_) return false;
  pos_ = static_cast<size_t>(offset - base);
  consumed_ = line_start_ = offset;
  line_no_ = line - 1;
  pending_lf_ = skipping_ = false;
  reset_line();
  return true;
}

void LineReader::restart(uint64_t offset, uint32_t line) {
  pos_ = end_ = 0;
  eof_ = err_ = false;
  pending_lf_ = false;
  skipping_ = false;
  reset_line();
  consumed_ = offset;
  line_start_ = offset;
  line_no_ = line - 1;
}

}  // namespace dexmill
