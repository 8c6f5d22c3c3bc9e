// Hands out 8-byte aligned pieces of one block of caller memory, or only
// counts them (with no block): how a layout is written once for both its
// size query and its set-up (core/sim/sim_create.cpp, the embedding API's
// display/api/sim_create.cpp).
#ifndef DEXMILL_CORE_SIM_CARVER_H
#define DEXMILL_CORE_SIM_CARVER_H

#include <stddef.h>

namespace dexmill {

class Carver {
 public:
  // base: the block (8-byte aligned), or null to count.
  explicit Carver(char* base) : base_(base) {}
  // Room for n T's at the next multiple of 8 bytes (null when counting).
  template <class T>
  T* take(size_t n) {
    const size_t at = (used_ + 7) & ~size_t{7};
    used_ = at + n * sizeof(T);
    return base_ ? reinterpret_cast<T*>(base_ + at) : nullptr;
  }
  // Bytes taken so far, padding included.
  size_t used() const { return used_; }

 private:
  char* base_;
  size_t used_ = 0;
};

}  // namespace dexmill

#endif
