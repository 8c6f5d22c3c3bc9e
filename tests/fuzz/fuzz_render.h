// The fuzz target's last stage: render the grid into a small frame. A
// no-op until display/ provides a renderer (then it draws and checks it).
#ifndef DEXMILL_TESTS_FUZZ_RENDER_H
#define DEXMILL_TESTS_FUZZ_RENDER_H

#include "core/grid.h"

inline void fuzz_render(const dexmill::DexelGrid<uint16_t>&) {}

#endif
