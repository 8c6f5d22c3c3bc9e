// `dexmill run`'s anti-aliased stills (display/supersample.h) on a known
// scene: the uncut block from straight above, turned 30 degrees, on the
// flat table, whose slanted edges cross the background's dark top rows.
// Along those rows the aliased picture (--no-antialias) steps from the
// background straight to the table, the anti-aliased one holds colours
// between the two; inside the block's flat top both pictures are the same.
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
