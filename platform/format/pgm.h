// Netpbm grey images: 16-bit PGM out (P5, maxval 65535, big-endian samples
// as the format requires); 8- or 16-bit PGM in (P5 binary or P2 text), for
// design parts drawn as height images.
#ifndef DEXMILL_PLATFORM_FORMAT_PGM_H
#define DEXMILL_PLATFORM_FORMAT_PGM_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dexmill {

// The whole file of `width` x `height` samples, row 0 first (the top row of
// the image), replacing *out: the "P5" header, then each sample most
// significant byte first.
void pgm16_encode(int width, int height, const uint16_t* samples, std::vector<uint8_t>* out);

// Writes the same bytes as `path`, atomically. On failure returns false with a message in err.
bool write_pgm16(const char* path, int width, int height, const uint16_t* samples, char* err, std::size_t errn);

// A grey image as read: row 0 first (the top of the picture).
struct PgmImage {
  int32_t width = 0, height = 0;
  uint32_t maxval = 0;            // 1..65535
  std::vector<uint16_t> samples;  // width * height, each <= maxval
};

enum class PgmRead : uint8_t { kOk, kInputError, kIoError };

// Reads a P5 or P2 PGM (comments allowed in the header, one image). Input
// errors ("FILE: error: ..."): a bad magic number or header, a size or maxval
// out of range (sides 1..65535, at most 2^28 samples), too few samples, a
// sample above maxval. I/O errors: the file cannot be read.
PgmRead read_pgm(const std::string& path, PgmImage* img, std::string* err);
// The same over a file's bytes already in memory; `name` stands for the
// file in messages (the fuzz target, tests/fuzz/fuzz_pgm.cpp, reads no file).
PgmRead pgm_parse(const std::string& name, const std::vector<unsigned char>& bytes, PgmImage* img, std::string* err);

}  // namespace dexmill

#endif
