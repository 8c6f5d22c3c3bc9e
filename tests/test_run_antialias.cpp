// `dexmill run`'s anti-aliased stills (display/view/supersample.h) on a known
// scene: the uncut block from straight above, turned 30 degrees, on the
// flat table, whose slanted edges cross the background's dark top rows.
// Along those rows the aliased picture (--no-antialias) steps from the
// background straight to the table, the anti-aliased one holds colours
// between the two; inside the block's flat top both pictures are the same.
#include <cstdint>
#include <cstdio>
#include <string>

#include "tests/run_cli_util.h"
#include "tests/runner.h"

namespace {

using namespace run_cli;

bool same(const unsigned char* p, const unsigned char* q) { return p[0] == q[0] && p[1] == q[1] && p[2] == q[2]; }

// Every channel strictly between lo's and hi's (lo darker in each).
bool between(const unsigned char* p, const unsigned char* lo, const unsigned char* hi) {
  for (int c = 0; c < 3; ++c)
    if (p[c] <= lo[c] || p[c] >= hi[c]) return false;
  return true;
}

// Pixels of the 3x3 block around (x, y) that are `a`.
int count_in_block(const Image& im, int x, int y, const unsigned char* a) {
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) n += same(im.at(x + dx, y + dy), a);
  return n;
}

}  // namespace

TEST(run_antialias_smooths_edges_and_keeps_flat_regions) {
  if (skip()) return;
  write_tmp("still.ngc", "G21 G90\nG0 Z10\nM2\n");
  const std::string base = "%/still.ngc -q --size 160x120 --hide-tool --no-decorations --elevation 90 --azimuth 30 ";
  CHECK_EQ(run(base + "--image %/aa.ppm").code, 0);
  CHECK_EQ(run(base + "--no-antialias --image %/al.ppm").code, 0);
  const Image aa = read_ppm(tmp_dir() + "/aa.ppm"), al = read_ppm(tmp_dir() + "/al.ppm");
  CHECK(aa.w == 160 && aa.h == 120 && al.w == 160 && al.h == 120);
  if (aa.w != 160 || al.w != 160 || aa.h != 120 || al.h != 120) return;
  // The top at the centre, the table at the middle of the frame's top edge.
  const unsigned char* top = al.at(80, 60);
  const unsigned char* table = al.at(80, 4);
  int rows = 0, soft = 0, hard = 0, flat = 0, flat_same = 0;
  for (int y = 1; y < 119; ++y) {
    // A row that starts in the background, darker than the table in every
    // channel by 16 or more: everything else in it (the table, the block's
    // top and its sides' slivers) is lighter than the table or the table.
    const unsigned char* bg = al.at(0, y);
    bool dark = same(al.at(1, y), bg);
    for (int c = 0; c < 3; ++c) dark = dark && bg[c] + 16 <= table[c];
    if (dark) {
      ++rows;
      for (int x = 0; x < 160; ++x) {
        soft += between(aa.at(x, y), bg, table);
        hard += between(al.at(x, y), bg, table);
      }
    }
    for (int x = 1; x < 159; ++x)
      if (count_in_block(al, x, y, top) == 9) {
        ++flat;
        flat_same += same(aa.at(x, y), al.at(x, y));
      }
  }
  std::printf("  %d dark rows: %d pixels between background and table anti-aliased, %d aliased; %d of %d flat "
              "pixels equal\n", rows, soft, hard, flat_same, flat);
  CHECK_GT(rows, 5);
  CHECK_GT(soft, rows);
  CHECK_EQ(hard, 0);
  CHECK_GT(flat, 2000);
  CHECK_EQ(flat_same, flat);
}

namespace {

// The ink of the path's done feeds (display/overlay/backplot.h: 24, 100, 255) over
// the grey stock, in pixels of full strength: blue over red, summed and
// divided by the colour's own. A line one pixel wide drawn one pixel wide at
// twice the size would average to half of the aliased picture's.
double feed_ink(const Image& im) {
  int64_t sum = 0;
  for (int y = 0; y < im.h; ++y)
    for (int x = 0; x < im.w; ++x) {
      const int d = im.at(x, y)[2] - im.at(x, y)[0];
      if (d > 24) sum += d;
    }
  return static_cast<double>(sum) / (255 - 24);
}

// Pixels where the design is blended over the cut (bluer than grey).
int blended_pixels(const Image& im) {
  int n = 0;
  for (int y = 0; y < im.h; ++y)
    for (int x = 0; x < im.w; ++x) n += im.at(x, y)[2] > im.at(x, y)[0] + 40;
  return n;
}

// Pixels of `al` inside a 3x3 block of one colour, and how many of them
// `aa` has the same.
void flat_equal(const Image& al, const Image& aa, int* flat, int* flat_same) {
  *flat = *flat_same = 0;
  for (int y = 1; y < al.h - 1; ++y)
    for (int x = 1; x < al.w - 1; ++x)
      if (count_in_block(al, x, y, al.at(x, y)) == 9) {
        ++*flat;
        *flat_same += same(aa.at(x, y), al.at(x, y));
      }
}

}  // namespace

// The still of `args` anti-aliased (the default) and with --no-antialias,
// 320x240; false (checked) when either is missing. Their flat regions
// (3x3 blocks of one colour in the aliased one) must be the same but at
// the edges.
bool still_pair(const std::string& args, const char* name, Image* aa, Image* al) {
  CHECK_EQ(run(args + "--image %/" + name + "-aa.ppm").code, 0);
  CHECK_EQ(run(args + "--no-antialias --image %/" + name + "-al.ppm").code, 0);
  *aa = read_ppm(tmp_dir() + "/" + name + "-aa.ppm");
  *al = read_ppm(tmp_dir() + "/" + name + "-al.ppm");
  CHECK(aa->w == 320 && al->w == 320);
  if (aa->w != 320 || al->w != 320) return false;
  int flat = 0, flat_same = 0;
  flat_equal(*al, *aa, &flat, &flat_same);
  std::printf("  %s: %d of %d flat pixels equal\n", name, flat_same, flat);
  CHECK_GT(flat, 20000);
  CHECK_GT(flat_same * 100, flat * 99);
  return true;
}

TEST(run_antialias_path_overlay_keeps_its_strength) {
  if (skip()) return;
  Image aa, al;
  if (!still_pair("pocket.ngc -q --size 320x240 --hide-tool --no-decorations --view top --path-overlay ", "path", &aa,
                  &al))
    return;
  const double ink_aa = feed_ink(aa), ink_al = feed_ink(al);
  std::printf("  path ink: %.0f pixels anti-aliased, %.0f aliased\n", ink_aa, ink_al);
  CHECK_GT(ink_al, 200);
  CHECK(ink_aa > 0.85 * ink_al && ink_aa < 1.15 * ink_al);
}

TEST(run_antialias_overlay_blends_at_twice_the_size) {
  if (skip()) return;
  Image aa, al;
  if (!still_pair("pocket.ngc -q --size 320x240 --hide-tool --no-decorations --design pocket_design.stl "
                  "--overlay design ",
                  "overlay", &aa, &al))
    return;
  const int blend_aa = blended_pixels(aa), blend_al = blended_pixels(al);
  std::printf("  design over the cut: %d pixels blended anti-aliased, %d aliased\n", blend_aa, blend_al);
  CHECK_GT(blend_al, 500);
  CHECK(blend_aa * 10 > blend_al * 9 && blend_aa * 10 < blend_al * 11);
  CHECK(aa.rgb != al.rgb);
}
