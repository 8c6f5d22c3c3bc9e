// LZ77 for DEFLATE (RFC 1951 section 4), platform/format/deflate.cpp's first
// stage: hash chains over the 32 KiB window, greedy parsing with one step
// of lazy matching, the search bounded by the tuning (DeflateTuning,
// platform/format/deflate.h). A template on what receives the literals and
// matches, so that the search calls it inline. Deterministic: every choice
// depends on the input bytes only.
#ifndef DEXMILL_PLATFORM_FORMAT_LZ77_H
#define DEXMILL_PLATFORM_FORMAT_LZ77_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "platform/format/deflate.h"

namespace dexmill {
namespace lz77 {

// Section 3.2.5: distances reach 32768 bytes back; lengths are 3..258.
constexpr std::size_t kWindowBytes = 32768;
constexpr int kMinMatchBytes = 3;
constexpr int kMaxMatchBytes = 258;
// Hash chains (section 4 suggests them): the bytes at a position select one
// of 2^kHashBits chain heads (MatchFinder says which bytes).
constexpr int kHashBits = 15;
// A 3-byte match farther back than this costs more bits (distance extra bits
// included) than its three literals on typical data, so it is not taken.
constexpr std::size_t kFarShortMatchBytes = 4096;

struct Match {
  int length_bytes = 0;  // 0: no match worth taking
  std::size_t distance_bytes = 0;
};

// How the match finder looks (besides the bytes at a position whose hash
// selects its chain, MatchFinder's HashBytes), bounds that keep time near
// linear: candidates examined per position, the length from which a
// second (lazy) search gets only a quarter of them (it only has to beat
// the first), a length that ends the search at once, the length below
// which the next position is searched too before a match is taken (lazy
// matching, section 4), and the length above which a run (a match at
// distance 1: one byte repeated) leaves its inside out of the chains, all
// but its last kRunTailInserts positions (0: every position goes in).
struct Effort {
  int max_chain_steps;
  int good_match_bytes;
  int nice_match_bytes;
  int lazy_below_bytes;
  int run_inserts_below_bytes;
};

// kGeneral: every 3-byte match on the chains, 128 candidates a position
// (the demo's frames, unfiltered RGB: five-byte hashes made them 4 % larger).
constexpr int kGeneralHashBytes = 3;
constexpr Effort kGeneralEffort = {128, 8, 128, 32, 0};
// kFilteredSamples16: a hash of three bytes put the small residues of
// filtered 16-bit rows (00 01 00 ...) on long chains of candidates that
// seldom matched further, and short matches of such data save little over
// its cheap literals. Found on heightmaps (tools/bench/bench_image.cpp's
// scale-4k, a carved relief's of 4503² dexels at 0.02 mm, tests/test_png.cpp's
// milled part): at chains of 128, scale-4k's took 1.6 s with three bytes,
// 1.2 s with four, 0.84 s with five, each 1-2 % smaller than the one
// before (the relief's 1 % smaller with four or five than with three);
// with five, chains of 64 took another 10-15 % off and left each
// heightmap smaller than kGeneralEffort's of the encoder before (scale-4k
// 8 632 443 bytes against 8 811 886, the relief 2 074 439 against
// 2 088 738, the part 29 930 against 29 951); 48 made the part's larger.
// Leaving the inside of every match longer than 64 bytes out of the chains
// saved little time and cost 0.5 %; leaving out only the inside of runs
// longer than 64 bytes (the filters make flat areas runs of zeros, and
// inserting each of their bytes was a fifth of the relief's instructions)
// took 20 % off its instructions (callgrind: 3.98 G -> 3.18 G with a
// driver that reads its PGM), left the relief's and the part's a little
// smaller (2 074 214 and 29 904 bytes) and scale-4k's 11 bytes larger.
constexpr int kFilteredSamples16HashBytes = 5;
constexpr Effort kFilteredSamples16Effort = {64, 16, 128, 32, 64};

// The chains' positions are 32-bit offsets from the start of a span of at
// most this many bytes; a longer input is searched span by span (a match
// never reaches into the span before: a loss of one window a GiB).
constexpr std::size_t kSpanBytes = std::size_t{1} << 30;
// The positions at the end of a long run still inserted: the next search
// finds the run it may continue.
constexpr int kRunTailInserts = 4;
// Hashes of more than 3 bytes read one word: with them no match starts in
// the last kHashReadBytes - 1 bytes (with 3, in the last 2).
constexpr int kHashReadBytes = 8;
constexpr uint32_t kNoPosition = 0xFFFFFFFFu;
// With hashes of more than 3 bytes, matches of 3 up to HashBytes - 1
// bytes come from a second table, of each 3-byte hash's latest position
// (no chain), and only from this near: farther, their distance codes cost
// about what their literals would. Against no such table (five-byte
// hashes, chains of 128): the milled part of tests/test_png.cpp 2.7 %
// smaller, the carved relief 0.6 % smaller, scale-4k's heightmap 0.3 %
// larger; reaching 4096 bytes, all three came out larger than at 128.
constexpr int kShortHashBits = 14;
constexpr std::size_t kShortMatchFarBytes = 128;

// Hash chains over the window: head_ holds the latest position of each
// hash of the HashBytes (3 to 7) bytes at a position, prev_ (indexed by
// position modulo the window) the position before it with the same hash,
// kNoPosition for none. A template, so that the hash and the short table
// cost nothing where they are not used.
template <int HashBytes>
class MatchFinder {
  static_assert(HashBytes >= kMinMatchBytes && HashBytes < kHashReadBytes, "hashed bytes");
  static constexpr bool kShortTable = HashBytes > kMinMatchBytes;
  // Bytes a position needs to be hashed.
  static constexpr std::size_t kHashedBytesMin = kShortTable ? kHashReadBytes : kMinMatchBytes;
  static constexpr uint64_t kHashMask = (uint64_t{1} << (8 * HashBytes)) - 1;

