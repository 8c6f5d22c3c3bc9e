// Words and amounts of a comment; see comment_text.h.
#include "core/tool/comment_text.h"

namespace dexmill {
namespace {

constexpr int64_t kE9 = 1000000000;
constexpr int64_t kWholeMax = 100000000;  // 10^8 units: no tool is larger
constexpr int kDenominatorDigitsMax = 6;

// Digits at s[*pos] as a number of at most 9 digits; false with none or
// more (*pos unchanged).
bool read_digits(const char* s, size_t n, size_t* pos, int64_t* v, int max_digits = 9) {
  size_t p = *pos;
  int64_t x = 0;
  int k = 0;
  while (p < n && text_is_digit(s[p])) {
    if (++k > max_digits) return false;
    x = x * 10 + (s[p] - '0');
    ++p;
  }
  if (k == 0) return false;
  *pos = p;
  *v = x;
  return true;
}

// "/D" at s[*pos] with a positive D: the fraction num/D in 1e-9, rounded.
bool read_over(const char* s, size_t n, size_t* pos, int64_t num, int64_t* e9) {
  size_t p = *pos;
  if (p >= n || s[p] != '/') return false;
  ++p;
  int64_t den = 0;
  if (!read_digits(s, n, &p, &den, kDenominatorDigitsMax) || den == 0) return false;
  if (num / den >= kWholeMax) return false;
  *e9 = (num * kE9 + den / 2) / den;  // num < 10^9, so num * 10^9 fits
  *pos = p;
  return true;
}

// The decimals after a '.', as 1e-9 units (rounded at the tenth decimal).
int64_t read_decimals(const char* s, size_t n, size_t* pos) {
  size_t p = *pos;
  int64_t frac = 0, scale = kE9;
  bool round_up = false;
  int k = 0;
  while (p < n && text_is_digit(s[p])) {
    if (k < 9) {
      scale /= 10;
      frac += (s[p] - '0') * scale;
    } else if (k == 9) {
      round_up = s[p] >= '5';
    }
    ++k;
    ++p;
  }
  *pos = p;
  return frac + (round_up ? 1 : 0);
}

}  // namespace

bool text_has_at(const char* s, size_t n, size_t at, const char* w) {
  for (size_t k = 0; w[k]; ++k)
    if (at + k >= n || text_lower(s[at + k]) != w[k]) return false;
  return true;
}

size_t text_find(const char* s, size_t n, const char* w, bool whole, size_t from) {
  size_t wn = 0;
  while (w[wn]) ++wn;
  for (size_t at = from; at + wn <= n; ++at) {
    if (at > 0 && text_is_letter(s[at - 1])) continue;
    if (!text_has_at(s, n, at, w)) continue;
    if (whole && at + wn < n && text_is_letter(s[at + wn])) continue;
    return at;
  }
  return n;
}

size_t text_skip_spaces(const char* s, size_t n, size_t at) {
  while (at < n && text_is_space(s[at])) ++at;
  return at;
}

int text_word_count(const char* s, size_t n) {
  int words = 0;
  for (size_t k = 0; k < n; ++k)
    if (!text_is_space(s[k]) && (k == 0 || text_is_space(s[k - 1]))) ++words;
  return words;
}

int32_t text_read_digits(const char* s, size_t n, size_t* pos, int* digits) {
  int32_t num = 0;
  *digits = 0;
  while (*pos < n && text_is_digit(s[*pos]) && *digits < 6) {
    num = num * 10 + (s[*pos] - '0');
    ++*pos;
    ++*digits;
  }
  return num;
}

bool text_read_amount(const char* s, size_t n, size_t* pos, int64_t* e9) {
  const size_t p = *pos;
  if (p > 0 && (text_is_letter(s[p - 1]) || text_is_digit(s[p - 1]) || s[p - 1] == '.')) return false;
  return text_read_amount_here(s, n, pos, e9);
}

bool text_read_amount_here(const char* s, size_t n, size_t* pos, int64_t* e9) {
  size_t p = *pos;
  int64_t whole = 0;
  const bool has_whole = read_digits(s, n, &p, &whole);
  if (!has_whole && p < n && text_is_digit(s[p])) return false;  // too many digits
  if (has_whole && whole > kWholeMax) return false;
  int64_t v = 0;
  if (has_whole && read_over(s, n, &p, whole, &v)) {  // 1/4
    *pos = p;
    *e9 = v;
    return true;
  }
  if (p < n && s[p] == '.') {
    size_t q = p + 1;
    if (!has_whole && (q >= n || !text_is_digit(s[q]))) return false;
    const int64_t frac = read_decimals(s, n, &q);
    *pos = q;
    *e9 = whole * kE9 + frac;
    return true;
  }
  if (!has_whole) return false;
  v = whole * kE9;
  // A whole part and a fraction: 1 1/4, 1-1/4.
  if (p + 1 < n && (s[p] == ' ' || s[p] == '-') && text_is_digit(s[p + 1])) {
    size_t q = p + 1;
    int64_t num = 0, part = 0;
    if (read_digits(s, n, &q, &num) && read_over(s, n, &q, num, &part) && part < kE9) {
      *pos = q;
      *e9 = v + part;
      return true;
    }
  }
  *pos = p;
  *e9 = v;
  return true;
}

bool text_read_signed(const char* s, size_t n, size_t* pos, int64_t* e9) {
  size_t p = *pos;
  const bool neg = p < n && s[p] == '-';
  if (p < n && (s[p] == '-' || s[p] == '+')) ++p;
  int64_t v = 0;
  if (!text_read_amount(s, n, &p, &v)) return false;  // a sign is no digit or letter: the amount may follow it
  *pos = p;
  *e9 = neg ? -v : v;
  return true;
}

TextUnit text_read_unit(const char* s, size_t n, size_t* pos) {
  size_t p = text_skip_spaces(s, n, *pos);
  if (p < n && s[p] == '"') {
    *pos = p + 1;
    return TextUnit::kInch;
  }
  if (p + 1 < n && s[p] == '\'' && s[p + 1] == '\'') {
    *pos = p + 2;
    return TextUnit::kInch;
  }
  static const struct {
    const char* word;
    TextUnit unit;
  } kUnits[] = {{"millimeters", TextUnit::kMm}, {"millimeter", TextUnit::kMm}, {"mm", TextUnit::kMm},
                {"inches", TextUnit::kInch},    {"inch", TextUnit::kInch},     {"in", TextUnit::kInch}};
  for (const auto& u : kUnits) {
    if (!text_has_at(s, n, p, u.word)) continue;
    size_t e = p;
    while (u.word[e - p]) ++e;
    if (e < n && text_is_letter(s[e])) continue;
    *pos = e;
    return u.unit;
  }
  return TextUnit::kNone;
}

bool text_read_degrees(const char* s, size_t n, size_t* pos) {
  size_t p = *pos;
  if (p < n && s[p] == '-') ++p;
  p = text_skip_spaces(s, n, p);
  if (p + 1 < n && static_cast<unsigned char>(s[p]) == 0xc2 && static_cast<unsigned char>(s[p + 1]) == 0xb0) {
    *pos = p + 2;
    return true;
  }
  static const char* const kWords[] = {"degrees", "degree", "deg"};
  for (const char* w : kWords) {
    if (!text_has_at(s, n, p, w)) continue;
    size_t e = p;
    while (w[e - p]) ++e;
    if (e < n && text_is_letter(s[e])) continue;
    *pos = e;
    return true;
  }
  return false;
}

}  // namespace dexmill
