// O-word lines; see oword.h. LinuxCNC lower-cases a line and drops its
// blanks before read_o looks at it, so `O100 END WHILE` reads as
// `o100endwhile`: blanks are skipped everywhere here too.
#include "core/gcode/oword.h"

#include <string.h>

#include "core/gcode/expr.h"
#include "core/gcode/lex.h"

namespace dexmill {
namespace {

inline bool blank(char c) { return gcode_is_blank(c); }
inline bool digit(char c) { return c >= '0' && c <= '9'; }

size_t skip_blanks(const char* s, size_t n, size_t i) {
  while (i < n && blank(s[i])) ++i;
  return i;
}

GcodeError fail(GcodeDiag* d, GcodeError e, size_t at, const char* s, size_t n, size_t len) {
  d->code = e;
  d->col = static_cast<uint16_t>(at + 1);
  gcode_set_word(d, s + at, at + len <= n ? len : n - at);
  return e;
}

// LinuxCNC's read_integer_value: a value within 0.0001 of a whole number
// (here also not negative, at most 1e9) into *r.
bool whole_number(GValue v, int64_t* r) {
  *r = (v.e9 + kGValueOne / 2) / kGValueOne;
  const int64_t off = v.e9 - *r * kGValueOne;
  return v.e9 >= 0 && off <= kGValueOne / 10000 && off >= -kGValueOne / 10000 && *r <= 1000000000;
}

// A numbered label as its name: the decimal digits of v >= 0.
void number_name(int64_t v, char* name) {
  char digits[16];
  int k = 0;
  do { digits[k++] = static_cast<char>('0' + v % 10); v /= 10; } while (v);
  int j = 0;
  while (k) name[j++] = digits[--k];
  name[j] = 0;
}

// Where the first word of a line is (after '/' and an N word).
size_t first_word(const char* s, size_t n) {
  size_t i = skip_blanks(s, n, 0);
  if (i < n && s[i] == '/') i = skip_blanks(s, n, i + 1);
  if (i < n && (s[i] == 'N' || s[i] == 'n')) {
    i = skip_blanks(s, n, i + 1);
    while (i < n && (digit(s[i]) || blank(s[i]))) ++i;
  }
  return i;
}

// Where the O of an o-word line is, or n.
size_t o_at(const char* s, size_t n) {
  const size_t i = first_word(s, n);
  return i < n && (s[i] == 'O' || s[i] == 'o') ? i : n;
}

// 98 or 99 when the first word, at i, is M98 or M99 (*after just past
// it), else 0.
int fanuc_m(const char* s, size_t n, size_t i, size_t* after) {
  if (i >= n || (s[i] != 'M' && s[i] != 'm')) return 0;
  i = skip_blanks(s, n, i + 1);
  while (i < n && s[i] == '0') i = skip_blanks(s, n, i + 1);
  if (i + 1 >= n || s[i] != '9' || (s[i + 1] != '8' && s[i + 1] != '9')) return 0;
  const int m = s[i + 1] == '8' ? 98 : 99;
  i = skip_blanks(s, n, i + 2);
  if (i < n && (digit(s[i]) || s[i] == '.')) return 0;  // M980, M98.1
  *after = i;
  return m;
}

// M98's P and L (LinuxCNC reads them as any words: computed values too).
GcodeError read_m98(const char* s, size_t n, size_t i, const ParamStore& p, OwordHead* h, GcodeDiag* d) {
  bool have_p = false;
  h->m98_count = 1;
  for (;;) {
    i = skip_blanks(s, n, i);
    if (i >= n || s[i] == ';') break;
    if (s[i] == '(') {
      while (i < n && s[i] != ')') ++i;
      if (i >= n) return fail(d, GcodeError::kUnterminatedComment, h->col - 1, s, n, 1);
      ++i;
      continue;
    }
    const char c = gcode_upper(s[i]);
    if (c != 'P' && c != 'L') return fail(d, GcodeError::kOwordTextAfter, i, s, n, 1);
    size_t at = i + 1;
    GValue v;
    const GcodeError e = expr_read_value(s, n, &at, p, &v, d);
    if (e != GcodeError::kOk) return e;
    int64_t r;
    if (!whole_number(v, &r)) return fail(d, GcodeError::kNotInteger, i, s, n, at - i);
    if (c == 'P') {
      have_p = true;
      number_name(r, h->name);
    } else {
      h->m98_count = r;
    }
    i = at;
  }
  if (!have_p) {
    d->code = GcodeError::kM98NoP;
    d->col = h->col;
    gcode_set_word(d, "M98", 3);
    return d->code;
  }
  h->rest = static_cast<uint16_t>(n);
  return GcodeError::kOk;
}

struct Statement {
  const char* word;
  OwordOp op;
};
// "elseif" before "else", its prefix.
const Statement kStatements[] = {
    {"sub", OwordOp::kSub},         {"endsub", OwordOp::kEndsub},       {"call", OwordOp::kCall},
    {"do", OwordOp::kDo},           {"while", OwordOp::kWhile},         {"repeat", OwordOp::kRepeat},
    {"if", OwordOp::kIf},           {"elseif", OwordOp::kElseif},       {"else", OwordOp::kElse},
    {"endif", OwordOp::kEndif},     {"break", OwordOp::kBreak},         {"continue", OwordOp::kContinue},
    {"endwhile", OwordOp::kEndwhile}, {"endrepeat", OwordOp::kEndrepeat}, {"return", OwordOp::kReturn},
};

// Does `word` start at s[i] (case-insensitive, blanks skipped)? *end is
// just after it.
bool word_at(const char* s, size_t n, size_t i, const char* word, size_t* end) {
  for (; *word; ++word) {
    i = skip_blanks(s, n, i);
    if (i >= n || gcode_upper(s[i]) != gcode_upper(*word)) return false;
    ++i;
  }
  *end = i;
  return true;
}

// The word of a statement must not run on into more letters ("dog" is no
// "do"): LinuxCNC would take "do" and then fail on "g"; the same error.
bool letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

}  // namespace

bool oword_line(const char* s, size_t n) {
  // Called for every line: most start with G or X and are told at once.
  const size_t i = first_word(s, n);
  if (i >= n) return false;
  if (s[i] == 'O' || s[i] == 'o') return true;
  size_t after;
  return fanuc_m(s, n, i, &after) != 0;
}

const char* oword_op_name(OwordOp op) {
  for (const Statement& st : kStatements)
    if (st.op == op) return st.word;
  return op == OwordOp::kProgramNumber ? "program number" : op == OwordOp::kM98 ? "M98" : op == OwordOp::kM99 ? "M99" : "";
}

GcodeError oword_read_head(const char* s, size_t n, const ParamStore& p, OwordHead* h, GcodeDiag* d) {
  h->op = OwordOp::kNone;
  h->name[0] = 0;
  h->m98_count = 1;
  const size_t o = o_at(s, n);
  if (o >= n) {
    size_t after = 0;
    const int m = fanuc_m(s, n, first_word(s, n), &after);
    if (m == 0) return GcodeError::kOk;
    h->col = static_cast<uint16_t>(first_word(s, n) + 1);
    h->rest = static_cast<uint16_t>(after);
    if (m == 99) {
      h->op = OwordOp::kM99;
      return GcodeError::kOk;
    }
    h->op = OwordOp::kM98;
    return read_m98(s, n, after, p, h, d);
  }
  h->col = static_cast<uint16_t>(o + 1);
  size_t i = skip_blanks(s, n, o + 1);
  if (i < n && s[i] == '<') {
    // o<name>: up to '>', folded as parameter names are.
    size_t e = i + 1;
    while (e < n && s[e] != '>') ++e;
    if (e >= n) return fail(d, GcodeError::kOwordBadLabel, o, s, n, e - o);
    if (!param_fold_name(s + i + 1, e - i - 1, h->name)) {
      d->a_nm = kOwordNameMax;
      return fail(d, GcodeError::kOwordBadLabel, o, s, n, e + 1 - o);
    }
    i = e + 1;
  } else {
    // A number, written or computed (LinuxCNC's read_integer_value).
    int64_t v = 0;
    if (i < n && digit(s[i])) {
      size_t e = i;
      while (e < n && digit(s[e])) {
        if (v > 100000000) return fail(d, GcodeError::kOwordBadLabel, o, s, n, e + 1 - o);
        v = v * 10 + (s[e] - '0');
        ++e;
      }
      i = e;
    } else if (i < n && (s[i] == '[' || s[i] == '#')) {
      GValue g;
      size_t at = i;
      const GcodeError e = expr_read_value(s, n, &at, p, &g, d);
      if (e != GcodeError::kOk) return e;
      if (!whole_number(g, &v)) return fail(d, GcodeError::kOwordBadLabel, o, s, n, at - o);
      i = at;
    } else {
      return fail(d, GcodeError::kOwordBadLabel, o, s, n, 1);
    }
    number_name(v, h->name);
  }
  i = skip_blanks(s, n, i);
  if (i >= n || s[i] == '(' || s[i] == ';') {
    h->op = OwordOp::kProgramNumber;
    h->rest = static_cast<uint16_t>(i);
    return GcodeError::kOk;
  }
  for (const Statement& st : kStatements) {
    size_t end = 0;
    if (!word_at(s, n, i, st.word, &end)) continue;
    const size_t after = skip_blanks(s, n, end);
    if (after < n && letter(s[after])) continue;
    h->op = st.op;
    h->rest = static_cast<uint16_t>(end);
    return GcodeError::kOk;
  }
  size_t e = i;
  while (e < n && !blank(s[e]) && s[e] != '[' && s[e] != '(') ++e;
  return fail(d, GcodeError::kOwordUnknownStatement, i, s, n, e - i);
}

GcodeError oword_read_rest(const char* s, size_t n, const OwordHead& h, const ParamStore& p, GValue* values,
                           int* count, GcodeDiag* d) {
  *count = 0;
  const bool takes_many = h.op == OwordOp::kCall;
  const bool takes_one = h.op == OwordOp::kWhile || h.op == OwordOp::kIf || h.op == OwordOp::kElseif ||
                         h.op == OwordOp::kRepeat || h.op == OwordOp::kReturn || h.op == OwordOp::kEndsub;
  const bool needs_one = takes_one && h.op != OwordOp::kReturn && h.op != OwordOp::kEndsub;
  size_t i = h.rest;
  for (;;) {
    i = skip_blanks(s, n, i);
    if (i >= n) break;
    if (s[i] == ';') break;
    if (s[i] == '(') {
      // A comment (LinuxCNC allows them between a call's arguments too).
      size_t e = i + 1;
      while (e < n && s[e] != ')') ++e;
      if (e >= n) return fail(d, GcodeError::kUnterminatedComment, i, s, n, 1);
      i = e + 1;
      continue;
    }
    if (s[i] == '[' && (takes_many || (takes_one && *count == 0))) {
      if (*count >= kOwordArgsMax) return fail(d, GcodeError::kOwordTooManyArgs, i, s, n, 1);
      size_t at = i;
      const GcodeError e = expr_read_value(s, n, &at, p, &values[*count], d);
      if (e != GcodeError::kOk) return e;
      ++*count;
      i = at;
      continue;
    }
    return fail(d, GcodeError::kOwordTextAfter, i, s, n, 1);
  }
  if (needs_one && *count == 0) {
    d->code = GcodeError::kOwordNoValue;
    d->col = h.col;
    const char* w = oword_op_name(h.op);
    gcode_set_word(d, w, strlen(w));
    return d->code;
  }
  return GcodeError::kOk;
}

}  // namespace dexmill
