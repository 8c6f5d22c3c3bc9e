// PNG encoding: filtering (PNG specification, W3C second edition, section 9),
// chunks (section 5) and the critical chunks IHDR, IDAT and IEND (11.2).
#include "platform/format/png.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "platform/format/deflate.h"
#include "platform/os/cpu_clones.h"
#include "platform/os/parallel.h"

namespace dexmill {
namespace {

// Section 5.2: the eight bytes every PNG datastream begins with.
constexpr uint8_t kPngSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
// Image data goes out in IDAT chunks of at most this many bytes (any size up
// to 2^31 - 1 is legal, section 5.3; smaller chunks suit streaming readers).
constexpr std::size_t kIdatMaxBytes = 65536;
// Section 11.2.2: colour types and the only compression, filter and
// interlace methods (deflate, adaptive filtering, no interlace).
constexpr uint8_t kColourGrey = 0;
constexpr uint8_t kColourTruecolour = 2;
constexpr uint8_t kMethodDefault = 0;
constexpr uint8_t kInterlaceNone = 0;
constexpr std::size_t kIhdrBytes = 13;
// Largest image data handled: the filtered rows are built as one byte string
// of at most this size (a limit far above any frame, and safe for 32-bit
// size_t arithmetic).
constexpr uint64_t kMaxFilteredBytes = uint64_t{1} << 30;

// Section 9.2: filter types of filter method 0.
enum FilterType : uint8_t { kNone = 0, kSub = 1, kUp = 2, kAverage = 3, kPaeth = 4 };
constexpr int kFilterTypes = 5;

void put_u32_be(uint32_t v, std::vector<uint8_t>* out) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<uint8_t>(v >> shift));
}

// Section 5.3: length, type, data, and the CRC of type and data.
void put_chunk(const char* type, const uint8_t* data, std::size_t n, std::vector<uint8_t>* out) {
  const uint8_t* type_bytes = reinterpret_cast<const uint8_t*>(type);
  put_u32_be(static_cast<uint32_t>(n), out);
  out->insert(out->end(), type_bytes, type_bytes + 4);
  out->insert(out->end(), data, data + n);
  const uint32_t crc = crc32_update(crc32_update(0, type_bytes, 4), data, n);
  put_u32_be(crc, out);
}

// Section 9.4: the Paeth predictor picks whichever of left (a), above (b)
// and upper left (c) is nearest to a + b - c, ties in that order.
inline uint8_t paeth(uint8_t a, uint8_t b, uint8_t c) {
  // |p - a|, |p - b|, |p - c| with p = a + b - c, in 16 bits and as selects,
  // so that the compiler vectorises the cost pass (row_costs) over it.
  const int16_t b_less_c = static_cast<int16_t>(b - c), a_less_c = static_cast<int16_t>(a - c);
  const int16_t sum = static_cast<int16_t>(b_less_c + a_less_c);
  const uint16_t pa = static_cast<uint16_t>(b_less_c < 0 ? -b_less_c : b_less_c);
  const uint16_t pb = static_cast<uint16_t>(a_less_c < 0 ? -a_less_c : a_less_c);
  const uint16_t pc = static_cast<uint16_t>(sum < 0 ? -sum : sum);
  const uint8_t b_or_c = pb <= pc ? b : c;
  return pa <= pb && pa <= pc ? a : b_or_c;
}

// Section 9.2: the prediction of filter type T for a byte from the byte one
// pixel to the left (a), the byte above (b) and the byte above that left (c);
// bytes outside the image count as 0.
template <FilterType T>
inline uint8_t predict(uint8_t a, uint8_t b, uint8_t c) {
  if constexpr (T == kNone) return 0;
  if constexpr (T == kSub) return a;
  if constexpr (T == kUp) return b;
  if constexpr (T == kAverage) return static_cast<uint8_t>((a + b) >> 1);
  if constexpr (T == kPaeth) return paeth(a, b, c);
  return 0;
}

// Filters one row (prior: the row above, zeros for the first) into dst.
template <FilterType T>
void filter_row(const uint8_t* row, const uint8_t* prior, std::size_t n, std::size_t bytes_per_pixel, uint8_t* dst) {
  for (std::size_t i = 0; i < n; ++i) {
    const uint8_t a = i >= bytes_per_pixel ? row[i - bytes_per_pixel] : 0;
    const uint8_t c = i >= bytes_per_pixel ? prior[i - bytes_per_pixel] : 0;
    dst[i] = static_cast<uint8_t>(row[i] - predict<T>(a, prior[i], c));
  }
}