 public:
  MatchFinder(const uint8_t* data, std::size_t n, const Effort& effort)
      : data_(data),
        n_(n),
        effort_(effort),
        head_(std::size_t{1} << kHashBits, kNoPosition),
        prev_(kWindowBytes, kNoPosition),
        short_head_(kShortTable ? std::size_t{1} << kShortHashBits : 0, kNoPosition) {}

  // The longest match for the bytes at pos among earlier positions in the
  // window (the nearest of equal length) if longer than longer_than_bytes,
  // or none.
  Match longest(std::size_t pos, int longer_than_bytes) const {
    if (n_ - pos < kHashedBytesMin) return Match{};
    const int max_len = static_cast<int>(std::min<std::size_t>(kMaxMatchBytes, n_ - pos));
    int best_len = std::max(kMinMatchBytes - 1, longer_than_bytes);
    if (best_len >= max_len) return Match{};
    const int max_steps = longer_than_bytes >= effort_.good_match_bytes ? effort_.max_chain_steps / 4 : effort_.max_chain_steps;
    const uint8_t* here = data_ + pos;
    Match best;
    uint32_t cand = head_[hash(pos)];
    for (int steps = 0; cand != kNoPosition && pos - cand <= kWindowBytes && steps < max_steps; ++steps) {
      const uint8_t* there = data_ + cand;
      // Only a candidate that also agrees at the best's last byte and one
      // past it can beat it (the two compared at once).
      if (load_le16(there + best_len - 1) == load_le16(here + best_len - 1)) {
        const int len = common_prefix(there, here, max_len);
        if (len > best_len) {
          best_len = len;
          best = Match{len, pos - cand};
          if (len >= effort_.nice_match_bytes || len == max_len) break;
        }
      }
      const uint32_t next = prev_[cand % kWindowBytes];
      if (next == kNoPosition || next >= cand) break;  // chains only run backwards
      cand = next;
    }
    if (kShortTable && best_len < HashBytes) shorter(pos, here, max_len, best_len, &best);
    if (best.length_bytes == kMinMatchBytes && best.distance_bytes > kFarShortMatchBytes) return Match{};
    return best;
  }

