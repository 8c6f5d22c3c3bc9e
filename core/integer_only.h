// Forced include (-include) for every translation unit of core/ and display/.
//
// core/README.md, invariant 1: no floating point in core/ or display/. The compiler
// enforces it: after this header, the identifiers `float` and `double` are
// poisoned, so any use is a hard error. `#pragma GCC poison` also fires inside
// system headers, so the few standard headers core/ and display/ may use are
// included here first (their include guards make later includes no-ops).
// Any other standard header included later fails to compile, which keeps these
// folders to the freestanding subset on purpose.
#ifndef DEXMILL_CORE_INTEGER_ONLY_H
#define DEXMILL_CORE_INTEGER_ONLY_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <limits>
#include <type_traits>
#include <utility>

#pragma GCC poison float double

#endif
