// --tool text: every shape, len=, canonical formatting, and each error.
#include <cstring>
#include <string>

#include "core/math/fixed.h"
#include "core/tool/spec.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {
ToolSpecError parse(const char* s, Tool* t) { return tool_spec_parse(s, std::strlen(s), t); }
std::string fmt(const Tool& t) {
  char b[64];
  tool_spec_format(t, b, sizeof b);
  return b;
}
}  // namespace

TEST(tool_spec_shapes) {
  Tool t;
  CHECK_EQ(parse("ball:6", &t), ToolSpecError::kOk);
  CHECK_EQ(t.kind, ToolKind::kBall);
  CHECK_EQ(t.diameter_nm, 6 * kNmPerMm);
  CHECK_EQ(t.length_nm, 30 * kNmPerMm);
  CHECK(fmt(t) == "ball:6");
  CHECK_EQ(parse("FLAT:3.175", &t), ToolSpecError::kOk);
  CHECK_EQ(t.kind, ToolKind::kFlat);
  CHECK_EQ(t.diameter_nm, 3175000);
  CHECK(fmt(t) == "flat:3.175");
  CHECK_EQ(parse("bull:10:1.5,len=25", &t), ToolSpecError::kOk);
  CHECK_EQ(t.kind, ToolKind::kBullNose);
  CHECK_EQ(t.corner_radius_nm, 1500000);
  CHECK_EQ(t.flute_length_nm, 25 * kNmPerMm);
  CHECK(fmt(t) == "bull:10:1.5,len=25");
  CHECK_EQ(parse("vbit:6:60", &t), ToolSpecError::kOk);
  CHECK_EQ(t.tip_angle_mdeg, 60000);
  CHECK(fmt(t) == "vbit:6:60");
  // A very narrow V-bit is taller than 30 mm: the stick-out follows it.
  CHECK_EQ(parse("vbit:20:10", &t), ToolSpecError::kOk);
  CHECK_GT(t.length_nm, 100 * kNmPerMm);
  CHECK_EQ(parse("flat:40", &t), ToolSpecError::kOk);
  CHECK_EQ(t.length_nm, 80 * kNmPerMm);
}

