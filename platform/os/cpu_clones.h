// DEXMILL_AVX2_CLONES before a function has the compiler build it twice on
// x86-64, for AVX2 (32-byte vectors) and for the baseline (SSE2), and pick
// the host's when the program loads (GCC and clang's target_clones, an ELF
// ifunc). For hot loops of integer arithmetic only, so that both builds
// give the same results: the bytes written never depend on the host.
// Elsewhere (other CPUs, wasm32) it is nothing.
#ifndef DEXMILL_PLATFORM_OS_CPU_CLONES_H
#define DEXMILL_PLATFORM_OS_CPU_CLONES_H

#if defined(__x86_64__) && defined(__ELF__) && (defined(__GNUC__) || defined(__clang__))
#define DEXMILL_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define DEXMILL_AVX2_CLONES
#endif

#endif
