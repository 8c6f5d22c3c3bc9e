// zlib (RFC 1950) and DEFLATE (RFC 1951) compression, CRC-32 and Adler-32.
//
// The compressor works in three stages:
//   1. LZ77 (RFC 1951 section 4, platform/format/lz77.h): a MatchFinder keeps
//      hash chains of every earlier position within the 32 KiB window;
//      lz77_parse walks the input with one-step lazy matching and hands
//      literals and matches on.
//   2. A BlockWriter buffers those symbols and, every block_symbols of them,
//      writes one block (section 3.2.3) as whichever is smallest of dynamic
//      Huffman (3.2.7), fixed Huffman (3.2.6) or stored (3.2.4).
//   3. Huffman codes are limited to 15 bits (7 for the code length code) by
//      the package-merge algorithm, which gives the best lengths under the
//      limit, and are assigned canonically (3.2.2).
// Every choice depends only on the input bytes, so output is deterministic.
#include "platform/format/deflate.h"
#include "platform/format/lz77.h"
#include "platform/os/cpu_clones.h"
#include "platform/os/parallel.h"

#include <algorithm>
#include <cstring>

namespace dexmill {

// ---- Adler-32 (RFC 1950 sections 8 and 9) ---------------------------------

namespace {

// The largest prime below 2^16 (RFC 1950 section 9, "ADLER32").
constexpr uint32_t kAdlerModulus = 65521;
// Bytes that may be summed before reducing: the largest n for which the sum
// s2 cannot pass 2^32 - 1 from reduced start values, i.e.
// 255 * n * (n + 1) / 2 + (n + 1) * (kAdlerModulus - 1) <= 2^32 - 1.
constexpr std::size_t kAdlerBytesPerReduction = 5552;
constexpr std::size_t kAdlerBlockBytes = 32;

}  // namespace

// Built for AVX2 too (platform/os/cpu_clones.h): a carved relief's
// heightmap's sums (40 MB) took 55 M instructions on AVX2 against 148 M.
DEXMILL_AVX2_CLONES
uint32_t adler32_update(uint32_t adler, const uint8_t* p, std::size_t n) {
  uint32_t s1 = adler & 0xFFFFu;
  uint32_t s2 = adler >> 16;
  while (n > 0) {
    const std::size_t run = std::min(n, kAdlerBytesPerReduction);
    std::size_t i = 0;
    // kAdlerBlockBytes at a time: s2 gains the block's length times s1 and
    // each byte times the count of sums it is in (the same s1 and s2 at
    // the block's end as byte by byte), sums the compiler vectorises.
    for (; i + kAdlerBlockBytes <= run; i += kAdlerBlockBytes) {
      uint32_t sum = 0, weighted = 0;
      for (std::size_t k = 0; k < kAdlerBlockBytes; ++k) {
        sum += p[i + k];
        weighted += static_cast<uint32_t>(kAdlerBlockBytes - k) * p[i + k];
      }
      s2 += static_cast<uint32_t>(kAdlerBlockBytes) * s1 + weighted;
      s1 += sum;
    }
    for (; i < run; ++i) {
      s1 += p[i];
      s2 += s1;
    }
    s1 %= kAdlerModulus;
    s2 %= kAdlerModulus;
    p += run;
    n -= run;
  }
  return (s2 << 16) | s1;
}

// With A's sums (a1, a2) and B's (b1, b2) over its len_b bytes, A then B has
// s1 = a1 + b1 - 1 (each s1 starts at 1), and each of B's len_b terms of s2
// is B's own plus a1 - 1: s2 = a2 + b2 + len_b * (a1 - 1), modulo 65521.
uint32_t adler32_combine(uint32_t adler_a, uint32_t adler_b, std::size_t len_b) {
  const uint64_t m = kAdlerModulus;
  const uint64_t rem = len_b % m;
  const uint64_t a1 = adler_a & 0xFFFFu, a2 = adler_a >> 16, b1 = adler_b & 0xFFFFu, b2 = adler_b >> 16;
  const uint64_t s1 = (a1 + b1 + m - 1) % m;
  const uint64_t s2 = (a2 + b2 + rem * ((a1 + m - 1) % m)) % m;
  return static_cast<uint32_t>(s2 << 16 | s1);
}

// ---- DEFLATE ---------------------------------------------------------------

namespace {

// Alphabets (RFC 1951 section 3.2.5): literal/length symbols 0..285 (256 ends
// a block), distance symbols 0..29, code length symbols 0..18 (3.2.7).
constexpr int kLitLenSymbols = 286;
// The fixed code (section 3.2.6) also assigns codes to 286 and 287, which
// never occur but shift the codes of every longer length, so it spans 288.
constexpr int kFixedLitLenSymbols = 288;
constexpr int kDistSymbols = 30;
constexpr int kCodeLengthSymbols = 19;
constexpr int kEndOfBlock = 256;
constexpr int kFirstLengthSymbol = 257;
// Fewest literal/length and distance codes a dynamic header may announce.
constexpr int kMinLitLenCodes = 257;
constexpr int kMinDistCodes = 1;
constexpr int kMinCodeLengthCodes = 4;
// Longest code lengths allowed (section 3.2.7: lengths 0..15, and the code
// length code's own lengths are sent in 3 bits).
constexpr int kMaxCodeBits = 15;
constexpr int kMaxCodeLengthCodeBits = 7;
// Section 3.2.7: widths of the dynamic header's fields HLIT, HDIST, HCLEN
// and of each code length code length.
constexpr int kHlitBits = 5, kHdistBits = 5, kHclenBits = 4, kCodeLengthCodeLengthBits = 3;

// Section 3.2.5: base and extra bits of each length symbol (from 257) and of
// each distance symbol.
constexpr int kLengthCodes = 29;
constexpr uint16_t kLengthBase[kLengthCodes] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr uint8_t kLengthExtraBits[kLengthCodes] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                          2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr uint16_t kDistBase[kDistSymbols] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,    65,    97,    129,
                                    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr uint8_t kDistExtraBits[kDistSymbols] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                        6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
// Section 3.2.7: the order in which the code length code's lengths are sent
// (the ones most often unused come last, so they can be left off).
constexpr uint8_t kCodeLengthOrder[kCodeLengthSymbols] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
// Section 3.2.7: code length symbols 16 (repeat the previous length 3..6
// times), 17 (3..10 zeros) and 18 (11..138 zeros), with their extra bits.
constexpr int kRepeatPrevious = 16;
constexpr int kRepeatZerosShort = 17;
constexpr int kRepeatZerosLong = 18;
constexpr int kRepeatMinCount = 3;  // the least any of the three repeats
constexpr int kRepeatPreviousMaxCount = 6;
constexpr int kZerosLongMinCount = 11;
constexpr int kZerosLongMaxCount = 138;
constexpr uint8_t kCodeLengthExtraBits[kCodeLengthSymbols] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                              0, 0, 0, 0, 0, 0, 2, 3, 7};

// Section 3.2.4: a stored block holds at most 65535 bytes (LEN is 16 bits).
constexpr std::size_t kStoredMaxBytes = 65535;
constexpr int kStoredLenBits = 16;  // LEN, then NLEN of the same width
// Section 3.2.3: BTYPE values.
constexpr uint32_t kBlockStored = 0, kBlockFixed = 1, kBlockDynamic = 2;
constexpr int kBlockTypeBits = 2;
constexpr int kBlockHeaderBits = 1 + kBlockTypeBits;  // BFINAL and BTYPE

// Symbols per block: enough that a dynamic header (typically 60 to 100
// bytes) costs little, few enough that codes follow changes in the data.
// Heightmaps' filtered rows change slowly: blocks of twice this made a
// carved relief's PNG (4503² at 0.02 mm, in pieces) 2 074 405 -> 2 073 511
// bytes and scale-4k's 8 633 685 -> 8 621 978 (three times: 2 074 433 and
// 8 617 875; half: 2 078 714 and 8 655 411), but the milled part of
// tests/test_png.cpp 29 904 -> 29 962: BlockWriter takes whichever is smaller.
constexpr std::size_t kBlockSymbols = 16384;

using lz77::kMaxMatchBytes;
using lz77::kMinMatchBytes;
using lz77::kWindowBytes;

// ---- bit output ----

// Appends bits to a byte vector least significant bit first, as section
// 3.1.1 packs data elements; Huffman codes are stored reversed so that they
// come out most significant bit first, as the same section requires. Bits
// gather in a 64-bit word and go out four bytes at a time into the vector,
// grown ahead in large steps (a push_back a byte cost a fifth of the time
// of a heightmap's PNG); finish() trims it to the bytes written.
class BitWriter {
 public:
  explicit BitWriter(std::vector<uint8_t>* out) : out_(out), size_(out->size()) {}