TEST(tool_spec_errors) {
  Tool t;
  CHECK_EQ(parse("drill:6", &t), ToolSpecError::kUnknownShape);
  CHECK_EQ(parse("", &t), ToolSpecError::kUnknownShape);
  CHECK_EQ(parse("ball:", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("ball:x", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("ball:-6", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("ball:0", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("ball:6:2", &t), ToolSpecError::kFieldCount);
  CHECK_EQ(parse("bull:6", &t), ToolSpecError::kFieldCount);
  CHECK_EQ(parse("vbit:6:60:1:2", &t), ToolSpecError::kFieldCount);
  CHECK_EQ(parse("ball:6,length=3", &t), ToolSpecError::kBadOption);
  CHECK_EQ(parse("ball:6,len=", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("bull:6:4", &t), ToolSpecError::kOutOfRange);
  CHECK_EQ(parse("vbit:6:180", &t), ToolSpecError::kOutOfRange);
  CHECK_EQ(parse("flat:2000", &t), ToolSpecError::kOutOfRange);
  CHECK(std::strlen(tool_spec_message(ToolSpecError::kFieldCount)) > 10);
}

// The parts above the flutes (the tool's body, core/safety/body.h): stick-out,
// shank, holder pieces, and the non-centre-cutting flag, each read and
// written back.
TEST(tool_spec_holder) {
  Tool t;
  CHECK_EQ(parse("flat:6,len=20,stick=35,holder=20x10,30-40x15", &t), ToolSpecError::kOk);
  CHECK_EQ(t.flute_length_nm, 20 * kNmPerMm);
  CHECK_EQ(t.stick_out_nm, 35 * kNmPerMm);
  CHECK_EQ(t.length_nm, 35 * kNmPerMm);
  CHECK_EQ(t.holder_segments, 2);
  CHECK_EQ(t.holder[0].bottom_diameter_nm, 20 * kNmPerMm);
  CHECK_EQ(t.holder[0].top_diameter_nm, 20 * kNmPerMm);
  CHECK_EQ(t.holder[0].height_nm, 10 * kNmPerMm);
  CHECK_EQ(t.holder[1].bottom_diameter_nm, 30 * kNmPerMm);
  CHECK_EQ(t.holder[1].top_diameter_nm, 40 * kNmPerMm);
  CHECK_EQ(t.holder[1].height_nm, 15 * kNmPerMm);
  CHECK(t.centre_cutting);
  CHECK(fmt(t) == "flat:6,len=20,stick=35,holder=20x10,30-40x15");
  // Options in any order; holder pieces end at the next key.
  CHECK_EQ(parse("ball:3,holder=12.5x8,shank=4,nocentre,len=9", &t), ToolSpecError::kOk);
  CHECK_EQ(t.holder_segments, 1);
  CHECK_EQ(t.shank_diameter_nm, 4 * kNmPerMm);
  CHECK(!t.centre_cutting);
  CHECK(fmt(t) == "ball:3,len=9,shank=4,holder=12.5x8,nocentre");
  CHECK_EQ(parse("flat:6,nocenter", &t), ToolSpecError::kOk);
  CHECK(!t.centre_cutting);
  // Errors.
  CHECK_EQ(parse("flat:6,holder=20", &t), ToolSpecError::kBadHolder);
  CHECK_EQ(parse("flat:6,holder=20x", &t), ToolSpecError::kBadHolder);
  CHECK_EQ(parse("flat:6,holder=x5", &t), ToolSpecError::kBadHolder);
  CHECK_EQ(parse("flat:6,holder=20-x5", &t), ToolSpecError::kBadHolder);
  CHECK_EQ(parse("flat:6,holder=1x1,2x2,3x3,4x4,5x5", &t), ToolSpecError::kBadHolder);
  CHECK_EQ(parse("flat:6,holder=1x1,holder=2x2", &t), ToolSpecError::kBadHolder);
  CHECK_EQ(parse("flat:6,20x10", &t), ToolSpecError::kBadOption);
  CHECK_EQ(parse("flat:6,stick=", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("flat:6,len=20,stick=10", &t), ToolSpecError::kOutOfRange);  // stick-out under the flutes
  CHECK_EQ(parse("ball:6,stick=2", &t), ToolSpecError::kOutOfRange);         // under the ball
  CHECK_EQ(parse("flat:6,shank=2000", &t), ToolSpecError::kOutOfRange);
  CHECK_EQ(parse("drill:6,foo", &t), ToolSpecError::kUnknownShape);
  CHECK(std::strlen(tool_spec_message(ToolSpecError::kBadHolder)) > 10);
}

TEST(tool_spec_flutes) {
  // flutes=N: the edges a chip per tooth divides the feed among; written back.
  Tool t;
  CHECK_EQ(parse("flat:6,flutes=3", &t), ToolSpecError::kOk);
  CHECK_EQ(t.flutes, 3);
  CHECK(fmt(t) == "flat:6,flutes=3");
  CHECK_EQ(parse("bull:10:1.5,len=25,flutes=12,nocentre", &t), ToolSpecError::kOk);
  CHECK(fmt(t) == "bull:10:1.5,len=25,nocentre,flutes=12");
  CHECK_EQ(parse("flat:6", &t), ToolSpecError::kOk);
  CHECK_EQ(t.flutes, 0);  // not given: kToolFlutesAssumed is taken, and said
  CHECK_EQ(parse("flat:6,flutes=0", &t), ToolSpecError::kOutOfRange);
  CHECK_EQ(parse("flat:6,flutes=65", &t), ToolSpecError::kOutOfRange);
  CHECK_EQ(parse("flat:6,flutes=2.5", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("flat:6,flutes=", &t), ToolSpecError::kBadNumber);
  CHECK_EQ(parse("flat:6,flutes=1000", &t), ToolSpecError::kOutOfRange);
}
