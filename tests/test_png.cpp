// Our own zlib/DEFLATE and PNG encoders (platform/format/deflate.h, platform/format/png.h)
// against independent references written here: a bitwise CRC-32, a modulo-
// every-byte Adler-32, an INFLATE decoder (tests/inflate_oracle.h, itself
// checked on streams made by Python's zlib), and a PNG reader that checks
// every chunk and undoes all five filters.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "platform/format/deflate.h"
#include "platform/format/png.h"
#include "tests/inflate_oracle.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using Bytes = std::vector<uint8_t>;

Bytes bytes_of(const char* s) { return Bytes(s, s + std::strlen(s)); }

Bytes from_hex(const char* hex) {
  Bytes b;
  for (std::size_t i = 0; hex[i] && hex[i + 1]; i += 2) {
    auto nibble = [](char c) { return c <= '9' ? c - '0' : c - 'a' + 10; };
    b.push_back(static_cast<uint8_t>(nibble(hex[i]) << 4 | nibble(hex[i + 1])));
  }
  return b;
}

Bytes random_bytes(std::size_t n, uint64_t seed) {
  t::Rng rng(seed);
  Bytes b(n);
  for (auto& v : b) v = static_cast<uint8_t>(rng.next() >> 56);
  return b;
}

// CRC-32 one bit at a time, straight from the definition (PNG section 5.5).
uint32_t crc32_bitwise(const uint8_t* p, std::size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

uint32_t crc_of(const char* s) { return crc32_update(0, reinterpret_cast<const uint8_t*>(s), std::strlen(s)); }
uint32_t adler_of(const char* s) { return adler32_update(1, reinterpret_cast<const uint8_t*>(s), std::strlen(s)); }

Bytes compress(const Bytes& in, DeflateTuning tuning = DeflateTuning::kGeneral) {
  Bytes out;
  zlib_compress(in.data(), in.size(), &out, tuning);
  return out;
}

// Compresses `in`, checks the zlib frame by hand and the round trip through
// the oracle; returns the compressed size and the oracle's counts.
std::size_t round_trip(const Bytes& in, oracle::InflateStats* st = nullptr,
                       DeflateTuning tuning = DeflateTuning::kGeneral) {
  const Bytes z = compress(in, tuning);
  CHECK_GE(z.size(), std::size_t{6});
  if (z.size() < 6) return 0;
  CHECK_EQ(z[0], 0x78);  // deflate, 32 KiB window
  CHECK_EQ((z[0] * 256 + z[1]) % 31, 0);
  CHECK_EQ(z[1] & 0x20, 0);  // no preset dictionary
  const uint32_t trailer = static_cast<uint32_t>(z[z.size() - 4]) << 24 | static_cast<uint32_t>(z[z.size() - 3]) << 16 |
                           static_cast<uint32_t>(z[z.size() - 2]) << 8 | z[z.size() - 1];
  CHECK_EQ(trailer, oracle::adler32_slow(in.data(), in.size()));
  oracle::InflateStats local;
  oracle::InflateStats* s = st ? st : &local;
  Bytes back;
  CHECK(oracle::zlib_decompress(z.data(), z.size(), &back, s));
  CHECK_EQ(back.size(), in.size());
  CHECK(back == in);
  CHECK_EQ(s->incomplete_codes, 0);  // the encoder always sends complete codes
  return z.size();
}

// The growth bound deflate.h promises for any input.
std::size_t worst_size(std::size_t n) { return n + 11 + 5 * (n / 16384); }

// Words from a small vocabulary with punctuation: compresses like prose.
Bytes text_like(std::size_t n, uint64_t seed) {
  static const char* const kWords[] = {"the", "cutter", "moves", "along", "a", "path", "of", "G1", "lines", "and", "arcs",
                                       "while", "stock", "is", "removed", "from", "grid", "column", "height", "feed",
                                       "spindle", "tool", "depth", "pass", "X12.500", "Y-3.25", "Z0.1", "F600"};
  t::Rng rng(seed);
  Bytes b;
  while (b.size() < n) {
    const char* w = kWords[rng.range(0, sizeof kWords / sizeof kWords[0] - 1)];
    b.insert(b.end(), w, w + std::strlen(w));
    b.push_back(rng.range(0, 9) == 0 ? '\n' : ' ');
  }
  b.resize(n);
  return b;
}


// A milled part's heightmap, w x h, integer only: a hole border, the
// stock's flat top, a pocket with a flat floor, a bowl whose ball-nose
// passes leave scallops between stepovers, and terraces of a stepped
// roughing.
std::vector<uint16_t> milled_heightmap(int32_t w, int32_t h) {
  std::vector<uint16_t> img(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      int64_t z = 40000;  // the uncut top
      const int64_t dx = x - w / 2, dy = y - h / 2, r2 = dx * dx + dy * dy;
      if (x >= w / 10 && x < w / 3 && y >= h / 8 && y < h / 2) z = 31000;  // the pocket's floor
      if (r2 < int64_t{w / 4} * (w / 4)) {
        const int64_t s = x % 9 - 4;  // across a 9-dexel stepover
        z = 22000 + r2 / 3 + s * s * 25;
      }
      if (x >= 2 * w / 3 && y >= h / 2) z = 26000 + 1500 * ((x + y) / 23 % 4);  // terraces
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1) z = 0;                 // holes
      img[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] = static_cast<uint16_t>(z);
    }
  return img;
}

