// Host memory of the user's size (a grid, a design, an image), which may
// not be there: asked for without throwing, so that the caller can say
// what it was for ("cannot allocate 768 MiB for the 8192x8192 grid", exit 3)
// instead of ending in an uncaught std::bad_alloc. What any other
// allocation does when memory runs out is the binary's (tools/cli/main.cpp).
#ifndef DEXMILL_PLATFORM_OS_MEMORY_H
#define DEXMILL_PLATFORM_OS_MEMORY_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace dexmill {

// A zeroed block (calloc: pages the cut never touches cost nothing).
class ZeroedBlock {
 public:
  ZeroedBlock() = default;
  ZeroedBlock(const ZeroedBlock&) = delete;
  ZeroedBlock& operator=(const ZeroedBlock&) = delete;
  ~ZeroedBlock();
  // False, with nothing held, when the memory is not there.
  bool allocate(std::size_t bytes);
  void* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  void* data_ = nullptr;
  std::size_t size_ = 0;
};

// "768 MiB", "1.5 GiB", "12 KiB", "100 bytes": a size for messages
// (rounded down), into out (n bytes; 32 hold any); the second allocates
// nothing, for a message about memory that ran out.
std::string size_text(uint64_t bytes);
void size_text(uint64_t bytes, char* out, std::size_t n);

}  // namespace dexmill

#endif