  // Appends the low count_bits (0..32) bits of value.
  void put(uint32_t value, int count_bits) {
    pending_ |= static_cast<uint64_t>(value) << pending_bits_;
    pending_bits_ += count_bits;
    if (pending_bits_ < 32) return;
    reserve(4);
    uint8_t* p = out_->data() + size_;
    // Byte by byte, so the order is the same on any host.
    for (int i = 0; i < 4; ++i) p[i] = static_cast<uint8_t>(pending_ >> (8 * i));
    size_ += 4;
    pending_ >>= 32;
    pending_bits_ -= 32;
  }
  // Pads with zero bits to the next byte boundary and moves every whole
  // pending byte out.
  void align_to_byte() {
    if (pending_bits_ % 8) put(0, 8 - pending_bits_ % 8);
    reserve(4);
    for (; pending_bits_ > 0; pending_bits_ -= 8, pending_ >>= 8) (*out_)[size_++] = static_cast<uint8_t>(pending_);
  }
  // Appends whole bytes; the writer must be at a byte boundary.
  void put_bytes(const uint8_t* p, std::size_t n) {
    align_to_byte();
    reserve(n);
    if (n > 0) std::memcpy(out_->data() + size_, p, n);
    size_ += n;
  }
  // Bits written since the last byte boundary (0..7).
  int pending_bits() const { return pending_bits_ % 8; }
  // Aligns to a byte and leaves the vector holding exactly what was written.
  void finish() {
    align_to_byte();
    out_->resize(size_);
  }

