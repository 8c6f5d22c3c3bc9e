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
#include "core/gcode/params.h"
#include "core/math/decimal.h"

namespace dexmill {

// White space RS274/NGC skips between (and inside) words, and letters in
// either case: the one definition the scanner, the block reader and the
// expression reader share.
inline bool gcode_is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline char gcode_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

struct GcodeWord {
  char letter;     // 'A'..'Z' (upper case), '@' or '^' (polar); 0 at the end of the line
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
  // With parameters: a word's value may be computed (#1, [1+2],
  // SIN[30]) from them, '#' at a word's start is an assignment (w->letter
  // '#', the position left at it for the block reader), and message
  // comments (DEBUG, PRINT, MSG) are noted. Null: those are refused as not
  // supported (the reader's uses that run no program).
  void set_params(const ParamStore* p) { params_ = p; }
  // The last message comment met: kind 0 none, 1 DEBUG, 2 PRINT, 3 MSG; its
  // text after the comma.
  uint8_t message_kind() const { return msg_kind_; }
  size_t message_at() const { return msg_at_; }
  size_t message_len() const { return msg_len_; }
  // Current byte offset (for the block reader's special line forms).
  size_t pos() const { return pos_; }
  void set_pos(size_t p) { pos_ = p; }
  // First error met by at_end() (an unterminated comment), or kOk.
  GcodeError pending() const { return pending_; }
  uint16_t pending_col() const { return pending_col_; }

 private:
  GcodeError skip_blank_and_comments(GcodeDiag* d);
  void note_message(size_t from, size_t to);

  const char* s_;
  size_t n_;
  size_t pos_ = 0;
  GcodeError pending_ = GcodeError::kOk;
  uint16_t pending_col_ = 0;
  const ParamStore* params_ = nullptr;
  uint8_t msg_kind_ = 0;
  size_t msg_at_ = 0, msg_len_ = 0;
};

// A lenient walk over a line that may not read (for telling which parts of
// the modal state a bad line meant to change; core/interp/interp_follow_on.cpp).
// It yields each letter that begins a word, as LinuxCNC would see it, with
// its value when that is a plain number. Comments, [ ] expressions and
// #<named> parameters are stepped over; other bytes are skipped.
struct GcodeLooseWord {
  char letter;   // 'A'..'Z', '@' or '^'
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
