// web_arena.cpp - the arena of web_arena.h over wasm32's linear memory.
#include "platform/web/web_arena.h"

// Defined by wasm-ld: the first byte past the module's data and stack.
extern "C" unsigned char __heap_base;

namespace dexmill {
namespace web {

namespace {
constexpr size_t kPage = 65536;  // a WebAssembly page
}

size_t arena_memory_bytes() { return __builtin_wasm_memory_size(0) * kPage; }

void* arena_reserve(size_t bytes) {
  const uintptr_t base = (reinterpret_cast<uintptr_t>(&__heap_base) + 7) & ~static_cast<uintptr_t>(7);
  const size_t have = arena_memory_bytes();
  if (bytes > SIZE_MAX - base) return nullptr;
  const size_t end = base + bytes;
  if (end > have) {
    const size_t pages = (end - have + kPage - 1) / kPage;
    if (__builtin_wasm_memory_grow(0, pages) == SIZE_MAX) return nullptr;
  }
  return reinterpret_cast<void*>(base);
}

}  // namespace web
}  // namespace dexmill
