// The golden machinery itself (tests/golden_check.h), on goldens of its own
// in a scratch folder: a right frame passes; a wrong one fails and leaves
// its expected, actual and difference pictures, named in the failure; a
// stale or missing picture fails; blessing writes the hash and the picture,
// and blessing again changes nothing.
#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "tests/golden_check.h"
#include "tests/rng.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using run_cli::slurp;

// A 12 x 9 picture with some of everything (a ramp, a random patch).
t::RgbImage picture() {
  t::RgbImage im;
  im.w = 12;
  im.h = 9;
  t::Rng rng(7);
  for (int y = 0; y < im.h; ++y)
    for (int x = 0; x < im.w; ++x) {
      const bool patch = x > 6 && y > 4;
      im.rgb.push_back(static_cast<uint8_t>(patch ? rng.next() : 20 * x));
      im.rgb.push_back(static_cast<uint8_t>(patch ? rng.next() : 25 * y));
      im.rgb.push_back(static_cast<uint8_t>(patch ? rng.next() : 200));
    }
  return im;
}

uint64_t hash_of(const t::RgbImage& im) { return run_cli::fnv(std::string(im.rgb.begin(), im.rgb.end())); }

t::RgbImage png_file(const std::string& path) {
  const std::string b = slurp(path);
  return t::rgb_of_png(std::vector<uint8_t>(b.begin(), b.end()));
}

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

bool equal(const t::RgbImage& a, const t::RgbImage& b) { return a.w == b.w && a.h == b.h && a.rgb == b.rgb; }

// A fresh place: hashes.txt pinning `pic` to the picture's hash, its PNG.
t::GoldenPlace place(const char* sub) {
  t::GoldenPlace at;
  at.dir = run_cli::tmp_dir() + "/" + sub;
  at.out_dir = at.dir + "/out";
  mkdir(at.dir.c_str(), 0755);
  mkdir((at.dir + "/frames").c_str(), 0755);
  char line[64];
  std::snprintf(line, sizeof line, "pic %016llx\nnopic 0000000000000001\n",
                static_cast<unsigned long long>(hash_of(picture())));
  run_cli::write_file(at.dir + "/hashes.txt", "# comment kept\n" + std::string(line));
  const std::vector<uint8_t> png = t::png_of(picture());
  run_cli::write_file(at.dir + "/frames/pic.png", std::string(png.begin(), png.end()));
  return at;
}

}  // namespace

TEST(golden_check_png_round_trip) {
  const t::RgbImage im = picture();
  CHECK(equal(t::rgb_of_png(t::png_of(im)), im));
  CHECK_EQ(t::rgb_of_png(std::vector<uint8_t>{1, 2, 3}).w, 0);
  std::string ppm = "P6\n12 9\n255\n" + std::string(im.rgb.begin(), im.rgb.end());
  CHECK(equal(t::rgb_of_ppm(ppm), im));
  CHECK_EQ(t::rgb_of_ppm(ppm + "x").w, 0);  // a byte too many: not one
}

TEST(golden_check_right_frame_passes_wrong_one_shows_pictures) {
  const t::GoldenPlace at = place("golden-machinery");
  const t::RgbImage want = picture();
  const t::GoldenResult right = t::golden_image_result(at, "pic", hash_of(want), want);
  CHECK(right.ok);
  CHECK(right.message.empty());
  CHECK(!exists(at.out_dir + "/pic.diff.png"));

  t::RgbImage got = want;
  got.rgb[0] ^= 0x40;                      // (0, 0): red off by 64
  got.rgb[(5 * 12 + 3) * 3 + 2] -= 1;      // (3, 5): blue off by one
  got.rgb[(8 * 12 + 11) * 3 + 1] += 100;   // (11, 8): green, in the random patch
  const t::GoldenResult wrong = t::golden_image_result(at, "pic", hash_of(got), got);
  CHECK(!wrong.ok);
  const std::string base = at.out_dir + "/pic";
  for (const char* kind : {".expected.png", ".actual.png", ".diff.png"}) {
    CHECK(exists(base + kind));
    if (!CHECK(wrong.message.find(base + kind) != std::string::npos)) std::printf("  message: %s\n", wrong.message.c_str());
  }
  CHECK(wrong.message.find("3 pixels differ") != std::string::npos);
  CHECK(wrong.message.find("hash ") != std::string::npos);
  CHECK(equal(png_file(base + ".expected.png"), want));
  CHECK(equal(png_file(base + ".actual.png"), got));
  // The difference: bright (>= 128) where they differ, in the channel that
  // does; the expected picture at a quarter, grey, elsewhere.
  const t::RgbImage d = png_file(base + ".diff.png");
  CHECK_EQ(d.w, 12);
  CHECK_EQ(d.h, 9);
  int bright = 0;
  for (int y = 0; y < d.h && d.w == 12; ++y)
    for (int x = 0; x < d.w; ++x) {
      const uint8_t* p = &d.rgb[(y * 12 + x) * 3];
      const bool differs = (x == 0 && y == 0) || (x == 3 && y == 5) || (x == 11 && y == 8);
      if (differs) {
        bright += p[0] >= 128 || p[1] >= 128 || p[2] >= 128;
      } else {
        CHECK(p[0] <= 63 && p[0] == p[1] && p[1] == p[2]);
      }
    }
  CHECK_EQ(bright, 3);
  const uint8_t* p00 = &d.rgb[0];
  CHECK_EQ(p00[0], 255);  // 128 + 4 * 64, at most 255
  CHECK_EQ(p00[1], 0);
  const uint8_t* p35 = &d.rgb[(5 * 12 + 3) * 3];
  CHECK_EQ(p35[2], 132);  // 128 + 4 * 1
  CHECK_EQ(p35[0], 0);
}