 private:
  void reserve(std::size_t n) {
    if (size_ + n > out_->size()) out_->resize(std::max(size_ + n, 2 * out_->size() + 4096));
  }

  std::vector<uint8_t>* out_;
  std::size_t size_;  // bytes written; the vector beyond them is room
  uint64_t pending_ = 0;
  int pending_bits_ = 0;  // 0..31 between calls
};

// ---- Huffman codes ----

// A prefix code over up to kFixedLitLenSymbols symbols: each symbol's code
// length (0 for a symbol not in the code) and its code with the bits reversed.
struct HuffmanCode {
  int symbols = 0;
  uint8_t bits[kFixedLitLenSymbols] = {};
  uint16_t reversed[kFixedLitLenSymbols] = {};
};

uint16_t reverse_bits(uint32_t code, int count_bits) {
  uint32_t r = 0;
  for (int i = 0; i < count_bits; ++i) r |= ((code >> i) & 1u) << (count_bits - 1 - i);
  return static_cast<uint16_t>(r);
}

// Section 3.2.2: codes of each length are consecutive integers in symbol
// order, and all codes of a length follow those of the length below.
void assign_canonical_codes(HuffmanCode* code) {
  uint32_t count_per_length[kMaxCodeBits + 1] = {};
  for (int s = 0; s < code->symbols; ++s) ++count_per_length[code->bits[s]];
  count_per_length[0] = 0;
  uint32_t next_code[kMaxCodeBits + 1] = {};
  uint32_t first = 0;
  for (int len = 1; len <= kMaxCodeBits; ++len) {
    first = (first + count_per_length[len - 1]) << 1;
    next_code[len] = first;
  }
  for (int s = 0; s < code->symbols; ++s) {
    const int len = code->bits[s];
    code->reversed[s] = len ? reverse_bits(next_code[len]++, len) : 0;
  }
}

// A node of package-merge: a leaf (one symbol) or a package of two items.
struct PackageNode {
  uint64_t weight;
  int32_t symbol;  // -1 for a package
  int32_t left, right;
};

// Adds one to the code length of every symbol below node: each time a
// symbol takes part in a chosen item its code grows by one bit.
void count_leaves(const std::vector<PackageNode>& nodes, int32_t node, uint8_t* bits) {
  const PackageNode& n = nodes[static_cast<std::size_t>(node)];
  if (n.symbol >= 0) {
    ++bits[n.symbol];
    return;
  }
  count_leaves(nodes, n.left, bits);
  count_leaves(nodes, n.right, bits);
}

// The leaves of package-merge, lightest first: every used symbol, and when
// fewer than two are used, the first unused ones as if seen once, so that
// every code is complete (one lone 1-bit code is legal, section 3.2.7, but
// not every decoder accepts it).
std::vector<PackageNode> package_leaves(const uint32_t* freq, int symbols) {
  std::vector<PackageNode> leaves;
  for (int s = 0; s < symbols; ++s)
    if (freq[s] > 0) leaves.push_back({freq[s], s, -1, -1});
  for (int s = 0; leaves.size() < 2 && s < symbols; ++s)
    if (freq[s] == 0) leaves.push_back({1, s, -1, -1});
  // (weight, symbol) orders totally, so the result never depends on the sort.
  std::sort(leaves.begin(), leaves.end(), [](const PackageNode& a, const PackageNode& b) {
    return a.weight != b.weight ? a.weight < b.weight : a.symbol < b.symbol;
  });
  return leaves;
}

}  // namespace

