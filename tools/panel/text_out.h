// Text output of the golden and panel programs: integers in decimal or
// fixed-width hex, built in a line buffer and handed to a write function
// (tools/panel/board.h), never through printf (newlib-nano prints %llx
// wrongly, and a microcontroller needs none). Integer only, no heap.
#ifndef DEXMILL_TOOLS_PANEL_TEXT_OUT_H
#define DEXMILL_TOOLS_PANEL_TEXT_OUT_H

#include <stddef.h>
#include <stdint.h>

namespace golden {

// Line-buffered output; a line longer than the buffer is cut, never merged
// with the next.
class Out {
 public:
  using WriteFn = void (*)(const char* s, size_t n);
  explicit Out(WriteFn write) : write_(write) {}

  Out& str(const char* s);
  Out& dec(int64_t v);
  Out& udec(uint64_t v);
  Out& hex(uint64_t v, int digits = 16);
  // " key=value" pairs, the usual shape of a golden line.
  Out& kv(const char* key, int64_t v) { return str(" ").str(key).str("=").dec(v); }
  Out& kx(const char* key, uint64_t v, int digits = 16) { return str(" ").str(key).str("=").hex(v, digits); }
  // Ends the line and writes it.
  void end();

  int lines() const { return lines_; }

 private:
  void put(char c);
  WriteFn write_;
  char buf_[240];
  size_t n_ = 0;
  int lines_ = 0;
};

// A deterministic 64-bit generator (splitmix64) for sampled inputs.
struct Rng {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
};

}  // namespace golden

#endif
