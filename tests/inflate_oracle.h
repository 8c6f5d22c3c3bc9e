// A small INFLATE decoder (RFC 1951) and zlib unwrapper (RFC 1950) for the
// tests only: the reference the encoder of platform/format/deflate.h is checked
// against. It shares no code with the encoder, reads bit by bit for
// simplicity rather than speed, and rejects anything malformed (bad block
// type, over-subscribed codes, bad repeat codes, distances before the start,
// LEN/NLEN mismatch, truncation, a bad zlib header or Adler-32). It also
// counts what it saw, so tests can ask which block types and match extremes
// a stream used.
#ifndef DEXMILL_TESTS_INFLATE_ORACLE_H
#define DEXMILL_TESTS_INFLATE_ORACLE_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace oracle {

struct InflateStats {
  int stored_blocks = 0;
  int fixed_blocks = 0;
  int dynamic_blocks = 0;
  int incomplete_codes = 0;  // Huffman codes whose lengths leave codes unused
  uint32_t max_distance = 0;
  uint32_t max_length = 0;
  std::size_t max_stored_bytes = 0;
};

// Reads bits least significant first (RFC 1951 section 3.1.1).
class BitReader {
 public:
  BitReader(const uint8_t* p, std::size_t n) : p_(p), n_(n) {}
  uint32_t bits(int count) {
    uint32_t v = 0;
    for (int i = 0; i < count; ++i) {
      if (pos_ / 8 >= n_) {
        overrun_ = true;
        return 0;
      }
      v |= static_cast<uint32_t>((p_[pos_ / 8] >> (pos_ % 8)) & 1u) << i;
      ++pos_;
    }
    return v;
  }
  void skip_to_byte() { pos_ = (pos_ + 7) / 8 * 8; }
  std::size_t byte_pos() const { return (pos_ + 7) / 8; }
  bool overrun() const { return overrun_; }

 private:
  const uint8_t* p_;
  std::size_t n_;
  std::size_t pos_ = 0;
  bool overrun_ = false;
};

// A canonical code (section 3.2.2) as the number of codes of each length and
// the symbols in code order; decoding walks the lengths one bit at a time.
struct Decoder {
  int count[16] = {};
  std::vector<int> symbol;
};

// False if the lengths over-subscribe the code space.
inline bool make_decoder(const uint8_t* lengths, int n, Decoder* d, InflateStats* st) {
  *d = Decoder{};
  for (int s = 0; s < n; ++s) ++d->count[lengths[s]];
  d->count[0] = 0;
  int left = 1;
  for (int len = 1; len < 16; ++len) {
    left = left * 2 - d->count[len];
    if (left < 0) return false;
  }
  if (left > 0) ++st->incomplete_codes;
  for (int len = 1; len < 16; ++len)
    for (int s = 0; s < n; ++s)
      if (lengths[s] == len) d->symbol.push_back(s);
  return true;
}

// The next symbol, or -1 for a code the decoder does not have.
inline int decode(BitReader* in, const Decoder& d) {
  int code = 0, first = 0, index = 0;
  for (int len = 1; len < 16; ++len) {
    code |= static_cast<int>(in->bits(1));
    if (code < first + d.count[len]) return d.symbol[static_cast<std::size_t>(index + code - first)];
    index += d.count[len];
    first = (first + d.count[len]) << 1;
    code <<= 1;
  }
  return -1;
}