// The samples most significant byte first, each row led by its filter
// type: None (0), or with `up` Up (2), each byte less the one above.
Bytes heightmap_rows(const std::vector<uint16_t>& img, int32_t w, int32_t h, bool up) {
  const std::size_t row_bytes = 2 * static_cast<std::size_t>(w);
  Bytes plain(row_bytes * static_cast<std::size_t>(h));
  for (std::size_t i = 0; i < img.size(); ++i) {
    plain[2 * i] = static_cast<uint8_t>(img[i] >> 8);
    plain[2 * i + 1] = static_cast<uint8_t>(img[i]);
  }
  Bytes rows;
  for (int32_t y = 0; y < h; ++y) {
    rows.push_back(up ? 2 : 0);
    for (std::size_t i = 0; i < row_bytes; ++i) {
      const std::size_t k = static_cast<std::size_t>(y) * row_bytes + i;
      rows.push_back(static_cast<uint8_t>(plain[k] - (up && y > 0 ? plain[k - row_bytes] : 0)));
    }
  }
  return rows;
}

}  // namespace

// ---- checksums ----

TEST(crc32_known_vectors) {
  CHECK_EQ(crc_of("123456789"), 0xCBF43926u);
  CHECK_EQ(crc_of(""), 0u);
  CHECK_EQ(crc_of("a"), 0xE8B7BE43u);
  CHECK_EQ(crc_of("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
  CHECK_EQ(crc_of("IEND"), 0xAE426082u);  // every PNG ends with these CRC bytes
}

TEST(crc32_matches_bitwise_definition_whole_and_in_pieces) {
  const Bytes data = random_bytes(5000, 11);
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{255}, std::size_t{4096}, std::size_t{5000}}) {
    CHECK_EQ(crc32_update(0, data.data(), n), crc32_bitwise(data.data(), n));
  }
  uint32_t crc = 0;
  for (std::size_t at = 0, step = 1; at < data.size(); at += step, step = step * 3 % 997 + 1)
    crc = crc32_update(crc, data.data() + at, std::min(step, data.size() - at));
  CHECK_EQ(crc, crc32_bitwise(data.data(), data.size()));
}

TEST(adler32_known_vectors) {
  CHECK_EQ(adler_of("Wikipedia"), 0x11E60398u);
  CHECK_EQ(adler_of(""), 1u);
  CHECK_EQ(adler_of("a"), 0x00620062u);
  CHECK_EQ(adler_of("abc"), 0x024D0127u);
  CHECK_EQ(adler_of("123456789"), 0x091E01DEu);
}

TEST(adler32_matches_modulo_every_byte_whole_and_in_pieces) {
  // All 0xFF bytes push the sums hardest between reductions.
  const Bytes ff(1 << 20, 0xFF);
  CHECK_EQ(adler32_update(1, ff.data(), ff.size()), oracle::adler32_slow(ff.data(), ff.size()));
  const Bytes data = random_bytes(100000, 12);
  CHECK_EQ(adler32_update(1, data.data(), data.size()), oracle::adler32_slow(data.data(), data.size()));
  uint32_t a = 1;
  for (std::size_t at = 0, step = 1; at < data.size(); at += step, step = step * 7 % 9001 + 1)
    a = adler32_update(a, data.data() + at, std::min(step, data.size() - at));
  CHECK_EQ(a, oracle::adler32_slow(data.data(), data.size()));
}

// ---- the oracle itself ----

TEST(inflate_oracle_reads_python_zlib_streams_and_rejects_damage) {
  // zlib.compress(b"hello", 0): one stored block.
  const Bytes stored = from_hex("7801010500faff68656c6c6f062c0215");
  // zlib.compress(b"hello hello hello hello", 9): fixed Huffman with a match.
  const Bytes fixed = from_hex("78dacb48cdc9c957c8402701680308b1");
  // zlib.compress(467 bytes of text, 9): a dynamic Huffman block.
  const Bytes dynamic = from_hex(
      "78dae58edb52c23014457fe53c0a624144ae2a0272bf631541440e4dda049a149a940e7e3d6598f12778dc7bf6acb54d46e1cfe56b50daa72820f4"
      "71a7e0addee855cc3a10d458fa4f9647a802976beaa3ab00250181da62511972cda015d8b64079d925801c250a6e41c8a8041d79ce34e011c1930e50"
      "e9050e33c0bcfa0337b1f86de2ce48a6eed30f99c76c2e5f28969e9e5fcaaf956a2d12375bed4eb7d71f0c47e3c9bbf9f139fd9acdbf173fcbdf15ae"
      "2d426d87f1cdd615d2dbed7da58343780218509f70");
  Bytes text;
  for (int i = 0; i < 3; ++i) {
    const Bytes s = bytes_of(
        "The zlib stream wraps DEFLATE data; DEFLATE codes literals and matches with Huffman codes, dynamic when the data is "
        "long enough. ");
    text.insert(text.end(), s.begin(), s.end());
  }
  for (int c = 40; c < 120; ++c) text.push_back(static_cast<uint8_t>(c));

  Bytes out;
  oracle::InflateStats st;
  CHECK(oracle::zlib_decompress(stored.data(), stored.size(), &out, &st));
  CHECK(out == bytes_of("hello"));
  CHECK(oracle::zlib_decompress(fixed.data(), fixed.size(), &out, &st));
  CHECK(out == bytes_of("hello hello hello hello"));
  CHECK(oracle::zlib_decompress(dynamic.data(), dynamic.size(), &out, &st));
  CHECK(out == text);
  CHECK_EQ(st.stored_blocks, 1);
  CHECK_EQ(st.fixed_blocks, 1);
  CHECK_EQ(st.dynamic_blocks, 1);

  Bytes bad = dynamic;
  bad.back() ^= 1;  // Adler-32
  CHECK(!oracle::zlib_decompress(bad.data(), bad.size(), &out, &st));
  bad = dynamic;
  bad[1] ^= 1;  // FCHECK
  CHECK(!oracle::zlib_decompress(bad.data(), bad.size(), &out, &st));
  bad = stored;
  bad[5] ^= 1;  // NLEN
  CHECK(!oracle::zlib_decompress(bad.data(), bad.size(), &out, &st));
  bad = fixed;
  bad.resize(bad.size() - 6);  // truncated
  CHECK(!oracle::zlib_decompress(bad.data(), bad.size(), &out, &st));
}

