// core/sim/blk_form_comment.h: Heidenhain's (BLK FORM 0.1 ...) and
// (BLK FORM 0.2 ...) comments read as the stock's box, absolute or
// incremental; what is not one is not read, with its reason; and `dexmill
// run` takes the box when no --stock is given.
#include <cstring>
#include <string>

#include "core/sim/blk_form_comment.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
bool read(const char* s, bool inch, BlkForm* st, WorkpieceBox* b, const char** why) {
  return blk_form_comment(s, std::strlen(s), inch, st, b, why);
}
}  // namespace

TEST(blk_form_comment_reads_min_and_max) {
  BlkForm st;
  WorkpieceBox b;
  const char* why = nullptr;
  // A MIN point alone is no box yet, and no complaint.
  CHECK(!read("(BLK FORM 0.1 Z X+0 Y-10 Z-40)", false, &st, &b, &why) && why == nullptr && st.have_min);
  CHECK(read("(BLK FORM 0.2 X+100 Y+90 Z+0)", false, &st, &b, &why));
  CHECK(b.kind == WorkpieceKind::kBox);
  CHECK(b.lo == (PointNm{0, -10 * kNmPerMm, -40 * kNmPerMm}) && b.hi == (PointNm{100 * kNmPerMm, 90 * kNmPerMm, 0}));
  CHECK(!st.have_min);  // used up
  // Incremental MAX, lower case, inches, after code on the line.
  CHECK(!read("G0 X0 (blk form 0.1 z x-1 y-1 z-0.5)", true, &st, &b, &why) && why == nullptr);
  CHECK(read("(blk form 0.2 ix2 iy2.5 iz0.5)", true, &st, &b, &why));
  CHECK(b.lo == (PointNm{-25400000, -25400000, -12700000}) && b.hi == (PointNm{25400000, 38100000, 0}));
  // Not one: none, or one with its reason.
  BlkForm fresh;
  CHECK(!read("(a comment)", false, &fresh, &b, &why) && why == nullptr);
  CHECK(!read("(BLK FORM 0.2 X1 Y1 Z0)", false, &fresh, &b, &why) && why != nullptr);  // no 0.1 before it
  const char* const bad_min[] = {"(BLK FORM 0.1 X X+0 Y+0 Z-40)", "(BLK FORM 0.1 X+0 Y+0 Z-40)",
                                 "(BLK FORM 0.1 Z X+0 Y+0)", "(BLK FORM 0.1 Z X+0 Y+0 Z-40",
                                 "(BLK FORM 0.1 Z IX+0 Y+0 Z-40)", "(BLK FORM 0.1 Z X+0 X+1 Y+0 Z-40)",
                                 "(BLK FORM 0.1 Z X+0 Y+0 Z-99999999)", "(BLK FORM CYLINDER Z R50 L105)",
                                 "(BLK FORM 0.15 Z X0 Y0 Z0)", "(BLK FORM 0.1 Z X+a Y+0 Z-40)"};
  for (const char* s : bad_min) {
    BlkForm f;
    why = nullptr;
    CHECK(!read(s, false, &f, &b, &why) && why != nullptr && !f.have_min);
  }
  // A MAX not above its MIN.
  BlkForm m;
  CHECK(!read("(BLK FORM 0.1 Z X0 Y0 Z0)", false, &m, &b, &why));
  CHECK(!read("(BLK FORM 0.2 X10 Y10 Z-5)", false, &m, &b, &why) && why != nullptr);
}

TEST(run_takes_the_blk_form_stock) {
  using namespace run_cli;
  if (skip()) return;
  write_tmp("blk.ngc", "G21 G90\n(BLK FORM 0.1 Z X+0 Y+0 Z-12.5)\n(BLK FORM 0.2 IX+40 IY+30 IZ+12.5)\nG0 X5 Y5 Z5\n"
                       "G1 Z-1 F300\nG1 X20\nM30\n");
  Result r = run("%/blk.ngc --tool flat:3 --pitch 0.5 -q");
  CHECK_EQ(r.code, 0);
  CHECK(has(r.out, "stock    X0.000..40.000 Y0.000..30.000 Z-12.500..0.000 mm (from BLK FORM comments)"));
  write_tmp("blk2.ngc", "G21 G90\n(BLK FORM 0.2 X40 Y30 Z0)\nG0 X5 Y5 Z5\nG1 Z-1 F300\nM30\n");
  r = run("%/blk2.ngc --tool flat:3 --pitch 0.5");
  CHECK(has(r.err, "blk2.ngc:2: warning: a (BLK FORM ...) comment not read: a BLK FORM 0.2 without its 0.1"));
  CHECK(has(r.out, "(from the program's moves"));
}
