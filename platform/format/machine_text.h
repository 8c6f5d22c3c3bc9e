// The text under the machine files' readers (machine_file.h): lines, spans
// of a line, exact numbers and errors at their columns, shared by the
// LinuxCNC INI, grbl and parameter-file readers (machine_ini.cpp,
// machine_grbl.cpp, machine_var.cpp). Internal to platform/format.
#ifndef DEXMILL_PLATFORM_FORMAT_MACHINE_TEXT_H
#define DEXMILL_PLATFORM_FORMAT_MACHINE_TEXT_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/math/decimal.h"
#include "platform/format/machine_file.h"

namespace dexmill {
namespace machine_text {

constexpr const char* kNotMachine = "not a LinuxCNC INI file or a grbl settings dump ($$)";
constexpr int64_t kLimitNm = int64_t{10000} * kNmPerMm;                   // 10 m, as G-code coordinates
constexpr int64_t kMaxVelocityNmPerMin = int64_t{600000} * kNmPerMm;       // 10 m/s
constexpr int64_t kMaxAccelNmPerS2 = int64_t{1000000} * kNmPerMm;          // 1000 m/s^2
constexpr int64_t kMaxFeedOverridePpm = 100000000;                         // 100 times
constexpr int32_t kMaxParameter = 5601;                                    // LinuxCNC's RS274NGC_MAX_PARAMETERS - 1


inline std::string error_at(const char* name, uint32_t line, std::size_t col, const std::string& what) {
  return std::string(name) + ":" + std::to_string(line) + ":" + std::to_string(col) + ": error: " + what;
}

inline bool blank(char c) { return c == ' ' || c == '\t'; }
inline bool digit(char c) { return c >= '0' && c <= '9'; }
inline char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// Text s[0, n) that starts at column col (1-based) of its line.
struct Span {
  const char* s;
  std::size_t n, col;
  bool is(const char* w) const { return std::strlen(w) == n && std::memcmp(s, w, n) == 0; }
  bool is_nocase(const char* w) const {
    if (std::strlen(w) != n) return false;
    for (std::size_t i = 0; i < n; ++i)
      if (lower(s[i]) != lower(w[i])) return false;
    return true;
  }
  bool starts(const char* w) const { return std::strlen(w) <= n && std::memcmp(s, w, std::strlen(w)) == 0; }
  std::string str() const { return std::string(s, n); }
  Span from(std::size_t k) const { return Span{s + k, n - k, col + k}; }
  Span upto(std::size_t k) const { return Span{s, k, col}; }
  // Where c is first (n when it is not).
  std::size_t find(char c) const {
    const void* p = std::memchr(s, c, n);
    return p ? static_cast<std::size_t>(static_cast<const char*>(p) - s) : n;
  }
};

inline Span trim(Span w) {
  while (w.n && blank(w.s[0])) w = w.from(1);
  while (w.n && blank(w.s[w.n - 1])) --w.n;
  return w;
}

// A value for a message, cut short when long.
inline std::string quoted(const Span& w) {
  return "'" + (w.n > 40 ? std::string(w.s, 40) + "..." : w.str()) + "'";
}

// A decimal filling all of w: no blank inside (decimal_parse would skip
// it), nothing after it.
inline bool decimal_all(const Span& w, Decimal* d) {
  if (w.n == 0) return false;
  for (std::size_t i = 0; i < w.n; ++i)
    if (blank(w.s[i])) return false;
  std::size_t pos = 0;
  return decimal_parse(w.s, w.n, &pos, d) == DecimalParse::kOk && pos == w.n;
}

// A numeric value without a comment after it (`25 # mm/s`: LinuxCNC reads
// the number with strtod, which stops at the blank, so real INI files have
// them).
inline Span number_part(const Span& v) {
  for (std::size_t i = 1; i < v.n; ++i)
    if ((v.s[i] == '#' || v.s[i] == ';') && blank(v.s[i - 1])) return trim(Span{v.s, i, v.col});
  return v;
}

// round(d * scale) within [lo, hi].
inline bool scaled(Decimal d, int64_t scale, int64_t lo, int64_t hi, int64_t* out) {
  *out = decimal_scale(d, scale);
  return *out >= lo && *out <= hi;
}

// A whole number within [lo, hi].
inline bool whole(const Span& w, int64_t lo, int64_t hi, int64_t* out) {
  Decimal d;
  return decimal_all(w, &d) && decimal_to_int(d, out) && *out >= lo && *out <= hi;
}

// The lines of a text, each without its '\n' and a '\r' before it; a
// UTF-8 byte-order mark at the start is passed over. A NUL or another
// control byte (but a tab) is an error: not a text file.
enum class Next : uint8_t { kLine, kEnd, kBad };

class Lines {
 public:
  Lines(const char* name, const char* s, std::size_t n) : name_(name), s_(s), n_(n) {
    if (n_ >= 3 && std::memcmp(s_, "\xEF\xBB\xBF", 3) == 0) pos_ = 3;
  }

  Next next(Span* out, uint32_t* line, std::string* err) {
    if (pos_ >= n_) return Next::kEnd;
    const std::size_t b = pos_;
    std::size_t e = b;
    while (e < n_ && s_[e] != '\n') ++e;
    pos_ = e + 1;
    ++line_;
    std::size_t len = e - b;
    if (len && s_[b + len - 1] == '\r') --len;
    for (std::size_t i = 0; i < len; ++i) {
      const unsigned char c = static_cast<unsigned char>(s_[b + i]);
      if (c == 0) {
        *err = error_at(name_, line_, i + 1, "a NUL byte (is this a text file?)");
        return Next::kBad;
      }
      if ((c < 0x20 && c != '\t') || c == 0x7f) {
        char what[80];
        std::snprintf(what, sizeof what, "a control byte 0x%02x (is this a text file?)", c);
        *err = error_at(name_, line_, i + 1, what);
        return Next::kBad;
      }
    }
    *out = Span{s_ + b, len, 1};
    *line = line_;
    return Next::kLine;
  }

 private:
  const char* name_;
  const char* s_;
  std::size_t n_, pos_ = 0;
  uint32_t line_ = 0;
};

// Calls fn(line, number) for each line of the text; false at a line that
// is no text (*err said) or when fn returns false (fn says why).
template <class Fn>
bool each_line(const char* name, const char* text, std::size_t n, std::string* err, Fn fn) {
  Lines lines(name, text, n);
  for (;;) {
    Span l;
    uint32_t no = 0;
    const Next r = lines.next(&l, &no, err);
    if (r == Next::kBad) return false;
    if (r == Next::kEnd) return true;
    if (!fn(l, no)) return false;
  }
}

// What a reader keeps of where it is, and its error at a column there.
struct ReaderPlace {
  explicit ReaderPlace(const char* name) : name_(name) {}
  const char* name_;
  uint32_t line_ = 0;
  std::string err_;
  bool fail(std::size_t col, const std::string& what) {
    err_ = error_at(name_, line_, col, what);
    return false;
  }
  const std::string& error() const { return err_; }
};

// The readers of each kind (into f, whose spec's kind they set).
bool parse_ini(const char* name, const char* text, std::size_t n, const std::string& dir, MachineFile* f,
               std::string* err);
bool parse_grbl(const char* name, const char* text, std::size_t n, MachineFile* f, std::string* err);

}  // namespace machine_text
}  // namespace dexmill

#endif
