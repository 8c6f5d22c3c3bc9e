// The machine's physical memory, which `dexmill run`'s default memory
// budget is a share of (tools/run/run_stock.h run_grid_budget).
#ifndef DEXMILL_PLATFORM_OS_MACHINE_MEMORY_H
#define DEXMILL_PLATFORM_OS_MACHINE_MEMORY_H

#include <cstdint>

namespace dexmill {

// The bytes of physical memory the OS reports (POSIX sysconf: pages times
// the page size), or 0 where it does not say.
uint64_t machine_memory_bytes();

}  // namespace dexmill

#endif