  // Makes pos a candidate for later positions. Insert each position after
  // searching it: its slot in prev_ is the one of pos - 32768, still needed
  // by that search.
  void insert(std::size_t pos) {
    if (n_ - pos < kHashedBytesMin) return;
    const uint32_t h = hash(pos);
    prev_[pos % kWindowBytes] = head_[h];
    head_[h] = static_cast<uint32_t>(pos);
    if (kShortTable) short_head_[short_hash(pos)] = static_cast<uint32_t>(pos);
  }

  // Searches then inserts pos; none past the end.
  Match step(std::size_t pos, int longer_than_bytes = 0) {
    if (pos >= n_) return Match{};
    const Match m = longest(pos, longer_than_bytes);
    insert(pos);
    return m;
  }

 private:
  // Multiplicative hashing (Knuth's 2654435761, near 2^32 / golden ratio,
  // and 2^64 / golden ratio for longer hashes) spreads the hashed bytes
  // over the table; words are put together byte by byte, so the hash is
  // the same on any byte order. Three bytes hash as in the encoder before
  // kFilteredSamples16 (the same chains, so the same stream: the golden
  // pictures of tests/golden/frames/ keep their bytes).
  uint32_t hash(std::size_t pos) const {
    if (HashBytes == kMinMatchBytes) {
      const uint8_t* p = data_ + pos;
      const uint32_t three = static_cast<uint32_t>(p[0]) << 16 | static_cast<uint32_t>(p[1]) << 8 | p[2];
      return (three * 2654435761u) >> (32 - kHashBits);
    }
    const uint64_t hashed = load_le64(data_ + pos) & kHashMask;
    return static_cast<uint32_t>((hashed * 0x9E3779B97F4A7C15ull) >> (64 - kHashBits));
  }

  // The last position whose first kMinMatchBytes bytes hash as pos's: the
  // short match that chains of longer hashes cannot hold.
  uint32_t short_hash(std::size_t pos) const {
    const uint64_t hashed = load_le64(data_ + pos) & ((uint64_t{1} << (8 * kMinMatchBytes)) - 1);
    return static_cast<uint32_t>((hashed * 0x9E3779B97F4A7C15ull) >> (64 - kShortHashBits));
  }

  // Takes the short table's candidate for pos into *best if it is in the
  // window and longer than best_len.
  void shorter(std::size_t pos, const uint8_t* here, int max_len, int best_len, Match* best) const {
    const uint32_t cand = short_head_[short_hash(pos)];
    if (cand == kNoPosition || pos - cand > kShortMatchFarBytes) return;
    const int len = common_prefix(data_ + cand, here, max_len);
    if (len > best_len) *best = Match{len, pos - cand};
  }

  static uint16_t load_le16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | p[1] << 8); }

  // Eight bytes as a little-endian number, byte by byte (compilers make it
  // one load where the host is little-endian).
  static uint64_t load_le64(const uint8_t* p) {
    const uint32_t lo = static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
                        static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
    const uint32_t hi = static_cast<uint32_t>(p[4]) | static_cast<uint32_t>(p[5]) << 8 |
                        static_cast<uint32_t>(p[6]) << 16 | static_cast<uint32_t>(p[7]) << 24;
    return static_cast<uint64_t>(hi) << 32 | lo;
  }

  // Compares eight bytes at a time while they agree; the first that
  // differs is the lowest set byte of the xor of the two little-endian
  // words, so the result is the same as byte by byte on any host.
  static int common_prefix(const uint8_t* a, const uint8_t* b, int max_len) {
    int len = 0;
    for (; len + 8 <= max_len; len += 8) {
      const uint64_t diff = load_le64(a + len) ^ load_le64(b + len);
      if (diff != 0) return len + lowest_set_byte(diff);
    }
    while (len < max_len && a[len] == b[len]) ++len;
    return len;
  }

