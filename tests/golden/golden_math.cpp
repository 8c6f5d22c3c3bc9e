// Golden section "math": core/math/fixed.h and core/math/trig.h at their edges and at
// sampled inputs. Edge cases print one value each (readable in a diff);
// sampled inputs print one hash over all results (compact, and any single
// differing bit changes it).
#include <stdint.h>

#include "core/grid/grid.h"
#include "core/math/fixed.h"
#include "core/math/hash.h"
#include "core/math/trig.h"
#include "tests/golden/golden.h"

using namespace dexmill;

namespace golden {
namespace {

constexpr int kSamples = 2000;

// A random int64 of random magnitude (1 to 63 bits) and sign.
int64_t sample_i64(Rng& r, int max_bits = 63) {
  const uint64_t bits = 1u + r.next() % static_cast<uint64_t>(max_bits);
  const uint64_t mag = r.next() >> (64u - bits);
  return (r.next() & 1u) ? static_cast<int64_t>(static_cast<uint64_t>(0) - mag) : static_cast<int64_t>(mag);
}
uint64_t sample_u64(Rng& r) { return r.next() >> (r.next() % 64u); }

void put_hash(Out& out, const char* name, int samples, const Hash64& h) {
  out.str(name).kv("samples", samples).kx("hash", h.value()).end();
}

void roots(Out& out) {
  const uint64_t edges[] = {0u, 1u, 2u, 3u, 4u, 15u, 16u, 17u, 0xFFFFFFFEu, 0xFFFFFFFFu, 0x100000000ull,
                            0xFFFFFFFE00000001ull, 0xFFFFFFFE00000002ull, 0xFFFFFFFF00000000ull, UINT64_MAX};
  for (uint64_t v : edges) {
    out.str("isqrt").kx("v", v).kv("floor", isqrt_u64(v)).kv("round", isqrt_round_u64(v)).end();
  }
  out.str("hypot").kv("3_4", hypot_round(3, 4)).kv("neg", hypot_round(-5, -12));
  out.kv("max", hypot_round(INT32_MAX, INT32_MIN + 1)).kv("half", hypot_round(1, 1)).end();
  const U128 wide[] = {{0, 0}, {0, 1}, {1, 0}, {UINT64_MAX, UINT64_MAX}, {0x3FFFFFFFFFFFFFFFull, 0x8000000000000001ull}};
  for (const U128& w : wide) out.str("isqrt128").kx("hi", w.hi).kx("lo", w.lo).kx("root", isqrt_u128(w)).end();

  Rng r{1};
  Hash64 h;
  for (int i = 0; i < kSamples; ++i) {
    const uint64_t v = sample_u64(r);
    h.uint_le(isqrt_u64(v), 4);
    h.uint_le(isqrt_round_u64(v), 4);
    const int64_t a = sample_i64(r, 31), b = sample_i64(r, 31);
    h.uint_le(hypot_round(a, b), 4);
    const U128 p = mul_wide_u64(sample_u64(r), sample_u64(r));
    h.uint_le(p.hi, 8);
    h.uint_le(p.lo, 8);
    h.uint_le(isqrt_u128(p), 8);
  }
  put_hash(out, "roots_sampled", kSamples, h);
}

void division(Out& out) {
  struct Pair { int64_t n, d; };
  const Pair edges[] = {{7, 2}, {-7, 2}, {7, -2}, {-7, -2}, {5, 10}, {-5, 10}, {4, 10}, {-4, 10}, {0, -3},
                        {INT64_MIN, -1}, {INT64_MIN, 1}, {INT64_MAX, -1}, {INT64_MIN, INT64_MAX}, {INT64_MAX, INT64_MIN},
                        {INT64_MIN, 2}, {INT64_MAX, 2}};
  for (const Pair& p : edges) {
    out.str("div").kv("n", p.n).kv("d", p.d).kv("floor", div_floor(p.n, p.d)).kv("ceil", div_ceil(p.n, p.d));
    out.kv("round", div_round(p.n, p.d)).end();
  }
  struct Triple { int64_t a, b, c; };
  const Triple md[] = {{1, 1, 2}, {-1, 1, 2}, {3, 5, -4}, {-3, -5, 4}, {INT64_MAX, INT64_MAX, INT64_MAX},
                       {INT64_MAX, INT64_MAX, 1}, {INT64_MIN, 1, 1}, {INT64_MIN, -1, 1}, {INT64_MIN, INT64_MIN, -1},
                       {1000000007, 998244353, 65537}, {-1000000007, 998244353, 65537}, {INT64_MIN, 3, 2}};
  for (const Triple& t : md) {
    out.str("muldiv").kv("a", t.a).kv("b", t.b).kv("c", t.c).kv("round", muldiv_round(t.a, t.b, t.c));
    out.kv("floor", muldiv_floor(t.a, t.b, t.c)).end();
  }
  Rng r{2};
  Hash64 h;
  for (int i = 0; i < kSamples; ++i) {
    const int64_t n = sample_i64(r);
    int64_t d = sample_i64(r);
    if (d == 0) d = 1;
    h.uint_le(static_cast<uint64_t>(div_floor(n, d)), 8);
    h.uint_le(static_cast<uint64_t>(div_ceil(n, d)), 8);
    h.uint_le(static_cast<uint64_t>(div_round(n, d)), 8);
    const int64_t a = sample_i64(r), b = sample_i64(r);
    int64_t c = sample_i64(r);
    if (c == 0) c = -1;
    h.uint_le(static_cast<uint64_t>(muldiv_round(a, b, c)), 8);
    h.uint_le(static_cast<uint64_t>(muldiv_floor(a, b, c)), 8);
  }
  put_hash(out, "division_sampled", kSamples, h);
}

void saturation(Out& out) {
  out.str("sat32").kv("add", sat_add_i32(INT32_MAX, 1)).kv("sub", sat_sub_i32(INT32_MIN, 1));
  out.kv("mul", sat_mul_i32(-65536, 65536)).kv("narrow", sat_i32(-(static_cast<int64_t>(1) << 40))).end();
  out.str("sat64").kv("add", sat_add_i64(INT64_MAX, 1)).kv("sub", sat_sub_i64(INT64_MIN, 1));
  out.kv("mul", sat_mul_i64(INT64_MIN, -1)).kv("abs", static_cast<int64_t>(abs_u64(INT64_MIN + 1))).end();
  const q16 a = q16::from_ratio(-7, 3), b = q16::from_ratio(22, 7);
  out.str("q16").kx("a", static_cast<uint32_t>(a.raw), 8).kx("b", static_cast<uint32_t>(b.raw), 8);
  out.kx("mul", static_cast<uint32_t>(sat_mul(a, b).raw), 8).kx("add", static_cast<uint32_t>(sat_add(a, b).raw), 8);
  out.kv("floor", a.floor_int()).kv("round", a.round_int()).kx("to8", static_cast<uint32_t>(a.to<8>().raw), 8);
  out.kx("to24", static_cast<uint32_t>(b.to<24>().raw), 8).kx("sat", static_cast<uint32_t>(q16::from_int(40000).raw), 8).end();
  const q30 c = q30::from_ratio(1, 3);
  out.str("q30").kx("third", static_cast<uint32_t>(c.raw), 8).kx("sq", static_cast<uint32_t>(sat_mul(c, c).raw), 8).end();
  out.str("lsb_for_range");
  const int64_t ranges[] = {1, 255, 256, 25 * kNmPerMm, 100 * kNmPerMm, 1000 * kNmPerMm};
  const int bits_list[] = {8, 16, 32};
  for (int bits : bits_list) {
    for (int64_t range : ranges) out.str(" ").dec(lsb_for_range(range, bits));
  }
  out.end();
}

void trig(Out& out) {
  for (uint32_t k = 0; k < 16; ++k) {
    const uint32_t a = k * 0x10000000u + (k & 1u ? 0x01234567u : 0u);
    const SinCosQ30 s = sincos_bam(a);
    out.str("sincos").kx("bam", a, 8).kv("cos", s.cos_q30).kv("sin", s.sin_q30).end();
  }
  struct V { int64_t y, x; };
  const V vs[] = {{0, 0}, {0, 1}, {1, 0}, {0, -1}, {-1, 0}, {1, 1}, {-1, -1}, {INT64_MAX, INT64_MIN},
                  {INT64_MIN, INT64_MIN}, {INT64_MIN, 0}, {3, -4}, {-1, 1000000000000LL}};
  out.str("atan2");
  for (const V& v : vs) out.str(" ").hex(atan2_bam(v.y, v.x), 8);
  out.end();
  out.str("bam_from_mdeg");
  const int64_t mdegs[] = {0, 1, 45000, 90000, -90000, 359999, 360000, 720001, -1, INT64_MIN / 2};
  for (int64_t m : mdegs) out.str(" ").hex(bam_from_mdeg(m), 8);
  out.end();
  Rng r{3};
  Hash64 h;
  for (int i = 0; i < kSamples; ++i) {
    const SinCosQ30 s = sincos_bam(static_cast<uint32_t>(r.next()));
    h.uint_le(static_cast<uint32_t>(s.cos_q30), 4);
    h.uint_le(static_cast<uint32_t>(s.sin_q30), 4);
    const int64_t y = sample_i64(r), x = sample_i64(r);
    h.uint_le(atan2_bam(y, x), 4);
    h.uint_le(bam_from_mdeg(sample_i64(r)), 4);
  }
  put_hash(out, "trig_sampled", kSamples, h);
}

}  // namespace

void golden_math(Out& out) {
  roots(out);
  division(out);
  saturation(out);
  trig(out);
}

}  // namespace golden
