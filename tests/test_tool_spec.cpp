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
