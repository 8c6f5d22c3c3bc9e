// `dexmill run`'s decorations and framing options on tests/run/pocket.ngc:
// the axis triad and scale bar in the images by default and only in their
// corner (--no-decorations leaves them out), the status line under saved
// frames with --frame-status (and not without), the final image without
// the cutter with --hide-tool, every other pixel unchanged.
#include <cstdio>
#include <string>
#include <vector>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

// The triad's X red (display/overlay/decorations.cpp), apart from the cutter's
// darker, shaded red.
bool axis_red(const unsigned char* p) { return p[0] > 225 && p[1] > 50 && p[1] < 90 && p[2] > 40 && p[2] < 70; }
// Any shade of the cutter's red.
bool reddish(const unsigned char* p) { return p[0] > 30 && p[0] > 2 * p[1] && p[0] > 2 * p[2]; }

const char* kBase = "pocket.ngc -q --size 320x240 ";

}  // namespace

TEST(run_draws_decorations_in_their_corner_unless_told_not_to) {
  if (skip()) return;
  CHECK_EQ(run(std::string(kBase) + "--hide-tool --image %/deco.ppm").code, 0);
  CHECK_EQ(run(std::string(kBase) + "--hide-tool --no-decorations --image %/plain.ppm").code, 0);
  const Image d = read_ppm(tmp_dir() + "/deco.ppm"), p = read_ppm(tmp_dir() + "/plain.ppm");
  CHECK_EQ(d.w, 320);
  CHECK_EQ(p.h, 240);
  if (d.h != 240 || p.w != 320) return;
  int red_d = 0, red_p = 0, differ = 0, differ_outside = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      red_d += axis_red(d.at(x, y));
      red_p += axis_red(p.at(x, y));
      const bool diff = d.at(x, y)[0] != p.at(x, y)[0] || d.at(x, y)[1] != p.at(x, y)[1] || d.at(x, y)[2] != p.at(x, y)[2];
      differ += diff;
      // The bottom-left corner: the triad and the bar beside it.
      differ_outside += diff && !(x < 160 && y >= 170);
    }
  std::printf("  triad red pixels %d (without: %d), %d pixels differ, %d outside the corner\n", red_d, red_p, differ,
              differ_outside);
  CHECK_GT(red_d, 20);
  CHECK_EQ(red_p, 0);
  CHECK_GT(differ, 300);
  CHECK_EQ(differ_outside, 0);  // the iso view leaves the corner free: the same framing
}

TEST(run_frame_status_puts_the_status_line_under_saved_frames) {
  if (skip()) return;
  CHECK_EQ(run(std::string(kBase) + "--frames %/fs --frame-format ppm --every 8 --frame-status --image %/fs.ppm").code, 0);
  CHECK_EQ(run(std::string(kBase) + "--frames %/fn --frame-format ppm --every 8 --image %/fn.ppm").code, 0);
  const Image first = read_ppm(tmp_dir() + "/fs/frame-000001.ppm"), last = read_ppm(tmp_dir() + "/fs/frame-000004.ppm");
  const Image plain = read_ppm(tmp_dir() + "/fn/frame-000004.ppm");
  // The picture keeps --size; the strip (8 + 4 rows below 960 pixels wide)
  // comes under it, as in the window.
  CHECK_EQ(first.w, 320);
  CHECK_EQ(first.h, 252);
  CHECK_EQ(plain.h, 240);
  if (first.h != 252 || last.h != 252 || plain.h != 240) return;
  int band = 0, ink = 0, picture_differs = 0, band_differs = 0;
  for (int y = 0; y < 252; ++y)
    for (int x = 0; x < 320; ++x) {
      const unsigned char* q = last.at(x, y);
      if (y >= 240) {
        band += q[0] == 24 && q[1] == 28 && q[2] == 36;
        ink += q[0] == 230 && q[1] == 232 && q[2] == 236;
        band_differs += q[0] != first.at(x, y)[0];
      } else {
        picture_differs += q[0] != plain.at(x, y)[0] || q[1] != plain.at(x, y)[1] || q[2] != plain.at(x, y)[2];
      }
    }
  std::printf("  status strip: %d background, %d ink pixels; %d differ from the first frame's\n", band, ink, band_differs);
  CHECK_GT(band, 320 * 12 / 2);
  CHECK_GT(ink, 300);
  CHECK_GT(band_differs, 20);     // the line, position and time moved on
  CHECK_EQ(picture_differs, 0);   // the picture is the frame without the strip
  // Without the option no strip: the last rows are the picture's.
  int plain_band = 0;
  for (int x = 0; x < 320; ++x) plain_band += plain.at(x, 239)[0] == 24 && plain.at(x, 239)[1] == 28;
  CHECK_EQ(plain_band, 0);
  // The final image is the picture alone, with or without the option.
  CHECK_EQ(file_hash(tmp_dir() + "/fs.ppm"), file_hash(tmp_dir() + "/fn.ppm"));
  CHECK_EQ(read_ppm(tmp_dir() + "/fs.ppm").h, 240);
}

TEST(run_hide_tool_takes_the_cutter_out_of_the_final_image) {
  if (skip()) return;
  // pocket.ngc ends with the tool 10 mm over the stock's corner.
  // Aliased: an anti-aliased tool's edge blends into what is behind it.
  CHECK_EQ(run(std::string(kBase) + "--no-antialias --image %/tool.ppm").code, 0);
  CHECK_EQ(run(std::string(kBase) + "--no-antialias --hide-tool --image %/notool.ppm").code, 0);
  const Image a = read_ppm(tmp_dir() + "/tool.ppm"), b = read_ppm(tmp_dir() + "/notool.ppm");
  CHECK(a.h == 240 && b.h == 240);
  if (a.h != 240 || b.h != 240) return;
  int differ = 0, differ_not_tool = 0, red_left = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      const unsigned char *p = a.at(x, y), *q = b.at(x, y);
      const bool diff = p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
      differ += diff;
      differ_not_tool += diff && !reddish(p);  // a changed pixel was the tool's
      red_left += diff && reddish(q);          // and is not red any more
    }
  std::printf("  %d tool pixels gone, %d other pixels changed\n", differ, differ_not_tool);
  CHECK_GT(differ, 500);
  CHECK_EQ(differ_not_tool, 0);
  CHECK_EQ(red_left, 0);
}
