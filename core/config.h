// Compile-time options of dexmill, in one place (core/README.md, habit 12).
#ifndef DEXMILL_CORE_CONFIG_H
#define DEXMILL_CORE_CONFIG_H

#include <stdint.h>

// m, the number of bits of a dexel height (paper §2.1): 8, 16 or 32.
// The grid and cutting code are templates over the height type, so tests
// exercise all three; this picks the one the program uses.
#ifndef DEXMILL_HEIGHT_BITS
#define DEXMILL_HEIGHT_BITS 16
#endif

// Checked arithmetic: 1 makes the helpers that rely on a caller's range
// argument instead of testing (mul_shift_fit, core/math/fixed.h) check it,
// and reach __builtin_unreachable where it fails, which UBSan reports
// (-fsanitize=unreachable) with the place. `make SAN=1` turns it on, so that
// the range tests (tests/test_ranges.cpp) prove those arguments; 0 (the
// default) compiles the checks away.
#ifndef DEXMILL_CHECKED_ARITH
#define DEXMILL_CHECKED_ARITH 0
#endif

// Whether the CPU multiplies 64 x 64 -> 128 bits in one instruction: the
// 64-bit CPUs, where the compiler has __int128. WebAssembly has __int128 in
// clang but no such instruction (i64.mul gives the low half; a 128-bit
// product is a call to the builtins' __multi3, a division __udivti3), so it
// takes the 32-bit CPUs' paths for products (mul_shift's test of int32
// operands first), with the same bits (core/math/fixed.h): KB-850's cut in
// the page went from about 720 to 620 ms (tools/scripts/web-test.sh).
#if defined(__SIZEOF_INT128__) && !defined(__wasm__)
#define DEXMILL_WIDE_MUL 1
#else
#define DEXMILL_WIDE_MUL 0
#endif

namespace dexmill {

constexpr bool kCheckedArith = DEXMILL_CHECKED_ARITH != 0;

// The word width of the sweep's column loops (core/cut/sweep_piece.h, the
// row kernels): 32-bit offsets, squares and slope products where the CPU
// has no 128-bit integers (mul_shift's test for a 32-bit CPU,
// core/math/fixed.h), 64-bit ones elsewhere, where those cost the same
// (WebAssembly among them: its 64-bit words are native, only the 128-bit
// product is not).
// Both widths give the same bits; the host tests run both (core/cut/
// sweep_internal.h, sweep_line_w).
#ifdef __SIZEOF_INT128__
constexpr int kSweepWordBits = 64;
#else
constexpr int kSweepWordBits = 32;
#endif

template <int Bits> struct HeightOfBits;
template <> struct HeightOfBits<8> { using type = uint8_t; };
template <> struct HeightOfBits<16> { using type = uint16_t; };
template <> struct HeightOfBits<32> { using type = uint32_t; };

// The program's dexel height type.
using height_t = typename HeightOfBits<DEXMILL_HEIGHT_BITS>::type;

}  // namespace dexmill

#endif