// ---- Huffman code lengths ----

namespace {

// Cost sum(freq * length) of an unlimited Huffman code: the sum of the
// weights of all merged nodes (repeatedly joining the two lightest).
uint64_t huffman_cost(std::vector<uint64_t> w) {
  w.erase(std::remove(w.begin(), w.end(), 0u), w.end());
  uint64_t cost = 0;
  while (w.size() > 1) {
    std::sort(w.begin(), w.end());
    const uint64_t joined = w[0] + w[1];
    cost += joined;
    w.erase(w.begin());
    w[0] = joined;
  }
  return cost;
}

// Checks lengths from huffman_code_lengths: within the limit, complete
// (Kraft sum exactly 1), used symbols coded; returns sum(freq * length).
uint64_t check_lengths(const std::vector<uint32_t>& freq, int max_bits) {
  std::vector<uint8_t> bits(freq.size(), 99);
  huffman_code_lengths(freq.data(), static_cast<int>(freq.size()), max_bits, bits.data());
  uint64_t kraft = 0, cost = 0;  // kraft in units of 2^-max_bits
  for (std::size_t s = 0; s < freq.size(); ++s) {
    CHECK_LE(bits[s], max_bits);
    if (freq[s] > 0) CHECK_GT(bits[s], 0);
    if (bits[s] > 0 && bits[s] <= max_bits) kraft += uint64_t{1} << (max_bits - bits[s]);
    cost += static_cast<uint64_t>(freq[s]) * bits[s];
  }
  CHECK_EQ(kraft, uint64_t{1} << max_bits);
  return cost;
}

}  // namespace

TEST(huffman_lengths_are_optimal_when_the_limit_does_not_bind) {
  // Weights within a factor of ten keep an unlimited code of 286 symbols
  // well under 15 bits, so the lengths must match Huffman's cost.
  t::Rng rng(21);
  for (int round = 0; round < 50; ++round) {
    std::vector<uint32_t> freq(static_cast<std::size_t>(rng.range(2, 286)));
    for (auto& f : freq) f = rng.range(0, 3) == 0 ? 0 : static_cast<uint32_t>(rng.range(100, 1000));
    freq[0] = freq[1] = 100;
    CHECK_EQ(check_lengths(freq, 15), huffman_cost(std::vector<uint64_t>(freq.begin(), freq.end())));
  }
}

namespace {

// The least sum(freq * length) over all lengths 1..max_bits whose Kraft sum
// is at most 1, by trying every assignment (small cases only).
uint64_t best_limited_cost(const std::vector<uint32_t>& freq, int max_bits) {
  std::vector<int> len(freq.size(), 1);
  uint64_t best = UINT64_MAX;
  for (;;) {
    uint64_t kraft = 0, cost = 0;
    for (std::size_t s = 0; s < freq.size(); ++s) {
      kraft += uint64_t{1} << (max_bits - len[s]);
      cost += static_cast<uint64_t>(freq[s]) * static_cast<uint64_t>(len[s]);
    }
    if (kraft <= (uint64_t{1} << max_bits)) best = std::min(best, cost);
    std::size_t k = 0;
    while (k < len.size() && len[k] == max_bits) len[k++] = 1;
    if (k == len.size()) return best;
    ++len[k];
  }
}

}  // namespace

TEST(huffman_lengths_are_optimal_under_a_binding_limit) {
  // Skewed weights with a limit just above log2(symbols): compared with an
  // exhaustive search.
  t::Rng rng(22);
  for (int round = 0; round < 150; ++round) {
    const int symbols = static_cast<int>(rng.range(2, 7));
    const int max_bits = symbols <= 4 ? static_cast<int>(rng.range(2, 3)) : static_cast<int>(rng.range(3, 4));
    std::vector<uint32_t> freq(static_cast<std::size_t>(symbols));
    for (auto& f : freq) f = static_cast<uint32_t>(1) << rng.range(0, 12);
    CHECK_EQ(check_lengths(freq, max_bits), best_limited_cost(freq, max_bits));
  }
}

