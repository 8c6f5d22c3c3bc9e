// Lossless compression of our own for PNG output (platform/format/png.h): a zlib
// stream (RFC 1950) of DEFLATE data (RFC 1951), and the two checksums those
// formats use (CRC-32 from core/math/crc32.h). No library: the standard library only.
//
// The output is a pure function of the input bytes (no time, no addresses,
// no platform-dependent choices), so every run on every platform writes the
// same stream.
#ifndef DEXMILL_PLATFORM_FORMAT_DEFLATE_H
#define DEXMILL_PLATFORM_FORMAT_DEFLATE_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math/crc32.h"

namespace dexmill {

// CRC-32 (PNG specification section 5.5) is core/math/crc32.h.

// Adler-32 (RFC 1950, sections 8 and 9). Start with adler = 1; data in pieces
// may be fed by passing each call's result to the next.
// adler32_update(1, "Wikipedia", 9) == 0x11E60398.
uint32_t adler32_update(uint32_t adler, const uint8_t* p, std::size_t n);

// The Adler-32 of A then B from adler32_update(1, A) and
// adler32_update(1, B) and B's length (RFC 1950 section 9's sums).
uint32_t adler32_combine(uint32_t adler_a, uint32_t adler_b, std::size_t len_b);

// What the data is, which sets how the match finder looks for repeats
// (deflate.cpp's efforts say what each costs and saves):
//   kGeneral           chains of every 3-byte hash (text, unfiltered RGB)
//   kFilteredSamples16 PNG's filtered rows of 16-bit samples (heightmaps):
//                      chains of 5-byte hashes, the latest of each 3-byte
//                      hash within 128 bytes for shorter matches, and the
//                      inside of long runs of one byte left off the chains
enum class DeflateTuning : uint8_t { kGeneral, kFilteredSamples16 };

// Replaces *out with a zlib stream (RFC 1950: header 0x78 0x9C, DEFLATE data,
// Adler-32 of the input) of the n bytes at data (data may be null when n is
// 0). The DEFLATE data is LZ77 over a 32 KiB window with hash chains and
// one-step lazy matching (with kFilteredSamples16 no match starts in the
// last 7 bytes); each block is written as dynamic Huffman, fixed
// Huffman or stored, whichever is smallest (a block holds 16384 symbols,
// 32768 with kFilteredSamples16, so at least 16 KiB but the last), so the
// stream never exceeds n + 11 + 5 * (n / 16384) bytes.
void zlib_compress(const uint8_t* data, std::size_t n, std::vector<uint8_t>* out,
                   DeflateTuning tuning = DeflateTuning::kGeneral);

// Raw DEFLATE data (no zlib frame) of data[dict_bytes, n) into *out, its
// matches reaching back into data[0, dict_bytes) too (a preset dictionary,
// at most 32 KiB): with final, the stream's last blocks; else blocks ending
// with an empty stored block, so at a byte boundary, for the next piece to
// follow byte for byte (platform/format/deflate_pieces.h). Leaves *out
// empty for a dictionary over 32 KiB or longer than n, or more than 1 GiB.
void deflate_piece(const uint8_t* data, std::size_t dict_bytes, std::size_t n, bool final, DeflateTuning tuning,
                   std::vector<uint8_t>* out);

// The size of zlib_compress_pieces' pieces of input: fixed, so that the
// stream does not depend on the thread count.
constexpr std::size_t kDeflatePieceBytes = std::size_t{1} << 20;

// zlib_compress' stream (the same header, data and trailer rules) made of
// pieces of kDeflatePieceBytes input bytes compressed each on its own by
// up to `threads` threads (<= 0: the host's, platform/os/parallel.h), the
// pigz way: each piece is deflate_piece's blocks with the 32 KiB before it
// as dictionary, the Adler-32s of the pieces combined. The same bytes for
// every thread count; against zlib_compress a few bytes a piece larger
// (the piece's last block and empty stored block).
void zlib_compress_pieces(const uint8_t* data, std::size_t n, std::vector<uint8_t>* out, DeflateTuning tuning,
                          int threads);

// The Huffman code lengths zlib_compress uses (public so tests can reach
// them): for symbols 0..symbols-1 seen freq[s] times, writes into bits[s]
// lengths of at most max_bits that minimise sum(freq[s] * bits[s]) (0 for an
// unused symbol; when fewer than two symbols are used the lowest unused ones
// count as used once, so the code is always complete: sum 2^-bits[s] == 1).
// Needs 2 <= symbols <= 2^max_bits and max_bits <= 15, else all bits are 0.
void huffman_code_lengths(const uint32_t* freq, int symbols, int max_bits, uint8_t* bits);

}  // namespace dexmill

#endif
