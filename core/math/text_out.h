// Text into a caller's buffer, snprintf-like without a C library: what
// fits is written, the length it would have is counted (core/gcode/error.cpp's
// messages, core/tool/table_row.cpp's).
#ifndef DEXMILL_CORE_MATH_TEXT_OUT_H
#define DEXMILL_CORE_MATH_TEXT_OUT_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

struct TextOut {
  char* buf;
  size_t n, len;
  void put(char c) {
    if (len + 1 < n) buf[len] = c;
    ++len;
  }
  void puts(const char* s) {
    while (*s) put(*s++);
  }
  void put(const char* s, size_t k) {
    for (size_t i = 0; i < k; ++i) put(s[i]);
  }
  void put_uint(uint64_t v) {
    char digits[24];
    int k = 0;
    do { digits[k++] = static_cast<char>('0' + v % 10); v /= 10; } while (v);
    while (k) put(digits[--k]);
  }
  void put_int(int64_t v) {
    if (v < 0) put('-');
    put_uint(v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v));
  }
  // NUL terminates what was written; the length written.
  size_t end() {
    if (n) buf[len < n ? len : n - 1] = 0;
    return len < n ? len : (n ? n - 1 : 0);
  }
};

}  // namespace dexmill

#endif
