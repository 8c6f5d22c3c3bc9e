// Counting global operator new/delete for the test binary: lets a test prove
// that a stretch of code made no heap allocation (core/README.md, invariant 2).
#ifndef DEXMILL_TESTS_ALLOC_COUNT_H
#define DEXMILL_TESTS_ALLOC_COUNT_H
#include <cstdint>
namespace t {
// Number of calls to any form of operator new since the program started.
std::uint64_t heap_allocations();
}
#endif