// Package-merge (Larmore and Hirschberg, 1990) finds the lengths: the list of
// level 1 is the leaves; each further level pairs neighbours of the list
// below into packages and merges them with the leaves by weight. The lightest
// 2n - 2 items of the last list, expanded into their leaves, give each
// symbol's length as the number of times it appears.
void huffman_code_lengths(const uint32_t* freq, int symbols, int max_bits, uint8_t* bits) {
  std::fill(bits, bits + std::max(symbols, 0), 0);
  if (symbols < 2 || max_bits < 1 || max_bits > kMaxCodeBits || symbols > (1 << max_bits)) return;
  std::vector<PackageNode> nodes = package_leaves(freq, symbols);
  const std::size_t leaf_count = nodes.size();
  std::vector<int32_t> list(leaf_count);
  for (std::size_t i = 0; i < leaf_count; ++i) list[i] = static_cast<int32_t>(i);
  for (int level = 2; level <= max_bits; ++level) {
    std::vector<int32_t> merged;
    merged.reserve(leaf_count + list.size() / 2);
    std::size_t leaf = 0;
    for (std::size_t i = 0; i + 1 < list.size(); i += 2) {
      const uint64_t weight = nodes[static_cast<std::size_t>(list[i])].weight + nodes[static_cast<std::size_t>(list[i + 1])].weight;
      while (leaf < leaf_count && nodes[leaf].weight <= weight) merged.push_back(static_cast<int32_t>(leaf++));
      nodes.push_back({weight, -1, list[i], list[i + 1]});
      merged.push_back(static_cast<int32_t>(nodes.size() - 1));
    }
    while (leaf < leaf_count) merged.push_back(static_cast<int32_t>(leaf++));
    list.swap(merged);
  }
  for (std::size_t i = 0; i < 2 * leaf_count - 2; ++i) count_leaves(nodes, list[i], bits);
}

