// Host memory of the user's size; see memory.h.
#include "platform/os/memory.h"

#include <cstdio>
#include <cstdlib>

namespace dexmill {

ZeroedBlock::~ZeroedBlock() { std::free(data_); }

bool ZeroedBlock::allocate(std::size_t bytes) {
  std::free(data_);
  data_ = std::calloc(bytes ? bytes : 1, 1);
  size_ = data_ ? bytes : 0;
  return data_ != nullptr;
}

std::string size_text(uint64_t bytes) {
  char b[32];
  size_text(bytes, b, sizeof b);
  return b;
}

void size_text(uint64_t bytes, char* b, std::size_t n) {
  if (bytes < 1024) {
    std::snprintf(b, n, "%llu bytes", static_cast<unsigned long long>(bytes));
  } else {
    static const char* const kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int u = 0;
    uint64_t whole = bytes >> 10, below = bytes;  // the size in kUnits[u], and in the unit below it
    while (whole >= 1024 && u < 5) {
      below = whole;
      whole >>= 10;
      ++u;
    }
    const unsigned tenth = static_cast<unsigned>((below & 1023) * 10 / 1024);  // rounded down
    if (whole < 10 && tenth)
      std::snprintf(b, n, "%llu.%u %s", static_cast<unsigned long long>(whole), tenth, kUnits[u]);
    else
      std::snprintf(b, n, "%llu %s", static_cast<unsigned long long>(whole), kUnits[u]);
  }
}

}  // namespace dexmill
