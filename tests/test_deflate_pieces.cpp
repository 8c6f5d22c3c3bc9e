// zlib_compress_pieces and its parts (platform/format/deflate.h): the
// Adler-32 of pieces combined, deflate_piece's preset dictionary, and
// streams that decode (tests/inflate_oracle.h) to the input at sizes on
// both sides of the piece size, the same bytes on every thread count.
#include <cstdint>
#include <vector>

#include "platform/format/deflate.h"
#include "tests/inflate_oracle.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using Bytes = std::vector<uint8_t>;

// Noise, and rows like a filtered heightmap's: long runs of zeros, small
// residues, a row type byte, repeats a row apart (what the dictionary must
// carry across a piece's start).
Bytes piece_input(std::size_t n, bool random, uint64_t seed) {
  t::Rng rng(seed);
  Bytes b(n);
  const std::size_t row = 1025;
  for (std::size_t i = 0; i < n; ++i) {
    const uint8_t noise = static_cast<uint8_t>(rng.next() >> 56);
    if (random) b[i] = noise;
    else if (i % row == 0) b[i] = static_cast<uint8_t>(i / row % 5);
    else if (i >= row && (i / row) % 3 == 1) b[i] = b[i - row];
    else b[i] = (i / 97) % 4 == 0 ? static_cast<uint8_t>(noise & 3) : 0;
  }
  return b;
}

Bytes pieces(const Bytes& in, int threads, DeflateTuning tuning = DeflateTuning::kFilteredSamples16) {
  Bytes out;
  zlib_compress_pieces(in.data(), in.size(), &out, tuning, threads);
  return out;
}

// Decodes z with the oracle (header, blocks, Adler-32) and compares.
bool decodes_to(const Bytes& z, const Bytes& in) {
  Bytes back;
  oracle::InflateStats st;
  return oracle::zlib_decompress(z.data(), z.size(), &back, &st) && back == in && st.incomplete_codes == 0;
}

}  // namespace

TEST(adler32_combine_equals_the_sum_of_the_whole) {
  t::Rng rng(5);
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5552}, std::size_t{65521}, std::size_t{200003}}) {
    Bytes b(n);
    for (auto& v : b) v = static_cast<uint8_t>(rng.next() >> 56);
    const uint32_t whole = adler32_update(1, b.data(), n);
    for (std::size_t cut : {std::size_t{0}, n / 3, n}) {
      const uint32_t a = adler32_update(1, b.data(), cut), c = adler32_update(1, b.data() + cut, n - cut);
      CHECK_EQ(adler32_combine(a, c, n - cut), whole);
    }
  }
  // Sums at the modulus' edges: all 0xFF bytes drive s1 and s2 near 65520.
  const Bytes ff(65521 * 2 + 17, 0xFF);
  const uint32_t a = adler32_update(1, ff.data(), 65521), c = adler32_update(1, ff.data() + 65521, ff.size() - 65521);
  CHECK_EQ(adler32_combine(a, c, ff.size() - 65521), adler32_update(1, ff.data(), ff.size()));
}

TEST(deflate_piece_reaches_into_its_dictionary_and_refuses_bad_ones) {
  // 40 000 bytes of noise, then the last 30 000 of them again: with the
  // first as dictionary the second piece is matches, without it noise.
  Bytes in = piece_input(40000, true, 6);
  in.insert(in.end(), in.end() - 30000, in.end());
  Bytes with, without;
  deflate_piece(in.data() + (40000 - 32768), 32768, 32768 + 30000, true, DeflateTuning::kFilteredSamples16, &with);
  deflate_piece(in.data() + 40000, 0, 30000, true, DeflateTuning::kFilteredSamples16, &without);
  CHECK_LT(with.size() * 50, without.size());
  Bytes out = {1};
  deflate_piece(in.data(), 32769, in.size(), true, DeflateTuning::kGeneral, &out);
  CHECK(out.empty());  // more than the window
  out = {1};
  deflate_piece(in.data(), 100, 99, true, DeflateTuning::kGeneral, &out);
  CHECK(out.empty());  // a dictionary past the end
  deflate_piece(in.data(), 0, 0, false, DeflateTuning::kGeneral, &out);
  CHECK_EQ(out.size(), std::size_t{6});  // an empty block, then the empty stored block: 3 + 5 + 32 bits, aligned
}

TEST(zlib_pieces_round_trip_around_the_piece_size_on_every_thread_count) {
  const std::size_t p = kDeflatePieceBytes;
  const std::size_t sizes[] = {0, 1, 7, p - 1, p, p + 1, 2 * p + 5};
  uint64_t seed = 40;
  for (std::size_t n : sizes)
    for (bool random : {false, true}) {
      const Bytes in = piece_input(n, random, ++seed);
      const Bytes z = pieces(in, 1);
      CHECK(decodes_to(z, in));
      CHECK_LE(z.size(), n + 11 + 5 * (n / 16384));  // deflate.h's bound holds in pieces too
      for (int threads : {2, 3, 7}) CHECK(pieces(in, threads) == z);
    }
}

TEST(zlib_pieces_of_one_piece_are_zlib_compress_and_cost_little_more_in_many) {
  // Up to one piece: the same stream as zlib_compress.
  const Bytes small = piece_input(300000, false, 50);
  Bytes one;
  zlib_compress(small.data(), small.size(), &one, DeflateTuning::kFilteredSamples16);
  CHECK(pieces(small, 2) == one);
  for (DeflateTuning tuning : {DeflateTuning::kGeneral, DeflateTuning::kFilteredSamples16}) {
    Bytes a, b;
    zlib_compress(small.data(), small.size(), &a, tuning);
    zlib_compress_pieces(small.data(), small.size(), &b, tuning, 3);
    CHECK(a == b);
  }
  // Five pieces: the dictionary keeps the repeats across the starts, so
  // the stream is within 0.5 % of one compressed whole.
  const Bytes big = piece_input(5 * kDeflatePieceBytes - 3, false, 51);
  Bytes whole;
  zlib_compress(big.data(), big.size(), &whole, DeflateTuning::kFilteredSamples16);
  const Bytes z = pieces(big, 0);
  CHECK(decodes_to(z, big));
  CHECK_LE(z.size() * 1000, whole.size() * 1005);
}
