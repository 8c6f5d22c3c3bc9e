// The report's number formatting: exact volumes and fixed decimals.
#include <string>

#include "platform/report/report_json.h"
#include "tests/runner.h"

using namespace dexmill;

TEST(report_volume_exact) {
  // 1000 LSB-dexels of 0.5 um at 0.25 mm pitch: 1000 * 500 * 250000^2 nm^3 = 0.03125 mm^3.
  CHECK(volume_mm3_text(1000, 500, 250000) == "0.031");
  CHECK(volume_mm3_text(1000000, 500, 250000) == "31.250");
  CHECK(volume_mm3_text(0, 500, 250000) == "0.000");
  // Rounding of the third decimal: 1 LSB-dexel of 1 um at 1 mm = 0.001 mm^3.
  CHECK(volume_mm3_text(1, 1000, 1000000) == "0.001");
  CHECK(volume_mm3_text(1, 499, 1000000) == "0.000");
  CHECK(volume_mm3_text(1, 500, 1000000) == "0.001");
  // Large: 64 M dexels x 65535 LSB of 5 um at 2 mm pitch.
  const uint64_t n = (64ULL << 20) * 65535ULL;
  CHECK(volume_mm3_text(n, 5000, 2000000) == "87959588044.800");
}

TEST(report_mm_text) {
  CHECK(nm_to_mm_text(1234567, 4) == "1.2346");
  CHECK(nm_to_mm_text(-1234567, 4) == "-1.2346");
  CHECK(nm_to_mm_text(-40, 4) == "0.0000");
  CHECK(nm_to_mm_text(5000000000LL, 0) == "5000");
  CHECK(nm_to_mm_text(250000, 6) == "0.250000");
}

TEST(report_json_strings_stay_valid_json) {
  // A file name is bytes; JSON is Unicode. Well-formed UTF-8 passes, any
  // other byte becomes the code point of its number.
  RunReport r;
  r.file = "caf\xc3\xa9 / caf\xe9 / \xe2\x82 / \xed\xa0\x80 / \xc0\xaf / \x7f.ngc";
  const std::string text = report_json_text(r);
  const std::string want = "\"file\": \"caf\xc3\xa9 / caf\\u00e9 / \\u00e2\\u0082 / \\u00ed\\u00a0\\u0080 / \\u00c0\\u00af / \\u007f.ngc\"";
  if (text.find(want) == std::string::npos) std::printf("  %s\n", text.substr(0, 160).c_str());
  CHECK(text.find(want) != std::string::npos);
}