namespace {

// The best code for these frequencies with lengths of at most max_bits.
void build_code(const uint32_t* freq, int symbols, int max_bits, HuffmanCode* code) {
  code->symbols = symbols;
  huffman_code_lengths(freq, symbols, max_bits, code->bits);
  assign_canonical_codes(code);
}

// Section 3.2.6: the fixed literal/length code (8, 9, 7 and 8 bits by range)
// and the fixed 5-bit distance code.
void build_fixed_codes(HuffmanCode* litlen, HuffmanCode* dist) {
  litlen->symbols = kFixedLitLenSymbols;
  for (int s = 0; s < kFixedLitLenSymbols; ++s) litlen->bits[s] = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
  assign_canonical_codes(litlen);
  dist->symbols = kDistSymbols;
  std::fill(dist->bits, dist->bits + kDistSymbols, 5);
  assign_canonical_codes(dist);
}

// ---- symbols of a block ----

// A literal (distance 0, value the byte) or a match (length 3..258 bytes,
// distance 1..32768 bytes).
struct LzSymbol {
  uint16_t value_or_length;
  uint16_t distance;
};

// Section 3.2.5's ranges as lookup tables (a search of kLengthBase and
// kDistBase for every match took 7 % of a heightmap's PNG): the length code
// of each length 0..258 (3..258 used), the distance code of distances
// 1..256 by distance - 1, and of longer ones by (distance - 1) >> 7, as
// every code from 16 on starts one past a multiple of 128 and spans whole
// multiples of 128.
struct CodeIndexTables {
  uint8_t length[kMaxMatchBytes + 1] = {};
  uint8_t dist_near[256] = {};
  uint8_t dist_far[256] = {};
};

constexpr CodeIndexTables make_code_index_tables() {
  CodeIndexTables t;
  int code = 0;
  for (int len = kMinMatchBytes; len <= kMaxMatchBytes; ++len) {
    while (code + 1 < kLengthCodes && kLengthBase[code + 1] <= len) ++code;
    t.length[len] = static_cast<uint8_t>(code);
  }
  code = 0;
  for (int d = 1; d <= static_cast<int>(kWindowBytes); ++d) {
    while (code + 1 < kDistSymbols && kDistBase[code + 1] <= d) ++code;
    if (d <= 256) t.dist_near[d - 1] = static_cast<uint8_t>(code);
    else t.dist_far[(d - 1) >> 7] = static_cast<uint8_t>(code);
  }
  return t;
}

constexpr CodeIndexTables kCodeIndex = make_code_index_tables();
static_assert(kCodeIndex.length[258] == 28 && kCodeIndex.length[257] == 27, "length codes");
static_assert(kCodeIndex.dist_far[(24577 - 1) >> 7] == 29 && kCodeIndex.dist_far[(24576 - 1) >> 7] == 28, "distance codes");

inline int length_index(uint32_t length_bytes) { return kCodeIndex.length[length_bytes]; }
inline int dist_index(uint32_t distance_bytes) {
  return distance_bytes <= 256 ? kCodeIndex.dist_near[distance_bytes - 1] : kCodeIndex.dist_far[(distance_bytes - 1) >> 7];
}

// Symbol counts of one block and the extra bits its matches carry (the same
// for every Huffman code).
struct BlockStats {
  uint32_t litlen[kLitLenSymbols] = {};
  uint32_t dist[kDistSymbols] = {};
  uint64_t extra_bits = 0;
};

BlockStats count_symbols(const LzSymbol* begin, const LzSymbol* end) {
  BlockStats st;
  for (const LzSymbol* p = begin; p != end; ++p) {
    const LzSymbol& s = *p;
    if (s.distance == 0) {
      ++st.litlen[s.value_or_length];
      continue;
    }
    const int li = length_index(s.value_or_length);
    const int di = dist_index(s.distance);
    ++st.litlen[kFirstLengthSymbol + li];
    ++st.dist[di];
    st.extra_bits += kLengthExtraBits[li] + kDistExtraBits[di];
  }
  st.litlen[kEndOfBlock] = 1;
  return st;
}

// Bits of the block's symbols (with end of block) under these codes.
uint64_t payload_bits(const BlockStats& st, const HuffmanCode& litlen, const HuffmanCode& dist) {
  uint64_t bits = st.extra_bits;
  for (int s = 0; s < kLitLenSymbols; ++s) bits += static_cast<uint64_t>(st.litlen[s]) * litlen.bits[s];
  for (int s = 0; s < kDistSymbols; ++s) bits += static_cast<uint64_t>(st.dist[s]) * dist.bits[s];
  return bits;
}

// ---- dynamic block header (section 3.2.7) ----

// One symbol of the code length alphabet with its extra-bits value.
struct CodeLengthItem {
  uint8_t symbol;
  uint8_t extra;
};

// Run-length codes `run` copies of length `len`: zeros by 17 and 18, other
// lengths once literally then by 16, leftovers shorter than a repeat code's
// minimum literally.
void encode_run(uint8_t len, int run, std::vector<CodeLengthItem>* items) {
  if (len == 0) {
    while (run >= kZerosLongMinCount) {
      const int take = std::min(run, kZerosLongMaxCount);
      items->push_back({kRepeatZerosLong, static_cast<uint8_t>(take - kZerosLongMinCount)});
      run -= take;
    }
    if (run >= kRepeatMinCount) {  // 3..10 zeros
      items->push_back({kRepeatZerosShort, static_cast<uint8_t>(run - kRepeatMinCount)});
      run = 0;
    }
  } else {
    items->push_back({len, 0});
    --run;
    while (run >= kRepeatMinCount) {
      const int take = std::min(run, kRepeatPreviousMaxCount);
      items->push_back({kRepeatPrevious, static_cast<uint8_t>(take - kRepeatMinCount)});
      run -= take;
    }
  }
  for (; run > 0; --run) items->push_back({len, 0});
}

// The literal/length and distance code lengths form one sequence, and runs
// may cross from one to the other (section 3.2.7).
std::vector<CodeLengthItem> run_length_code(const uint8_t* lengths, int count) {
  std::vector<CodeLengthItem> items;
  for (int i = 0; i < count;) {
    int run = 1;
    while (i + run < count && lengths[i + run] == lengths[i]) ++run;
    encode_run(lengths[i], run, &items);
    i += run;
  }
  return items;
}

struct DynamicHeader {
  int litlen_codes = 0;       // HLIT + 257
  int dist_codes = 0;         // HDIST + 1
  int code_length_codes = 0;  // HCLEN + 4
  std::vector<CodeLengthItem> items;
  HuffmanCode code_length_code;
  uint64_t bits = 0;  // the header's size after BFINAL and BTYPE
};

// Number of codes to send: trailing unused ones are left off, down to min.
int used_codes(const uint8_t* bits, int count, int min) {
  while (count > min && bits[count - 1] == 0) --count;
  return count;
}

DynamicHeader plan_dynamic_header(const HuffmanCode& litlen, const HuffmanCode& dist) {
  DynamicHeader h;
  h.litlen_codes = used_codes(litlen.bits, kLitLenSymbols, kMinLitLenCodes);
  h.dist_codes = used_codes(dist.bits, kDistSymbols, kMinDistCodes);
  uint8_t lengths[kLitLenSymbols + kDistSymbols];
  std::copy(litlen.bits, litlen.bits + h.litlen_codes, lengths);
  std::copy(dist.bits, dist.bits + h.dist_codes, lengths + h.litlen_codes);
  h.items = run_length_code(lengths, h.litlen_codes + h.dist_codes);

  uint32_t freq[kCodeLengthSymbols] = {};
  for (const CodeLengthItem& it : h.items) ++freq[it.symbol];
  build_code(freq, kCodeLengthSymbols, kMaxCodeLengthCodeBits, &h.code_length_code);
  uint8_t sent_order[kCodeLengthSymbols];
  for (int i = 0; i < kCodeLengthSymbols; ++i) sent_order[i] = h.code_length_code.bits[kCodeLengthOrder[i]];
  h.code_length_codes = used_codes(sent_order, kCodeLengthSymbols, kMinCodeLengthCodes);

  h.bits = kHlitBits + kHdistBits + kHclenBits + kCodeLengthCodeLengthBits * static_cast<uint64_t>(h.code_length_codes);
  for (const CodeLengthItem& it : h.items) h.bits += h.code_length_code.bits[it.symbol] + kCodeLengthExtraBits[it.symbol];
  return h;
}

void write_dynamic_header(const DynamicHeader& h, BitWriter* out) {
  out->put(static_cast<uint32_t>(h.litlen_codes - kMinLitLenCodes), kHlitBits);
  out->put(static_cast<uint32_t>(h.dist_codes - kMinDistCodes), kHdistBits);
  out->put(static_cast<uint32_t>(h.code_length_codes - kMinCodeLengthCodes), kHclenBits);
  for (int i = 0; i < h.code_length_codes; ++i)
    out->put(h.code_length_code.bits[kCodeLengthOrder[i]], kCodeLengthCodeLengthBits);
  for (const CodeLengthItem& it : h.items) {
    out->put(h.code_length_code.reversed[it.symbol], h.code_length_code.bits[it.symbol]);
    out->put(it.extra, kCodeLengthExtraBits[it.symbol]);
  }
}

// ---- block output ----

// Section 3.2.3: BFINAL (set on the last block), then BTYPE.
void put_block_header(bool final, uint32_t type, BitWriter* out) {
  out->put(final ? 1 : 0, 1);
  out->put(type, kBlockTypeBits);
}

void put_symbol(const HuffmanCode& code, int symbol, BitWriter* out) {
  out->put(code.reversed[symbol], code.bits[symbol]);
}

// Section 3.2.5: a match is its length symbol and extra bits, then its
// distance symbol and extra bits.
void write_symbols(const LzSymbol* begin, const LzSymbol* end, const HuffmanCode& litlen, const HuffmanCode& dist,
                   BitWriter* out) {
  for (const LzSymbol* p = begin; p != end; ++p) {
    const LzSymbol& s = *p;
    if (s.distance == 0) {
      put_symbol(litlen, s.value_or_length, out);
      continue;
    }
    const int li = length_index(s.value_or_length);
    put_symbol(litlen, kFirstLengthSymbol + li, out);
    out->put(s.value_or_length - kLengthBase[li], kLengthExtraBits[li]);
    const int di = dist_index(s.distance);
    put_symbol(dist, di, out);
    out->put(s.distance - kDistBase[di], kDistExtraBits[di]);
  }
  put_symbol(litlen, kEndOfBlock, out);
}

// Section 3.2.4: stored blocks of at most 65535 bytes each, each aligned to a
// byte and led by LEN and its one's complement NLEN. `final` marks the last.
// Returns the bits written, or with out null the bits it would write when
// started pending_bits after a byte boundary.
uint64_t stored_blocks(const uint8_t* p, std::size_t n, bool final, int pending_bits, BitWriter* out) {
  uint64_t bits = 0;
  do {
    const std::size_t take = std::min(n, kStoredMaxBytes);
    const bool last = final && take == n;
    const int pad_bits = (8 - (pending_bits + kBlockHeaderBits) % 8) % 8;
    bits += kBlockHeaderBits + pad_bits + 2 * kStoredLenBits + 8 * static_cast<uint64_t>(take);
    pending_bits = 0;
    if (out) {
      put_block_header(last, kBlockStored, out);
      out->align_to_byte();
      out->put(static_cast<uint32_t>(take), kStoredLenBits);
      out->put(static_cast<uint32_t>(~take & 0xFFFFu), kStoredLenBits);
      out->put_bytes(p, take);
    }
    p += take;
    n -= take;
  } while (n > 0);
  return bits;
}

// A block's three encodings sized (section 3.2.3): which to write and its codes.
struct BlockPlan {
  HuffmanCode litlen, dist;
  DynamicHeader header;
  uint64_t dynamic_bits = 0, fixed_bits = 0, stored_bits = 0;
  uint64_t bits() const { return std::min(stored_bits, std::min(dynamic_bits, fixed_bits)); }
};

// Collects the LZ77 symbols of the input and writes them block by block.
// With kFilteredSamples16 a block gathers up to two of kBlockSymbols and
// goes out as one block or as two, whichever is smaller.
class BlockWriter {
 public:
  BlockWriter(const uint8_t* data, DeflateTuning tuning, BitWriter* out)
      : data_(data), out_(out), may_split_(tuning == DeflateTuning::kFilteredSamples16) {
    build_fixed_codes(&fixed_litlen_, &fixed_dist_);
    symbols_.reserve(capacity());
  }

