// A canned cycle's words, from the block or kept from the last one
// (BlockRunner::cycle_words, interp_cycles.cpp). A part of the block runner
// (block_runner.h), for the interpreter's own files only.
#ifndef DEXMILL_CORE_INTERP_CYCLE_WORDS_H
#define DEXMILL_CORE_INTERP_CYCLE_WORDS_H

#include <stdint.h>

namespace dexmill {

struct CycleWords {
  int64_t r_raw, z_raw;  // R and the plane axis's word as written, nm
  int64_t repeats;       // L
  int64_t q;             // G73/G83 peck, nm
  int64_t p_ms;          // dwell
  int64_t ijk[3];        // G87's I, J, K, nm
};

}  // namespace dexmill

#endif
