// dexmill: entry point; dispatches to the subcommands (tools/cli/cli.h).
//
// And the binary's operator new: as the library's (malloc, free), but an
// allocation that fails ends the process with the size it asked for,
// exit 3, and the temporaries removed, rather than an uncaught
// std::bad_alloc (abort, exit 134, the temporaries left). No unwinding: a
// failure may come while core/ (built without exceptions) is on the stack.
// Memory of the user's size is asked for without throwing first, so that
// its message says what it was for (platform/os/memory.h). Here, not in
// platform/: the tests replace operator new themselves (tests/alloc_count.cpp).
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <new>

#include "platform/os/memory.h"
#include "platform/os/process.h"
#include "tools/cli/cli.h"

namespace {

[[noreturn]] void out_of_memory(std::size_t bytes) {
  char size[32], msg[128];
  dexmill::size_text(bytes, size, sizeof size);
  const int n = std::snprintf(msg, sizeof msg, "dexmill: error: out of memory: cannot allocate %s\n", size);
  if (n > 0) (void)!write(2, msg, static_cast<std::size_t>(n));
  dexmill::cleanup_remove_all();
  _exit(dexmill::cli::kExitIo);
}

}  // namespace

void* operator new(std::size_t n) {
  if (void* p = std::malloc(n ? n : 1)) return p;
  out_of_memory(n);
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return std::malloc(n ? n : 1); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return std::malloc(n ? n : 1); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

int main(int argc, char** argv) { return dexmill::cli::main(argc, argv); }
