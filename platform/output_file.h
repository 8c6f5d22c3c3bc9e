// Output files are written completely or not at all: data goes to a
// temporary file beside the target, which is renamed over it on commit.
#ifndef DEXMILL_PLATFORM_ATOMIC_FILE_H
#define DEXMILL_PLATFORM_ATOMIC_FILE_H

#include <cstddef>
#include <cstdio>

namespace dexmill {

class AtomicFile {
 public:
  AtomicFile() = default;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // abandons (removes the temporary) unless committed

  // Opens "<path>.tmp-<pid>" for writing. False on failure (see error()).
  bool open(const char* path);
  // Appends bytes; failures are remembered and reported by commit().
  void write(const void* data, std::size_t n);
  void printf(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
  // Flushes, closes and renames onto the target. False on any failure, in
  // which case the target is untouched and the temporary removed.
  bool commit();
  // Text of the first failure, e.g. "cannot write 'out/x.ppm': No space left on device".
  const char* error() const { return error_; }

 private:
  void set_error(const char* what, const char* path);
  void abandon();

  std::FILE* f_ = nullptr;
  char path_[1024] = {0};
  char tmp_[1100] = {0};
  char error_[1200] = {0};
  bool failed_ = false;
};

}  // namespace dexmill

#endif
