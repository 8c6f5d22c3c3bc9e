#include "platform/os/parallel.h"

#include <algorithm>
#include <atomic>
#include <system_error>
#include <thread>
#include <vector>

namespace dexmill {

namespace {
constexpr int kMaxThreads = 64;
}  // namespace

int host_threads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(std::min<unsigned>(n, kMaxThreads));
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& task) {
  const int want = threads <= 0 ? host_threads() : std::min(threads, kMaxThreads);
  const std::size_t workers = std::min<std::size_t>(count, static_cast<std::size_t>(want));
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) task(i);
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) {
    try {
      pool.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads: those started and this one share the tasks
    }
  }
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace dexmill