// |v| of a byte taken as signed (0..128): the smaller of v and -v modulo
// 256, which vectorises as two byte operations (took the cost pass of
// a carved relief's 4503² heightmap from 742 M to 519 M instructions,
// callgrind).
inline uint8_t signed_magnitude(uint8_t v) {
  const uint8_t negated = static_cast<uint8_t>(0u - v);
  return v < negated ? v : negated;
}

// The filters (row_costs, filter_row_adaptive) are built for AVX2 too
// (platform/os/cpu_clones.h): a carved relief's 4503² heightmap's filters
// took 180 M instructions on AVX2 against 480 M (callgrind).

// Bytes of a row summed in 16 bits before adding to the 64-bit costs (128
// times this fits): the compiler then sums eight bytes to a vector.
constexpr std::size_t kCostPieceBytes = 256;

// Section 12.8's heuristic for all five filter types in one pass over the
// row, writing nothing: cost[T] is the sum of |byte| (bytes taken as
// signed) of the row filtered by T, added to cost[T] (zeros to start).
// Filtering the row five times into scratch rows took a quarter of a
// heightmap's PNG.
DEXMILL_AVX2_CLONES
void row_costs(const uint8_t* row, const uint8_t* prior, std::size_t n, std::size_t bytes_per_pixel, uint64_t* cost) {
  const std::size_t lead = std::min(n, bytes_per_pixel);
  for (std::size_t i = 0; i < lead; ++i) {  // the first pixel: a = c = 0
    const uint8_t x = row[i], b = prior[i];
    cost[kNone] += signed_magnitude(x);
    cost[kSub] += signed_magnitude(x);
    cost[kUp] += signed_magnitude(static_cast<uint8_t>(x - b));
    cost[kAverage] += signed_magnitude(static_cast<uint8_t>(x - (b >> 1)));
    cost[kPaeth] += signed_magnitude(static_cast<uint8_t>(x - b));  // Paeth of (0, b, 0) is b
  }
  const uint8_t* left = row - bytes_per_pixel;
  const uint8_t* upper_left = prior - bytes_per_pixel;
  for (std::size_t start = lead; start < n; start += kCostPieceBytes) {
    const std::size_t end = std::min(n, start + kCostPieceBytes);
    uint16_t none = 0, sub = 0, up = 0, average = 0, pae = 0;
    for (std::size_t i = start; i < end; ++i) {
      const uint8_t x = row[i], a = left[i], b = prior[i], c = upper_left[i];
      none = static_cast<uint16_t>(none + signed_magnitude(x));
      sub = static_cast<uint16_t>(sub + signed_magnitude(static_cast<uint8_t>(x - a)));
      up = static_cast<uint16_t>(up + signed_magnitude(static_cast<uint8_t>(x - b)));
      average = static_cast<uint16_t>(average + signed_magnitude(static_cast<uint8_t>(x - ((a + b) >> 1))));
      pae = static_cast<uint16_t>(pae + signed_magnitude(static_cast<uint8_t>(x - paeth(a, b, c))));
    }
    cost[kNone] += none;
    cost[kSub] += sub;
    cost[kUp] += up;
    cost[kAverage] += average;
    cost[kPaeth] += pae;
  }
}

