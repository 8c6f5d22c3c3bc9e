// The word scanner; see lex.h.
#include "core/gcode/lex.h"

#include "core/gcode/expr.h"

namespace dexmill {

namespace {

inline bool is_blank(char c) { return gcode_is_blank(c); }
inline char upper(char c) { return gcode_upper(c); }

void set_diag(GcodeDiag* d, GcodeError e, size_t pos) {
  d->code = e;
  d->col = static_cast<uint16_t>(pos + 1);
}

}  // namespace

void gcode_set_word(GcodeDiag* d, const char* text, size_t len) {
  static const char kHex[] = "0123456789ABCDEF";
  size_t k = 0;
  for (size_t i = 0; i < len && k < sizeof d->word - 1; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      d->word[k++] = upper(static_cast<char>(c));
    } else {
      if (k + 4 >= sizeof d->word) break;
      d->word[k++] = '\\';
      d->word[k++] = 'x';
      d->word[k++] = kHex[c >> 4];
      d->word[k++] = kHex[c & 15];
    }
  }
  d->word[k] = 0;
}

GcodeError GcodeScanner::skip_blank_and_comments(GcodeDiag* d) {
  while (pos_ < n_) {
    char c = s_[pos_];
    if (is_blank(c)) {
      ++pos_;
    } else if (c == ';') {
      pos_ = n_;  // the rest of the line is a comment
    } else if (c == '(') {
      // RS274/NGC: a comment ends at the first ')'; a '(' inside is an error.
      size_t open = pos_;
      size_t i = pos_ + 1;
      for (; i < n_ && s_[i] != ')'; ++i) {
        if (s_[i] == '(') {
          set_diag(d, GcodeError::kNestedComment, i);
          gcode_set_word(d, "(", 1);
          return GcodeError::kNestedComment;
        }
      }
      if (i >= n_) {
        set_diag(d, GcodeError::kUnterminatedComment, open);
        gcode_set_word(d, "(", 1);
        return GcodeError::kUnterminatedComment;
      }
      if (params_) note_message(open + 1, i);
      pos_ = i + 1;
    } else {
      break;
    }
  }
  return GcodeError::kOk;
}

// LinuxCNC's message comments: (DEBUG,text) (PRINT,text) (MSG,text), the
// keyword in any case, blanks before the comma allowed.
void GcodeScanner::note_message(size_t from, size_t to) {
  static const char* const kKinds[] = {"DEBUG", "PRINT", "MSG"};
  size_t i = from;
  while (i < to && is_blank(s_[i])) ++i;
  const char first = i < to ? upper(s_[i]) : 0;
  if (first != 'D' && first != 'P' && first != 'M') return;  // most comments
  for (uint8_t k = 0; k < 3; ++k) {
    size_t j = i, c = 0;
    while (kKinds[k][c] && j < to && upper(s_[j]) == kKinds[k][c]) ++j, ++c;
    if (kKinds[k][c]) continue;
    while (j < to && is_blank(s_[j])) ++j;
    if (j >= to || s_[j] != ',') continue;
    msg_kind_ = static_cast<uint8_t>(k + 1);
    msg_at_ = j + 1;
    msg_len_ = to - (j + 1);
    return;
  }
}

bool GcodeScanner::at_end() {
  GcodeDiag d{};
  GcodeError e = skip_blank_and_comments(&d);
  if (e != GcodeError::kOk) {
    pending_ = e;
    pending_col_ = d.col;
    return false;
  }
  return pos_ >= n_;
}

