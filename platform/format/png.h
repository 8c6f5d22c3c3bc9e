// PNG images (PNG specification, ISO/IEC 15948, W3C second edition; RFC 2083
// for the first) in memory, compressed by our own zlib (platform/format/deflate.h).
//
// Each encoder replaces *out with a whole file: the signature, IHDR, the
// image data in IDAT chunks of at most 64 KiB, and IEND, each chunk with its
// CRC. Grey images' rows are filtered one by one with the filter type
// (None, Sub, Up, Average, Paeth) whose output has the least sum of absolute
// values taken as signed bytes (the specification's suggested heuristic,
// section 12.8); RGB frames are left unfiltered (png.cpp says why). The
// output depends only on the pixels: the same bytes on every run and
// platform (no time chunk, no other ancillary chunks).
//
// A width or height below 1, or an image of more than 1 GiB of filtered rows
// (height * (1 + row bytes)), leaves *out empty.
#ifndef DEXMILL_PLATFORM_FORMAT_PNG_H
#define DEXMILL_PLATFORM_FORMAT_PNG_H

#include <cstdint>
#include <vector>

namespace dexmill {

// rgb: height rows, top row first, each width pixels of R, G, B bytes.
// Written as colour type 2 (truecolour), bit depth 8.
void png_encode_rgb8(const uint8_t* rgb, int32_t width, int32_t height, std::vector<uint8_t>* out);

// samples: height rows, top row first, each width grey samples in native
// byte order. Written as colour type 0 (greyscale), bit depth 16, each
// sample most significant byte first as PNG requires. Filtered and
// compressed on up to `threads` threads (<= 0: the host's), the image
// data by zlib_compress_pieces (platform/format/deflate.h): the same bytes
// for every thread count.
void png_encode_gray16(const uint16_t* samples, int32_t width, int32_t height, std::vector<uint8_t>* out,
                       int threads = 0);

}  // namespace dexmill

#endif