// Section 3.2.5 tables, written out again here on purpose.
constexpr int kLenBase[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr int kLenExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int kDistBase[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                               1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr int kDistExtra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

inline bool inflate_codes(BitReader* in, const Decoder& lit, const Decoder& dist, std::vector<uint8_t>* out, InflateStats* st) {
  for (;;) {
    const int sym = decode(in, lit);
    if (in->overrun() || sym < 0) return false;
    if (sym < 256) {
      out->push_back(static_cast<uint8_t>(sym));
      continue;
    }
    if (sym == 256) return true;
    if (sym > 285) return false;
    const int len = kLenBase[sym - 257] + static_cast<int>(in->bits(kLenExtra[sym - 257]));
    const int dsym = decode(in, dist);
    if (dsym < 0 || dsym > 29) return false;
    const std::size_t d = static_cast<std::size_t>(kDistBase[dsym]) + in->bits(kDistExtra[dsym]);
    if (in->overrun() || d > out->size() || d > 32768) return false;
    for (int i = 0; i < len; ++i) out->push_back((*out)[out->size() - d]);
    if (d > st->max_distance) st->max_distance = static_cast<uint32_t>(d);
    if (static_cast<uint32_t>(len) > st->max_length) st->max_length = static_cast<uint32_t>(len);
  }
}

inline bool inflate_stored(BitReader* in, const uint8_t* p, std::size_t n, std::vector<uint8_t>* out, InflateStats* st) {
  in->skip_to_byte();
  const uint32_t len = in->bits(16);
  const uint32_t nlen = in->bits(16);
  if (in->overrun() || (len ^ 0xFFFFu) != nlen) return false;
  const std::size_t at = in->byte_pos();
  if (at + len > n) return false;
  out->insert(out->end(), p + at, p + at + len);
  for (uint32_t i = 0; i < len; ++i) in->bits(8);
  ++st->stored_blocks;
  if (len > st->max_stored_bytes) st->max_stored_bytes = len;
  return true;
}

inline bool inflate_fixed(BitReader* in, std::vector<uint8_t>* out, InflateStats* st) {
  uint8_t lengths[288 + 32];
  for (int s = 0; s < 288; ++s) lengths[s] = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
  for (int s = 0; s < 32; ++s) lengths[288 + s] = 5;
  Decoder lit, dist;
  InflateStats ignore;  // the fixed codes are complete; nothing to count
  make_decoder(lengths, 288, &lit, &ignore);
  make_decoder(lengths + 288, 32, &dist, &ignore);
  ++st->fixed_blocks;
  return inflate_codes(in, lit, dist, out, st);
}

inline bool inflate_dynamic(BitReader* in, std::vector<uint8_t>* out, InflateStats* st) {
  static const int kOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
  const int hlit = static_cast<int>(in->bits(5)) + 257;
  const int hdist = static_cast<int>(in->bits(5)) + 1;
  const int hclen = static_cast<int>(in->bits(4)) + 4;
  if (hlit > 286 || hdist > 30) return false;
  uint8_t cl_lengths[19] = {};
  for (int i = 0; i < hclen; ++i) cl_lengths[kOrder[i]] = static_cast<uint8_t>(in->bits(3));
  Decoder cl;
  if (!make_decoder(cl_lengths, 19, &cl, st)) return false;
  uint8_t lengths[286 + 30] = {};
  for (int i = 0; i < hlit + hdist;) {
    const int sym = decode(in, cl);
    if (sym < 0 || in->overrun()) return false;
    int value = sym, repeat = 1;
    if (sym == 16) {
      if (i == 0) return false;
      value = lengths[i - 1];
      repeat = 3 + static_cast<int>(in->bits(2));
    } else if (sym == 17) {
      value = 0;
      repeat = 3 + static_cast<int>(in->bits(3));
    } else if (sym == 18) {
      value = 0;
      repeat = 11 + static_cast<int>(in->bits(7));
    }
    if (i + repeat > hlit + hdist) return false;
    for (int k = 0; k < repeat; ++k) lengths[i++] = static_cast<uint8_t>(value);
  }
  if (lengths[256] == 0) return false;  // a block must be able to end
  Decoder lit, dist;
  if (!make_decoder(lengths, hlit, &lit, st) || !make_decoder(lengths + hlit, hdist, &dist, st)) return false;
  ++st->dynamic_blocks;
  return inflate_codes(in, lit, dist, out, st);
}

// Raw DEFLATE data; *consumed: bytes up to the end of the final block.
inline bool inflate_raw(const uint8_t* p, std::size_t n, std::vector<uint8_t>* out, InflateStats* st, std::size_t* consumed) {
  BitReader in(p, n);
  for (;;) {
    const uint32_t final = in.bits(1);
    const uint32_t type = in.bits(2);
    bool ok = false;
    if (type == 0) ok = inflate_stored(&in, p, n, out, st);
    else if (type == 1) ok = inflate_fixed(&in, out, st);
    else if (type == 2) ok = inflate_dynamic(&in, out, st);
    if (!ok || in.overrun()) return false;
    if (final) break;
  }
  *consumed = in.byte_pos();
  return true;
}

inline uint32_t adler32_slow(const uint8_t* p, std::size_t n) {
  uint32_t a = 1, b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    a = (a + p[i]) % 65521;
    b = (b + a) % 65521;
  }
  return b << 16 | a;
}

// A whole zlib stream (RFC 1950): header checked, no preset dictionary,
// nothing after the Adler-32 trailer, which must match.
inline bool zlib_decompress(const uint8_t* p, std::size_t n, std::vector<uint8_t>* out, InflateStats* st) {
  out->clear();
  if (n < 6) return false;
  const unsigned cmf = p[0], flg = p[1];
  if ((cmf & 0x0F) != 8 || (cmf >> 4) > 7 || (cmf * 256 + flg) % 31 != 0 || (flg & 0x20)) return false;
  std::size_t used = 0;
  if (!inflate_raw(p + 2, n - 2, out, st, &used)) return false;
  if (2 + used + 4 != n) return false;
  const uint8_t* t = p + 2 + used;
  const uint32_t adler = static_cast<uint32_t>(t[0]) << 24 | static_cast<uint32_t>(t[1]) << 16 | static_cast<uint32_t>(t[2]) << 8 | t[3];
  return adler == adler32_slow(out->data(), out->size());
}

}  // namespace oracle

#endif
