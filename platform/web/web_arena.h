// web_arena.h - the one arena of the WebAssembly build: the linear memory
// past the module's own data (the linker's __heap_base), grown to a job's
// size while the job is made (web_api.cpp: the simulation, then its view,
// which is sized from it), never while cutting. A job as large as or
// smaller than the last reuses it as it is.
#ifndef DEXMILL_PLATFORM_WEB_WEB_ARENA_H
#define DEXMILL_PLATFORM_WEB_WEB_ARENA_H

namespace dexmill {
namespace web {

// The arena's start (8-byte aligned) with at least `bytes` behind it, the
// memory grown first if it is short; null if the browser refuses to grow it.
void* arena_reserve(size_t bytes);

// The linear memory's size in bytes, as the page sees it.
size_t arena_memory_bytes();

}  // namespace web
}  // namespace dexmill

#endif