TEST(golden_check_stale_and_missing_pictures_fail) {
  const t::GoldenPlace at = place("golden-machinery-stale");
  t::RgbImage other = picture();
  other.rgb[5] ^= 1;
  // The hash is right but the picture is another: it must not pass.
  const t::GoldenResult stale = t::golden_image_result(at, "pic", hash_of(picture()), other);
  CHECK(!stale.ok);
  CHECK(stale.message.find("stale") != std::string::npos);
  CHECK(exists(at.out_dir + "/pic.diff.png"));
  // No picture: fails, and shows the actual frame.
  const t::GoldenResult none = t::golden_image_result(at, "nopic", 1, picture());
  CHECK(!none.ok);
  CHECK(none.message.find("is missing") != std::string::npos);
  CHECK(exists(at.out_dir + "/nopic.actual.png"));
  // No hash.
  const t::GoldenResult unknown = t::golden_hash_result(at, "nobody", 5);
  CHECK(!unknown.ok);
  CHECK(unknown.message.find("make bless") != std::string::npos);
}

TEST(golden_check_bless_writes_then_changes_nothing) {
  t::GoldenPlace at = place("golden-machinery-bless");
  t::RgbImage got = picture();
  got.rgb[7] ^= 0x11;
  at.bless = true;
  CHECK(t::golden_image_result(at, "pic", hash_of(got), got).ok);
  CHECK(t::golden_hash_result(at, "new-one", 0xabcdef).ok);
  CHECK(t::golden_text_result(at, at.dir + "/some.golden", "text\n").ok);
  const std::string hashes = slurp(at.dir + "/hashes.txt");
  char line[64];
  std::snprintf(line, sizeof line, "pic %016llx\n", static_cast<unsigned long long>(hash_of(got)));
  CHECK_EQ(hashes, "# comment kept\n" + std::string(line) + "nopic 0000000000000001\nnew-one 0000000000abcdef\n");
  CHECK(equal(png_file(at.dir + "/frames/pic.png"), got));
  CHECK_EQ(slurp(at.dir + "/some.golden"), std::string("text\n"));
  // Blessed again with the same values: the same bytes (no churn).
  const std::string png = slurp(at.dir + "/frames/pic.png");
  CHECK(t::golden_image_result(at, "pic", hash_of(got), got).ok);
  CHECK(t::golden_hash_result(at, "new-one", 0xabcdef).ok);
  CHECK_EQ(slurp(at.dir + "/hashes.txt"), hashes);
  CHECK_EQ(slurp(at.dir + "/frames/pic.png"), png);
  // And now they pass as checks.
  at.bless = false;
  CHECK(t::golden_image_result(at, "pic", hash_of(got), got).ok);
  CHECK(t::golden_text_result(at, at.dir + "/some.golden", "text\n").ok);
  const t::GoldenResult text = t::golden_text_result(at, at.dir + "/some.golden", "test\n");
  CHECK(!text.ok);
  CHECK(text.message.find("line 1") != std::string::npos);
}

TEST(golden_check_knows_the_running_case) {
  CHECK_EQ(std::string(t::current_case()), std::string("golden_check_knows_the_running_case"));
  // tests/test_stamp.cpp reads its pins from golden.out this way.
  CHECK_EQ(t::golden_out_value("stamp stamp-test m=8 ", "grid").size(), 16u);
  CHECK_EQ(t::golden_out_value("stamp stamp-test m=8 ", "lsb_nm"), std::string("100000"));
  CHECK(t::golden_out_value("no such line", "grid").empty());
}
