// The machine's physical memory; see machine_memory.h.
#include "platform/os/machine_memory.h"

#include <unistd.h>

namespace dexmill {

uint64_t machine_memory_bytes() {
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGE_SIZE)
  const long pages = sysconf(_SC_PHYS_PAGES), page_bytes = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_bytes <= 0) return 0;
  const uint64_t p = static_cast<uint64_t>(pages), b = static_cast<uint64_t>(page_bytes);
  return p > UINT64_MAX / b ? UINT64_MAX : p * b;
#else
  return 0;
#endif
}

}  // namespace dexmill