  void literal() { add({data_[end_], 0}, 1); }
  void match(int length_bytes, std::size_t distance_bytes) {
    add({static_cast<uint16_t>(length_bytes), static_cast<uint16_t>(distance_bytes)}, static_cast<std::size_t>(length_bytes));
  }
  // Writes what is left as the final block (an empty one for empty input),
  // or with final false as a block that is not, followed by an empty
  // stored block (section 3.2.4), which ends at a byte boundary: what comes
  // next may start as a stream of its own (zlib_compress_pieces, deflate.h).
  void finish(bool final) {
    write_blocks(final);
    if (!final) stored_blocks(nullptr, 0, false, out_->pending_bits(), out_);
  }

 private:
  std::size_t capacity() const { return may_split_ ? 2 * kBlockSymbols : kBlockSymbols; }

  void add(LzSymbol s, std::size_t bytes) {
    // Full blocks are written only once more input follows, so the last
    // block written is never empty unless the input is.
    if (symbols_.size() == capacity()) write_blocks(false);
    if (symbols_.size() == kBlockSymbols) half_end_ = end_;
    symbols_.push_back(s);
    end_ += bytes;
  }

  // The block of symbols [first, last) covering input bytes [begin, end),
  // started pending_bits after a byte boundary.
  BlockPlan plan(std::size_t first, std::size_t last, std::size_t begin, std::size_t end, bool final,
                 int pending_bits) const {
    BlockPlan p;
    const BlockStats st = count_symbols(symbols_.data() + first, symbols_.data() + last);
    build_code(st.litlen, kLitLenSymbols, kMaxCodeBits, &p.litlen);
    build_code(st.dist, kDistSymbols, kMaxCodeBits, &p.dist);
    p.header = plan_dynamic_header(p.litlen, p.dist);
    p.dynamic_bits = kBlockHeaderBits + p.header.bits + payload_bits(st, p.litlen, p.dist);
    p.fixed_bits = kBlockHeaderBits + payload_bits(st, fixed_litlen_, fixed_dist_);
    p.stored_bits = stored_blocks(data_ + begin, end - begin, final, pending_bits, nullptr);
    return p;
  }

