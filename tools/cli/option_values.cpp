// Option values; see option_values.h.
#include "tools/cli/option_values.h"

#include <strings.h>

#include <cstring>

#include "core/math/decimal.h"
#include "core/math/fixed.h"
#include "core/interp/interp.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {

bool parse_scaled(const char* s, std::size_t n, int64_t scale, int64_t* out) {
  Decimal d;
  std::size_t pos = 0;
  if (n == 0 || decimal_parse(s, n, &pos, &d) != DecimalParse::kOk || pos != n) return false;
  *out = decimal_scale(d, scale);
  return true;
}

bool parse_scaled(const char* s, int64_t scale, int64_t* out) { return parse_scaled(s, std::strlen(s), scale, out); }

bool parse_pair(const char* s, int64_t lo, int64_t hi, int32_t* a, int32_t* b) {
  const char* x = std::strchr(s, 'x');
  if (!x) x = std::strchr(s, 'X');
  if (!x) return false;
  int64_t va, vb;
  if (!parse_scaled(s, static_cast<std::size_t>(x - s), 1, &va) || !parse_scaled(x + 1, 1, &vb)) return false;
  for (const char* p = s; *p; ++p)
    if (*p == '.' || *p == '-' || *p == '+' || *p == ' ') return false;
  if (va < lo || va > hi || vb < lo || vb > hi) return false;
  *a = static_cast<int32_t>(va);
  *b = static_cast<int32_t>(vb);
  return true;
}

bool parse_size_bytes(const char* s, uint64_t* bytes) {
  uint64_t n = 0;
  const char* p = s;
  for (; *p >= '0' && *p <= '9'; ++p) {
    const uint64_t digit = static_cast<uint64_t>(*p - '0');
    if (n > (UINT64_MAX - digit) / 10) return false;
    n = n * 10 + digit;
  }
  if (p == s) return false;
  int shift_bits = 0;
  if (*p) {
    switch (*p) {
      case 'K': case 'k': shift_bits = 10; break;
      case 'M': case 'm': shift_bits = 20; break;
      case 'G': case 'g': shift_bits = 30; break;
      default: return false;
    }
    if (p[1]) return false;
  }
  if (n == 0 || n > (UINT64_MAX >> shift_bits)) return false;
  *bytes = n << shift_bits;
  return true;
}

bool parse_mm_list(const char* s, int n, int64_t* v) {
  int k = 0;
  const char* p = s;
  for (;;) {
    const char* c = std::strchr(p, ',');
    const std::size_t len = c ? static_cast<std::size_t>(c - p) : std::strlen(p);
    if (k == n || !parse_scaled(p, len, kNmPerMm, &v[k])) return false;
    if (v[k] > kGcodeMaxCoordNm || v[k] < -kGcodeMaxCoordNm) return false;
    ++k;
    if (!c) break;
    p = c + 1;
  }
  return k == n;
}

bool parse_box(const char* s, int64_t* v) {
  return parse_mm_list(s, 6, v) && v[0] < v[3] && v[1] < v[4] && v[2] < v[5];
}

bool has_extension(const std::string& name, const char* ext) {
  const std::size_t e = std::strlen(ext);
  return name.size() > e && strcasecmp(name.c_str() + name.size() - e, ext) == 0;
}

int take_file(std::string* file, const char* arg, int index) {
  if (index > 0) return fail(kExitUsage, "more than one input file ('%s' and '%s')", file->c_str(), arg);
  *file = arg;
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