GcodeError GcodeScanner::next(GcodeWord* w, GcodeDiag* d) {
  w->letter = 0;
  GcodeError e = skip_blank_and_comments(d);
  if (e != GcodeError::kOk) return e;
  if (pos_ >= n_) return GcodeError::kOk;
  const size_t start = pos_;
  const char c = upper(s_[pos_]);
  GcodeError bad = GcodeError::kOk;
  // LinuxCNC's polar words (@ distance, ^ angle) are read like any other
  // word, so '@' with no number after it is a typo, not polar coordinates.
  if (c >= 'A' && c <= 'Z') {
    if (c == 'E') bad = GcodeError::kUnknownWord;
    if (c == 'O') bad = GcodeError::kUnsupportedOword;
  } else if (c == '#') {
    if (params_) {  // an assignment: the block reader's
      w->letter = '#';
      w->col = static_cast<uint16_t>(start + 1);
      return GcodeError::kOk;
    }
    bad = GcodeError::kUnsupportedParameter;
  } else if (c == '[') {
    bad = GcodeError::kUnsupportedExpression;
  } else if (c == ')') {
    bad = GcodeError::kStrayCloseParen;
  } else if (c != '@' && c != '^') {
    bad = GcodeError::kBadCharacter;
  }
  if (bad != GcodeError::kOk) {
    set_diag(d, bad, start);
    gcode_set_word(d, s_ + start, 1);
    return bad;
  }
  pos_ = start + 1;
  Decimal v{0, 0};
  DecimalParse r = decimal_parse(s_, n_, &pos_, &v);
  // Not a plain number: with parameters, a computed value (#1, [1+2],
  // SIN[30], -#1); a plain number, the usual word, pays nothing for it.
  if (r != DecimalParse::kOk && params_ && expr_starts_computed(s_, n_, start + 1)) {
    pos_ = start + 1;
    GValue g;
    const GcodeError ee = expr_read_value(s_, n_, &pos_, *params_, &g, d);
    if (ee != GcodeError::kOk) return ee;
    w->letter = c;
    w->value = gvalue_to_decimal(g);
    w->col = static_cast<uint16_t>(start + 1);
    return GcodeError::kOk;
  }
  size_t i = start + 1;
  while (i < n_ && (s_[i] == ' ' || s_[i] == '\t')) ++i;
  // A value LinuxCNC would compute: X[1+2], X#1.
  const bool computed = r != DecimalParse::kOk && i < n_ && (s_[i] == '[' || s_[i] == '#');
  if (computed) {
    GcodeError err = s_[i] == '[' ? GcodeError::kUnsupportedExpression : GcodeError::kUnsupportedParameter;
    set_diag(d, err, i);
    gcode_set_word(d, s_ + i, 1);
    return err;
  }
  if (r != DecimalParse::kOk) {
    // "X" followed by nothing numeric is a missing number; "X-" or "X." a bad one.
    bool started = i < n_ && (s_[i] == '-' || s_[i] == '+' || s_[i] == '.');
    GcodeError err = r == DecimalParse::kTooLarge ? GcodeError::kNumberTooLarge
                     : started                    ? GcodeError::kBadNumber
                                                  : GcodeError::kMissingNumber;
    set_diag(d, err, start);
    gcode_set_word(d, &c, 1);
    pos_ = start;
    return err;
  }
  w->letter = c;
  w->value = v;
  w->col = static_cast<uint16_t>(start + 1);
  return GcodeError::kOk;
}

bool GcodeLooseScanner::next(GcodeLooseWord* w) {
  while (pos_ < n_) {
    const char c = upper(s_[pos_]);
    if (c == ';') break;
    if (c == '(') {
      while (pos_ < n_ && s_[pos_] != ')') ++pos_;
      ++pos_;
      continue;
    }
    if (c == '[') {
      for (int depth = 0; pos_ < n_; ++pos_) {
        depth += s_[pos_] == '[' ? 1 : s_[pos_] == ']' ? -1 : 0;
        if (depth == 0) break;
      }
      ++pos_;
      continue;
    }
    if (c == '#' && pos_ + 1 < n_ && s_[pos_ + 1] == '<') {
      while (pos_ < n_ && s_[pos_] != '>') ++pos_;
      ++pos_;
      continue;
    }
    ++pos_;
    if ((c < 'A' || c > 'Z') && c != '@' && c != '^') continue;
    w->letter = c;
    w->first = !seen_word_;
    if (c != 'N') seen_word_ = true;
    size_t p = pos_;
    w->known = decimal_parse(s_, n_, &p, &w->value) == DecimalParse::kOk;
    if (w->known) pos_ = p;
    return true;
  }
  pos_ = n_;
  return false;
}

}  // namespace dexmill