TEST(huffman_lengths_obey_the_limit_on_fibonacci_frequencies) {
  // Fibonacci weights make an unlimited Huffman tree as deep as it has
  // symbols; 30 of them need 29 bits unlimited.
  std::vector<uint32_t> freq(30);
  freq[0] = freq[1] = 1;
  for (std::size_t i = 2; i < freq.size(); ++i) freq[i] = freq[i - 1] + freq[i - 2];
  const uint64_t limited = check_lengths(freq, 15);
  CHECK_GE(limited, huffman_cost(std::vector<uint64_t>(freq.begin(), freq.end())));
  std::vector<uint32_t> cl(freq.begin(), freq.begin() + 19);  // the code length code: 7 bits
  check_lengths(cl, 7);
  // One or no used symbol still gives a complete two-symbol code.
  check_lengths(std::vector<uint32_t>(30, 0), 15);
  std::vector<uint32_t> one(19, 0);
  one[7] = 40;
  check_lengths(one, 7);
  // Arguments out of range: all zero.
  uint8_t bits[4] = {9, 9, 9, 9};
  const uint32_t f4[4] = {1, 2, 3, 4};
  huffman_code_lengths(f4, 4, 1, bits);
  CHECK_EQ(bits[0] + bits[1] + bits[2] + bits[3], 0);
}

// ---- zlib streams ----

TEST(zlib_header_and_adler_trailer) {
  const Bytes in = bytes_of("Wikipedia");
  const Bytes z = compress(in);
  CHECK_EQ(z.size() >= 6 ? z[0] : 0, 0x78);
  CHECK_EQ(z.size() >= 6 ? z[1] : 0, 0x9C);
  const Bytes tail(z.end() - 4, z.end());
  CHECK(tail == (Bytes{0x11, 0xE6, 0x03, 0x98}));
  round_trip(in);
}

TEST(zlib_empty_and_tiny_inputs) {
  oracle::InflateStats st;
  CHECK_LE(round_trip(Bytes{}, &st), std::size_t{8});
  for (int v = 0; v < 256; ++v) CHECK_LE(round_trip(Bytes{static_cast<uint8_t>(v)}), std::size_t{9});
  // Every length up to 600 of a pattern with short repeats: the ends of
  // input during matching and lazy evaluation.
  Bytes pattern = text_like(600, 3);
  for (std::size_t n = 0; n <= pattern.size(); ++n) round_trip(Bytes(pattern.begin(), pattern.begin() + static_cast<long>(n)));
}

TEST(zlib_zeros_compress_to_almost_nothing) {
  oracle::InflateStats st;
  const std::size_t size = round_trip(Bytes(100000, 0), &st);
  CHECK_LE(size, std::size_t{200});
  CHECK_EQ(st.max_length, 258u);
  CHECK_EQ(st.max_distance, 1u);
}

TEST(zlib_random_bytes_go_out_stored_within_the_bound) {
  for (std::size_t n : {std::size_t{1000}, std::size_t{65535}, std::size_t{65536}, std::size_t{300000}}) {
    const Bytes in = random_bytes(n, n);
    oracle::InflateStats st;
    const std::size_t size = round_trip(in, &st);
    CHECK_LE(size, worst_size(n));
    CHECK_GE(st.stored_blocks, 1);
    if (n > 65536) CHECK_GE(st.stored_blocks, 4);  // more than one block of 65535 could hold
    CHECK_LE(st.max_stored_bytes, std::size_t{65535});
  }
}

TEST(zlib_text_like_data_uses_dynamic_blocks) {
  const Bytes in = text_like(500000, 4);
  oracle::InflateStats st;
  const std::size_t size = round_trip(in, &st);
  CHECK_LE(size * 3, in.size());  // words from a small vocabulary
  CHECK_GE(st.dynamic_blocks, 2);
  CHECK_EQ(st.stored_blocks, 0);
}

TEST(zlib_matches_at_distance_32768_and_length_258) {
  // A random 32 KiB block three times: every match reaches back the full
  // window, and runs of 258 bytes are the longest a match may copy.
  const Bytes block = random_bytes(32768, 5);
  Bytes in;
  for (int i = 0; i < 3; ++i) in.insert(in.end(), block.begin(), block.end());
  oracle::InflateStats st;
  const std::size_t size = round_trip(in, &st);
  CHECK_EQ(st.max_distance, 32768u);
  CHECK_EQ(st.max_length, 258u);
  CHECK_LE(size, std::size_t{32768 + 2000});

  // One byte more than the window: the copy is out of reach.
  Bytes far = random_bytes(32769, 6);
  far.insert(far.end(), far.begin(), far.begin() + 300);
  st = oracle::InflateStats{};
  round_trip(far, &st);
  CHECK_LE(st.max_distance, 32768u);
}

TEST(zlib_every_match_length_and_many_distances) {
  // Copies of each length 3..300 from distances spread over the window,
  // separated by random bytes, so the edges of every length code occur.
  t::Rng rng(7);
  Bytes in = random_bytes(40000, 8);
  for (int len = 3; len <= 300; ++len) {
    const std::size_t dist = static_cast<std::size_t>(rng.range(1, 32768));
    const std::size_t from = in.size() - dist;
    for (int i = 0; i < len; ++i) in.push_back(in[from + static_cast<std::size_t>(i)]);
    for (int i = 0; i < 5; ++i) in.push_back(static_cast<uint8_t>(rng.next() >> 56));
  }
  oracle::InflateStats st;
  round_trip(in, &st);
  CHECK_EQ(st.max_length, 258u);
}