// Section 12.8: with `adaptive`, each row gets the filter whose output has
// the least sum of absolute values (the lowest type on a tie), else None.
// Writes the filter type byte and the filtered row to dst (1 + n bytes).
DEXMILL_AVX2_CLONES
void filter_row_adaptive(const uint8_t* row, const uint8_t* prior, std::size_t n, std::size_t bytes_per_pixel,
                         bool adaptive, uint8_t* dst) {
  if (adaptive && n > 0 && std::memcmp(row, prior, n) == 0) {
    // A row equal to the one above (a heightmap's untouched top): Up costs
    // 0, and None and Sub cost 0 only for a row of zeros, where None wins
    // the tie; either way every filtered byte is 0, so the choice the cost
    // pass would make is known without it.
    const bool zeros = row[0] == 0 && (n == 1 || std::memcmp(row, row + 1, n - 1) == 0);
    dst[0] = zeros ? kNone : kUp;
    std::memset(dst + 1, 0, n);
    return;
  }
  uint64_t cost[kFilterTypes] = {};
  if (adaptive) row_costs(row, prior, n, bytes_per_pixel, cost);
  const int best = static_cast<int>(std::min_element(cost, cost + kFilterTypes) - cost);
  dst[0] = static_cast<uint8_t>(best);
  switch (best) {
    case kNone: filter_row<kNone>(row, prior, n, bytes_per_pixel, dst + 1); break;
    case kSub: filter_row<kSub>(row, prior, n, bytes_per_pixel, dst + 1); break;
    case kUp: filter_row<kUp>(row, prior, n, bytes_per_pixel, dst + 1); break;
    case kAverage: filter_row<kAverage>(row, prior, n, bytes_per_pixel, dst + 1); break;
    default: filter_row<kPaeth>(row, prior, n, bytes_per_pixel, dst + 1); break;
  }
}

// Section 7.1: n 16-bit samples most significant byte first into dst. On
// a little-endian host each sample's bytes swapped as a 16-bit word (which
// the compiler vectorises: byte by byte, the swap was 8 instructions a
// sample, callgrind); the same bytes either way.
void big_endian_samples(const uint16_t* samples, std::size_t n, uint8_t* dst) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  for (std::size_t i = 0; i < n; ++i) {
    const uint16_t swapped = static_cast<uint16_t>(samples[i] >> 8 | samples[i] << 8);
    std::memcpy(dst + 2 * i, &swapped, 2);
  }
#else
  for (std::size_t i = 0; i < n; ++i) {
    dst[2 * i] = static_cast<uint8_t>(samples[i] >> 8);
    dst[2 * i + 1] = static_cast<uint8_t>(samples[i]);
  }
#endif
}

// Bytes of one row, or 0 when the image is empty or too large to handle.
std::size_t row_bytes_of(int32_t width, int32_t height, std::size_t bytes_per_pixel) {
  if (width < 1 || height < 1) return 0;
  const uint64_t row = static_cast<uint64_t>(width) * bytes_per_pixel;
  if ((row + 1) * static_cast<uint64_t>(height) > kMaxFilteredBytes) return 0;
  return static_cast<std::size_t>(row);
}

// Section 11.2.2: the image header.
void put_ihdr(int32_t width, int32_t height, uint8_t bit_depth, uint8_t colour_type, std::vector<uint8_t>* out) {
  std::vector<uint8_t> ihdr;
  put_u32_be(static_cast<uint32_t>(width), &ihdr);
  put_u32_be(static_cast<uint32_t>(height), &ihdr);
  ihdr.push_back(bit_depth);
  ihdr.push_back(colour_type);
  ihdr.push_back(kMethodDefault);  // compression
  ihdr.push_back(kMethodDefault);  // filter
  ihdr.push_back(kInterlaceNone);
  put_chunk("IHDR", ihdr.data(), kIhdrBytes, out);
}

// The shape of an image as PNG describes it.
struct PngFormat {
  uint8_t colour_type;
  uint8_t bit_depth;
  std::size_t bytes_per_pixel;  // the filters' distance to "the pixel to the left"
  bool adaptive;                // filters chosen per row (else None throughout)
  DeflateTuning tuning;         // how the image data is compressed
  bool in_pieces;               // by zlib_compress_pieces (else zlib_compress)
};

// Rows filtered by one task: enough that a task's start (the row above it
// read again) costs little, few enough that two to eight threads share a
// heightmap's rows evenly.
constexpr int32_t kFilterBandRows = 64;

