// The golden-output program (`make xcheck`): one text output that must be
// byte-identical on every compiler, optimisation level and CPU, from x86-64
// to a Cortex-M0+ with no FPU and no 64-bit multiplier.
//
// The output is a list of sections, each a function that prints lines
// through an Out. To add output (frame hashes in both pixel formats, G-code
// path traces, ...): write `void golden_NAME(Out& out)` in
// tests/golden/golden_NAME.cpp (any tests/golden/golden_*.cpp is built on
// every target), declare it below, add one line to kSections in golden.cpp,
// then run `make bless` to re-pin tests/golden/golden.out from this host's
// build and `make xcheck` to see every target agree, and say why in the
// commit (tests/golden/README.md).
//
// Rules for section code, so that it runs unchanged on a microcontroller:
// integer only (it is compiled with core/integer_only.h forced in), no heap
// (grids and cutters come from the static Arena), no stdio (print with Out),
// and keep the work small: the Cortex-M targets run at -Os under qemu's TCG.
#ifndef DEXMILL_TESTS_GOLDEN_GOLDEN_H
#define DEXMILL_TESTS_GOLDEN_GOLDEN_H

#include <stddef.h>
#include <stdint.h>

#include "tools/panel/text_out.h"

namespace golden {

// Static scratch memory for grids and cutters (no heap anywhere). take()
// returns null when the arena is exhausted; reset() frees everything.
class Arena {
 public:
  template <class T>
  T* take(size_t count) {
    return static_cast<T*>(take_bytes(count * sizeof(T), alignof(T)));
  }
  void reset() { used_ = 0; }
  size_t used() const { return used_; }
  size_t capacity() const;

 private:
  void* take_bytes(size_t bytes, size_t align);
  size_t used_ = 0;
};
Arena& arena();

struct Section {
  const char* name;
  void (*run)(Out& out);
};

// The sections, in output order (golden.cpp).
extern const Section kSections[];
extern const size_t kSectionCount;

// Prints the header, every section and a trailer; returns the exit status
// (non-zero when a section reported a failure through fail()).
int run_all(Out::WriteFn write);

// A section that cannot produce its output (arena exhausted, a set-up call
// failed) says so on a line and makes the program exit non-zero.
void fail(Out& out, const char* what);

// ---- sections ---------------------------------------------------------------
void golden_math(Out& out);   // golden_math.cpp: fixed point, roots, muldiv, CORDIC
void golden_tool(Out& out);   // golden_tool.cpp: tool profiles and cutter dexel sets
void golden_stamp(Out& out);  // golden_stamp.cpp: grid hashes of cutting programs, m = 8/16/32
void golden_mill(Out& out);   // golden_mill.cpp: a G-code program cut by core/mill (sweep, stamp), m = 8/16/32
void golden_path(Out& out);   // golden_mill.cpp: the same program's canonical records and arc chords, hashed
void golden_flow(Out& out);   // golden_mill.cpp: a program of expressions and o-word loops and calls, traced
void golden_motion(Out& out);  // golden_motion.cpp: G33/G33.1, G95, G43.2, M70-M73, rotation, NURBS, traced
void golden_frame(Out& out);  // golden_frame.cpp: frames in both pixel and z formats, full and incremental
void golden_safety(Out& out);  // golden_safety.cpp: one finding of each safety check, traced to its line
void golden_texture(Out& out);  // golden_texture.cpp: noise, textures and material presets (core/material)
void golden_regress(Out& out);  // golden_regress.cpp: regression cases named after their bug
void golden_builtin(Out& out);  // golden_builtin.cpp: the built-in design parts (the paper's four workpieces)
void golden_demo(Out& out);  // golden_demo.cpp: the paper's four workpieces cut by their zig paths, assessed, drawn

}  // namespace golden

#endif