TEST(zlib_repeated_runs_and_skewed_bytes) {
  t::Rng rng(9);
  Bytes runs;
  while (runs.size() < 200000) runs.insert(runs.end(), static_cast<std::size_t>(rng.range(1, 600)), static_cast<uint8_t>(rng.range(0, 255)));
  round_trip(runs);
  // Byte values with Fibonacci counts, shuffled: deep Huffman trees.
  Bytes skewed;
  uint32_t a = 1, b = 1;
  for (int v = 0; v < 24; ++v, b = a + b, a = b - a) skewed.insert(skewed.end(), a, static_cast<uint8_t>(v));
  for (std::size_t i = skewed.size(); i > 1; --i) std::swap(skewed[i - 1], skewed[rng.next() % i]);
  round_trip(skewed);
}

TEST(zlib_output_is_deterministic) {
  const Bytes in = text_like(70000, 10);
  CHECK(compress(in) == compress(in));
}

const DeflateTuning kTunings[] = {DeflateTuning::kGeneral, DeflateTuning::kFilteredSamples16};

TEST(zlib_heightmap_rows_round_trip) {
  // A heightmap's rows as PNG filters leave them: most of them runs at
  // distance 1 or 2 (flat top, floor, holes), the rest short repeats.
  const int32_t w = 480, h = 360;
  const std::vector<uint16_t> img = milled_heightmap(w, h);
  for (DeflateTuning tuning : kTunings)
    for (bool up : {false, true}) {
      const Bytes rows = heightmap_rows(img, w, h, up);
      oracle::InflateStats st;
      const std::size_t size = round_trip(rows, &st, tuning);
      CHECK_LE(size * 4, rows.size());
      CHECK_EQ(st.stored_blocks, 0);
      CHECK_EQ(st.max_length, 258u);
    }
}

TEST(zlib_every_tuning_round_trips_random_runs_tiny_and_incompressible_inputs) {
  // The last bytes of the input start no match (the hash reads eight), and
  // with kFilteredSamples16 matches of 3 or 4 bytes come from their own
  // table within a short reach: every length of runs, of 2-byte patterns
  // and of repeats at distances on both sides of that reach round-trips;
  // random bytes go out stored within deflate.h's bound.
  t::Rng rng(11);
  for (DeflateTuning tuning : kTunings) {
    CHECK_LE(round_trip(Bytes{}, nullptr, tuning), std::size_t{8});
    for (std::size_t n = 0; n <= 40; ++n) {
      round_trip(Bytes(n, static_cast<uint8_t>(n)), nullptr, tuning);
      Bytes pairs(n);
      for (std::size_t i = 0; i < n; ++i) pairs[i] = i % 2 ? 0xFF : 0x01;
      round_trip(pairs, nullptr, tuning);
      for (std::size_t dist : {std::size_t{3}, std::size_t{100}, std::size_t{128}, std::size_t{129}, std::size_t{200}}) {
        Bytes in = random_bytes(dist, n * 7 + dist);
        for (std::size_t i = 0; i < n; ++i) in.push_back(in[in.size() - dist]);
        in.push_back(static_cast<uint8_t>(rng.next() >> 56));
        round_trip(in, nullptr, tuning);
      }
    }
    for (std::size_t n : {std::size_t{1}, std::size_t{65536}, std::size_t{200000}}) {
      oracle::InflateStats st;
      CHECK_LE(round_trip(random_bytes(n, n + 3), &st, tuning), worst_size(n));
      if (n > 1) CHECK_GE(st.stored_blocks, 1);  // one byte goes out shorter in a fixed block
    }
    round_trip(text_like(100000, 12), nullptr, tuning);
  }
}

// ---- PNG ----

namespace {

uint32_t be32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) << 24 | static_cast<uint32_t>(p[1]) << 16 | static_cast<uint32_t>(p[2]) << 8 | p[3];
}

struct DecodedPng {
  bool ok = false;
  uint32_t width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
  int idat_chunks = 0;
  std::size_t max_idat_bytes = 0;
  int filter_counts[5] = {};
  Bytes pixels;    // unfiltered rows, PNG byte order
  Bytes filtered;  // the decompressed image data, filter bytes included
};

// Walks the chunks: signature, IHDR first, consecutive IDATs, IEND last and
// empty, every CRC right (by the bitwise reference). Fills header fields
// and collects the IDAT data into *zdata.
bool read_chunks(const Bytes& png, DecodedPng* d, Bytes* zdata) {
  static const uint8_t kSig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (png.size() < 8 || !std::equal(kSig, kSig + 8, png.begin())) return false;
  std::size_t at = 8;
  std::vector<std::string> order;
  while (at + 12 <= png.size()) {
    const uint32_t len = be32(&png[at]);
    if (at + 12 + len > png.size()) return false;
    const std::string type(png.begin() + static_cast<long>(at) + 4, png.begin() + static_cast<long>(at) + 8);
    const uint8_t* body = &png[at + 8];
    if (crc32_bitwise(&png[at + 4], 4 + len) != be32(body + len)) return false;
    if (!order.empty() && order.back() == "IEND") return false;
    if (type == "IHDR") {
      if (len != 13 || !order.empty()) return false;
      d->width = be32(body);
      d->height = be32(body + 4);
      d->bit_depth = body[8];
      d->colour_type = body[9];
      if (body[10] != 0 || body[11] != 0 || body[12] != 0) return false;  // methods, no interlace
    } else if (type == "IDAT") {
      if (order.empty() || (order.back() != "IHDR" && order.back() != "IDAT")) return false;
      zdata->insert(zdata->end(), body, body + len);
      ++d->idat_chunks;
      d->max_idat_bytes = std::max<std::size_t>(d->max_idat_bytes, len);
    } else if (type == "IEND") {
      if (len != 0 || order.empty() || order.back() != "IDAT") return false;
    } else {
      return false;  // the encoder writes no other chunks
    }
    order.push_back(type);
    at += 12 + len;
  }
  return at == png.size() && !order.empty() && order.back() == "IEND";
}