  // The index (0..7) of the lowest nonzero byte of v != 0.
  static int lowest_set_byte(uint64_t v) { return __builtin_ctzll(v) / 8; }

  const uint8_t* data_;
  std::size_t n_;
  Effort effort_;
  std::vector<uint32_t> head_;
  std::vector<uint32_t> prev_;
  std::vector<uint32_t> short_head_;
};

// Greedy parsing with one step of lazy evaluation (section 4): a match found
// at pos is deferred when pos + 1 has a longer one, pos then going out as a
// literal. Every position is inserted into the chains once, but the
// inside of a long run where the effort says so. The symbols are those of
// data[start, n); the bytes before start are a preset dictionary (RFC
// 1951 section 3.2's window carried over from before), put on the chains
// and never sent.
template <int HashBytes, class Sink>
void lz77_parse_span(const uint8_t* data, std::size_t start, std::size_t n, const Effort& effort, Sink* out) {
  MatchFinder<HashBytes> finder(data, n, effort);
  for (std::size_t p = 0; p < start; ++p) finder.insert(p);
  std::size_t pos = start;
  Match cur = finder.step(start);
  while (pos < n) {
    if (cur.length_bytes == 0) {
      out->literal();
      cur = finder.step(++pos);
      continue;
    }
    std::size_t inserted_to = pos + 1;  // positions below this are in the chains
    if (cur.length_bytes < effort.lazy_below_bytes) {
      const Match next = finder.step(pos + 1, cur.length_bytes);
      ++inserted_to;
      if (next.length_bytes > cur.length_bytes) {
        out->literal();
        ++pos;
        cur = next;
        continue;
      }
    }
    const std::size_t end = pos + static_cast<std::size_t>(cur.length_bytes);
    if (effort.run_inserts_below_bytes > 0 && cur.distance_bytes == 1 && cur.length_bytes > effort.run_inserts_below_bytes)
      inserted_to = std::max(inserted_to, end - kRunTailInserts);
    for (std::size_t p = inserted_to; p < end; ++p) finder.insert(p);
    out->match(cur.length_bytes, cur.distance_bytes);
    pos = end;
    cur = finder.step(pos);
  }
}

}  // namespace lz77

// The literals and matches of data[0, n), in order, to out->literal() (the
// next byte) and out->match(length_bytes, distance_bytes).
template <class Sink>
void lz77_parse(const uint8_t* data, std::size_t n, DeflateTuning tuning, Sink* out) {
  using namespace lz77;
  for (std::size_t at = 0; at < n; at += kSpanBytes) {
    const std::size_t span = std::min(kSpanBytes, n - at);
    if (tuning == DeflateTuning::kFilteredSamples16)
      lz77_parse_span<kFilteredSamples16HashBytes>(data + at, 0, span, kFilteredSamples16Effort, out);
    else
      lz77_parse_span<kGeneralHashBytes>(data + at, 0, span, kGeneralEffort, out);
  }
}

// The literals and matches of data[dict_bytes, n) as lz77_parse gives them,
// matches reaching back into data[0, dict_bytes) as well (a preset
// dictionary of at most the window; n at most lz77::kSpanBytes).
template <class Sink>
void lz77_parse_after(const uint8_t* data, std::size_t dict_bytes, std::size_t n, DeflateTuning tuning, Sink* out) {
  using namespace lz77;
  if (tuning == DeflateTuning::kFilteredSamples16)
    lz77_parse_span<kFilteredSamples16HashBytes>(data, dict_bytes, n, kFilteredSamples16Effort, out);
  else
    lz77_parse_span<kGeneralHashBytes>(data, dict_bytes, n, kGeneralEffort, out);
}

}  // namespace dexmill

#endif
