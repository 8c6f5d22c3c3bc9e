// core/sim/workpiece_comment.h: LinuxCNC's (WORKPIECE,...) comments read as
// the stock's box; what is not one is not read, with its reason; and
// `dexmill run` takes the box when no --stock is given.
#include <cstring>
#include <string>

#include "core/sim/workpiece_comment.h"
#include "tests/run_cli_util.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
bool read(const char* s, bool inch, WorkpieceBox* b, const char** why) { return workpiece_comment(s, std::strlen(s), inch, b, why); }
}  // namespace

TEST(workpiece_comment_reads_box_cylinder_tube) {
  WorkpieceBox b;
  const char* why = nullptr;
  CHECK(read("(WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=-40,XMAX=100,YMAX=100,ZMAX=0)", false, &b, &why));
  CHECK(b.kind == WorkpieceKind::kBox);
  CHECK(b.lo == (PointNm{0, 0, -40 * kNmPerMm}) && b.hi == (PointNm{100 * kNmPerMm, 100 * kNmPerMm, 0}));
  // Keys in any order and case, after code on the line; inches.
  CHECK(read("G0 X1 (workpiece,box,zmax=0,xmax=2,ymax=1.5,xmin=0,ymin=0,zmin=-0.25)", true, &b, &why));
  CHECK(b.hi == (PointNm{50800000, 38100000, 0}) && b.lo.z_nm == -6350000);
  CHECK(read("(WORKPIECE,CYLINDER,AXIS=Z,X=10,Y=-5,ZMIN=-40,ZMAX=0,DIAMETER=80)", false, &b, &why));
  CHECK(b.kind == WorkpieceKind::kCylinder);
  CHECK(b.lo == (PointNm{-30 * kNmPerMm, -45 * kNmPerMm, -40 * kNmPerMm}) && b.hi == (PointNm{50 * kNmPerMm, 35 * kNmPerMm, 0}));
  CHECK(read("(WORKPIECE,TUBE,AXIS=Z,X=0,Y=0,ZMIN=-40,ZMAX=0,DIAMETER=80,INNER_DIAMETER=40)", false, &b, &why));
  CHECK(b.kind == WorkpieceKind::kTube);
  // Not one: none, or one with its reason.
  CHECK(!read("(a comment)", false, &b, &why) && why == nullptr);
  CHECK(!read("(WORKPIECE,SPHERE,R=3)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=0,XMAX=1,YMAX=1)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,BOX,XMIN=5,YMIN=0,ZMIN=-1,XMAX=1,YMAX=1,ZMAX=0)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=-1,XMAX=1e3,YMAX=1,ZMAX=0)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=-1,XMAX=99999999,YMAX=1,ZMAX=0)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,TUBE,AXIS=Z,X=0,Y=0,ZMIN=-4,ZMAX=0,DIAMETER=8,INNER_DIAMETER=9)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,CYLINDER,AXIS=X,X=0,Y=0,ZMIN=-4,ZMAX=0,DIAMETER=8)", false, &b, &why) && why != nullptr);
  CHECK(!read("(WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=-1,XMAX=1,YMAX=1,ZMAX=0", false, &b, &why) && why != nullptr);
}

TEST(run_takes_the_stock_from_a_workpiece_comment) {
  using namespace run_cli;
  if (skip()) return;
  // Two comments add up; G54 moves them with the program.
  write_tmp("wp.ngc", "G10 L2 P1 X100\nG54\n(WORKPIECE,BOX,XMIN=0,YMIN=0,ZMIN=-12,XMAX=40,YMAX=30,ZMAX=0)\n"
                      "(WORKPIECE,BOX,XMIN=30,YMIN=20,ZMIN=-12,XMAX=50,YMAX=40,ZMAX=0)\nG21 G90\nG0 X5 Y5 Z5\n"
                      "G1 Z-2 F300\nG1 X20 F600\nM30\n");
  Result r = run("%/wp.ngc --tool flat:3 --pitch 0.5 --report %/wp.json");
  CHECK_EQ(r.code, 0);
  CHECK(has(slurp(tmp_dir() + "/wp.json"),
            "\"stock\": {\"min_mm\": [100.0000, 0.0000, -12.0000], \"max_mm\": [150.0000, 40.0000, 0.0000], \"source\": \"workpiece comment\"}"));
  // --stock wins over the comment.
  r = run("%/wp.ngc --tool flat:3 --pitch 0.5 --stock 90,0,-5,130,30,0 --report %/wp2.json");
  CHECK(has(slurp(tmp_dir() + "/wp2.json"), "\"source\": \"option\""));
}