int paeth_ref(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// The prediction of filter `type` (PNG section 9.2) from left, above, upper left.
int predictor(int type, int a, int b, int c) {
  switch (type) {
    case 1: return a;
    case 2: return b;
    case 3: return (a + b) / 2;
    case 4: return paeth_ref(a, b, c);
    default: return 0;
  }
}

// Undoes the filters row by row; every filter byte must be 0..4, and the
// chosen one must have the least sum |signed byte| (lowest type on ties)
// when `adaptive`, else be None.
bool unfilter(DecodedPng* d, std::size_t bpp, bool adaptive) {
  const std::size_t row = d->width * bpp;
  if (d->filtered.size() != d->height * (row + 1)) return false;
  d->pixels.assign(d->height * row, 0);
  Bytes prior(row, 0);
  for (std::size_t y = 0; y < d->height; ++y) {
    const uint8_t* in = &d->filtered[y * (row + 1)];
    const int type = in[0];
    if (type > 4) return false;
    ++d->filter_counts[type];
    uint8_t* out = &d->pixels[y * row];
    for (std::size_t i = 0; i < row; ++i) {
      const int a = i >= bpp ? out[i - bpp] : 0, c = i >= bpp ? prior[i - bpp] : 0;
      out[i] = static_cast<uint8_t>(in[1 + i] + predictor(type, a, prior[i], c));
    }
    uint64_t cost[5] = {};
    for (int f = 0; f < 5; ++f)
      for (std::size_t i = 0; i < row; ++i) {
        const int a = i >= bpp ? out[i - bpp] : 0, c = i >= bpp ? prior[i - bpp] : 0;
        cost[f] += static_cast<uint64_t>(std::abs(static_cast<int8_t>(static_cast<uint8_t>(out[i] - predictor(f, a, prior[i], c)))));
      }
    if ((adaptive ? std::min_element(cost, cost + 5) - cost : 0) != type) return false;
    prior.assign(out, out + row);
  }
  return true;
}

DecodedPng decode_png(const Bytes& png) {
  DecodedPng d;
  Bytes zdata;
  if (!read_chunks(png, &d, &zdata)) return d;
  oracle::InflateStats st;
  if (!oracle::zlib_decompress(zdata.data(), zdata.size(), &d.filtered, &st)) return d;
  std::size_t bpp = 0;
  if (d.colour_type == 2 && d.bit_depth == 8) bpp = 3;
  if (d.colour_type == 0 && d.bit_depth == 16) bpp = 2;
  // Grey images are filtered row by row, RGB frames not (platform/format/png.cpp).
  d.ok = bpp != 0 && unfilter(&d, bpp, d.colour_type == 0);
  return d;
}

// Decodes png, checks it is a w x h image of this colour type and bit depth,
// and adds its filter types to filter_counts (when not null).
DecodedPng decode_checked(const Bytes& png, int32_t w, int32_t h, int colour_type, int bit_depth, int* filter_counts) {
  DecodedPng d = decode_png(png);
  CHECK(d.ok);
  CHECK_EQ(d.width, static_cast<uint32_t>(w));
  CHECK_EQ(d.height, static_cast<uint32_t>(h));
  CHECK_EQ(d.colour_type, colour_type);
  CHECK_EQ(d.bit_depth, bit_depth);
  for (int f = 0; filter_counts && f < 5; ++f) filter_counts[f] += d.filter_counts[f];
  return d;
}

// Checks an RGB8 encoding decodes to exactly `rgb`; returns the file size.
std::size_t check_rgb8(const Bytes& rgb, int32_t w, int32_t h, int* filter_counts = nullptr) {
  Bytes png;
  png_encode_rgb8(rgb.data(), w, h, &png);
  CHECK(decode_checked(png, w, h, 2, 8, filter_counts).pixels == rgb);
  return png.size();
}

std::size_t check_gray16(const std::vector<uint16_t>& samples, int32_t w, int32_t h, int* filter_counts = nullptr,
                         Bytes* file = nullptr) {
  Bytes local;
  Bytes& png = file ? *file : local;
  png_encode_gray16(samples.data(), w, h, &png);
  const DecodedPng d = decode_checked(png, w, h, 0, 16, filter_counts);
  bool same = d.pixels.size() == 2 * samples.size();
  for (std::size_t i = 0; same && i < samples.size(); ++i)
    same = (d.pixels[2 * i] << 8 | d.pixels[2 * i + 1]) == samples[i];  // big-endian in the file
  CHECK(same);
  return png.size();
}

// Test images, by kind: random, smooth gradients in both directions, flat,
// and a mix of rows that calls for every filter type.
enum class Kind { kRandom, kGradient, kFlat, kMixed };
const Kind kKinds[] = {Kind::kRandom, Kind::kGradient, Kind::kFlat, Kind::kMixed};

// Row y of a kMixed image, by y % 7: noise (no prediction helps), a ramp
// (Sub), a pattern, that pattern again (Up), each byte one above the mean of
// left and above (Average), then two rows of a plane (Paeth on the second).
uint32_t mixed_sample(const std::vector<uint32_t>& img, std::size_t i, std::size_t row, std::size_t channels, int32_t x,
                      int32_t y, uint32_t k, uint32_t noise, uint32_t max) {
  const uint32_t scale = max / 255;
  const uint32_t left = i >= channels && x > 0 ? img[i - channels] : 0;
  const uint32_t above = y > 0 ? img[i - row] : 0;
  const uint32_t ux = static_cast<uint32_t>(x), uy = static_cast<uint32_t>(y);
  switch (y % 7) {
    case 0: return noise;
    case 1: return (ux * 5 + k) * scale % (max + 1);
    case 2: return ((ux * ux) % 97 + k) * scale;
    case 3: return above;
    case 4: return ((left + above) / 2 + scale) % (max + 1);
    default: return (ux * 9 + uy * 11 + k) * scale % (max + 1);
  }
}

// Samples of a w x h image of `channels` per pixel, each 0..max.
std::vector<uint32_t> make_samples(Kind kind, int32_t w, int32_t h, std::size_t channels, uint32_t max, uint64_t seed) {
  t::Rng rng(seed);
  std::vector<uint32_t> img;
  const std::size_t row = static_cast<std::size_t>(w) * channels;
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x)
      for (uint32_t k = 0; k < channels; ++k) {
        const uint32_t noise = static_cast<uint32_t>(rng.next() >> 40) % (max + 1);
        const uint32_t gradient = (static_cast<uint32_t>(x * 7 + y * 3) + k * 50) * (max / 255) % (max + 1);
        uint32_t v = 0;
        switch (kind) {
          case Kind::kRandom: v = noise; break;
          case Kind::kGradient: v = gradient; break;
          case Kind::kFlat: v = max / 3; break;
          case Kind::kMixed: v = mixed_sample(img, img.size(), row, channels, x, y, k, noise, max); break;
        }
        img.push_back(v);
      }
  return img;
}

