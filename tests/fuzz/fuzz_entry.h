// Each fuzz target's body is a function of its own, `int fuzz_NAME(const
// uint8_t*, size_t)`, and DEXMILL_FUZZ_ENTRY makes it libFuzzer's entry
// point. tests/test_fuzz_regress.cpp includes every target into one program
// to replay their inputs in `make test`; it defines DEXMILL_FUZZ_REPLAY so
// that the entry points (one name each) are left out.
#ifndef DEXMILL_TESTS_FUZZ_ENTRY_H
#define DEXMILL_TESTS_FUZZ_ENTRY_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#ifdef DEXMILL_FUZZ_REPLAY
#define DEXMILL_FUZZ_ENTRY(fn)
#else
#define DEXMILL_FUZZ_ENTRY(fn) \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return fn(data, size); }
#endif

// A broken promise of the code under test: abort, which libFuzzer reports
// as a crash with the input that did it (and `make test` as a dead process).
#define FUZZ_REQUIRE(cond)                                                              \
  do {                                                                                  \
    if (!(cond)) {                                                                      \
      std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                     \
    }                                                                                   \
  } while (0)

#endif
