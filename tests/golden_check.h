// Goldens, one way (tests/golden/README.md): every value a unit test pins
// is read from tests/golden/ or from a golden file beside its inputs, and
// under DEXMILL_BLESS=1 (`make bless`) the actual value is written there
// instead of checked.
//
//   hashes  tests/golden/hashes.txt, one `NAME VALUE` a line (VALUE 16 hex
//           digits): CHECK_GOLDEN_HASH(name, got)
//   frames  a hash in hashes.txt and the picture tests/golden/frames/NAME.png:
//           CHECK_GOLDEN_FRAME(name, framebuffer), CHECK_GOLDEN_FILE(name,
//           path) for a binary PPM (any other file is pinned by its hash
//           alone). When a frame differs, NAME.expected.png, NAME.actual.png
//           and NAME.diff.png are written to golden_place().out_dir and the
//           failure names them.
//   texts   a whole file compared byte for byte: CHECK_GOLDEN_TEXT(path, got)
//
// Hashes of files and text are FNV-1a 64 over the bytes (run_cli::fnv), of
// frames display/raster/framebuffer.h frame_hash (the stored pixel values).
//
// A check is allowed only in a case whose name holds "golden": `make bless`
// runs exactly those cases (tests/bless.sh), so no golden can be left out.
#ifndef DEXMILL_TESTS_GOLDEN_CHECK_H
#define DEXMILL_TESTS_GOLDEN_CHECK_H

#include <cstdint>
#include <string>
#include <vector>

#include "display/raster/framebuffer.h"

namespace t {

// DEXMILL_BLESS=1 in the environment.
bool blessing();

// Where goldens are read (and written when blessing), and where the
// pictures of a failing frame go.
struct GoldenPlace {
  std::string dir;      // holds hashes.txt and frames/
  std::string out_dir;  // NAME.expected.png, NAME.actual.png, NAME.diff.png
  bool bless = false;
};
// tests/golden, $DEXMILL_GOLDEN_OUT (make test: build/golden-diff) or
// /tmp/dexmill-golden-out, blessing().
GoldenPlace golden_place();

// RGB8 pixels, row by row, top row first.
struct RgbImage {
  int32_t w = 0, h = 0;
  std::vector<uint8_t> rgb;
};
RgbImage rgb_of_frame(const dexmill::FrameView& fb);
// A binary PPM (P6, maxval 255); w = h = 0 when the bytes are not one.
RgbImage rgb_of_ppm(const std::string& bytes);
// Our own PNG encoding of img (platform/format/png.h), and the way back for a PNG
// of colour type 2, depth 8 (what png_encode_rgb8 writes); w = h = 0 when
// the bytes are not such a PNG.
std::vector<uint8_t> png_of(const RgbImage& img);
RgbImage rgb_of_png(const std::vector<uint8_t>& png);
// The difference image of two pictures: where they are equal the expected
// pixel dimmed to a quarter grey (every channel <= 63), where they differ
// 128 + 4 * |difference| in each channel that differs (at most 255), 0 in
// the others; outside the smaller picture (sizes differ) magenta.
// *differing counts the differing pixels (those outside one picture too).
RgbImage diff_image(const RgbImage& expected, const RgbImage& actual, int64_t* differing);

struct GoldenResult {
  bool ok = true;
  std::string message;  // why not, when !ok
};
// The checks without the failure: what CHECK_GOLDEN_* report.
GoldenResult golden_hash_result(const GoldenPlace& at, const std::string& name, uint64_t got);
GoldenResult golden_image_result(const GoldenPlace& at, const std::string& name, uint64_t got, const RgbImage& actual);
GoldenResult golden_text_result(const GoldenPlace& at, const std::string& path, const std::string& got);

// A value of tests/golden/golden.out: `key=` of the line beginning with
// `line_prefix` (empty when there is none). Values pinned there are not
// pinned again in a test (tests/test_stamp.cpp reads its grid hashes).
std::string golden_out_value(const std::string& line_prefix, const char* key);

// Record a failure at file:line unless ok.
bool check_golden_hash(const char* file, int line, const std::string& name, uint64_t got);
bool check_golden_frame(const char* file, int line, const std::string& name, const dexmill::FrameView& fb);
bool check_golden_file(const char* file, int line, const std::string& name, const std::string& path);
bool check_golden_text(const char* file, int line, const std::string& path, const std::string& got);

}  // namespace t

#define CHECK_GOLDEN_HASH(name, got) ::t::check_golden_hash(__FILE__, __LINE__, (name), (got))
#define CHECK_GOLDEN_FRAME(name, fb) ::t::check_golden_frame(__FILE__, __LINE__, (name), (fb))
#define CHECK_GOLDEN_FILE(name, path) ::t::check_golden_file(__FILE__, __LINE__, (name), (path))
#define CHECK_GOLDEN_TEXT(path, got) ::t::check_golden_text(__FILE__, __LINE__, (path), (got))

#endif