Bytes make_rgb(Kind kind, int32_t w, int32_t h, uint64_t seed) {
  const std::vector<uint32_t> s = make_samples(kind, w, h, 3, 255, seed);
  return Bytes(s.begin(), s.end());
}

std::vector<uint16_t> make_gray(Kind kind, int32_t w, int32_t h, uint64_t seed) {
  const std::vector<uint32_t> s = make_samples(kind, w, h, 1, 65535, seed);
  return std::vector<uint16_t>(s.begin(), s.end());
}

const int32_t kSizes[][2] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {13, 11}, {37, 23}, {64, 3}, {3, 64}, {101, 47}};

}  // namespace

TEST(png_rgb8_round_trips_every_size_and_kind) {
  int filters[5] = {};
  uint64_t seed = 100;
  for (const auto& s : kSizes)
    for (Kind kind : kKinds) check_rgb8(make_rgb(kind, s[0], s[1], ++seed), s[0], s[1], filters);
  for (int f = 1; f < 5; ++f) CHECK_EQ(filters[f], 0);  // frames are not filtered
  CHECK_GT(filters[0], 0);
}

TEST(png_gray16_round_trips_every_size_and_kind) {
  int filters[5] = {};
  uint64_t seed = 200;
  for (const auto& s : kSizes)
    for (Kind kind : kKinds) check_gray16(make_gray(kind, s[0], s[1], ++seed), s[0], s[1], filters);
  for (int f = 0; f < 5; ++f) CHECK_GT(filters[f], 0);
}

TEST(png_gray16_samples_are_big_endian) {
  const std::vector<uint16_t> one = {0x1234};
  Bytes png;
  png_encode_gray16(one.data(), 1, 1, &png);
  const DecodedPng d = decode_png(png);
  CHECK(d.ok);
  CHECK(d.filtered == (Bytes{0, 0x12, 0x34}));  // filter None, then the sample
}

TEST(png_chunks_split_large_image_data) {
  const int32_t w = 300, h = 200;
  const Bytes rgb = make_rgb(Kind::kRandom, w, h, 300);
  Bytes png;
  png_encode_rgb8(rgb.data(), w, h, &png);
  DecodedPng d;
  Bytes zdata;
  CHECK(read_chunks(png, &d, &zdata));
  CHECK_GE(d.idat_chunks, 3);  // 180 KB of noise does not compress
  CHECK_LE(d.max_idat_bytes, std::size_t{65536});
  // Signature, IHDR (25 bytes) and IEND (12) by hand.
  CHECK_EQ(be32(&png[8]), 13u);
  CHECK(std::memcmp(&png[12], "IHDR", 4) == 0);
  CHECK(std::memcmp(&png[png.size() - 12], "\0\0\0\0IEND\xAE\x42\x60\x82", 12) == 0);
  check_rgb8(rgb, w, h);
}

