// Tasks spread over threads (threads are allowed in platform/ and tools/,
// never in core/ or display/). A caller whose output must not depend on
// the thread count gives each task its own result slot: which thread runs
// a task, and when, is the only thing that varies.
#ifndef DEXMILL_PLATFORM_OS_PARALLEL_H
#define DEXMILL_PLATFORM_OS_PARALLEL_H

#include <cstddef>
#include <functional>

namespace dexmill {

// The host's hardware threads (1 when it does not say), at most 64.
int host_threads();

// Runs task(0) .. task(count - 1), each once, on up to `threads` threads
// (this one among them; threads <= 0: host_threads()), and returns when all
// are done. Tasks are handed out in order as threads come free. When a
// thread cannot be started, the ones running (this one at least) do the rest.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& task);

}  // namespace dexmill

#endif
