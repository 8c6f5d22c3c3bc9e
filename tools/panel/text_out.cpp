// Out (golden_out.h): decimal and hex formatting into a line buffer.
#include "tools/panel/text_out.h"

namespace golden {

void Out::put(char c) {
  if (n_ < sizeof buf_) buf_[n_++] = c;
}

Out& Out::str(const char* s) {
  while (*s) put(*s++);
  return *this;
}

Out& Out::udec(uint64_t v) {
  char d[20];
  int n = 0;
  do {
    d[n++] = static_cast<char>('0' + v % 10u);
    v /= 10u;
  } while (v != 0);
  while (n > 0) put(d[--n]);
  return *this;
}

Out& Out::dec(int64_t v) {
  if (v < 0) {
    put('-');
    return udec(static_cast<uint64_t>(0) - static_cast<uint64_t>(v));
  }
  return udec(static_cast<uint64_t>(v));
}

Out& Out::hex(uint64_t v, int digits) {
  for (int i = digits - 1; i >= 0; --i) put("0123456789abcdef"[(v >> (4 * i)) & 15u]);
  return *this;
}

void Out::end() {
  put('\n');
  if (n_ == sizeof buf_) buf_[n_ - 1] = '\n';  // an over-long line is cut, never merged
  write_(buf_, n_);
  n_ = 0;
  ++lines_;
}

}  // namespace golden