TEST(png_bad_sizes_give_no_output) {
  const Bytes rgb(30, 7);
  const std::vector<uint16_t> g(30, 7);
  Bytes png = {1, 2, 3};
  png_encode_rgb8(rgb.data(), 0, 5, &png);
  CHECK(png.empty());
  png = {1};
  png_encode_rgb8(rgb.data(), 5, -1, &png);
  CHECK(png.empty());
  png = {1};
  png_encode_gray16(g.data(), -3, 2, &png);
  CHECK(png.empty());
  png = {1};
  png_encode_gray16(g.data(), 1 << 30, 1 << 30, &png);  // far over 1 GiB: refused before reading
  CHECK(png.empty());
}

TEST(png_gray16_milled_part_round_trips_no_larger_than_before) {
  // The match finder of five-byte hash chains and a short table
  // (platform/format/deflate.cpp): the same pixels back, in no more bytes
  // than the one of three-byte chains before it wrote (29 951; this one
  // writes 29 904).
  const int32_t w = 480, h = 360;
  int filters[5] = {};
  const std::size_t size = check_gray16(milled_heightmap(w, h), w, h, filters);
  CHECK_LE(size, std::size_t{29951});
  CHECK_GT(filters[2] + filters[4], 0);  // Up or Paeth: smooth rows
}

TEST(png_gray16_in_pieces_round_trips_the_same_bytes_on_every_thread_count) {
  // The filtered rows, h * (2 w + 1) bytes, go to zlib_compress_pieces:
  // one row; one byte short of a piece (512 x 1023); one byte over
  // (8 x 61681; an odd row length never fills a piece exactly, tests/
  // test_deflate_pieces.cpp has that size); two and a bit pieces; random
  // samples, a milled part, rows of every filter, flat rows (equal to the
  // one above: Up) and rows of zeros (None).
  const int32_t sizes[][2] = {{1000, 1}, {512, 1023}, {8, 61681}, {900, 1300}};
  uint64_t seed = 500;
  for (const auto& s : sizes) {
    const int32_t w = s[0], h = s[1];
    std::vector<uint16_t> zeros_then_flat(static_cast<std::size_t>(w) * h, 0);
    std::fill(zeros_then_flat.begin() + static_cast<long>(zeros_then_flat.size() / 2), zeros_then_flat.end(), 777);
    const std::vector<uint16_t> images[] = {make_gray(Kind::kRandom, w, h, ++seed), milled_heightmap(w, h),
                                            make_gray(Kind::kMixed, w, h, ++seed), zeros_then_flat};
    for (const std::vector<uint16_t>& img : images) {
      Bytes png;
      int filters[5] = {};
      check_gray16(img, w, h, filters, &png);
      for (int threads : {1, 2, 3, 7}) {
        Bytes again;
        png_encode_gray16(img.data(), w, h, &again, threads);
        CHECK(again == png);
      }
    }
  }
}

TEST(png_output_is_deterministic) {
  const Bytes rgb = make_rgb(Kind::kMixed, 77, 55, 400);
  Bytes a, b;
  png_encode_rgb8(rgb.data(), 77, 55, &a);
  png_encode_rgb8(rgb.data(), 77, 55, &b);
  CHECK(a == b);
}

namespace {

// A frame like a render: a vertical gradient background, a shaded ellipsoid
// (Lambert, one light) and a box with three flat faces, 8 bits a channel.
Bytes render_like_frame(int32_t w, int32_t h) {
  Bytes rgb(static_cast<std::size_t>(w) * h * 3);
  const double lx = -0.4, ly = -0.5, lz = 0.768;  // unit light direction
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      double c[3] = {40 + 50.0 * y / h, 44 + 52.0 * y / h, 60 + 60.0 * y / h};
      const double ex = (x - 360) / 200.0, ey = (y - 220) / 140.0;
      const double r2 = ex * ex + ey * ey;
      if (r2 < 1) {
        const double nz = std::sqrt(1 - r2);
        const double lambert = std::max(0.0, ex * lx + ey * ly + nz * lz);
        const double base[3] = {205, 165, 95};
        for (int k = 0; k < 3; ++k) c[k] = base[k] * (0.2 + 0.8 * lambert);
      } else if (x >= 60 && x < 200 && y >= 300 && y < 440) {
        const double face = y < 330 ? 200 : x < 90 ? 120 : 160;  // top, left, front
        c[0] = c[1] = c[2] = face;
      }
      for (int k = 0; k < 3; ++k) rgb[(static_cast<std::size_t>(y) * w + x) * 3 + k] = static_cast<uint8_t>(c[k] + 0.5);
    }
  return rgb;
}

}  // namespace

TEST(png_render_like_frame_is_under_a_quarter_of_its_ppm) {
  const int32_t w = 640, h = 480;
  const std::size_t ppm_bytes = 15 + static_cast<std::size_t>(w) * h * 3;  // "P6\n640 480\n255\n" + pixels
  CHECK_EQ(ppm_bytes, std::size_t{921615});
  const std::size_t png_bytes = check_rgb8(render_like_frame(w, h), w, h);
  CHECK_LE(png_bytes * 4, ppm_bytes);
  CHECK_LE(png_bytes * 20, ppm_bytes);  // in fact far below: smooth areas filter to near zero
}