  void write(const BlockPlan& p, std::size_t first, std::size_t last, std::size_t begin, std::size_t end, bool final) {
    const LzSymbol* s = symbols_.data();
    if (p.stored_bits < p.dynamic_bits && p.stored_bits < p.fixed_bits) {
      stored_blocks(data_ + begin, end - begin, final, out_->pending_bits(), out_);
    } else if (p.fixed_bits <= p.dynamic_bits) {
      put_block_header(final, kBlockFixed, out_);
      write_symbols(s + first, s + last, fixed_litlen_, fixed_dist_, out_);
    } else {
      put_block_header(final, kBlockDynamic, out_);
      write_dynamic_header(p.header, out_);
      write_symbols(s + first, s + last, p.litlen, p.dist, out_);
    }
  }

  // The symbols gathered as one block, or as two when that is smaller (the
  // second sized as if from a byte boundary).
  void write_blocks(bool final) {
    const std::size_t n = symbols_.size();
    const BlockPlan whole = plan(0, n, start_, end_, final, out_->pending_bits());
    if (n > kBlockSymbols) {
      const BlockPlan head = plan(0, kBlockSymbols, start_, half_end_, false, out_->pending_bits());
      const BlockPlan tail = plan(kBlockSymbols, n, half_end_, end_, final, 0);
      if (head.bits() + tail.bits() < whole.bits()) {
        write(head, 0, kBlockSymbols, start_, half_end_, false);
        write(tail, kBlockSymbols, n, half_end_, end_, final);
        symbols_.clear();
        start_ = end_;
        return;
      }
    }
    write(whole, 0, n, start_, end_, final);
    symbols_.clear();
    start_ = end_;
  }