// Writes the whole file for rows of row_bytes bytes each, filtered and
// compressed; row_bytes comes from row_bytes_of. row_at(y, scratch) gives
// row y in PNG's byte order, in scratch's half y % 2 (2 * row_bytes bytes)
// or elsewhere; its pointer must stay valid while the scratch's other
// half is written (the next row's filters read it). Bands of rows are
// filtered on up to `threads` threads, each its own scratch: a row's
// filter depends only on it and the row above, so the bytes do not depend
// on the thread count.
template <class RowAt>
void encode(RowAt row_at, std::size_t row_bytes, int32_t width, int32_t height, PngFormat format, int threads,
            std::vector<uint8_t>* out) {
  // Every byte is written by the filters, so the buffer is not zeroed first
  // (a vector's would be a pass over the whole image data).
  const std::size_t filtered_bytes = (row_bytes + 1) * static_cast<std::size_t>(height);
  const std::unique_ptr<uint8_t[]> filtered(new uint8_t[filtered_bytes]);
  const std::vector<uint8_t> zero_row(row_bytes, 0);
  const std::size_t bands = static_cast<std::size_t>((height - 1) / kFilterBandRows + 1);
  parallel_for(bands, threads, [&](std::size_t band) {
    std::vector<uint8_t> scratch(2 * row_bytes);
    const int32_t y0 = static_cast<int32_t>(band) * kFilterBandRows;
    const int32_t y1 = std::min(height, y0 + kFilterBandRows);
    const uint8_t* prior = y0 == 0 ? zero_row.data() : row_at(y0 - 1, scratch.data());
    for (int32_t y = y0; y < y1; ++y) {
      const uint8_t* row = row_at(y, scratch.data());
      filter_row_adaptive(row, prior, row_bytes, format.bytes_per_pixel, format.adaptive,
                          filtered.get() + static_cast<std::size_t>(y) * (row_bytes + 1));
      prior = row;
    }
  });
  std::vector<uint8_t> compressed;
  if (format.in_pieces)
    zlib_compress_pieces(filtered.get(), filtered_bytes, &compressed, format.tuning, threads);
  else
    zlib_compress(filtered.get(), filtered_bytes, &compressed, format.tuning);

  out->assign(kPngSignature, kPngSignature + sizeof kPngSignature);
  put_ihdr(width, height, format.bit_depth, format.colour_type, out);
  // Section 11.2.4: the zlib stream may be split between IDAT chunks anywhere.
  for (std::size_t at = 0; at < compressed.size(); at += kIdatMaxBytes)
    put_chunk("IDAT", compressed.data() + at, std::min(kIdatMaxBytes, compressed.size() - at), out);
  put_chunk("IEND", nullptr, 0, out);
}

}  // namespace

void png_encode_rgb8(const uint8_t* rgb, int32_t width, int32_t height, std::vector<uint8_t>* out) {
  out->clear();
  // Rendered frames are flat colours and shading ramps that repeat exactly:
  // LZ77 finds the repeats in the raw pixels better than in filtered ones
  // (the demo's final frame: 38 210 bytes unfiltered, 45 953 adaptive; its
  // hundred frames 22 % faster). One stream on this thread: a frame is
  // small, and its bytes are the golden pictures' (tests/golden/frames/).
  const PngFormat format{kColourTruecolour, 8, 3, false, DeflateTuning::kGeneral, false};
  const std::size_t row_bytes = row_bytes_of(width, height, format.bytes_per_pixel);
  if (row_bytes == 0) return;
  const auto row_at = [&](int32_t y, uint8_t*) { return rgb + static_cast<std::size_t>(y) * row_bytes; };
  encode(row_at, row_bytes, width, height, format, 1, out);
}

void png_encode_gray16(const uint16_t* samples, int32_t width, int32_t height, std::vector<uint8_t>* out,
                       int threads) {
  out->clear();
  // Height images are smooth surfaces: the filters pay (tiger.nc's
  // heightmap: 206 424 bytes adaptive, 273 811 unfiltered).
  const PngFormat format{kColourGrey, 16, 2, true, DeflateTuning::kFilteredSamples16, true};
  const std::size_t row_bytes = row_bytes_of(width, height, format.bytes_per_pixel);
  if (row_bytes == 0) return;
  // Section 7.1: 16-bit samples are stored most significant byte first,
  // each row turned so as it is filtered.
  const std::size_t row_samples = row_bytes / 2;
  const auto row_at = [&](int32_t y, uint8_t* scratch) {
    uint8_t* row = scratch + static_cast<std::size_t>(y % 2) * row_bytes;
    big_endian_samples(samples + static_cast<std::size_t>(y) * row_samples, row_samples, row);
    return static_cast<const uint8_t*>(row);
  };
  encode(row_at, row_bytes, width, height, format, threads, out);
}

}  // namespace dexmill
