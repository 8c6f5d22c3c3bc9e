// The word scanner of one G-code line (RS274/NGC section 3.3, as LinuxCNC
// reads it): letters in either case, white space anywhere outside comments
// (`G 1 X 1 0` is G1 X10), `( )` comments anywhere, `;` to the end of the
// line, a trailing '\r' of CRLF files. It yields one word at a time; it knows
// nothing about what the words mean.
#ifndef DEXMILL_CORE_GCODE_LEX_H
#define DEXMILL_CORE_GCODE_LEX_H

#include <stddef.h>
#include <stdint.h>

#include "core/gcode/error.h"
#include "core/math/decimal.h"

namespace dexmill {

struct GcodeWord {
  char letter;     // 'A'..'Z' (upper case); 0 at the end of the line
  Decimal value;
  uint16_t col;    // 1-based column of the letter
};

class GcodeScanner {
 public:
  GcodeScanner(const char* text, size_t len) : s_(text), n_(len) {}

  // The next word into *w (w->letter == 0 at the end of the line). On an
  // error, fills d->code, d->col and d->word and returns the code.
  [[nodiscard]] GcodeError next(GcodeWord* w, GcodeDiag* d);

  // Skips white space and comments; true if only those remain.
  [[nodiscard]] bool at_end();
  // Current byte offset (for the block reader's special line forms).
  size_t pos() const { return pos_; }
  void set_pos(size_t p) { pos_ = p; }
  // First error met by at_end() (an unterminated comment), or kOk.
  GcodeError pending() const { return pending_; }
  uint16_t pending_col() const { return pending_col_; }

 private:
  GcodeError skip_blank_and_comments(GcodeDiag* d);

  const char* s_;
  size_t n_;
  size_t pos_ = 0;
  GcodeError pending_ = GcodeError::kOk;
  uint16_t pending_col_ = 0;
};

// A lenient walk over a line that may not read (for telling which parts of
// the modal state a bad line meant to change; core/motion/interp_follow_on.cpp).
// It yields each letter that begins a word, as LinuxCNC would see it, with
// its value when that is a plain number. Comments, [ ] expressions and
// #<named> parameters are stepped over; other bytes are skipped.
struct GcodeLooseWord {
  char letter;   // 'A'..'Z'
  bool known;    // value holds the number written
  bool first;    // the first word of the line (after '/' and an N word)
  Decimal value;
};

class GcodeLooseScanner {
 public:
  GcodeLooseScanner(const char* text, size_t len) : s_(text), n_(len) {}
  // The next word; false at the end of the line.
  bool next(GcodeLooseWord* w);

 private:
  const char* s_;
  size_t n_;
  size_t pos_ = 0;
  bool seen_word_ = false;  // a word other than N was yielded
};

// Copies up to 15 bytes of printable text into word[16] (non-printable bytes
// as \xNN), for diagnostics.
void gcode_set_word(GcodeDiag* d, const char* text, size_t len);

}  // namespace dexmill

#endif