  const uint8_t* data_;
  BitWriter* out_;
  bool may_split_;
  HuffmanCode fixed_litlen_, fixed_dist_;
  std::vector<LzSymbol> symbols_;
  std::size_t start_ = 0;     // first input byte of the block being collected
  std::size_t half_end_ = 0;  // one past the last of its first kBlockSymbols symbols
  std::size_t end_ = 0;       // one past its last
};

// RFC 1950 section 2.2: CMF 0x78 is method 8 (deflate) with CINFO 7 (a
// 32 KiB window); FLG 0x9C has no preset dictionary, FLEVEL 2 (the default
// algorithm) and FCHECK making CMF * 256 + FLG a multiple of 31.
constexpr uint8_t kZlibCmf = 0x78;
constexpr uint8_t kZlibFlg = 0x9C;
static_assert((kZlibCmf * 256 + kZlibFlg) % 31 == 0, "FCHECK");

}  // namespace

namespace {

// RFC 1950 section 2.2: ADLER32 of the uncompressed data, most significant
// byte first.
void put_adler_trailer(uint32_t adler, std::vector<uint8_t>* out) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<uint8_t>(adler >> shift));
}

}  // namespace

void zlib_compress(const uint8_t* data, std::size_t n, std::vector<uint8_t>* out, DeflateTuning tuning) {
  out->clear();
  out->reserve(n / 4 + 64);
  out->push_back(kZlibCmf);
  out->push_back(kZlibFlg);
  BitWriter bits(out);
  BlockWriter blocks(data, tuning, &bits);
  if (n > 0) lz77_parse(data, n, tuning, &blocks);
  blocks.finish(true);
  bits.finish();
  put_adler_trailer(adler32_update(1, data, n), out);
}

void zlib_compress_pieces(const uint8_t* data, std::size_t n, std::vector<uint8_t>* out, DeflateTuning tuning,
                          int threads) {
  const std::size_t pieces = n == 0 ? 1 : (n - 1) / kDeflatePieceBytes + 1;
  std::vector<std::vector<uint8_t>> parts(pieces);
  std::vector<uint32_t> adlers(pieces);
  parallel_for(pieces, threads, [&](std::size_t i) {
    const std::size_t begin = i * kDeflatePieceBytes, end = std::min(n, begin + kDeflatePieceBytes);
    const std::size_t dict = std::min(begin, kWindowBytes);
    deflate_piece(data + (begin - dict), dict, end - begin + dict, i + 1 == pieces, tuning, &parts[i]);
    adlers[i] = adler32_update(1, data + begin, end - begin);
  });
  std::size_t total = 2 + 4;
  for (const std::vector<uint8_t>& part : parts) total += part.size();
  out->clear();
  out->reserve(total);
  out->push_back(kZlibCmf);
  out->push_back(kZlibFlg);
  uint32_t adler = 1;
  for (std::size_t i = 0; i < pieces; ++i) {
    out->insert(out->end(), parts[i].begin(), parts[i].end());
    adler = adler32_combine(adler, adlers[i], std::min(n - i * kDeflatePieceBytes, kDeflatePieceBytes));
  }
  put_adler_trailer(adler, out);
}

void deflate_piece(const uint8_t* data, std::size_t dict_bytes, std::size_t n, bool final, DeflateTuning tuning,
                   std::vector<uint8_t>* out) {
  out->clear();
  if (dict_bytes > n || dict_bytes > kWindowBytes || n - dict_bytes > lz77::kSpanBytes) return;
  out->reserve((n - dict_bytes) / 4 + 64);
  BitWriter bits(out);
  BlockWriter blocks(data + dict_bytes, tuning, &bits);
  if (n > dict_bytes) lz77_parse_after(data, dict_bytes, n, tuning, &blocks);
  blocks.finish(final);
  bits.finish();
}

}  // namespace dexmill
