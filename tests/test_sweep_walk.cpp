// The sweep's column walks (core/cut/sweep_cut.h, RoundWalk30*): a column's
// u or v, round(acc / 2^30) with acc stepping by d, from the 64-bit
// accumulator and from the split whole/fraction form 32-bit CPUs use. Hosts
// cut with the 64-bit form, so the golden output checks only that one; here
// both are held to the definition, (acc + 2^29) >> 30 with exact 64-bit
// arithmetic, at every column whose value fits int32 (the only values the
// sweep reads; a column past one that did not still has to come out right:
// the whole part is kept mod 2^32).
#include <cstdint>

#include "core/cut/sweep_cut.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

struct WalkCheck {
  uint64_t values = 0, bad = 0;
  void row(int64_t acc0, int64_t d, int n) {
    RoundWalk30Split split;
    RoundWalk30Acc<int32_t> acc32;
    RoundWalk30Acc<int64_t> acc64;
    split.start(acc0, d);
    acc32.start(acc0, d);
    acc64.start(acc0, d);
    int64_t acc = acc0;
    for (int i = 0; i < n; ++i, acc += d, split.next(), acc32.next(), acc64.next()) {
      const int64_t want = (acc + (static_cast<int64_t>(1) << 29)) >> 30;
      if (acc64.value() != want) ++bad;
      if (want != static_cast<int32_t>(want)) continue;
      ++values;
      if (split.value() != want || acc32.value() != want) ++bad;
    }
  }
};

}  // namespace

// Random rows: starts anywhere in +-2^31 U (q30), steps from a fraction of
// a U to 2^31 U a column, both signs, rows that leave the int32 range and
// come back (negative steps after positive starts and the reverse).
TEST(sweep_walk_random) {
  t::Rng rng(2501);
  WalkCheck c;
  constexpr int64_t kLim = static_cast<int64_t>(1) << 61;  // 2^31 U in q30
  for (int row = 0; row < 100000; ++row) {
    const int bits = static_cast<int>(rng.next() % 62);
    const int64_t acc0 = rng.range(-(static_cast<int64_t>(1) << bits), static_cast<int64_t>(1) << bits);
    const int step_bits = static_cast<int>(rng.next() % 62);
    int64_t d = rng.range(0, static_cast<int64_t>(1) << step_bits);
    if (rng.next() & 1) d = -d;
    int n = 1 + static_cast<int>(rng.next() % 64);
    // Stay within 2^62 (no overflow of the reference accumulator).
    if (d != 0 && n > (kLim * 2) / (d < 0 ? -d : d)) n = static_cast<int>((kLim * 2) / (d < 0 ? -d : d));
    c.row(acc0, d, n);
  }
  CHECK_EQ(c.bad, uint64_t{0});
  CHECK_GT(c.values, uint64_t{1000000});
}

// The edges: values next to INT32_MIN and INT32_MAX, fractions next to the
// rounding tie (2^29) and the carry (2^30), unit, zero and tiny steps.
TEST(sweep_walk_edges) {
  WalkCheck c;
  constexpr int64_t kQ30 = static_cast<int64_t>(1) << 30, kHalf = kQ30 / 2;
  const int64_t wholes[] = {INT32_MIN, INT32_MIN + 1, -1, 0, 1, INT32_MAX - 1, INT32_MAX};
  const int64_t fracs[] = {-kHalf - 1, -kHalf, -kHalf + 1, -1, 0, 1, kHalf - 1, kHalf, kHalf + 1};
  const int64_t steps[] = {0, 1, -1, kHalf, -kHalf, kQ30 - 1, -(kQ30 - 1), kQ30, -kQ30, kQ30 + 1, -(kQ30 + 1),
                           3 * kQ30 + 12345, -(3 * kQ30 + 12345), static_cast<int64_t>(1) << 40};
  for (int64_t w : wholes)
    for (int64_t f : fracs)
      for (int64_t d : steps) c.row(w * kQ30 + f, d, 40);
  CHECK_EQ(c.bad, uint64_t{0});
  CHECK_GT(c.values, uint64_t{10000});
}
